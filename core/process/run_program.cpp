#include "core/process/run_program.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <string_view>

extern char** environ;

namespace haptex::process {

namespace {


class FileActions {
 public:
  FileActions() { posix_spawn_file_actions_init(&actions_); }
  ~FileActions() { posix_spawn_file_actions_destroy(&actions_); }
  FileActions(const FileActions&) = delete;
  FileActions& operator=(const FileActions&) = delete;

  bool open(int fd, const std::string& path, int flags) {
    return posix_spawn_file_actions_addopen(&actions_, fd, path.empty() ? "/dev/null" : path.c_str(), flags, 0644) == 0;
  }
  bool dup(int from, int to) { return posix_spawn_file_actions_adddup2(&actions_, from, to) == 0; }
  bool close_from(int first) { return posix_spawn_file_actions_addclosefrom_np(&actions_, first) == 0; }
  bool chdir(const std::string& directory) {
    return directory.empty() || posix_spawn_file_actions_addchdir_np(&actions_, directory.c_str()) == 0;
  }
  const posix_spawn_file_actions_t* get() const { return &actions_; }

 private:
  posix_spawn_file_actions_t actions_;
};

// This process's environment with run.environment's variables set over it.
std::vector<char*> environment_of(const ProgramRun& run) {
  std::vector<char*> envp;
  for (char** variable = environ; *variable; ++variable) {
    const std::string_view entry(*variable), name = entry.substr(0, entry.find('='));
    const bool replaced = std::any_of(run.environment.begin(), run.environment.end(), [&](const std::string& set) {
      return set.size() > name.size() && set.compare(0, name.size(), name) == 0 && set[name.size()] == '=';
    });
    if (!replaced) envp.push_back(*variable);
  }
  for (const std::string& set : run.environment) envp.push_back(const_cast<char*>(set.c_str()));
  envp.push_back(nullptr);
  return envp;
}

// Starts the program; its standard output goes to `stdout_pipe` when that is a descriptor (>= 0), else
// to run.stdout_path; `passed`, when one, becomes its kPassedDescriptor. Returns its pid, or -1 when it
// could not be started.
pid_t start_program(const ProgramRun& run, int stdout_pipe, int passed = -1) {
  if (run.argv.empty()) return -1;
  FileActions actions;
  const int out_flags = O_WRONLY | O_CREAT | O_TRUNC;  // no O_CLOEXEC: these are the child's own descriptors
  const bool out = stdout_pipe >= 0 ? actions.dup(stdout_pipe, STDOUT_FILENO) : actions.open(STDOUT_FILENO, run.stdout_path, out_flags);
  // Nothing else of haptex's reaches the child: not an output's lock, not a temporary being written.
  if (!actions.open(STDIN_FILENO, run.stdin_path, O_RDONLY) || !out || !actions.open(STDERR_FILENO, run.stderr_path, out_flags) ||
      !actions.chdir(run.directory) || (passed >= 0 && !actions.dup(passed, kPassedDescriptor)) ||
      !actions.close_from(passed >= 0 ? kPassedDescriptor + 1 : STDERR_FILENO + 1))
    return -1;
  std::vector<char*> argv;
  for (const std::string& arg : run.argv) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  const std::vector<char*> envp = environment_of(run);
  // The child starts with no signal blocked and default actions, whatever haptex blocks for itself
  // (core/temporary_name.hpp): Ctrl-C stops it too.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none, all;
  sigemptyset(&none);
  sigfillset(&all);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setsigdefault(&attributes, &all);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, argv[0], actions.get(), &attributes, argv.data(), envp.data());
  posix_spawnattr_destroy(&attributes);
  if (spawned != 0) errno = spawned;  // kNotStarted's reason, as a failed pipe2 leaves it
  return spawned == 0 ? pid : -1;
}

int wait_for_program(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return kNotStarted;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : kNotStarted;
}

}  // namespace

int run_program(const ProgramRun& run) {
  const pid_t pid = start_program(run, -1);
  return pid < 0 ? kNotStarted : wait_for_program(pid);
}

int run_program_reading(const ProgramRun& run, std::string& tail, std::size_t most, int descriptor) {
  tail.clear();
  int ends[2];
  if (pipe2(ends, O_CLOEXEC) != 0) return kNotStarted;
  // Above the descriptors the child's are put at (0 to kPassedDescriptor): with haptex's stdin closed
  // (`<&-`) the pipe or the passed file could be descriptor 0 and be replaced before it is moved.
  const int write_end = fcntl(ends[1], F_DUPFD_CLOEXEC, kPassedDescriptor + 1);
  const int passed = descriptor >= 0 ? fcntl(descriptor, F_DUPFD_CLOEXEC, kPassedDescriptor + 1) : -1;
  ::close(ends[1]);
  const pid_t pid = write_end >= 0 && (descriptor < 0 || passed >= 0) ? start_program(run, write_end, passed) : -1;
  const int not_started = errno;  // when pid < 0: why the descriptors or the start failed
  if (write_end >= 0) ::close(write_end);
  if (passed >= 0) ::close(passed);
  char buffer[4096];
  for (;;) {
    const ssize_t got = ::read(ends[0], buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) break;
    tail.append(buffer, std::size_t(got));
    if (tail.size() > most) tail.erase(0, tail.size() - most);
  }
  ::close(ends[0]);
  if (pid >= 0) return wait_for_program(pid);
  errno = not_started;
  return kNotStarted;
}

bool program_on_path(const std::string& name) {
  if (name.empty()) return false;
  if (name.find('/') != std::string::npos) return ::access(name.c_str(), X_OK) == 0;
  const char* path = std::getenv("PATH");
  std::string_view folders = path ? path : "/usr/local/bin:/usr/bin:/bin";
  while (true) {
    const std::size_t colon = folders.find(':');
    const std::string_view folder = folders.substr(0, colon);
    const std::string candidate = (folder.empty() ? std::string(".") : std::string(folder)) + "/" + name;
    if (::access(candidate.c_str(), X_OK) == 0) return true;
    if (colon == std::string_view::npos) return false;
    folders.remove_prefix(colon + 1);
  }
}

}  // namespace haptex::process
