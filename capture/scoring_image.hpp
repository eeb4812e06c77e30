#pragma once
// The small grey image contact scores are computed on: the frame's grey levels averaged over
// f x f pixel blocks, f chosen so the image is about 160 pixels wide (320 x 240 -> 160 x 120,
// 960 x 720 -> 160 x 120, 3280 x 2464 -> 156 x 117). Averaging blocks divides the sensor noise by f
// while a press, which covers thousands of pixels, survives intact; and scoring 20 000 pixels instead
// of 8 million is what lets the recorder score every frame live.
//
// MJPG frames are decoded straight to a 2x, 4x or 8x smaller grey image (libjpeg's DCT scaling,
// OpenCV's IMREAD_REDUCED_GRAYSCALE_*), which costs a fraction of a full decode.
#include <cstdint>
#include <span>

#include <opencv2/core.hpp>

namespace haptex::capture {

cv::Size scoring_size(cv::Size frame);
// From a decoded frame (BGR or grey, 8 bit). Returns CV_32FC1 of scoring_size(frame.size()).
cv::Mat scoring_image(const cv::Mat& frame);
// From MJPG bytes of a frame of size `frame`. Returns an empty Mat when the bytes do not decode
// to an image of that size (a corrupt or truncated payload).
cv::Mat scoring_image_from_jpeg(std::span<const std::uint8_t> jpeg, cv::Size frame);
// A whole JPEG starts with SOI (FF D8) and ends with EOI (FF D9), perhaps followed by padding some
// cameras add. A cut-off frame lacks EOI; libjpeg would still "decode" it, the missing part grey,
// and that would score as contact.
bool is_complete_jpeg(std::span<const std::uint8_t> jpeg);
// From packed YUYV (4:2:2) bytes: the Y samples are the grey image. Empty Mat on a size mismatch.
cv::Mat scoring_image_from_yuyv(std::span<const std::uint8_t> yuyv, cv::Size frame);
// The DCT scaling (1, 2, 4 or 8) used for a frame of this size.
int jpeg_reduction(cv::Size frame);

}  // namespace haptex::capture
