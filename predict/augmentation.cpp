#include "predict/augmentation.hpp"

#include "core/error.hpp"

namespace haptex::predict {

cv::Mat augment(const cv::Mat& image, int variant) {
  if (variant < 0 || variant >= kAugmentations)
    throw failure("augment: variant " + std::to_string(variant) + " is not in 0..7");
  cv::Mat out = image.clone();
  if (variant >= 4) cv::flip(out, out, 1);
  switch (variant % 4) {
    case 1: cv::rotate(out, out, cv::ROTATE_90_COUNTERCLOCKWISE); break;
    case 2: cv::rotate(out, out, cv::ROTATE_180); break;
    case 3: cv::rotate(out, out, cv::ROTATE_90_CLOCKWISE); break;
    default: break;
  }
  return out;
}

std::vector<cv::Mat> all_augmentations(const cv::Mat& image) {
  std::vector<cv::Mat> out;
  for (int v = 0; v < kAugmentations; ++v) out.push_back(augment(image, v));
  return out;
}

}  // namespace haptex::predict
