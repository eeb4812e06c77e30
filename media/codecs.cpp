#include "media/codecs.hpp"

#include <dlfcn.h>

#include <mutex>

#include "core/error.hpp"
#include "media/plugin.hpp"

namespace haptex::media {
namespace {

const Plugin* load_plugin() {
  // By name, so the loader searches the RUNPATH of the program (media/codecs.hpp says where).
  void* library = dlopen(kPluginFile, RTLD_NOW | RTLD_LOCAL);
  const auto fix = std::string("Reinstall haptex (make install puts it in lib/haptex beside bin/), or add its folder to LD_LIBRARY_PATH");
  if (library == nullptr)
    throw failure(std::string("cannot load OpenCV's image and video codecs: ") + dlerror() + ". " + fix);
  using Entry = const Plugin* (*)();
  const auto entry = reinterpret_cast<Entry>(dlsym(library, kPluginSymbol));
  const Plugin* plugin = entry != nullptr ? entry() : nullptr;
  if (plugin == nullptr || plugin->abi != kPluginAbi)
    throw failure(std::string(kPluginFile) + " is from another haptex build (its table is not this one's). " + fix);
  return plugin;
}

const Plugin& plugin() {
  static std::once_flag once;
  static const Plugin* loaded = nullptr;
  std::call_once(once, [] { loaded = load_plugin(); });  // a throw leaves `once` unset: tried again next time
  return *loaded;
}

}  // namespace

bool encode_image(const std::string& extension, const cv::Mat& image, std::vector<unsigned char>& bytes, const std::vector<int>& parameters) {
  return plugin().encode_image(extension, image, bytes, parameters);
}

cv::Mat decode_image(cv::InputArray bytes, int flags) { return plugin().decode_image(bytes, flags); }

cv::Mat read_image(const std::string& path, int flags) { return plugin().read_image(path, flags); }

std::unique_ptr<VideoReader> open_video(const std::string& path, int api) {
  return std::unique_ptr<VideoReader>(plugin().open_video(path, api));
}

std::unique_ptr<VideoWriter> create_video(const std::string& path, int api, int fourcc, double fps, cv::Size size, bool colour) {
  return std::unique_ptr<VideoWriter>(plugin().create_video(path, api, fourcc, fps, size, colour));
}

}  // namespace haptex::media
