#include "core/owned_folder.hpp"

#include "core/json/schema.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>

#include "core/durable_file.hpp"
#include "core/error.hpp"
#include "core/sha256.hpp"

namespace haptex {
namespace fs = std::filesystem;

namespace {

struct FileList {
  std::string written_by;
  std::set<std::string> files;
  std::map<std::string, std::string> sha256;  // of each file, by name; empty in lists of earlier haptex
};

// A name inside the folder as written in the list: its own path, never a link's target.
std::string listed_name(const fs::path& entry, const fs::path& folder) { return entry.lexically_relative(folder).generic_string(); }

FileList listed_files(const std::string& folder, const fs::path& list_path) {
  FileList out;
  nlohmann::json list;
  try {
    list = json::read_file(list_path.string());
  } catch (const Error& e) {
    throw input_error(folder, "", "--force would replace this folder, but its " + std::string(kFileListName) +
                                      " cannot be read, so haptex cannot tell its own files from yours (" + e.what() + ")",
                      "Move the folder away yourself, or choose another output name");
  }
  if (!list.is_object()) return out;
  if (list.contains("written_by") && list["written_by"].is_string()) out.written_by = list["written_by"].get<std::string>();
  if (!list.contains("files") || !list["files"].is_array()) return out;
  for (const nlohmann::json& f : list["files"])
    if (f.is_string()) out.files.insert(f.get<std::string>());
  if (list.contains("sha256") && list["sha256"].is_object())
    for (const auto& [name, hash] : list["sha256"].items())
      if (hash.is_string()) out.sha256[name] = hash.get<std::string>();
  return out;
}

}  // namespace

void write_file_list(const std::string& dir, std::string_view written_by, std::string_view owner) {
  nlohmann::json files = nlohmann::json::array(), hashes = nlohmann::json::object();
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(dir)) {
    files.push_back(listed_name(entry.path(), dir));
    if (entry.is_regular_file()) hashes[listed_name(entry.path(), dir)] = sha256_file(entry.path().string());
  }
  nlohmann::json list = {
      {"about", "The files haptex wrote in this folder. haptex --force replaces the folder only while it holds "
                "nothing else; add a file of your own and it refuses."},
      {"written_by", written_by},
      {"files", files},
      {"sha256", hashes}};
  if (!owner.empty()) list["owner"] = owner;
  write_file_durably((fs::path(dir) / kFileListName).string(), list.dump(1) + "\n", false);
}

void check_only_haptex_files(const std::string& folder, std::string_view written_by) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec) || fs::is_empty(folder, ec)) return;
  const fs::path list_path = fs::path(folder) / kFileListName;
  if (!fs::is_regular_file(list_path, ec))
    throw input_error(folder, "", "--force would replace this folder, but it has no " + std::string(kFileListName) +
                                      ", so haptex cannot tell its own files from yours",
                      "Choose a new folder with -o, or empty this one yourself");
  const FileList list = listed_files(folder, list_path);
  // Another command's folder (split -o z.json --force meeting synth's z.plots) is not this one's to replace.
  if (list.written_by != written_by)
    throw input_error(folder, "", "--force would replace this folder, but " + (list.written_by.empty() ? std::string("its list names no command") : list.written_by + " wrote it") +
                                      ", not " + std::string(written_by),
                      "Choose another output name, or move the folder away yourself");
  const std::set<std::string>& listed = list.files;
  for (const fs::directory_entry& entry : fs::recursive_directory_iterator(folder, ec)) {
    const std::string name = listed_name(entry.path(), folder);
    if (name != kFileListName && !listed.contains(name))
      throw input_error(folder, name, "--force would replace this folder, but haptex did not write this file",
                        "Move your files out of the folder, or choose a new folder with -o");
    if (entry.is_symlink(ec))
      throw input_error(folder, name, "--force would replace this folder, but this is a symbolic link, which haptex never writes",
                        "Move it out of the folder, or choose a new folder with -o");
    const auto hash = list.sha256.find(name);
    if (hash != list.sha256.end() && entry.is_regular_file(ec) && sha256_file(entry.path().string()) != hash->second)
      throw input_error(folder, name, "--force would replace this folder, but this file is not the one haptex wrote (its SHA-256 differs)",
                        "Move your file out of the folder, or choose a new folder with -o");
  }
  if (ec) throw input_error(folder, "", "cannot list the folder (" + ec.message() + ")", "Check its permissions");
}

bool is_haptex_folder(const std::string& folder, std::string_view written_by) {
  std::error_code ec;
  if (!std::filesystem::is_directory(std::filesystem::symlink_status(folder, ec)) ||
      !std::filesystem::is_regular_file(std::filesystem::path(folder) / kFileListName, ec))
    return false;
  try {
    check_only_haptex_files(folder, written_by);
  } catch (const Error&) {
    return false;
  }
  return true;
}

std::string folder_owner(const std::string& folder) {
  try {
    const nlohmann::json list = json::read_file((fs::path(folder) / kFileListName).string());
    const auto owner = list.is_object() ? list.find("owner") : list.end();
    if (!list.is_object() || owner == list.end() || !owner->is_string()) return "";
    return (fs::path(folder) / owner->get<std::string>()).lexically_normal().string();
  } catch (const Error&) {
    return "";
  }
}

}  // namespace haptex
