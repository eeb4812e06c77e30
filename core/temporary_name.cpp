#include "core/temporary_name.hpp"

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <mutex>
#include <random>
#include <set>
#include <thread>

#include "core/error.hpp"
#include "core/open_files.hpp"
#include "core/sha256.hpp"

namespace haptex {
namespace fs = std::filesystem;
namespace {

constexpr std::string_view kSuffix = ".partial";
constexpr std::size_t kRandomLetters = 8;
constexpr std::size_t kLongestName = 255;  // NAME_MAX of Linux file systems

std::string folder_of(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  return parent.empty() ? "." : parent.string();
}

// What a temporary's name holds before ".<8>.partial": the output's own name or, when the temporary's
// name would then pass the file system's 255 bytes, the output name's first bytes (cut between
// characters), "~" and 8 hex digits of its SHA-256, so that every legal output name can be written
// and two outputs still have temporaries of their own.
std::string stem_of(const std::string& final_name) {
  const std::size_t room = kLongestName - 1 - kRandomLetters - kSuffix.size();
  if (final_name.size() <= room) return final_name;
  std::size_t keep = room - 9;
  while (keep > 0 && (static_cast<unsigned char>(final_name[keep]) & 0xC0) == 0x80) --keep;  // a UTF-8 continuation byte
  return final_name.substr(0, keep) + "~" + sha256_hex(final_name).substr(0, 8);
}

std::string fresh_name(const std::string& final_path) {
  static constexpr char kLetters[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  thread_local std::mt19937_64 random{std::random_device{}()};
  std::uniform_int_distribution<std::size_t> pick(0, sizeof kLetters - 2);
  std::string name = stem_of(fs::path(final_path).filename().string()) + ".";
  for (std::size_t i = 0; i < kRandomLetters; ++i) name += kLetters[pick(random)];
  return (fs::path(final_path).parent_path() / (name + std::string(kSuffix))).string();
}

bool is_temporary_of(const std::string& entry, const std::string& final_name) {
  const std::string stem = stem_of(final_name);
  if (entry.size() != stem.size() + 1 + kRandomLetters + kSuffix.size()) return false;
  if (!entry.starts_with(stem + ".") || !entry.ends_with(kSuffix)) return false;
  for (std::size_t i = stem.size() + 1; i < stem.size() + 1 + kRandomLetters; ++i)
    if (!std::isalnum(static_cast<unsigned char>(entry[i]))) return false;
  return true;
}

// Whether another run holds the lock of one of final_path's temporaries. Opening one neither
// follows a link nor blocks on a FIFO, and changes nothing.
bool another_run_writes(const std::string& final_path, const std::string& own) {
  for (const std::string& other : temporaries_of(final_path)) {
    struct stat kind {};
    // Only a file or folder can be a run's temporary: a FIFO of that name is not opened (that would
    // release a writer blocked on it), nor is anything else.
    if (other == own || ::lstat(other.c_str(), &kind) != 0 || !(S_ISREG(kind.st_mode) || S_ISDIR(kind.st_mode))) continue;
    const int fd = ::open(other.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) continue;
    struct stat st {};
    const bool ours = ::fstat(fd, &st) == 0 && (S_ISREG(st.st_mode) || S_ISDIR(st.st_mode));
    const bool locked = ours && ::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
    ::close(fd);
    if (locked) return true;
  }
  return false;
}

// The temporaries this process has made and not yet renamed or removed. The lock is held while one
// is made and listed, and for good once a signal is taken (the process is ending).
std::mutex& listed_lock() {
  static std::mutex lock;
  return lock;
}
std::set<std::string>& listed() {
  static std::set<std::string> paths;
  return paths;
}

// The ending signals this process was not told to ignore: `nohup` (HUP) and a shell's `cmd &` (INT)
// start it with them ignored, and it must then go on as they meant.
sigset_t ending_signals() {
  sigset_t set;
  sigemptyset(&set);
  for (const int s : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction now {};
    if (sigaction(s, nullptr, &now) == 0 && now.sa_handler != SIG_IGN) sigaddset(&set, s);
  }
  return set;
}

// Removes a temporary while the run's other threads may still write into it. A file is unlinked:
// whatever holds it open writes on into nothing (libraries that open it by name do so while the
// temporaries are held: PartialFile::open_by_name). A folder is first renamed, so that a file made
// in it by name from then on fails to find it; then removed, again if a file made just before the
// rename kept it from going.
bool remove_temporary(const std::string& path) {
  std::error_code ec;
  if (!fs::is_directory(fs::symlink_status(path, ec))) return fs::remove(path, ec);
  std::string doomed = path;
  doomed.replace(doomed.size() - kSuffix.size() - kRandomLetters, kRandomLetters, "REMOVING");  // still a temporary's name
  if (::renameat2(AT_FDCWD, path.c_str(), AT_FDCWD, doomed.c_str(), RENAME_NOREPLACE) != 0) doomed = path;
  for (int attempt = 0; attempt < 3 && fs::exists(fs::symlink_status(doomed, ec)); ++attempt) fs::remove_all(doomed, ec);
  return !fs::exists(fs::symlink_status(doomed, ec));
}

[[noreturn]] void remove_listed_and_end(int signal) {
  const std::size_t removed = remove_every_temporary();
  std::fprintf(stderr, "haptex: %s: stopped; %zu unfinished output%s removed\n", strsignal(signal), removed,
               removed == 1 ? "" : "s");
  std::fflush(stderr);
  ::signal(signal, SIG_DFL);
  sigset_t only;
  sigemptyset(&only);
  sigaddset(&only, signal);
  pthread_sigmask(SIG_UNBLOCK, &only, nullptr);
  ::raise(signal);
  std::_Exit(128 + signal);  // not reached: the default action ends the process
}

// Makes a fresh temporary with `make` (which returns an open descriptor, or -1 with errno EEXIST when
// the name exists), locks it, then looks for a concurrent run writing the same output.
template <class Make>
Temporary create_temporary(const std::string& final_path, const char* what, Make make) {
  require_name_fits(final_path);
  Temporary t;
  std::unique_lock<std::mutex> lock(listed_lock());
  for (int attempt = 0;; ++attempt) {
    t.path = fresh_name(final_path);
    if ((t.fd = make(t.path)) >= 0) break;
    if (errno == ENAMETOOLONG)
      throw input_error(final_path, "", "is longer than the file system allows (255 bytes a name, 4096 a path)",
                        "Choose a shorter output name");
    refuse_if_out_of_descriptors(errno, final_path);
    if (errno != EEXIST || attempt == 100)
      throw input_error(final_path, "", std::string("cannot create a ") + what + " beside it to write it in: " + std::strerror(errno),
                        "Choose a folder you can write to");
  }
  if (::flock(t.fd, LOCK_EX | LOCK_NB) != 0 || another_run_writes(final_path, t.path)) {
    ::close(t.fd);
    std::error_code ignored;
    fs::remove(t.path, ignored);  // empty: only this run made it
    lock.unlock();
    throw input_error(final_path, "", "another haptex run is writing this output right now (it holds a locked " +
                                          std::string(what) + " beside it)",
                      "Wait for it to finish, or choose another output name");
  }
  listed().insert(t.path);
  return t;
}

}  // namespace

void require_name_fits(const std::string& final_path) {
  const long longest = ::pathconf(folder_of(final_path).c_str(), _PC_NAME_MAX);
  if (fs::path(final_path).filename().string().size() > std::size_t(longest > 0 ? longest : long(kLongestName)))
    throw input_error(final_path, "", "is longer than the file system allows (" + std::to_string(longest > 0 ? longest : long(kLongestName)) +
                                          " bytes a name)",
                      "Choose a shorter output name");
}

Temporary create_temporary_file(const std::string& final_path) {
  return create_temporary(final_path, "temporary file", [](const std::string& p) {
    return ::open(p.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  });
}

Temporary create_temporary_folder(const std::string& final_path) {
  return create_temporary(final_path, "temporary folder", [](const std::string& p) {
    if (::mkdir(p.c_str(), 0777) != 0) return -1;
    const int fd = ::open(p.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) {
      const int saved = errno;
      ::rmdir(p.c_str());
      errno = saved == EEXIST ? EIO : saved;  // not a name to draw again
    }
    return fd;
  });
}

namespace {

// Whether path (through a last link when `follow`) is the file fd was opened on: same device and inode.
bool names_descriptor(const std::string& path, int fd, bool follow) {
  struct stat named {}, opened {};
  const int found = follow ? ::stat(path.c_str(), &named) : ::lstat(path.c_str(), &named);
  return found == 0 && ::fstat(fd, &opened) == 0 && named.st_dev == opened.st_dev && named.st_ino == opened.st_ino;
}

}  // namespace

bool still_names(const std::string& path, int fd) { return names_descriptor(path, fd, false); }

void require_still_named(const std::string& path, int fd, const std::string& final_path) {
  if (!still_names(path, fd))
    throw failure(final_path + ": its temporary " + path +
                  " was replaced (by a link or another file or folder) while haptex wrote it; nothing was put in place. Make sure no "
                  "other program writes in this folder, and run again");
}

std::string name_of_descriptor(int fd, const std::string& path) {
  const std::string magic = "/proc/self/fd/" + std::to_string(fd);
  return names_descriptor(magic, fd, true) ? magic : path;
}

std::vector<std::string> temporaries_of(const std::string& final_path) {
  std::vector<std::string> found;
  const std::string folder = folder_of(final_path), name = fs::path(final_path).filename().string();
  std::error_code ec;
  for (auto it = fs::directory_iterator(folder, ec); !ec && it != fs::directory_iterator(); it.increment(ec))
    if (is_temporary_of(it->path().filename().string(), name))
      found.push_back((fs::path(final_path).parent_path() / it->path().filename()).string());
  return found;
}

std::size_t remove_every_temporary() {
  listed_lock().lock();  // never released: nothing is made from here on
  std::size_t removed = 0;
  for (const std::string& path : listed()) removed += remove_temporary(path) ? 1 : 0;
  return removed;
}

std::unique_lock<std::mutex> hold_temporaries() { return std::unique_lock<std::mutex>(listed_lock()); }

void let_a_taken_signal_finish() { const std::lock_guard<std::mutex> wait(listed_lock()); }

void forget_temporary(const std::string& path) {
  const std::lock_guard<std::mutex> lock(listed_lock());
  listed().erase(path);
}

void remove_temporaries_on_signals() {
  const sigset_t set = ending_signals();
  if (sigisemptyset(&set)) return;  // all three ignored: nothing to wait for
  pthread_sigmask(SIG_BLOCK, &set, nullptr);
  std::thread([set] {
    int signal = 0;
    while (sigwait(&set, &signal) != 0) {
    }
    remove_listed_and_end(signal);
  }).detach();
}

}  // namespace haptex
