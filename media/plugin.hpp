#pragma once
// What the codecs plugin (plugins/opencv_codecs.cpp) gives media/codecs.cpp: one table of functions,
// returned by its only exported symbol. kPluginAbi changes whenever the table or the classes of
// media/codecs.hpp change, so a plugin left over from another build is refused, not called.
#include <string>
#include <vector>

#include "media/codecs.hpp"

namespace haptex::media {

inline constexpr int kPluginAbi = 1;
inline constexpr const char* kPluginFile = "libhaptex_opencv_codecs.so";
inline constexpr const char* kPluginSymbol = "haptex_opencv_codecs";

struct Plugin {
  int abi;
  bool (*encode_image)(const std::string&, const cv::Mat&, std::vector<unsigned char>&, const std::vector<int>&);
  cv::Mat (*decode_image)(cv::InputArray, int);
  cv::Mat (*read_image)(const std::string&, int);
  VideoReader* (*open_video)(const std::string&, int);
  VideoWriter* (*create_video)(const std::string&, int, int, double, cv::Size, bool);
};

}  // namespace haptex::media
