// A press image given on the command line (predict and render --image, --reference) is a sensor
// frame: a PNG, or a JPEG libjpeg decodes without a warning, of a frame's size and shape. Anything
// else is refused naming the file, before a spectrum is made from grey or garbage pixels (review 4,
// finding 8: a JPEG with 200 bytes overwritten, a 1 x 1 and a 1 x 20000 image and a TIFF gave
// spectra with exit code 0).
#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <opencv2/imgproc.hpp>

#include "tests/hostile/hostile_support.hpp"
#include "tests/support/ar_fixture.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

cv::Mat frame(int rows, int cols) {
  cv::Mat image(rows, cols, CV_8UC3);
  cv::randu(image, 0, 255);
  cv::GaussianBlur(image, image, cv::Size(9, 9), 3);
  return image;
}

void write_bytes(const std::string& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

CommandResult predict_from(const std::string& image) {
  return run_haptex({"predict", quick_model(), "--image", image, "--normal-force", "1", "--speed", "100"});
}

TEST(PressImage, AFrameThatIsDamagedTinyStretchedOrNeitherPngNorJpegIsRefused) {
  const TempDir dir;
  std::vector<std::uint8_t> jpeg;
  ASSERT_TRUE(cv::imencode(".jpg", frame(480, 640), jpeg));
  write_bytes(dir.file("ok.jpg"), jpeg);
  // Cut in its coded data and closed with an end marker (a transfer cut short): libjpeg warns
  // "premature end of data segment" and draws the rest grey.
  jpeg.resize(jpeg.size() * 3 / 5);
  jpeg.insert(jpeg.end(), {0xFF, 0xD9});
  write_bytes(dir.file("damaged.jpg"), jpeg);
  ASSERT_TRUE(cv::imwrite(dir.file("ok.png"), frame(120, 160)));
  ASSERT_TRUE(cv::imwrite(dir.file("tiny.png"), frame(1, 1)));
  ASSERT_TRUE(cv::imwrite(dir.file("line.png"), frame(1, 20000)));
  ASSERT_TRUE(cv::imwrite(dir.file("frame.tiff"), frame(120, 160)));
  ASSERT_TRUE(cv::imwrite(dir.file("frame.bmp"), frame(120, 160)));
  EXPECT_EQ(predict_from(dir.file("ok.jpg")).exit_code, 0);
  EXPECT_EQ(predict_from(dir.file("ok.png")).exit_code, 0);
  expect_refusal(predict_from(dir.file("damaged.jpg")), {dir.file("damaged.jpg"), "does not decode whole", "libjpeg: Corrupt JPEG data"});
  expect_refusal(predict_from(dir.file("tiny.png")), {dir.file("tiny.png"), "1 x 1 pixels", "no sensor frame"});
  expect_refusal(predict_from(dir.file("line.png")), {dir.file("line.png"), "20000 x 1 pixels", "no sensor frame"});
  expect_refusal(predict_from(dir.file("frame.tiff")), {dir.file("frame.tiff"), "not a PNG or JPEG image"});
  expect_refusal(predict_from(dir.file("frame.bmp")), {dir.file("frame.bmp"), "not a PNG or JPEG"});
  const CommandResult r = run_haptex({"predict", quick_model(), "--image", dir.file("ok.png"), "--reference", dir.file("damaged.jpg"),
                                      "--normal-force", "1", "--speed", "100"});
  expect_refusal(r, {dir.file("damaged.jpg"), "does not decode whole"});
  EXPECT_EQ(r.err.find("Corrupt JPEG data: premature"), r.err.rfind("Corrupt JPEG data: premature")) << "libjpeg printed nothing itself: " << r.err;
}

// Review 23, F2: synth hatt read its texture photographs through OpenCV: a JPEG whose header states
// 60000 x 60000 ended in OpenCV's assertion text (exit 1), one cut short was taken (exit 0, libjpeg's
// warning printed raw, presses cut from a half-grey photograph). It reads them as predict --image does.
TEST(PressImage, SynthHattRefusesAPhotographThatIsHugeOrCutShort) {
  const TempDir dir;
  std::vector<std::uint8_t> jpeg;
  ASSERT_TRUE(cv::imencode(".jpg", frame(1000, 1000), jpeg));
  std::vector<std::uint8_t> huge = jpeg, cut(jpeg.begin(), jpeg.begin() + std::ptrdiff_t(jpeg.size() / 3));
  const std::uint8_t start_of_frame[] = {0xFF, 0xC0};
  const auto sof = std::search(huge.begin(), huge.end(), std::begin(start_of_frame), std::end(start_of_frame));
  ASSERT_NE(sof, huge.end());
  sof[5] = sof[7] = 0xEA, sof[6] = sof[8] = 0x60;  // height and width, big-endian: 60000 each
  fs::create_directories(dir.file("models"));
  std::ofstream(dir.file("models/Models_Fixture.xml")) << kArFixtureXml;
  for (const auto& [name, bytes] : {std::pair{"huge", huge}, std::pair{"cut", cut}, std::pair{"ok", jpeg}}) {
    fs::create_directories(dir.file(name));
    write_bytes(dir.file(std::string(name) + "/Fixture_square.jpg"), bytes);
    const CommandResult r = run_haptex({"synth", "hatt", "--models", dir.file("models"), "--images", dir.file(name), "-o",
                                        dir.file(std::string(name) + ".out"), "--recordings", "1", "--seconds", "0.5"});
    if (std::string(name) == "ok") {
      EXPECT_EQ(r.exit_code, 0) << r.err;
      continue;
    }
    expect_refusal(r, {dir.file(std::string(name) + "/Fixture_square.jpg"), name == std::string("huge") ? "over 64 megapixels" : "does not decode whole"});
    EXPECT_EQ(r.err.find("OpenCV"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("Premature end"), std::string::npos) << "libjpeg printed nothing itself: " << r.err;
    EXPECT_FALSE(fs::exists(dir.file(std::string(name) + ".out")));
  }
}

}  // namespace
}  // namespace haptex::test
