#include "capture/recording/session_folder.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <algorithm>
#include <string_view>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "capture/recording/session_manifest.hpp"
#include "core/error.hpp"
#include "core/format_version.hpp"
#include "core/h5/atomic_file.hpp"
#include "core/content_mark.hpp"
#include "core/json/schema.hpp"
#include "core/output_is_input.hpp"
#include "core/sha256.hpp"
#include "core/temporary_name.hpp"
#include "core/version.hpp"
#include "dataset/format.hpp"

namespace haptex::capture {
namespace fs = std::filesystem;
namespace {

// "press_<digits>.h5", checked by hand: std::regex matches by recursion, once per character, and a
// session.json naming a 300 000-digit press file overflowed the stack (review 23, F7).
bool is_press_file_name(std::string_view name) {
  if (!name.starts_with("press_") || !name.ends_with(".h5")) return false;
  const std::string_view digits = name.substr(6, name.size() - 9);
  return !digits.empty() && std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
}

bool is_session_file(const fs::path& p) {
  const std::string name = p.filename().string();
  return name == "session.json" || (name.starts_with("press_") && p.extension() == ".h5");
}

std::vector<fs::path> session_files(const std::string& dir) {
  std::vector<fs::path> found;
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return found;
  for (const auto& entry : fs::directory_iterator(dir))
    if (is_session_file(entry.path())) found.push_back(entry.path());
  return found;
}

[[noreturn]] void refuse_replacing(const std::string& dir, const fs::path& file, const std::string& why) {
  throw input_error(dir, "", "--force replaces only the old session's own files, and " + file.filename().string() + " " + why,
                    "Move it out of the folder, or record into a new folder with -o");
}

// The old session's files, which --force may remove: session.json and the press files it lists.
std::vector<fs::path> old_session_files(const std::string& dir) {
  const fs::path manifest = fs::path(dir) / "session.json";
  std::error_code ec;
  if (!fs::is_regular_file(fs::symlink_status(manifest, ec)))
    refuse_replacing(dir, manifest, "is missing or not a plain file, so nothing says which press files haptex wrote");
  const nlohmann::json doc = json::read_file(manifest.string());
  const std::string format = doc.is_object() && doc.contains("format") && doc["format"].is_string() ? doc["format"].get<std::string>() : "";
  if (is_newer_version(format, kSessionManifestFormat))
    refuse_replacing(dir, manifest, "is " + format + ", written by a newer haptex than this one (" + std::string(kVersion) + ")");
  if (format != kSessionManifestFormat || !doc.contains("presses") || !doc["presses"].is_array())
    refuse_replacing(dir, manifest, "is not a capture session's manifest (format " + std::string(kSessionManifestFormat) + ")");
  // Review 21, F6: an edited manifest is the user's now.
  try {
    require_content_mark(manifest.string());
  } catch (const Error&) {
    refuse_replacing(dir, manifest, "is not as haptex wrote it (edited, copied, or written by a haptex before the mark: docs/architecture.md, \"Outputs are atomic\")");
  }
  std::vector<fs::path> owned{manifest};
  std::vector<std::pair<fs::path, std::string>> recorded;  // each listed press and the SHA-256 it was saved with
  for (const nlohmann::json& press : doc["presses"])
    if (press.is_object() && press.contains("file") && press["file"].is_string() &&
        is_press_file_name(press["file"].get<std::string>())) {
      owned.push_back(fs::path(dir) / press["file"].get<std::string>());
      recorded.emplace_back(owned.back(), press.contains("sha256") && press["sha256"].is_string() ? press["sha256"].get<std::string>() : "");
    }
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (std::find(owned.begin(), owned.end(), entry.path()) == owned.end())
      refuse_replacing(dir, entry.path(), "is not one of them (session.json does not list it)");
    if (!entry.is_regular_file(ec) || entry.is_symlink(ec)) refuse_replacing(dir, entry.path(), "is not a plain file");
  }
  std::erase_if(owned, [](const fs::path& p) {
    std::error_code ignored;
    return !fs::exists(fs::symlink_status(p, ignored));
  });
  for (const fs::path& p : owned)
    if (p.extension() == ".h5") h5::require_replaceable(p.string(), dataset::format_name(dataset::Kind::press));
  // Review 30, F4: another take's press moved in under a listed name is a haptex press file too.
  for (const auto& [press, sha256] : recorded)
    if (fs::exists(fs::symlink_status(press, ec)) && sha256_file(press.string()) != sha256)
      refuse_replacing(dir, press,
                       sha256.empty() ? "has no SHA-256 in session.json (an earlier haptex recorded none), so nothing says it is the press that session saved"
                                      : "is not the press that session saved (its SHA-256 differs from session.json's: moved or copied in from elsewhere, or changed)");
  return owned;
}

}  // namespace

void check_session_dir(const std::string& dir, bool overwrite, const std::vector<std::string>& inputs) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw input_error(dir, "", "exists and is not a folder", "Give a folder for the session with -o");
  // The nearest existing folder must be writable: the session folder is made inside it.
  fs::path existing = fs::absolute(dir);
  while (!fs::exists(existing, ec) && existing.has_parent_path() && existing != existing.parent_path())
    existing = existing.parent_path();
  if (::access(existing.c_str(), W_OK) != 0)
    throw input_error(dir, "", existing.string() + " is not writable", "Choose a folder you can write to with -o");
  if (fs::is_directory(dir, ec)) SessionDirLock free_now(dir);  // a take recording there is refused before the sensor opens
  const auto existing_files = session_files(dir);
  if (existing_files.empty()) return;
  if (!overwrite) {
    // --force is offered only where it would be taken (review 9, C4: a user's own press_0.h5).
    bool replaceable = true;
    try {
      old_session_files(dir);
    } catch (const Error&) {
      replaceable = false;
    }
    if (!replaceable)
      throw input_error(dir, "", "holds files named like a take's (" + existing_files.front().filename().string() +
                                     ") that are not a capture session haptex wrote",
                        "Record into a new folder with -o");
    throw input_error(dir, "", "already holds a capture session (" + existing_files.front().filename().string() + ")",
                      "Record into a new folder with -o, or pass --force to replace the old session");
  }
  for (const fs::path& old : old_session_files(dir)) refuse_output_among_inputs(old.string(), inputs);
}

EarlierSession::EarlierSession(std::string dir, const std::vector<fs::path>& files) : dir_(std::move(dir)) {
  // Beside the folder, on its file system ("rec/" and "." name the folder itself).
  std::string folder = fs::absolute(dir_).lexically_normal().string();
  while (folder.size() > 1 && folder.back() == '/') folder.pop_back();
  Temporary aside = create_temporary_folder(folder);
  aside_ = aside.path, lock_ = aside.fd;
  for (const fs::path& file : files) {
    std::error_code ec;
    fs::rename(file, fs::path(aside_) / file.filename(), ec);
    if (ec) {
      settle();  // no press file is new yet: what was moved goes back
      throw failure(file.string() + ": cannot set the old session's file aside: " + ec.message());
    }
  }
}

EarlierSession::~EarlierSession() { settle(); }

void EarlierSession::settle() noexcept {
  if (aside_.empty()) return;
  std::error_code ec;
  bool pressed = false;  // a press file in the folder now is the new take's
  for (const auto& entry : fs::directory_iterator(dir_, ec))
    pressed = pressed || is_press_file_name(entry.path().filename().string());
  if (pressed) {
    fs::remove_all(aside_, ec);
  } else {
    fs::remove(fs::path(dir_) / "session.json", ec);  // the new take's, listing no press
    for (const auto& entry : fs::directory_iterator(aside_, ec)) fs::rename(entry.path(), fs::path(dir_) / entry.path().filename(), ec);
    fs::remove(aside_, ec);  // only when every file went back
  }
  forget_temporary(aside_);
  ::close(lock_);
  aside_.clear();
}

SessionDirLock::SessionDirLock(const std::string& dir) {
  fd_ = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd_ < 0) throw input_error(dir, "", std::string("cannot open the session folder: ") + std::strerror(errno), "Choose a folder you can write to with -o");
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    ::close(fd_);
    throw input_error(dir, "", "another haptex take is recording into this folder right now",
                      "Wait for it to end, or record into another folder with -o");
  }
}

SessionDirLock::~SessionDirLock() { ::close(fd_); }

PreparedSessionDir prepare_session_dir(const std::string& dir, bool overwrite, const std::vector<std::string>& inputs) {
  check_session_dir(dir, overwrite, inputs);
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw input_error(dir, "", "cannot create the session folder: " + ec.message(), "Choose a folder you can write to with -o");
  PreparedSessionDir prepared;
  prepared.lock = std::make_unique<SessionDirLock>(dir);
  if (!session_files(dir).empty()) prepared.earlier = std::make_unique<EarlierSession>(dir, old_session_files(dir));
  return prepared;
}

}  // namespace haptex::capture
