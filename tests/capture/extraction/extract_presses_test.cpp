// capture extract: videos and press files -> the gelsight file and contact sheets, or nothing at all.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <cmath>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "capture/extraction/capture_inputs.hpp"
#include "capture/extraction/extract_presses.hpp"
#include "capture/recording/press_recorder.hpp"
#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/image_header.hpp"
#include "core/temporary_name.hpp"
#include "dataset/press_images.hpp"
#include "dataset/vlen_bytes.hpp"
#include "tests/capture/fake_setup.hpp"
#include "tests/capture/press_videos.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::capture {
namespace {

namespace fs = std::filesystem;
using fixtures::quick_presses;

class Extract : public ::testing::Test {
 protected:
  std::string video(const std::string& material, const std::string& name, int presses, int frames = 60) {
    fs::create_directories(dir_.path() / "videos" / material);
    const std::string path = (dir_.path() / "videos" / material / name).string();
    fixtures::write_press_video(path, quick_presses(presses), frames);
    return path;
  }
  std::string out(const std::string& name = "gelsight.h5") const { return dir_.file(name); }
  void expect_nothing_written() const {
    EXPECT_FALSE(fs::exists(out()));
    EXPECT_TRUE(temporaries_of(out()).empty());
    EXPECT_FALSE(fs::exists(dir_.file("gelsight_sheets")));
    EXPECT_TRUE(temporaries_of(dir_.file("gelsight_sheets")).empty());
  }
  haptex::test::TempDir dir_;
};

// Every element of a dataset of encoded images.
std::vector<dataset::EncodedImage> encoded(const h5::Dataset& d) {
  std::vector<dataset::EncodedImage> images;
  for (std::size_t i = 0; i < d.shape()[0]; ++i) images.push_back(dataset::read_vlen_bytes(d, i));
  return images;
}

TEST_F(Extract, AFolderOfMaterialFoldersGivesStablePressNumbers) {
  video("Cork", "press_10.mkv", 1);
  video("Cork", "press_2.mkv", 2, 75);
  video("Brick 2", "press_0.mkv", 1);
  const ExtractResult r = extract_presses({dir_.file("videos")}, out(), {});
  ASSERT_EQ(r.presses.size(), 4u);
  EXPECT_EQ(r.sources, 3u);
  // Materials in folder order; files by number: press_2 before press_10.
  EXPECT_EQ(r.presses[0].material, "Brick 2");
  EXPECT_EQ(r.presses[0].material_id, "brick_2");
  EXPECT_EQ(r.presses[1].material, "Cork");
  EXPECT_NE(r.presses[1].source.find("press_2.mkv"), std::string::npos);
  EXPECT_EQ(r.presses[2].press_in_source, 1);
  EXPECT_NE(r.presses[3].source.find("press_10.mkv"), std::string::npos);
  EXPECT_EQ(r.presses[3].press, 2);
  h5::File f = h5::File::open(out());
  EXPECT_EQ(f.root().attr_string("haptex_format"), "gelsight/2");
  const h5::Group cork = f.root().open_group("materials").open_group("cork");
  EXPECT_EQ(cork.attr_string("name"), "Cork");
  EXPECT_EQ(cork.open_group("presses").children(), (std::vector<std::string>{"0", "1", "2"}));
  for (const auto& p : r.presses) EXPECT_TRUE(fs::exists(dir_.path() / p.contact_sheet)) << p.contact_sheet;
}

// Issue 11 point 5: a video cut off in the middle of a press (MJPG: its last frame's JPEG is cut
// short and would decode, concealed, into a half-grey frame that scores as the strongest contact).
// No frame that did not decode whole is a peak or kept, and the result counts the lost frames.
TEST_F(Extract, AVideoCutShortKeepsNoDamagedFrame) {
  fs::create_directories(dir_.path() / "videos");
  const std::string full = dir_.file("videos/full.avi"), cut = dir_.file("videos/cut.avi");
  fixtures::write_press_video(full, quick_presses(1), 45, 160, 120, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'));
  std::vector<dataset::EncodedImage> frames;  // each frame's JPEG, as the file holds it
  cv::VideoCapture reader(full, cv::CAP_FFMPEG);
  ASSERT_TRUE(reader.set(cv::CAP_PROP_FORMAT, -1));
  for (cv::Mat f; reader.read(f);) frames.emplace_back(f.data, f.data + f.total());
  ASSERT_EQ(frames.size(), 45u);
  fs::copy_file(full, cut);
  fs::resize_file(cut, fs::file_size(full) * 81 / 100);  // inside frame 36's JPEG, during the press's hold

  const ExtractResult r = extract_presses({cut}, out(), {});
  ASSERT_EQ(r.presses.size(), 1u);
  EXPECT_GT(r.frames_unreadable, 0) << "the frames the container announced but that never decoded";
  const h5::Group press = h5::File::open(out()).root().open_group("materials/videos/presses/0");
  const auto indices = press.open_dataset("frame_indices").read<std::int64_t>();
  const std::vector<dataset::EncodedImage> kept = encoded(press.open_dataset("frames"));
  ASSERT_EQ(kept.size(), indices.size());
  EXPECT_EQ(press.open_dataset("frames").attr_string("encoding"), "jpeg");
  for (std::size_t k = 0; k < indices.size(); ++k) {
    ASSERT_LT(std::size_t(indices[k]), frames.size());
    EXPECT_EQ(kept[k], frames[std::size_t(indices[k])]) << "kept frame " << indices[k] << " is not the whole JPEG the file held";
  }
  const std::int64_t peak = press.open_dataset("peak_index").read<std::int64_t>().at(0);
  EXPECT_EQ(press.attr_int("source_frames_unreadable"), r.frames_unreadable) << "the gelsight file records them for qa";
  EXPECT_LT(peak, 36) << "the cut frame (36) or later";
}

TEST_F(Extract, EachPressHoldsReferencePeakTwelveFramesAndScores) {
  const std::string path = video("Cork", "press_0.mkv", 1);
  const ExtractResult r = extract_presses({path}, out(), {});
  ASSERT_EQ(r.presses.size(), 1u);
  h5::File f = h5::File::open(out());
  const h5::Group g = f.root().open_group("materials").open_group("cork").open_group("presses").open_group("0");
  EXPECT_EQ(g.attr_string("source_file"), path);
  EXPECT_EQ(g.attr_string("source_sha256").size(), 64u);
  const std::int64_t start = g.attr_int("frame_start"), end = g.attr_int("frame_end");
  const auto contrast = g.open_dataset("contrast").read<float>();
  EXPECT_EQ(std::int64_t(contrast.size()), end - start + 1);
  EXPECT_EQ(g.attr_int("samples"), std::int64_t(contrast.size()));
  const auto peak_index = g.open_dataset("peak_index");
  EXPECT_TRUE(peak_index.shape().empty()) << "a scalar";
  const std::int64_t peak = peak_index.read<std::int64_t>()[0];
  EXPECT_GE(peak, g.attr_int("contact_first"));
  EXPECT_LE(peak, g.attr_int("contact_last"));
  EXPECT_FLOAT_EQ(contrast[std::size_t(peak - start)], float(g.attr_double("peak_score")));
  EXPECT_EQ(g.open_dataset("frames").shape(), (h5::Shape{12}));
  EXPECT_EQ(g.open_dataset("peak").shape(), (h5::Shape{1}));
  EXPECT_EQ(g.open_dataset("reference").shape(), (h5::Shape{1}));
  EXPECT_EQ(g.open_dataset("peak").attr_string("channel_order"), "RGB");
  for (const char* name : {"frames", "peak", "reference"}) {
    EXPECT_EQ(g.open_dataset(name).attr_string("encoding"), "png") << name << ": FFV1 frames and the reference are lossless";
    for (const cv::Mat& image : dataset::read_press_images(g, name)) EXPECT_EQ(image.size(), cv::Size(160, 120)) << name;
  }
  // The peak is one of the 12 frames, byte for byte.
  const auto indices = g.open_dataset("frame_indices").read<std::int64_t>();
  const auto at = std::find(indices.begin(), indices.end(), peak) - indices.begin();
  ASSERT_LT(at, 12);
  EXPECT_EQ(encoded(g.open_dataset("peak")).at(0), encoded(g.open_dataset("frames")).at(std::size_t(at)));
}

TEST_F(Extract, PressFilesFromTheRecorderNameTheirMaterial) {
  FakeCamera camera(fixtures::small_camera());
  SessionRequest request;
  request.node = "/dev/video0";
  request.output_dir = dir_.file("session");
  RecorderOptions options;
  options.material = "Sandpaper 100";
  options.presses = 2;
  record_session(camera, request, options);
  const ExtractResult r = extract_presses({dir_.file("session")}, out(), {});
  ASSERT_EQ(r.presses.size(), 2u);
  EXPECT_EQ(r.presses[0].material, "Sandpaper 100") << "from the file, not the folder 'session'";
  h5::File f = h5::File::open(out());
  const h5::Group g = f.root().open_group("materials").open_group("sandpaper_100").open_group("presses").open_group("1");
  EXPECT_NE(g.attr_string("reference_source").find("stored in the press file"), std::string::npos);
  EXPECT_EQ(g.open_dataset("frames").shape()[0], 12u);
}

TEST_F(Extract, NoPressAnywhereIsAFailureThatWritesNothing) {
  const std::string still = video("Glass", "still.mkv", 0, 30);
  try {
    extract_presses({still}, out(), {});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::failed);
    EXPECT_NE(std::string(e.what()).find("no press found"), std::string::npos) << e.what();
  }
  expect_nothing_written();
}

// A lab's example video whose sensor light was off (16 frames of mean grey 5.5, GelSight-lab's
// EstimateModulus example.avi) was refused as "only 0 usable frames", which says nothing of why.
TEST_F(Extract, AVideoOfBlackFramesSaysTheyAreBlack) {
  const fs::path folder = dir_.path() / "gelsight" / "Dark" / "press_0";
  fs::create_directories(folder);
  for (int i = 0; i < 16; ++i)
    cv::imwrite((folder / ("frame_" + std::to_string(100 + i) + ".png")).string(), cv::Mat(120, 160, CV_8UC3, cv::Scalar(6, 5, 5)));
  try {
    extract_presses({folder.string()}, out(), {});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find("only 0 usable frames (16 are black, a mean grey under 10 of 255)"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("light was on"), std::string::npos) << e.what();
  }
  expect_nothing_written();
}

TEST_F(Extract, AnUnreadableInputLeavesNothingBehind) {
  const std::string good = video("Cork", "press_0.mkv", 1);
  std::ofstream(dir_.file("videos/Cork/press_1.mkv")) << "not a video";
  try {
    extract_presses({dir_.file("videos")}, out(), {});
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find("press_1.mkv"), std::string::npos) << e.what();
  }
  expect_nothing_written();
}

TEST_F(Extract, RefusesToOverwriteWithoutForce) {
  const std::string path = video("Cork", "press_0.mkv", 1);
  extract_presses({path}, out(), {});
  EXPECT_THROW(extract_presses({path}, out(), {}), Error);
  ExtractOptions force;
  force.overwrite = true;
  EXPECT_NO_THROW(extract_presses({path}, out(), force));
}

TEST_F(Extract, AGivenReferenceImageReplacesTheLeadingFrames) {
  const std::string path = video("Cork", "press_0.mkv", 1);
  const FakeScene scene(V4L2_PIX_FMT_MJPEG, 160, 120, quick_presses(1));
  cv::imwrite(dir_.file("ref.png"), scene.image(0, 0));
  ExtractOptions options;
  options.reference_path = dir_.file("ref.png");
  options.sheets = false;
  const ExtractResult r = extract_presses({path}, out(), options);
  ASSERT_EQ(r.presses.size(), 1u);
  EXPECT_TRUE(r.sheets_dir.empty());
  h5::File f = h5::File::open(out());
  const h5::Group g = f.root().open_group("materials").open_group("cork").open_group("presses").open_group("0");
  EXPECT_EQ(g.attr_string("reference_source"), "image " + dir_.file("ref.png"));
  EXPECT_FALSE(g.has_attr("contact_sheet"));
}

// A press video as a folder of PNG frames, as `haptex synth` writes them.
void write_png_sequence(const fs::path& folder, int presses, int frames, const std::string& ext = ".png") {
  fs::create_directories(folder);
  const FakeScene scene(V4L2_PIX_FMT_MJPEG, 160, 120, quick_presses(presses));
  for (int i = 0; i < frames; ++i) {
    const int level = int(std::lround(scene.depth(std::uint64_t(i)) * FakeScene::kDepthLevels));
    const cv::Mat frame = scene.black(std::uint64_t(i)) ? cv::Mat::zeros(120, 160, CV_8UC3) : scene.image(level, i % 2);
    cv::imwrite((folder / ("frame_" + std::to_string(1000 + i).substr(1) + ext)).string(), frame);
  }
}

// Image sequences are analysed several at a time (the next ones while the last are written), but
// written in their order: one thread or three, the same presses, numbers and frames. A source that
// fails is reported as one at a time would report it: the first in order.
TEST_F(Extract, SequencesOnSeveralThreadsGiveTheSameFileAsOneAtATime) {
  for (int i = 0; i < 5; ++i)
    write_png_sequence(dir_.path() / "gelsight" / (i % 2 ? "Cork" : "Felt") / ("press_" + std::to_string(i)), 1 + i % 2, 60 + 10 * i);
  ExtractOptions one, three;
  one.threads = 1;
  three.threads = 3;
  three.sheets = one.sheets = false;
  const ExtractResult a = extract_presses({dir_.file("gelsight")}, out("one.h5"), one);
  const ExtractResult b = extract_presses({dir_.file("gelsight")}, out("three.h5"), three);
  ASSERT_EQ(a.presses.size(), 7u);
  ASSERT_EQ(b.presses.size(), a.presses.size());
  EXPECT_EQ(b.frames_scored, a.frames_scored);
  const h5::File fa = h5::File::open(out("one.h5")), fb = h5::File::open(out("three.h5"));
  for (std::size_t i = 0; i < a.presses.size(); ++i) {
    const auto &pa = a.presses[i], &pb = b.presses[i];
    EXPECT_EQ(pb.source, pa.source);
    EXPECT_EQ(pb.press, pa.press);
    EXPECT_EQ(pb.peak_index, pa.peak_index);
    const auto group = [&](const h5::File& f, const ExtractedPressSummary& p) {
      return f.root().open_group("materials").open_group(p.material_id).open_group("presses").open_group(std::to_string(p.press));
    };
    for (const char* name : {"frames", "peak", "reference"})
      EXPECT_EQ(encoded(group(fb, pb).open_dataset(name)), encoded(group(fa, pa).open_dataset(name)))
          << pa.source << " " << name;
  }
  // Two unreadable frames in two sequences of one chunk: the error names the first in order.
  std::ofstream(dir_.file("gelsight/Cork/press_1/frame_010.png")) << "not an image";
  std::ofstream(dir_.file("gelsight/Cork/press_3/frame_010.png")) << "not an image";
  three.overwrite = true;
  try {
    extract_presses({dir_.file("gelsight")}, out("three.h5"), three);
    FAIL() << "unreadable frames were accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("press_1/frame_010.png"), std::string::npos) << e.what();
  }
}

TEST_F(Extract, FoldersOfFrameImagesAreVideos) {
  write_png_sequence(dir_.path() / "gelsight" / "Woven 1" / "press_0", 1, 50);
  write_png_sequence(dir_.path() / "gelsight" / "Woven 1" / "press_1", 1, 51);  // one frame more: another video
  std::ofstream(dir_.file("gelsight/Woven 1/press_0.json")) << "{}";  // sidecars are ignored
  const ExtractResult r = extract_presses({dir_.file("gelsight")}, out(), {});
  ASSERT_EQ(r.presses.size(), 2u);
  EXPECT_EQ(r.presses[1].material, "Woven 1");
  EXPECT_EQ(r.presses[1].press, 1);
  const FakeScene scene(V4L2_PIX_FMT_MJPEG, 16, 16, quick_presses(1));
  EXPECT_EQ(scene.depth(std::uint64_t(r.presses[0].peak_index)), 1.0) << "the peak is a frame at full depth";
  // One sequence folder given directly: its material is the folder above it.
  ExtractOptions force;
  force.overwrite = true;
  const ExtractResult one = extract_presses({dir_.file("gelsight/Woven 1/press_1/")}, out(), force);
  ASSERT_EQ(one.presses.size(), 1u);
  EXPECT_EQ(one.presses[0].material, "Woven 1");
  h5::File f = h5::File::open(out());
  EXPECT_EQ(f.root().open_group("materials/woven_1/presses/0").attr_string("source_sha256").size(), 64u);
}

// An 8-bit RGB PNG frame file is kept byte for byte; a grey or RGBA one, which PIL would hand over as
// one or four channels, is stored as the RGB PNG of its decoded frame, so every stored PNG is one
// every reader decodes alike (schemas/hdf5-layout.md).
TEST_F(Extract, OnlyRgbPngFramesAreKeptAsTheyAre) {
  write_png_sequence(dir_.path() / "gelsight" / "Cork" / "press_0", 1, 50);
  write_png_sequence(dir_.path() / "gelsight" / "Felt" / "press_0", 1, 50);
  for (const auto& file : fs::directory_iterator(dir_.path() / "gelsight" / "Felt" / "press_0")) {
    cv::Mat rgba;
    cv::cvtColor(cv::imread(file.path().string()), rgba, cv::COLOR_BGR2BGRA);
    cv::imwrite(file.path().string(), rgba);
  }
  ExtractOptions options;
  options.sheets = false;
  const ExtractResult r = extract_presses({dir_.file("gelsight")}, out(), options);
  ASSERT_EQ(r.presses.size(), 2u);
  const h5::File f = h5::File::open(out());
  for (const ExtractedPressSummary& p : r.presses) {
    const h5::Group press = f.root().open_group("materials/" + p.material_id + "/presses/0");
    const std::vector<std::uint8_t> peak = dataset::read_vlen_bytes(press.open_dataset("peak"), 0);
    EXPECT_TRUE(is_plain_rgb_png(peak)) << p.material;
    EXPECT_NO_THROW(dataset::require_whole_press_images(press, "frames"));
    const std::string file = (dir_.path() / "gelsight" / p.material / "press_0" / ("frame_" + std::to_string(1000 + p.peak_index).substr(1) + ".png")).string();
    std::ifstream in(file, std::ios::binary);
    const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_EQ(peak == bytes, p.material == "Cork") << p.material << ": the RGB file kept as it is, the RGBA one stored anew";
  }
}

// Review 20, F3: frame k of a folder is its k-th file, so a missing number joined frames apart in time,
// and two files of one number (frame_1, frame_0001) were two frames; each is refused, naming the file.
TEST_F(Extract, AFolderOfFramesWhoseNumbersDoNotRunOnIsRefused) {
  const std::vector<std::pair<std::function<void(const fs::path&)>, std::string>> cases = {
      {[](const fs::path& d) { fs::remove(d / "frame_005.png"); }, "frame_006.png: is frame 6, after frame_004.png (frame 4): frames are missing"},
      {[](const fs::path& d) { fs::copy_file(d / "frame_001.png", d / "frame_1.png"); }, "two files give one frame"},
      {[](const fs::path& d) { fs::copy_file(d / "frame_001.png", d / "frame_99999999999999999999999.png"); }, "beyond any video's"},
      {[](const fs::path& d) { fs::copy_file(d / "frame_001.png", d / "still.png"); }, "still.png: holds no frame number"},
  };
  int k = 0;
  for (const auto& [change, says] : cases) {
    SCOPED_TRACE(says);
    const fs::path folder = dir_.path() / ("frames" + std::to_string(k++));
    write_png_sequence(folder, 1, 12);
    change(folder);
    try {
      open_image_sequence(folder.string());
      ADD_FAILURE() << "accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::bad_input);
      EXPECT_NE(std::string(e.what()).find(says), std::string::npos) << e.what();
    }
  }
  // Review 21, F2: a number every name shares (a camera's) is not the frame number.
  const fs::path cam = dir_.path() / "cam";
  write_png_sequence(cam, 1, 12);
  for (int i = 0; i < 12; ++i) {
    const std::string number = std::to_string(1000 + i).substr(1);
    fs::rename(cam / ("frame_" + number + ".png"), cam / ("frame_" + number + "_cam2.png"));
  }
  EXPECT_NO_THROW(open_image_sequence(cam.string()));
  // Review 22, F1: a second number that changes (a time stamp, a save counter) leaves the frame number unknown.
  const fs::path stamped = dir_.path() / "stamped";
  write_png_sequence(stamped, 1, 12);
  for (int i = 0; i < 12; ++i) {
    const std::string number = std::to_string(1000 + i).substr(1);
    fs::rename(stamped / ("frame_" + number + ".png"), stamped / ("frame_" + number + "_t" + std::to_string(33 * i) + ".png"));
  }
  try {
    open_image_sequence(stamped.string());
    ADD_FAILURE() << "two changing numbers accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("which one counts the frames cannot be told"), std::string::npos) << e.what();
  }
}

TEST_F(Extract, LosslessSourcesGetLowerFloorsThanLossyOnes) {
  write_png_sequence(dir_.path() / "png", 1, 12);
  write_png_sequence(dir_.path() / "jpg", 1, 12, ".jpg");
  const auto png = open_image_sequence(dir_.file("png"));
  const auto jpg = open_image_sequence(dir_.file("jpg"));
  EXPECT_TRUE(png->lossless());
  EXPECT_FALSE(jpg->lossless());
  EXPECT_FLOAT_EQ(score_settings(*png, {}).image_pixel_threshold, 1.0f);
  EXPECT_FLOAT_EQ(score_settings(*png, {}).image_trigger, 0.02f);
  EXPECT_FLOAT_EQ(score_settings(*jpg, {}).image_pixel_threshold, 6.0f);
  EXPECT_FLOAT_EQ(score_settings(*jpg, {}).image_trigger, 0.25f);
  ExtractSettings chosen;
  chosen.pixel_threshold = 3.0f;
  EXPECT_EQ(score_settings(*png, chosen).pixel_threshold, 3.0f);
  EXPECT_TRUE(open_video(video("Cork", "press_0.mkv", 1))->lossless()) << "FFV1";
  const std::string mjpg = dir_.file("mjpg.avi");
  fixtures::write_press_video(mjpg, quick_presses(1), 12, 160, 120, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'));
  EXPECT_FALSE(open_video(mjpg)->lossless());
}

TEST(CaptureInputs, NumbersInFileNamesCompareByValue) {
  EXPECT_TRUE(natural_less("press_2.mkv", "press_10.mkv"));
  EXPECT_FALSE(natural_less("press_10.mkv", "press_2.mkv"));
  EXPECT_TRUE(natural_less("press_02.mkv", "press_3.mkv"));
  EXPECT_TRUE(natural_less("a.mkv", "b.mkv"));
  EXPECT_FALSE(natural_less("a.mkv", "a.mkv"));
}

TEST(CaptureInputs, RefusesMissingPathsAndEmptyFolders) {
  haptex::test::TempDir dir;
  EXPECT_THROW(expand_capture_inputs({dir.file("nowhere")}, std::nullopt), Error);
  std::ofstream(dir.file("notes.txt")) << "x";
  try {
    expand_capture_inputs({dir.path().string()}, std::nullopt);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("holds no video"), std::string::npos) << e.what();
  }
}

// Review 2, #15: a link inside the input folder back to a folder holding it (`loop -> ../..`) made
// extract read everything around the input. It is refused by its own name; a link to a material
// folder elsewhere is still followed.
TEST(CaptureInputs, ALinkToAFolderHoldingTheInputIsRefused) {
  haptex::test::TempDir dir;
  const std::filesystem::path in = dir.path() / "in", elsewhere = dir.path() / "elsewhere" / "cork";
  std::filesystem::create_directories(in / "felt");
  std::filesystem::create_directories(elsewhere);
  std::ofstream(in / "felt" / "press_0.avi") << "x";
  std::ofstream(elsewhere / "press_0.avi") << "x";
  std::filesystem::create_directory_symlink(elsewhere, in / "cork");
  const std::vector<CaptureInput> found = expand_capture_inputs({in.string()}, std::nullopt);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].material, "cork");
  std::filesystem::create_directory_symlink("../..", in / "loop");
  try {
    expand_capture_inputs({in.string()}, std::nullopt);
    FAIL() << "the link back was followed";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find((in / "loop").string() + ": is a link to"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace haptex::capture
