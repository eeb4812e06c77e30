#include "capture/extraction/capture_inputs.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "dataset/press_file.hpp"
#include "core/error.hpp"
#include "core/naming.hpp"
#include "core/input_file.hpp"
#include "core/text/utf8.hpp"

namespace haptex::capture {
namespace fs = std::filesystem;
namespace {

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

void sort_by_name(std::vector<std::string>& paths) {
  std::sort(paths.begin(), paths.end(), [](const std::string& a, const std::string& b) {
    return natural_less(fs::path(a).filename().string(), fs::path(b).filename().string());
  });
}

// A file named like a video or press file; one that is not a regular file (a FIFO, a dangling link)
// is refused by name rather than skipped.
bool is_source_file(const fs::directory_entry& entry) {
  const std::string p = entry.path().string();
  if (!(is_video_name(p) || dataset::is_press_file_name(p)) || entry.is_directory()) return false;
  require_regular_file(p);
  return true;
}

// A folder inside `dir` to look into. A link to a folder elsewhere is followed (materials gathered by
// links), but one to `dir` itself or a folder holding it would read everything around the input
// (`loop -> ../..`): it is refused by its own name, and so is a dangling link of any name (review 14,
// F8), which would otherwise be passed over as no folder.
bool is_folder_to_read(const fs::directory_entry& entry) {
  refuse_dangling_link(entry.path().string());
  std::error_code ec;
  if (!entry.is_directory(ec)) return false;
  refuse_link_to_its_own_folder(entry.path());
  return true;
}

// The sources directly in a folder: video and press files, and image-sequence folders.
std::vector<std::string> sources_in(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& entry : fs::directory_iterator(dir))
    if (is_source_file(entry) || (is_folder_to_read(entry) && is_image_sequence_dir(entry.path().string())))
      out.push_back(entry.path().string());
  sort_by_name(out);
  return out;
}

std::vector<std::string> subfolders(const std::string& dir) {
  std::vector<std::string> out;
  for (const auto& entry : fs::directory_iterator(dir))
    if (is_folder_to_read(entry)) out.push_back(entry.path().string());
  sort_by_name(out);
  return out;
}

CaptureInput input_for(const std::string& path, const std::string& material_name,
                       const std::optional<std::string>& material) {
  text::require_utf8(path, path, "the file's name");  // it is stored as the press's source
  std::error_code ec;
  const bool press = dataset::is_press_file_name(path);
  const auto kind = press ? CaptureInput::Kind::press_file
                  : fs::is_directory(path, ec) ? CaptureInput::Kind::image_sequence
                                               : CaptureInput::Kind::video;
  const std::string name = material.value_or(press ? "" : material_name);  // a press file states its own
  if (!name.empty()) checked_material_id(name, material ? "--material" : path, material ? "" : "the material (its folder's name)");
  return CaptureInput{path, name, kind};
}

// The folder's own name, also for "", ".", "./" and "dir/" (the current folder's name, "dir").
std::string directory_name(const std::string& path) {
  fs::path p = fs::absolute(path.empty() ? fs::path(".") : fs::path(path)).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();
  return p.filename().string();
}

}  // namespace

bool natural_less(const std::string& a, const std::string& b) {
  std::size_t i = 0, j = 0;
  while (i < a.size() && j < b.size()) {
    if (std::isdigit(static_cast<unsigned char>(a[i])) && std::isdigit(static_cast<unsigned char>(b[j]))) {
      std::size_t i_end = i, j_end = j;
      while (i_end < a.size() && std::isdigit(static_cast<unsigned char>(a[i_end]))) ++i_end;
      while (j_end < b.size() && std::isdigit(static_cast<unsigned char>(b[j_end]))) ++j_end;
      std::string x = a.substr(i, i_end - i), y = b.substr(j, j_end - j);
      x.erase(0, std::min(x.find_first_not_of('0'), x.size()));
      y.erase(0, std::min(y.find_first_not_of('0'), y.size()));
      if (x.size() != y.size()) return x.size() < y.size();
      if (x != y) return x < y;
      i = i_end;
      j = j_end;
    } else {
      if (a[i] != b[j]) return a[i] < b[j];
      ++i;
      ++j;
    }
  }
  return a.size() - i < b.size() - j || (a.size() - i == b.size() - j && a < b);
}

bool is_video_name(const std::string& path) {
  static const char* const kVideo[] = {".avi", ".mkv", ".mp4", ".mov", ".m4v", ".webm", ".mpg", ".mpeg", ".wmv", ".ogv", ".flv"};
  const std::string ext = lower_extension(path);
  return std::any_of(std::begin(kVideo), std::end(kVideo), [&](const char* v) { return ext == v; });
}


bool is_image_name(const std::string& path) {
  static const char* const kImage[] = {".png", ".jpg", ".jpeg", ".bmp", ".tif", ".tiff"};
  const std::string ext = lower_extension(path);
  return std::any_of(std::begin(kImage), std::end(kImage), [&](const char* v) { return ext == v; });
}

bool is_image_sequence_dir(const std::string& path) {
  std::error_code ec;
  if (!fs::is_directory(path, ec)) return false;
  int images = 0;
  for (const auto& entry : fs::directory_iterator(path, ec))
    if (entry.is_regular_file() && is_image_name(entry.path().string()) && ++images >= 2) return true;
  return false;
}

std::vector<CaptureInput> expand_capture_inputs(const std::vector<std::string>& arguments,
                                                const std::optional<std::string>& material) {
  std::vector<CaptureInput> out;
  for (const std::string& argument : arguments) {
    std::error_code ec;
    if (fs::is_regular_file(argument, ec) || is_image_sequence_dir(argument)) {  // one source
      fs::path p = fs::path(argument).lexically_normal();
      if (p.filename().empty()) p = p.parent_path();  // "press_0/" names press_0
      out.push_back(input_for(argument, directory_name(p.parent_path().string()), material));
      continue;
    }
    if (!fs::exists(fs::symlink_status(argument, ec)))
      throw input_error(argument, "", "no such file or directory", "Check the path");
    if (!fs::is_directory(argument, ec)) require_regular_file(argument);  // says why it is neither
    const std::vector<std::string> sources = sources_in(argument);
    if (!sources.empty()) {  // one material
      for (const auto& s : sources) out.push_back(input_for(s, directory_name(argument), material));
      continue;
    }
    const std::size_t before = out.size();
    for (const auto& dir : subfolders(argument))
      for (const auto& s : sources_in(dir)) out.push_back(input_for(s, directory_name(dir), material));
    if (out.size() == before)
      throw input_error(argument, "",
                        "holds no video (.avi .mkv .mp4 ..., or a folder of frame images), press file (.h5), "
                        "nor folders of them",
                        "Give a folder per material with its press videos or press files, or a folder of such folders");
  }
  return out;
}

}  // namespace haptex::capture
