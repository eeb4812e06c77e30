#pragma once
// Test helpers: press videos read back the way a user would (cv::VideoCapture), and the frame
// statistics the press properties are stated in.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>
#include <string>
#include <vector>

namespace haptex::test {

// All frames of a press video, as many as OpenCV counts in it (empty when it cannot open it).
inline std::vector<cv::Mat> read_press_frames(const std::string& path) {
  cv::VideoCapture capture(path);
  std::vector<cv::Mat> frames;
  if (!capture.isOpened()) return frames;
  const int count = int(capture.get(cv::CAP_PROP_FRAME_COUNT));
  for (cv::Mat frame; int(frames.size()) < count && capture.read(frame);) frames.push_back(frame.clone());
  return frames;
}

// Mean absolute difference over all pixels and channels, in grey levels.
inline double mean_abs_difference(const cv::Mat& a, const cv::Mat& b) {
  cv::Mat difference;
  cv::absdiff(a, b, difference);
  const cv::Scalar mean = cv::mean(difference);
  return (mean[0] + mean[1] + mean[2]) / 3;
}

// The frame that differs most from the first: how `capture extract` finds a press's peak.
inline int frame_most_unlike_first(const std::vector<cv::Mat>& frames) {
  int best = 0;
  double best_difference = -1;
  for (int i = 0; i < int(frames.size()); ++i) {
    const double difference = mean_abs_difference(frames[std::size_t(i)], frames[0]);
    if (difference > best_difference) best_difference = difference, best = i;
  }
  return best;
}

inline std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every regular file under `root`, by relative path, with its bytes.
inline std::vector<std::pair<std::string, std::string>> tree_contents(const std::filesystem::path& root) {
  std::vector<std::pair<std::string, std::string>> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root))
    if (entry.is_regular_file())
      files.emplace_back(std::filesystem::relative(entry.path(), root).string(), file_bytes(entry.path()));
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace haptex::test
