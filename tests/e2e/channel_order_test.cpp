// Colour order through extract and predict (the any-sensor issue, section 3): files say which
// channel order their images use, and readers honour it. Each test turns a file into its twin with
// blue stored first (pixels swapped, `channel_order` BGR), which must read exactly as the original,
// and into the same swap left saying RGB: what a reader ignoring the attribute would see, which must
// differ, or these tests could not fail.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "capture/device/fake_scene.hpp"
#include "core/temporary_name.hpp"
#include "dataset/press_images.hpp"
#include "dataset/vlen_bytes.hpp"
#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "predict/model_file.hpp"
#include "predict/predictor.hpp"
#include "predict/texture_descriptor.hpp"
#include "predict/training_data.hpp"
#include "tests/capture/fake_setup.hpp"
#include "tests/capture/press_videos.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/small_pipeline.hpp"

namespace haptex::test {
namespace {

namespace fs = std::filesystem;

void swap_red_blue(std::vector<std::uint8_t>& pixels) {
  for (std::size_t i = 0; i + 2 < pixels.size(); i += 3) std::swap(pixels[i], pixels[i + 2]);
}

// Mean |R - B| over interleaved pixels: how much a swap changes them.
double red_blue_difference(const std::vector<std::uint8_t>& pixels) {
  double sum = 0;
  for (std::size_t i = 0; i + 2 < pixels.size(); i += 3) sum += std::abs(int(pixels[i]) - int(pixels[i + 2]));
  return sum / double(pixels.size() / 3);
}

// The pixels a dataset stores, interleaved in their stored order: an array's as they are, encoded
// images' as their format decodes them (R first), one after the other.
std::vector<std::uint8_t> stored(const std::string& file, const std::string& path) {
  const h5::Dataset d = h5::File::open(file).root().open_dataset(path);
  if (!dataset::is_vlen_bytes(d)) return d.read<std::uint8_t>();
  std::vector<std::uint8_t> pixels;
  for (std::size_t i = 0; i < d.shape()[0]; ++i) {
    cv::Mat rgb;
    cv::cvtColor(cv::imdecode(dataset::read_vlen_bytes(d, i), cv::IMREAD_COLOR), rgb, cv::COLOR_BGR2RGB);
    pixels.insert(pixels.end(), rgb.data, rgb.data + rgb.total() * 3);
  }
  return pixels;
}

// The stored pixels of `images` (datasets of the group `press`) swapped, and `order` stated on the
// group and on each image; encoded images are stored again as PNG, lossless.
void swap_images(const std::string& file, const std::string& press, const std::vector<std::string>& images,
                 const std::string& order) {
  Edit e(file);
  const std::string prefix = press.empty() ? "" : press + "/";
  for (const auto& name : images) {
    const h5::Dataset d = e.dataset(prefix + name);
    if (!dataset::is_vlen_bytes(d)) {
      e.change_bytes(prefix + name, swap_red_blue);
    } else {
      std::vector<dataset::EncodedImage> swapped;
      for (std::size_t i = 0; i < d.shape()[0]; ++i) {
        cv::Mat image = cv::imdecode(dataset::read_vlen_bytes(d, i), cv::IMREAD_COLOR);
        cv::cvtColor(image, image, cv::COLOR_BGR2RGB);
        swapped.push_back(dataset::encode_png(image));
      }
      e.remove(prefix + name);
      h5::Group g = press.empty() ? e.root() : e.group(press);
      dataset::write_press_images(g, name, swapped, "swapped by a test");
    }
    e.dataset(prefix + name).set_attr("channel_order", order);
  }
  (press.empty() ? e.root() : e.group(press)).set_attr("channel_order", order);
}

// A press file with every colour swapped, saying `order`: its frames encoded again as they were
// (YUYV frames as lossless PNG, MJPG frames as JPEG of quality 100).
void swap_press_file(const std::string& file, const std::string& order) {
  swap_images(file, "", {"reference"}, order);
  Edit e(file);
  const bool jpeg = e.root().attr_string("encoding") == "jpeg";
  std::vector<std::vector<std::uint8_t>> encoded;
  const h5::Dataset frames = e.dataset("frames");
  for (std::size_t i = 0; i < frames.shape()[0]; ++i) {
    cv::Mat image = cv::imdecode(dataset::read_vlen_bytes(frames, i), cv::IMREAD_COLOR);
    cv::cvtColor(image, image, cv::COLOR_BGR2RGB);
    std::vector<std::uint8_t> bytes;
    ASSERT_TRUE(cv::imencode(jpeg ? ".jpg" : ".png", image, bytes, {cv::IMWRITE_JPEG_QUALITY, 100}));
    encoded.push_back(std::move(bytes));
  }
  e.remove("frames");
  h5::Group root = e.root();
  dataset::VlenBytesWriter writer(root, "frames");
  for (const auto& bytes : encoded) writer.append(bytes);
}

void extract(const std::string& input, const std::string& output, std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"capture", "extract", input, "-o", output, "--no-sheets"};
  args.insert(args.end(), extra.begin(), extra.end());
  const CommandResult r = run_haptex(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
}

// The texture descriptor of a gelsight press, its images read by haptex (dataset::read_press_image
// honours the stated order) and handed over as RGB, the order texture_descriptor takes.
std::vector<float> descriptor_of(const std::string& gelsight, const std::string& press) {
  const h5::File f = h5::File::open(gelsight);
  const h5::Group g = f.root().open_group(press);
  cv::Mat peak = dataset::read_press_image(g, "peak"), reference = dataset::read_press_image(g, "reference");
  cv::cvtColor(peak, peak, cv::COLOR_BGR2RGB);
  cv::cvtColor(reference, reference, cv::COLOR_BGR2RGB);
  return predict::texture_descriptor(peak, reference);
}

double largest_difference(const std::vector<float>& a, const std::vector<float>& b) {
  double worst = 0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) worst = std::max(worst, double(std::abs(a[i] - b[i])));
  return worst;
}

const std::string kGelsightPress = "materials/cork/presses/0";

class ColourOrder : public ::testing::Test {
 protected:
  // A press file recorded from the fake sensor (YUYV or MJPG), and its twins: blue first saying BGR,
  // and blue first still saying RGB.
  struct Twins {
    std::string original, blue_first, ignored;
  };
  Twins record_press_and_twins(const std::string& format = "YUYV") const {
    const std::string session = dir_.file("session_" + format);
    const CommandResult r = run_haptex({"capture", "record", "--device", "fake:size=320x240,format=" + format + ",lockstep",
                                        "--material", "Cork", "--presses", "1", "-o", session});
    EXPECT_EQ(r.exit_code, 0) << r.err;
    const Twins t{session + "/press_0.h5", copy_into(dir_, session + "/press_0.h5", format + "_blue_first.h5"),
                  copy_into(dir_, session + "/press_0.h5", format + "_ignored.h5")};
    swap_press_file(t.blue_first, "BGR");
    swap_press_file(t.ignored, "RGB");
    return t;
  }
  TempDir dir_;
};

TEST_F(ColourOrder, APressFileStoredBlueFirstExtractsAsTheOriginal) {
  const auto [original, blue_first, ignored] = record_press_and_twins();
  ASSERT_FALSE(HasFailure());
  EXPECT_EQ(h5::File::open(original).root().attr_string("channel_order"), "RGB") << "press files say their order";
  extract(original, dir_.file("g.h5"));
  extract(blue_first, dir_.file("g_blue_first.h5"));
  extract(ignored, dir_.file("g_ignored.h5"));

  const std::vector<std::uint8_t> peak = stored(dir_.file("g.h5"), kGelsightPress + "/peak");
  ASSERT_GT(red_blue_difference(peak), 20.0) << "the fake gel's red and blue must differ for the test to mean anything";
  for (const std::string name : {"peak", "reference", "frames"})
    EXPECT_EQ(stored(dir_.file("g_blue_first.h5"), kGelsightPress + "/" + name), stored(dir_.file("g.h5"), kGelsightPress + "/" + name))
        << name;
  for (const std::string name : {"peak_index", "frame_indices"})
    EXPECT_EQ(h5::File::open(dir_.file("g_blue_first.h5")).root().open_dataset(kGelsightPress + "/" + name).read<std::int64_t>(),
              h5::File::open(dir_.file("g.h5")).root().open_dataset(kGelsightPress + "/" + name).read<std::int64_t>())
        << name;
  EXPECT_NE(stored(dir_.file("g_ignored.h5"), kGelsightPress + "/peak"), peak);
  const std::vector<float> d = descriptor_of(dir_.file("g.h5"), kGelsightPress);
  EXPECT_EQ(descriptor_of(dir_.file("g_blue_first.h5"), kGelsightPress), d);
  EXPECT_GT(largest_difference(descriptor_of(dir_.file("g_ignored.h5"), kGelsightPress), d), 1e-3);
}

// Replayed as a sensor (`--device replay:`), a press file stored blue first sends its frames in their
// true colours again: the new take's reference is the original's replayed, pixel for pixel from raw
// frames, and within a grey level on average from MJPG (decoded, reordered and encoded again).
TEST_F(ColourOrder, APressFileStoredBlueFirstReplaysInItsTrueColours) {
  for (const std::string format : {"YUYV", "MJPG"}) {
    SCOPED_TRACE(format);
    const Twins twins = record_press_and_twins(format);
    ASSERT_FALSE(HasFailure());
    const auto replay = [&](const std::string& file, const std::string& name) {
      const CommandResult take = run_haptex({"capture", "record", "--device", "replay:" + file + ",lockstep", "--material",
                                             "Cork", "--presses", "1", "--warmup", "0", "-o", dir_.file(format + name)});
      EXPECT_EQ(take.exit_code, 0) << take.err;
      return stored(dir_.file(format + name) + "/press_0.h5", "reference");
    };
    const auto mean_difference = [](const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
      double sum = 0;
      for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) sum += std::abs(int(a[i]) - int(b[i]));
      return a.size() == b.size() ? sum / double(a.size()) : INFINITY;
    };
    const std::vector<std::uint8_t> reference = replay(twins.original, "again");
    ASSERT_GT(red_blue_difference(reference), 20.0);
    const double blue_first = mean_difference(replay(twins.blue_first, "blue_first"), reference);
    const double ignored = mean_difference(replay(twins.ignored, "ignored"), reference);
    if (format == "YUYV") {
      EXPECT_EQ(blue_first, 0.0);
    }
    EXPECT_LT(blue_first, 1.0);
    EXPECT_GT(ignored, 10.0);
  }
}

TEST_F(ColourOrder, AVideoIsStoredInItsTrueColoursAndReadBackInTheStatedOrder) {
  const capture::PressSchedule schedule = capture::fixtures::quick_presses(1);
  const std::string video = dir_.file("cork.mkv");
  const std::vector<double> depth = capture::fixtures::write_press_video(video, schedule, 90);
  extract(video, dir_.file("g.h5"), {"--material", "Cork"});
  const h5::File f = h5::File::open(dir_.file("g.h5"));
  const h5::Group press = f.root().open_group(kGelsightPress);
  EXPECT_EQ(press.attr_string("channel_order"), "RGB");
  // The peak holds the video's frame, red first: FFV1 is lossless.
  const std::int64_t at = press.open_dataset("peak_index").read<std::int64_t>().at(0);
  const capture::FakeScene scene(V4L2_PIX_FMT_MJPEG, 160, 120, schedule);
  cv::Mat frame = scene.image(int(std::lround(depth[std::size_t(at)] * capture::FakeScene::kDepthLevels)), int(at % 2)), rgb;
  cv::cvtColor(frame, rgb, cv::COLOR_BGR2RGB);
  const std::vector<std::uint8_t> peak = stored(dir_.file("g.h5"), kGelsightPress + "/peak");
  ASSERT_EQ(peak, std::vector<std::uint8_t>(rgb.data, rgb.data + rgb.total() * 3));
  EXPECT_EQ(press.open_dataset("peak").attr_string("encoding"), "png") << "FFV1 frames are stored losslessly";
  ASSERT_GT(red_blue_difference(peak), 20.0);

  const std::string blue_first = copy_into(dir_, dir_.file("g.h5"), "blue_first.h5"),
                    ignored = copy_into(dir_, dir_.file("g.h5"), "ignored.h5");
  swap_images(blue_first, kGelsightPress, {"peak", "reference", "frames"}, "BGR");
  swap_images(ignored, kGelsightPress, {"peak", "reference", "frames"}, "RGB");
  const std::vector<float> d = descriptor_of(dir_.file("g.h5"), kGelsightPress);
  EXPECT_EQ(descriptor_of(blue_first, kGelsightPress), d);
  EXPECT_GT(largest_difference(descriptor_of(ignored, kGelsightPress), d), 1e-3);
}

// Train, evaluate and the texture encoder read a dataset's presses through press_descriptors.
TEST_F(ColourOrder, ADatasetPressStoredBlueFirstGivesTheSameDescriptorsAndTextureCode) {
  const std::string id = small_material(), press = "materials/" + id + "/presses/0";
  const std::string original = small_pipeline().dataset;
  ASSERT_GT(red_blue_difference(stored(original, press + "/peak")), 5.0) << "the synthetic gel's red and blue must differ";
  const std::string blue_first = copy_into(dir_, original, "blue_first.h5"), ignored = copy_into(dir_, original, "ignored.h5");
  swap_images(blue_first, press, {"peak", "reference", "frames"}, "BGR");
  swap_images(ignored, press, {"peak", "reference", "frames"}, "RGB");
  const predict::Model model = predict::read_model(quick_model());
  const predict::Predictor predictor(model);
  for (const bool training : {false, true}) {
    const auto descriptors = [&](const std::string& file) {
      return predict::press_descriptors(file, id, 0, training, model.descriptor);
    };
    const predict::Descriptors d = descriptors(original);
    EXPECT_EQ(descriptors(blue_first), d) << (training ? "12 frames x 8 augmentations" : "the peak");
    EXPECT_GT(largest_difference(descriptors(ignored).front(), d.front()), 1e-3);
    const predict::TextureCode code = predictor.encode_descriptors(d);
    EXPECT_EQ(predictor.encode_descriptors(descriptors(blue_first)).latent, code.latent);
    EXPECT_NE(predictor.encode_descriptors(descriptors(ignored)).image_latent, code.image_latent);
  }
}

TEST_F(ColourOrder, AnUnknownOrderIsRefusedNamingTheFileAndTheAttribute) {
  const std::string id = small_material(), press = "materials/" + id + "/presses/0";
  const std::string dataset = copy_into(dir_, small_pipeline().dataset, "dataset.h5");
  Edit(dataset).group(press).set_attr("channel_order", "GRB");
  try {
    predict::press_descriptors(dataset, id, 0, false, {});
    FAIL() << "an unknown order was read";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find(dataset + ": /" + press + "/@channel_order: unknown channel order 'GRB'"),
              std::string::npos) << e.what();
  }
  // A press and its image that disagree: which one is right cannot be known.
  Edit(dataset).group(press).set_attr("channel_order", "BGR");
  EXPECT_THROW(predict::press_descriptors(dataset, id, 0, false, {}), Error);

  // align refuses such a gelsight file before writing anything.
  const std::string gelsight = copy_into(dir_, small_pipeline().gelsight, "gelsight.h5");
  Edit(gelsight).group(press).set_attr("channel_order", "GRB");
  const CommandResult r = run_haptex({"align", "--recordings", small_pipeline().recordings, "--gelsight", gelsight, "-o", dir_.file("d.h5")});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(gelsight + ": /" + press + "/@channel_order: unknown channel order 'GRB'. Set it to RGB or BGR"),
            std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir_.file("d.h5")));
  EXPECT_TRUE(temporaries_of(dir_.file("d.h5")).empty());
}

}  // namespace
}  // namespace haptex::test
