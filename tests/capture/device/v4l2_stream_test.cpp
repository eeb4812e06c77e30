// Streaming through the fake camera: every frame with its metadata, and every kind of loss counted.
#include <gtest/gtest.h>
#include <linux/videodev2.h>

#include <chrono>
#include <thread>

#include "capture/device/format_negotiation.hpp"
#include "capture/device/v4l2_stream.hpp"
#include "core/error.hpp"
#include "tests/capture/fake_setup.hpp"

namespace haptex::capture {
namespace {

struct Streamed {
  std::vector<Frame> frames;
  StreamStatus last = StreamStatus::frame;
  int timeouts = 0;
};

// Reads until `frames` frames arrived, the device is gone, or too many timeouts in a row.
Streamed stream_frames(V4l2Stream& stream, std::size_t frames) {
  Streamed out;
  int quiet = 0;
  while (out.frames.size() < frames && quiet < 50) {
    Frame f;
    out.last = stream.next(f);
    if (out.last == StreamStatus::disconnected || out.last == StreamStatus::ended) break;
    if (out.last == StreamStatus::no_frame) continue;
    if (out.last == StreamStatus::timeout) {
      ++out.timeouts;
      ++quiet;
      continue;
    }
    quiet = 0;
    out.frames.push_back(std::move(f));
  }
  return out;
}

class StreamTest : public ::testing::Test {
 protected:
  void open(FakeCameraConfig config, unsigned buffers = 6) {
    stream_.reset();
    device_.reset();
    camera_ = std::make_unique<FakeCamera>(std::move(config));
    device_ = std::make_unique<V4l2Device>(*camera_, "/dev/video0");
    stream_ = std::make_unique<V4l2Stream>(*device_, negotiate_format(*device_, {}), buffers);
    stream_->start();
  }
  std::unique_ptr<FakeCamera> camera_;
  std::unique_ptr<V4l2Device> device_;
  std::unique_ptr<V4l2Stream> stream_;
};

TEST_F(StreamTest, FramesKeepSequenceTimestampFlagsAndBytes) {
  open(fixtures::small_camera());
  const Streamed s = stream_frames(*stream_, 12);
  ASSERT_EQ(s.frames.size(), 12u);
  for (std::size_t i = 0; i < s.frames.size(); ++i) {
    const Frame& f = s.frames[i];
    EXPECT_EQ(f.sequence, i);
    EXPECT_TRUE(f.flags & V4L2_BUF_FLAG_TIMESTAMP_MONOTONIC);
    EXPECT_EQ(f.bytes, camera_->scene()->payload(i)) << "frame " << i << " is the sensor's payload, byte for byte";
    if (i > 0) {
      EXPECT_NEAR(double(f.timestamp_ns - s.frames[i - 1].timestamp_ns), 1e9 / 30, 1000);
    }
  }
  EXPECT_EQ(stream_->drops().dropped(), 0u);
  EXPECT_EQ(stream_->stats().frames, 12u);
}

TEST_F(StreamTest, AsksForFourToEightBuffers) {
  open(fixtures::small_camera(), 2);
  EXPECT_EQ(stream_->buffer_count(), 4u);
  open(fixtures::small_camera(), 20);
  EXPECT_EQ(stream_->buffer_count(), 8u);
  EXPECT_EQ(camera_->mapped_buffers(), 8u);
  stream_.reset();
  EXPECT_EQ(camera_->mapped_buffers(), 0u) << "unmapped when the stream ends";
}

TEST(Stream, RefusesADriverGrantingTooFewBuffers) {
  FakeCameraConfig config = fixtures::small_camera();
  config.max_buffers = 3;
  FakeCamera camera(config);
  V4l2Device device(camera, "/dev/video0");
  try {
    V4l2Stream stream(device, negotiate_format(device, {}));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("granted 3 capture buffers"), std::string::npos) << e.what();
  }
  EXPECT_EQ(camera.mapped_buffers(), 0u);
}

TEST_F(StreamTest, LostFramesAreCountedFromSequenceGaps) {
  FakeCameraConfig config = fixtures::small_camera();
  config.drop_percent = 20;
  open(config);
  const Streamed s = stream_frames(*stream_, 200);
  ASSERT_EQ(s.frames.size(), 200u);
  EXPECT_GT(camera_->stats().camera_drops, 10u);
  // Frames the camera lost between the first and last delivered ones: all of them seen as gaps.
  const std::uint64_t lost_before_last = s.frames.back().sequence - s.frames.front().sequence + 1 - s.frames.size();
  EXPECT_EQ(stream_->drops().dropped(), lost_before_last);
  EXPECT_EQ(stream_->drops().sequence_gaps(), lost_before_last);
}

TEST_F(StreamTest, StallsAreTimeoutsAndTimestampGaps) {
  FakeCameraConfig config = fixtures::small_camera();
  config.stalls = {{20, 1000}};  // frame 20 comes a second late
  open(config);
  const Streamed s = stream_frames(*stream_, 30);
  ASSERT_EQ(s.frames.size(), 30u);
  EXPECT_EQ(stream_->poll_timeout_ms(), 100);  // 3 periods at 30 fps
  EXPECT_GE(s.timeouts, 9);
  EXPECT_EQ(stream_->stats().poll_timeouts, std::uint64_t(s.timeouts));
  EXPECT_EQ(stream_->drops().sequence_gaps(), 0u);
  EXPECT_EQ(stream_->drops().timestamp_gaps(), 30u) << "a second at 30 fps";
}

TEST_F(StreamTest, ErrorFlaggedBuffersAreCountedRequeuedAndNotDelivered) {
  FakeCameraConfig config = fixtures::small_camera();
  config.error_percent = 10;
  open(config, 4);
  const Streamed s = stream_frames(*stream_, 300);
  ASSERT_EQ(s.frames.size(), 300u) << "buffers came back: the stream never starved";
  const auto& fake = camera_->stats();
  EXPECT_GT(fake.error_buffers, 10u);
  EXPECT_EQ(stream_->stats().error_buffers, fake.error_buffers);
  for (const auto& f : s.frames) EXPECT_FALSE(f.flags & V4L2_BUF_FLAG_ERROR);
  EXPECT_EQ(stream_->drops().dropped(), 0u) << "a flagged buffer is an error, not also a loss";
  EXPECT_EQ(fake.delivered, s.frames.size() + fake.error_buffers);
}

TEST_F(StreamTest, DisconnectEndsTheStreamAfterEveryFrameTaken) {
  FakeCameraConfig config = fixtures::small_camera();
  config.disconnect_after = 37;
  open(config);
  const Streamed s = stream_frames(*stream_, 1000);
  EXPECT_EQ(s.last, StreamStatus::disconnected);
  EXPECT_EQ(s.frames.size(), 37u);
  Frame f;
  EXPECT_EQ(stream_->next(f), StreamStatus::disconnected) << "and it stays gone";
  stream_.reset();  // STREAMOFF and REQBUFS fail with ENODEV; tearing down must not throw
  EXPECT_EQ(camera_->mapped_buffers(), 0u);
}

TEST_F(StreamTest, RealTimeCameraLosesFramesTheHostDoesNotCollect) {
  FakeCameraConfig config = fixtures::small_camera(V4L2_PIX_FMT_MJPEG, 320, 240, 200);
  config.realtime = true;
  open(config, 4);
  Frame f;
  ASSERT_EQ(stream_->next(f), StreamStatus::frame);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));  // 20 frames due, 4 buffers
  const Streamed s = stream_frames(*stream_, 10);
  ASSERT_EQ(s.frames.size(), 10u);
  EXPECT_GE(camera_->stats().host_drops, 10u);
  EXPECT_GE(stream_->drops().dropped(), 10u) << "the host sees the gap in sequence numbers";
}

// The synthetic gel for `frames` frames, then nothing: what a replayed file is to the camera.
class FiniteScene : public CameraScene {
 public:
  FiniteScene(const FakeMode& mode, std::uint64_t frames)
      : scene_(mode.fourcc, int(mode.width), int(mode.height), fixtures::quick_presses()), frames_(frames) {}
  const std::vector<std::uint8_t>* frame(std::uint64_t k) override { return k < frames_ ? scene_.frame(k) : nullptr; }

 private:
  FakeScene scene_;
  std::uint64_t frames_;
};

FakeCameraConfig finite_camera(std::uint64_t frames, double fps = 30) {
  FakeCameraConfig config = fixtures::small_camera(V4L2_PIX_FMT_MJPEG, 320, 240, fps);
  config.film = [frames](const FakeMode& mode) { return std::make_unique<FiniteScene>(mode, frames); };
  return config;
}

TEST_F(StreamTest, AFiniteSceneEndsTheStreamAfterItsLastFrame) {
  open(finite_camera(25));
  const Streamed s = stream_frames(*stream_, 1000);
  EXPECT_EQ(s.last, StreamStatus::ended);
  ASSERT_EQ(s.frames.size(), 25u) << "every frame, then the end";
  for (std::size_t i = 0; i < s.frames.size(); ++i) EXPECT_EQ(s.frames[i].sequence, i);
  EXPECT_EQ(stream_->stats().error_buffers, 0u) << "the empty LAST buffer is no error buffer";
  EXPECT_EQ(stream_->drops().dropped(), 0u) << "nor a loss";
  Frame f;
  EXPECT_EQ(stream_->next(f), StreamStatus::ended) << "and it stays ended";
  // What the driver says from now on, as vb2 does after a LAST buffer: readable, and DQBUF fails with EPIPE.
  pollfd p{device_->fd(), POLLIN, 0};
  EXPECT_EQ(camera_->poll(&p, 1, 100), 1);
  EXPECT_TRUE(p.revents & POLLIN);
  v4l2_buffer b{};
  b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  b.memory = V4L2_MEMORY_MMAP;
  EXPECT_EQ(device_->try_ioctl(VIDIOC_DQBUF, &b), EPIPE);
  v4l2_capability caps{};
  EXPECT_EQ(device_->try_ioctl(VIDIOC_QUERYCAP, &caps), 0) << "ended, not unplugged";
}

TEST_F(StreamTest, AFiniteSceneEndsEvenWhenItsLastFramesAreLost) {
  FakeCameraConfig config = finite_camera(200);
  config.drop_percent = 30;
  open(config);
  const Streamed s = stream_frames(*stream_, 1000);
  EXPECT_EQ(s.last, StreamStatus::ended);
  const auto& fake = camera_->stats();
  EXPECT_EQ(fake.produced, 200u);
  EXPECT_GT(fake.camera_drops, 20u);
  EXPECT_EQ(s.frames.size() + fake.camera_drops, 200u) << "every frame the scene had is accounted for";
  // Losses before the first and after the last delivered frame leave no gap to see; the others are counted.
  const std::uint64_t unseen = s.frames.front().sequence + (199 - s.frames.back().sequence);
  EXPECT_EQ(stream_->drops().dropped() + unseen, fake.camera_drops);
}

TEST_F(StreamTest, AFiniteSceneEndsInRealTimeOnePeriodAfterItsLastFrame) {
  FakeCameraConfig config = finite_camera(20, 100);
  config.realtime = true;
  const auto start = std::chrono::steady_clock::now();
  open(config);
  const Streamed s = stream_frames(*stream_, 1000);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(s.last, StreamStatus::ended);
  EXPECT_EQ(s.frames.size(), 20u);
  EXPECT_GE(seconds, 0.19) << "20 frames at 100 fps are played at their rate, not at once";
  EXPECT_EQ(s.timeouts, 0) << "the end is no stall";
}

// A scene that takes longer than a frame period to make each frame, like a large replayed video.
class SlowScene : public FiniteScene {
 public:
  using FiniteScene::FiniteScene;
  const std::vector<std::uint8_t>* frame(std::uint64_t k) override {
    std::this_thread::sleep_for(std::chrono::milliseconds(15));
    return FiniteScene::frame(k);
  }
};

TEST_F(StreamTest, ASlowSceneInRealTimePlaysSlowerInsteadOfLosingFrames) {
  FakeCameraConfig config = finite_camera(20, 100);  // a period of 10 ms, each frame taking 15 to make
  config.film = [](const FakeMode& mode) { return std::make_unique<SlowScene>(mode, 20); };
  config.realtime = true;
  open(config, 4);
  const Streamed s = stream_frames(*stream_, 1000);
  EXPECT_EQ(s.last, StreamStatus::ended);
  EXPECT_EQ(s.frames.size(), 20u);
  EXPECT_EQ(camera_->stats().host_drops, 0u) << "the camera's own slowness is not the host's";
  EXPECT_EQ(stream_->drops().dropped(), 0u);
}

}  // namespace
}  // namespace haptex::capture
