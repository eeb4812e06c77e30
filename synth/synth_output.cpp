#include "synth/synth_output.hpp"

#include <filesystem>

#include "core/error.hpp"
#include "core/naming.hpp"
#include "core/owned_folder.hpp"

namespace haptex::synth {
namespace fs = std::filesystem;

OutputFolder::OutputFolder(std::string out, bool overwrite) : out_(std::move(out)), staging_(out_ + ".partial") {
  std::error_code ec;
  if (fs::exists(out_, ec) && !fs::is_directory(out_, ec))
    throw input_error(out_, "", "exists and is not a directory", "Choose a folder with -o");
  if (fs::is_directory(out_, ec) && !fs::is_empty(out_, ec) && !overwrite)
    throw input_error(out_, "", "the output folder is not empty", "Choose a new folder with -o, or pass --force to replace it");
  if (overwrite) check_only_haptex_files(out_);
  fs::remove_all(staging_, ec);  // the leftovers of a killed run
  for (const char* sub : {"recordings", "gelsight"}) {
    fs::create_directories(fs::path(staging_) / sub, ec);
    if (ec) throw input_error(out_, "", "cannot create the output folder (" + ec.message() + ")", "Choose a writable place with -o");
  }
}

OutputFolder::~OutputFolder() {
  std::error_code ec;
  if (!committed_) fs::remove_all(staging_, ec);
}

void OutputFolder::commit() {
  write_file_list(staging_, "haptex synth");
  check_only_haptex_files(out_);  // a file of the user's may have appeared while we wrote
  std::error_code ec;
  fs::remove_all(out_, ec);
  fs::rename(staging_, out_, ec);
  if (ec) throw failure(staging_ + ": cannot rename to " + out_ + " (" + ec.message() + ")");
  committed_ = true;
}

std::string recording_path(const std::string& out, const std::string& material, int index) {
  return (fs::path(out) / "recordings" / (material_id(material) + "_" + std::to_string(index) + ".xml")).string();
}

std::string gelsight_directory(const std::string& out, const std::string& material) {
  return (fs::path(out) / "gelsight" / material).string();
}

}  // namespace haptex::synth
