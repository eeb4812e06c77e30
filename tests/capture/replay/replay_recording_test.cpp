// The recorder on replayed files (lockstep): a press video cuts the same presses live as extraction
// finds offline, the end of the file ends the take with every frame kept, drops and error buffers are
// counted as the fake camera's are, a disconnect keeps every frame taken, and a press file is played
// back byte for byte.
#include <gtest/gtest.h>
#include <linux/videodev2.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include "capture/extraction/extract_presses.hpp"
#include "capture/recording/press_recorder.hpp"
#include "capture/replay/replay_device.hpp"
#include "core/temporary_name.hpp"
#include "dataset/vlen_bytes.hpp"
#include "core/h5/file.hpp"
#include "core/json/schema.hpp"
#include "tests/capture/fake_setup.hpp"
#include "tests/capture/press_videos.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::capture {
namespace {

namespace fs = std::filesystem;

// 3 presses: contact from frames 30, 58 and 86, released by frame 98; the file ends 22 frames later.
constexpr int kVideoFrames = 120;
constexpr int kPresses = 3;

class ReplayRecording : public ::testing::Test {
 protected:
  std::string press_video(const std::string& name, int fourcc) const {
    const std::string path = dir_.file(name);
    fixtures::write_press_video(path, fixtures::quick_presses(kPresses), kVideoFrames, 320, 240, fourcc);
    return path;
  }
  std::string mjpg_video() const { return press_video("presses.avi", cv::VideoWriter::fourcc('M', 'J', 'P', 'G')); }
  std::string ffv1_video() const { return press_video("presses.mkv", cv::VideoWriter::fourcc('F', 'F', 'V', '1')); }

  RecordingResult replay(const std::string& device, const RecorderOptions& options, const std::string& session = "session") {
    const FakeDevice replay = parse_replay_device(device);
    camera_ = std::make_unique<FakeCamera>(replay.config);
    SessionRequest request;
    request.node = replay.node;
    request.output_dir = dir_.file(session);
    request.command = "test";
    return record_session(*camera_, request, options);
  }
  static RecorderOptions options(int presses = 10) {
    RecorderOptions o;
    o.material = "Cork";
    o.presses = presses;
    return o;
  }
  std::string file(const std::string& session, const std::string& name) const { return dir_.file(session + "/" + name); }

  haptex::test::TempDir dir_;
  std::unique_ptr<FakeCamera> camera_;
};

// Contact intervals and peaks the recorder cut live against those extraction finds in the same file:
// equal where the device sends the file's own pixels (lossless), within `frames` where it re-encodes
// them (a lossy video is sent as JPEG at quality 95, which moves a score near the release a little).
void expect_same_presses(const RecordingResult& live, const ExtractResult& offline, int frames = 0) {
  ASSERT_EQ(live.presses.size(), offline.presses.size());
  for (std::size_t j = 0; j < live.presses.size(); ++j) {
    const RecordedPress& l = live.presses[j];
    const ExtractedPressSummary& o = offline.presses[j];
    EXPECT_LE(std::abs(l.contact_first - o.contact_first), frames) << "press " << j;
    EXPECT_LE(std::abs(l.contact_last - o.contact_last), frames) << "press " << j;
    // The synthetic press holds its full depth for 4 frames: the peak may be any of them.
    EXPECT_NEAR(double(l.peak_frame), double(o.peak_index), 3.0) << "press " << j;
  }
}

ExtractResult extract(const std::string& video, const std::string& output) {
  ExtractOptions o;
  o.sheets = false;
  o.material = "Cork";
  return extract_presses({video}, output, o);
}

TEST_F(ReplayRecording, ALossyVideoCutsTheSamePressesLiveAsOffline) {
  const std::string video = mjpg_video();
  const RecordingResult live = replay("replay:" + video + ",lockstep", options());
  EXPECT_EQ(live.session.format.fourcc, std::uint32_t(V4L2_PIX_FMT_MJPEG));
  EXPECT_EQ(live.ended_by, "source ended");
  EXPECT_EQ(live.totals.frames, std::uint64_t(kVideoFrames)) << "every frame of the file, none lost";
  ASSERT_EQ(live.presses.size(), std::size_t(kPresses));
  expect_same_presses(live, extract(video, dir_.file("g.h5")), 1);
  for (const auto& p : live.presses) EXPECT_EQ(p.ended_by, "release");
  const nlohmann::json manifest = json::read_file(file("session", "session.json"));
  EXPECT_NO_THROW(json::validate(manifest, "capture-session.schema.json", "session.json"));
  EXPECT_EQ(manifest["ended_by"], "source ended");
  EXPECT_EQ(manifest["device"]["node"], "replay:" + video);
}

TEST_F(ReplayRecording, ALosslessVideoStaysLosslessAndCutsTheSamePresses) {
  const std::string video = ffv1_video();
  const RecordingResult live = replay("replay:" + video + ",lockstep", options());
  EXPECT_EQ(live.session.format.fourcc, std::uint32_t(V4L2_PIX_FMT_YUYV));
  EXPECT_EQ(live.ended_by, "source ended");
  expect_same_presses(live, extract(video, dir_.file("g.h5")));
  // Stored as lossless PNG: the frames are the video's, to the chroma subsampling of YUYV.
  h5::File press = h5::File::open(file("session", "press_0.h5"));
  EXPECT_EQ(press.root().attr_string("encoding"), "png");
  EXPECT_LT(press.root().attr_double("pixel_threshold"), 6.0) << "scored with the lossless floors, as offline";
}

TEST_F(ReplayRecording, ThePressOpenWhenTheFileEndsKeepsEveryFrame) {
  const std::string video = dir_.file("cut.avi");
  // The file stops during the third press's hold (contact from 86).
  fixtures::write_press_video(video, fixtures::quick_presses(kPresses), 92, 320, 240, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'));
  const RecordingResult r = replay("replay:" + video + ",lockstep", options());
  EXPECT_EQ(r.ended_by, "source ended");
  EXPECT_FALSE(r.device_fault()) << "the end of a file is no fault";
  ASSERT_EQ(r.presses.size(), 3u);
  const RecordedPress& last = r.presses.back();
  EXPECT_EQ(last.ended_by, "source ended");
  EXPECT_EQ(last.take_last_frame, 91) << "up to the file's last frame";
  EXPECT_EQ(last.contact_last, 91);
  EXPECT_EQ(h5::File::open(file("session", last.file)).root().attr_string("ended_by"), "source ended");
  EXPECT_TRUE(temporaries_of(file("session", last.file)).empty());
}

TEST_F(ReplayRecording, DropsAndErrorBuffersAreCountedAsTheFakeCamerasAre) {
  const std::string video = mjpg_video();
  // Seed 3 loses neither the file's first frame nor its last, so every loss lies between two frames taken.
  const RecordingResult r = replay("replay:" + video + ",lockstep,drop=6,error=6,seed=3", options());
  EXPECT_EQ(r.ended_by, "source ended");
  const FakeCameraStats& fake = camera_->stats();
  EXPECT_EQ(fake.produced, std::uint64_t(kVideoFrames));
  EXPECT_GT(fake.camera_drops, 2u);
  EXPECT_GT(fake.error_buffers, 2u);
  EXPECT_EQ(r.totals.dropped_frames, fake.camera_drops) << "every loss seen, and no error buffer counted as one";
  EXPECT_EQ(r.totals.error_buffers, fake.error_buffers);
  EXPECT_EQ(r.totals.frames + r.totals.dropped_frames + r.totals.error_buffers, std::uint64_t(kVideoFrames))
      << "every frame of the file is taken, lost or an error buffer";
  EXPECT_EQ(r.presses.size(), std::size_t(kPresses)) << "the presses survive a few lost frames";
  std::uint64_t press_losses = 0;
  for (const auto& p : r.presses) {
    // A replayed frame's sequence number is its frame number in the file: within a press file every
    // number is a frame kept, a frame lost or an error buffer.
    EXPECT_EQ(std::uint64_t(p.last_sequence - p.first_sequence + 1), p.frames + p.dropped_frames + p.error_frames)
        << p.file;
    const h5::Group root = h5::File::open(file("session", p.file)).root();
    EXPECT_EQ(root.attr_int("dropped_frames"), std::int64_t(p.dropped_frames));
    EXPECT_EQ(root.attr_int("error_frames"), std::int64_t(p.error_frames));
    press_losses += p.dropped_frames + p.error_frames;
  }
  EXPECT_GT(press_losses, 0u) << "the presses saw losses too";
}

TEST_F(ReplayRecording, ADisconnectEndsTheTakeKeepingEveryFrameTaken) {
  const std::string video = mjpg_video();
  // Unplugged during the second press's contact (frames 58..).
  const RecordingResult r = replay("replay:" + video + ",lockstep,disconnect=64", options());
  EXPECT_EQ(r.ended_by, "disconnected");
  EXPECT_TRUE(r.device_fault());
  EXPECT_EQ(r.totals.frames, 64u);
  ASSERT_EQ(r.presses.size(), 2u);
  EXPECT_EQ(r.presses[0].ended_by, "release");
  const RecordedPress& cut = r.presses[1];
  EXPECT_EQ(cut.ended_by, "disconnected");
  EXPECT_EQ(cut.take_last_frame, 63) << "the last frame taken is in the file";
  const h5::Group root = h5::File::open(file("session", cut.file)).root();
  EXPECT_EQ(root.attr_string("ended_by"), "disconnected");
  EXPECT_EQ(root.open_dataset("sequence").read<std::uint32_t>().back(), 63u);
  EXPECT_EQ(json::read_file(file("session", "session.json"))["ended_by"], "disconnected");
}

TEST_F(ReplayRecording, APressFileIsPlayedBackByteForByte) {
  // Record a press with 15 frames before the contact, enough for a reference when it is replayed.
  FakeCameraConfig config = fixtures::small_camera();
  FakeCamera camera(config);
  SessionRequest request;
  request.node = "/dev/video0";
  request.output_dir = dir_.file("original");
  RecorderOptions first = options(1);
  first.pre_frames = 15;
  const RecordingResult original = record_session(camera, request, first);
  ASSERT_EQ(original.presses.size(), 1u);
  const std::string original_file = file("original", "press_0.h5");

  RecorderOptions again = options(1);
  again.warmup_frames = 0;  // the press file starts with no-contact frames, no start-up frames
  const RecordingResult r = replay("replay:" + original_file + ",lockstep", again);
  ASSERT_EQ(r.presses.size(), 1u);
  const RecordedPress& p = r.presses[0];
  EXPECT_EQ(p.contact_first, original.presses[0].contact_first - original.presses[0].take_first_frame);
  EXPECT_EQ(p.contact_last, original.presses[0].contact_last - original.presses[0].take_first_frame);
  const h5::Group before = h5::File::open(original_file).root(), after = h5::File::open(file("session", p.file)).root();
  const h5::Dataset stored = before.open_dataset("frames"), replayed = after.open_dataset("frames");
  const auto sequence = after.open_dataset("sequence").read<std::uint32_t>();
  ASSERT_EQ(sequence.size(), p.frames);
  for (std::size_t i = 0; i < sequence.size(); ++i)
    EXPECT_EQ(dataset::read_vlen_bytes(replayed, i), dataset::read_vlen_bytes(stored, sequence[i])) << "frame " << i << " re-encoded";
}

TEST_F(ReplayRecording, ARawPressFileIsPlayedBackAsYuyv) {
  FakeCamera camera(fixtures::small_camera(V4L2_PIX_FMT_YUYV));
  SessionRequest request;
  request.node = "/dev/video0";
  request.output_dir = dir_.file("original");
  RecorderOptions first = options(1);
  first.pre_frames = 15;
  ASSERT_EQ(record_session(camera, request, first).presses.size(), 1u);
  const std::string original_file = file("original", "press_0.h5");

  RecorderOptions again = options(1);
  again.warmup_frames = 0;
  const RecordingResult r = replay("replay:" + original_file + ",lockstep", again);
  EXPECT_EQ(r.session.format.fourcc, std::uint32_t(V4L2_PIX_FMT_YUYV));
  ASSERT_EQ(r.presses.size(), 1u);
  const h5::Group before = h5::File::open(original_file).root(), after = h5::File::open(file("session", r.presses[0].file)).root();
  const auto sequence = after.open_dataset("sequence").read<std::uint32_t>();
  for (std::size_t i = 0; i < sequence.size(); ++i) {
    const cv::Mat a = cv::imdecode(dataset::read_vlen_bytes(before.open_dataset("frames"), sequence[i]), cv::IMREAD_COLOR);
    const cv::Mat b = cv::imdecode(dataset::read_vlen_bytes(after.open_dataset("frames"), i), cv::IMREAD_COLOR);
    ASSERT_EQ(a.size(), b.size()) << "frame " << i;
    // PNG -> YUYV -> PNG: the same image but for rounding in the colour conversion.
    EXPECT_LE(cv::norm(a, b, cv::NORM_INF), 3.0) << "frame " << i;
  }
}

}  // namespace
}  // namespace haptex::capture
