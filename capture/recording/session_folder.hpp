#pragma once
// The folder a take records into (docs/capture.md, "Recording"): press_<j>.h5 files and session.json.
// A folder that already holds a session is refused unless --force, and --force replaces only what the
// old session wrote, as its session.json lists it: session.json itself and the press files it names
// (each one a file haptex wrote). A folder holding anything else, a session.json that is not haptex's,
// a press file it does not list, a link, or one of the take's inputs (a replayed press file), is refused
// naming the file, and nothing is deleted.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace haptex::capture {

// Refuses (haptex::Error, bad_input) a folder that cannot be made or already holds a session (unless
// overwrite, within the rule above), touching nothing. `inputs`: files the take reads.
void check_session_dir(const std::string& dir, bool overwrite, const std::vector<std::string>& inputs = {});
// An old session's files, set aside (in a temporary folder beside the session folder) while a --force
// take records: its recordings cannot be made again, so they go only once the new take has saved a
// press. Settled when destroyed: the new take saved a press, and the old files are removed; it saved
// none (Ctrl-C, an unplugged sensor, a stall before the first press), and they are put back in place
// of its empty session.json.
class EarlierSession {
 public:
  EarlierSession(std::string dir, const std::vector<std::filesystem::path>& files);
  ~EarlierSession();
  EarlierSession(const EarlierSession&) = delete;
  EarlierSession& operator=(const EarlierSession&) = delete;

 private:
  void settle() noexcept;
  std::string dir_, aside_;
  int lock_ = -1;
};

// The session folder locked (flock) while a take records into it, so a second take into the same
// folder, with or without --force, is refused instead of setting the running take's files aside.
class SessionDirLock {
 public:
  // Throws haptex::Error (bad_input) naming dir when another take holds it.
  explicit SessionDirLock(const std::string& dir);
  ~SessionDirLock();
  SessionDirLock(const SessionDirLock&) = delete;
  SessionDirLock& operator=(const SessionDirLock&) = delete;

 private:
  int fd_ = -1;
};

// A folder ready for a take: locked, and an old session set aside (when --force found one).
// Members go in reverse order: the old session is settled before the lock is let go.
struct PreparedSessionDir {
  std::unique_ptr<SessionDirLock> lock;
  std::unique_ptr<EarlierSession> earlier;
};

// The same checks, then creates and locks the folder; with overwrite, sets an old session's files aside.
PreparedSessionDir prepare_session_dir(const std::string& dir, bool overwrite, const std::vector<std::string>& inputs = {});

}  // namespace haptex::capture
