#pragma once
// The grey image contact scores are computed on: the frame's grey levels averaged over r x r pixel
// blocks, r = 2, 4 or 8 (the largest that leaves the image at least about 160 pixels wide):
// 320 x 240 -> 160 x 120, 960 x 720 -> 240 x 180, 3280 x 2464 -> 410 x 308. Averaging blocks divides
// the sensor noise by r and makes scoring cheap enough to score every frame live, while keeping the
// texture a press imprints on the gel (a coarser image would average a sandpaper's grains away).
//
// MJPG frames are decoded straight to this size (libjpeg's DCT scaling, OpenCV's
// IMREAD_REDUCED_GRAYSCALE_*), which costs a fraction of a full decode; decoded frames are averaged
// over the same blocks, so both paths give (almost) the same image.
#include <cstdint>
#include <span>

#include <opencv2/core.hpp>

#include "core/image_header.hpp"

namespace haptex::capture {

cv::Size scoring_size(cv::Size frame);
// From a decoded frame (BGR or grey, 8 bit). Returns CV_32FC1 of scoring_size(frame.size()).
cv::Mat scoring_image(const cv::Mat& frame);
// From MJPG bytes of a frame of size `frame`. Returns an empty Mat when the bytes do not decode
// to an image of that size (a corrupt or truncated payload).
cv::Mat scoring_image_from_jpeg(std::span<const std::uint8_t> jpeg, cv::Size frame);
// is_complete_jpeg: core/image_header.hpp.
// From packed YUYV (4:2:2) bytes: the Y samples (BT.601 video range) are the grey image. Empty Mat on
// a size mismatch.
cv::Mat scoring_image_from_yuyv(std::span<const std::uint8_t> yuyv, cv::Size frame);
// r: the block size (1, 2, 4 or 8) used for a frame of this size.
int jpeg_reduction(cv::Size frame);

}  // namespace haptex::capture
