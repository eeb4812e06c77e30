#include "tests/support/sound_server.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

#include "tests/support/run_haptex.hpp"

extern char** environ;

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

bool pulse_plugin_installed() {
  for (const char* lib : {"/usr/lib/x86_64-linux-gnu", "/usr/lib/aarch64-linux-gnu", "/usr/lib"})
    if (fs::exists(std::string(lib) + "/alsa-lib/libasound_module_pcm_pulse.so")) return true;
  return false;
}

// Starts argv in the background, standard output to `out`; -1 where it cannot.
int start(const std::vector<std::string>& argv, const std::string& out) {
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  const int failed = posix_spawnp(&pid, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return failed ? -1 : pid;
}

void stop(int& pid) {
  if (pid <= 0) return;
  ::kill(pid, SIGTERM);
  ::waitpid(pid, nullptr, 0);
  pid = -1;
}

}  // namespace

SoundServer::SoundServer() {
  if (run_program({"pulseaudio", "--version"}).exit_code != 0 || run_program({"parec", "--version"}).exit_code != 0 ||
      !pulse_plugin_installed()) {
    missing_ = "pulseaudio, pulseaudio-utils or libasound2-plugins is not installed (make deps installs them)";
    return;
  }
  fs::create_directories(dir_.file("runtime"));
  fs::permissions(dir_.file("runtime"), fs::perms::owner_all);
  std::ofstream(dir_.file("client.conf")) << "autospawn = no\n";
  ::setenv("XDG_RUNTIME_DIR", dir_.file("runtime").c_str(), 1);
  if (const char* home = std::getenv("HOME")) home_ = home;
  changed_environment_ = true;
  ::setenv("HOME", dir_.path().c_str(), 1);  // the server's cookie
  ::setenv("PULSE_CLIENTCONFIG", dir_.file("client.conf").c_str(), 1);
  ::unsetenv("ALSA_CONFIG_PATH");
  server_ = start({"pulseaudio", "-n", "--daemonize=no", "--exit-idle-time=-1", "--load=module-native-protocol-unix",
                   "--load=module-null-sink sink_name=card rate=48000 format=s16le channels=1"},
                  "/dev/null");
  for (int i = 0; i < 100 && run_program({"pactl", "info"}).exit_code != 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  if (run_program({"pactl", "info"}).exit_code != 0) {
    missing_ = "the private PulseAudio server did not start";
    return;
  }
  recorder_ = start({"parec", "-d", "card.monitor", "--format=s16le", "--rate=48000", "--channels=1", "--raw"}, dir_.file("monitor.raw"));
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // the recording runs before anything plays
}

SoundServer::~SoundServer() {
  stop(recorder_);
  stop(server_);
  if (!changed_environment_) return;
  for (const char* name : {"XDG_RUNTIME_DIR", "PULSE_CLIENTCONFIG"}) ::unsetenv(name);
  if (home_) ::setenv("HOME", home_->c_str(), 1);
  else ::unsetenv("HOME");
}

std::vector<std::int16_t> SoundServer::stop_and_take() {
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // the sink's last samples reach the monitor
  stop(recorder_);
  std::ifstream in(dir_.file("monitor.raw"), std::ios::binary);
  std::vector<std::int16_t> out(fs::file_size(dir_.file("monitor.raw")) / 2);
  in.read(reinterpret_cast<char*>(out.data()), std::streamsize(out.size() * 2));
  return out;
}

}  // namespace haptex::test
