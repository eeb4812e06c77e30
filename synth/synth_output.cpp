#include "synth/synth_output.hpp"

#include <filesystem>

#include "core/error.hpp"
#include "core/naming.hpp"

namespace haptex::synth {
namespace fs = std::filesystem;

OutputFolder::OutputFolder(const std::string& out, bool overwrite) : partial_(out, {overwrite, "output folder", "-o", "haptex synth"}) {
  for (const char* sub : {"recordings", "gelsight"}) {
    std::error_code ec;
    // One level only: a temporary folder a signal has just taken away is not made again.
    fs::create_directory(fs::path(path()) / sub, ec);
    if (ec) throw input_error(out, "", "cannot create the output folder (" + ec.message() + ")", "Choose a writable place with -o");
  }
}

std::string recording_path(const std::string& out, const std::string& material, int index) {
  return (fs::path(out) / "recordings" / (material_id(material) + "_" + std::to_string(index) + ".xml.gz")).string();
}

std::string gelsight_directory(const std::string& out, const std::string& material) {
  return (fs::path(out) / "gelsight" / material).string();
}

}  // namespace haptex::synth
