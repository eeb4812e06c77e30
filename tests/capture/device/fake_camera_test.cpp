// The fake camera answers like a UVC driver; the V4L2 code's tests rely on that.
#include <gtest/gtest.h>
#include <linux/videodev2.h>
#include <fcntl.h>
#include <sys/mman.h>

#include <cerrno>

#include "capture/device/fake_camera.hpp"
#include "tests/capture/fake_setup.hpp"

namespace haptex::capture {
namespace {

TEST(FakeCamera, OpensItsTwoNodesAndNothingElse) {
  FakeCamera camera;
  EXPECT_EQ(camera.open("/dev/video7", O_RDWR), -1);
  EXPECT_EQ(errno, ENOENT);
  const int capture = camera.open("/dev/video0", O_RDWR);
  const int metadata = camera.open("/dev/video1", O_RDWR);
  ASSERT_GE(capture, 0);
  ASSERT_GE(metadata, 0);
  v4l2_capability caps{};
  ASSERT_EQ(camera.ioctl(metadata, VIDIOC_QUERYCAP, &caps), 0);
  EXPECT_TRUE(caps.device_caps & V4L2_CAP_META_CAPTURE);
  EXPECT_FALSE(caps.device_caps & V4L2_CAP_VIDEO_CAPTURE);
  ASSERT_EQ(camera.ioctl(capture, VIDIOC_QUERYCAP, &caps), 0);
  EXPECT_TRUE(caps.device_caps & V4L2_CAP_VIDEO_CAPTURE);
  EXPECT_EQ(camera.close(capture), 0);
  EXPECT_EQ(camera.close(metadata), 0);
  EXPECT_EQ(camera.open_descriptors(), 0u);
}

TEST(FakeCamera, SnapsFormatsLikeADriver) {
  FakeCameraConfig config;
  config.modes = {{V4L2_PIX_FMT_MJPEG, 640, 480, {30, 15}}, {V4L2_PIX_FMT_MJPEG, 320, 240, {60}}};
  FakeCamera camera(config);
  const int fd = camera.open("/dev/video0", O_RDWR);
  v4l2_format f{};
  f.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  f.fmt.pix.pixelformat = V4L2_PIX_FMT_NV12;  // not offered: the driver picks its own
  f.fmt.pix.width = 330;
  f.fmt.pix.height = 250;
  ASSERT_EQ(camera.ioctl(fd, VIDIOC_S_FMT, &f), 0);
  EXPECT_EQ(f.fmt.pix.pixelformat, V4L2_PIX_FMT_MJPEG);
  EXPECT_EQ(f.fmt.pix.width, 320u);
  EXPECT_EQ(f.fmt.pix.height, 240u);
  v4l2_streamparm p{};
  p.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  p.parm.capture.timeperframe = {1, 50};
  ASSERT_EQ(camera.ioctl(fd, VIDIOC_S_PARM, &p), 0);
  EXPECT_EQ(p.parm.capture.timeperframe.denominator, 60u);  // the nearest rate offered at 320x240
}

TEST(FakeCamera, BuffersMapQueueAndStream) {
  FakeCamera camera(fixtures::small_camera());
  const int fd = camera.open("/dev/video0", O_RDWR);
  v4l2_requestbuffers r{};
  r.count = 12;
  r.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  r.memory = V4L2_MEMORY_MMAP;
  ASSERT_EQ(camera.ioctl(fd, VIDIOC_REQBUFS, &r), 0);
  EXPECT_EQ(r.count, 8u);  // the default cap
  v4l2_buffer b{};
  b.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  b.memory = V4L2_MEMORY_MMAP;
  b.index = 0;
  ASSERT_EQ(camera.ioctl(fd, VIDIOC_QUERYBUF, &b), 0);
  void* p = camera.mmap(nullptr, b.length, PROT_READ, MAP_SHARED, fd, b.m.offset);
  ASSERT_NE(p, MAP_FAILED);
  EXPECT_EQ(camera.ioctl(fd, VIDIOC_QBUF, &b), 0);
  EXPECT_EQ(camera.ioctl(fd, VIDIOC_QBUF, &b), -1) << "queued twice";
  int type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  ASSERT_EQ(camera.ioctl(fd, VIDIOC_STREAMON, &type), 0);
  pollfd pfd{fd, POLLIN, 0};
  ASSERT_EQ(camera.poll(&pfd, 1, 100), 1);
  v4l2_buffer out{};
  out.type = V4L2_BUF_TYPE_VIDEO_CAPTURE;
  out.memory = V4L2_MEMORY_MMAP;
  ASSERT_EQ(camera.ioctl(fd, VIDIOC_DQBUF, &out), 0);
  EXPECT_EQ(out.sequence, 0u);
  EXPECT_GT(out.bytesused, 100u);
  EXPECT_EQ(camera.ioctl(fd, VIDIOC_DQBUF, &out), -1);
  EXPECT_EQ(errno, EAGAIN);
  EXPECT_EQ(camera.poll(&pfd, 1, 100), 0) << "no buffer queued: nothing can arrive";
  EXPECT_EQ(camera.ioctl(fd, VIDIOC_REQBUFS, &r), -1) << "freeing while streaming";
  ASSERT_EQ(camera.ioctl(fd, VIDIOC_STREAMOFF, &type), 0);
  r.count = 0;
  EXPECT_EQ(camera.ioctl(fd, VIDIOC_REQBUFS, &r), -1) << "freeing mapped buffers";
  EXPECT_EQ(camera.munmap(p, b.length), 0);
  EXPECT_EQ(camera.ioctl(fd, VIDIOC_REQBUFS, &r), 0);
}

TEST(FakeCamera, SceneRisesHoldsAndReleases) {
  const PressSchedule s = fixtures::quick_presses(2);
  FakeScene scene(V4L2_PIX_FMT_MJPEG, 64, 48, s);
  EXPECT_TRUE(scene.black(0));
  EXPECT_FALSE(scene.black(5));
  EXPECT_EQ(scene.depth(29), 0.0);
  EXPECT_GT(scene.depth(30), 0.0);
  EXPECT_EQ(scene.depth(33), 1.0);
  EXPECT_EQ(scene.depth(30 + 12), 0.0);
  EXPECT_GT(scene.depth(30 + 28), 0.0);  // the second press
  EXPECT_EQ(scene.depth(30 + 56), 0.0);  // no third
  EXPECT_NE(scene.payload(10), scene.payload(11)) << "two noise patterns alternate";
}

}  // namespace
}  // namespace haptex::capture
