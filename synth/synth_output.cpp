#include "synth/synth_output.hpp"

#include <filesystem>

#include "core/error.hpp"
#include "core/naming.hpp"

namespace haptex::synth {
namespace fs = std::filesystem;

void prepare_output_directory(const std::string& out, bool overwrite) {
  std::error_code ec;
  if (fs::exists(out, ec) && !fs::is_directory(out, ec))
    throw input_error(out, "", "exists and is not a directory", "Choose a folder with -o");
  if (fs::is_directory(out, ec) && !fs::is_empty(out, ec) && !overwrite)
    throw input_error(out, "", "the output folder is not empty", "Choose a new folder with -o, or pass --force");
  for (const char* sub : {"", "recordings", "gelsight"}) {
    fs::create_directories(fs::path(out) / sub, ec);
    if (ec) throw input_error(out, "", "cannot create the output folder (" + ec.message() + ")", "Choose a writable place with -o");
  }
}

std::string recording_path(const std::string& out, const std::string& material, int index) {
  return (fs::path(out) / "recordings" / (material_id(material) + "_" + std::to_string(index) + ".xml")).string();
}

std::string gelsight_directory(const std::string& out, const std::string& material) {
  return (fs::path(out) / "gelsight" / material).string();
}

}  // namespace haptex::synth
