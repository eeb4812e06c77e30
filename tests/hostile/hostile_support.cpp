#include "tests/hostile/hostile_support.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace haptex::test {
namespace fs = std::filesystem;

void expect_refusal(const CommandResult& r, const std::vector<std::string>& mentions, int code) {
  EXPECT_EQ(r.exit_code, code) << r.err << r.out;
  for (const std::string& m : mentions) EXPECT_NE(r.err.find(m), std::string::npos) << "no '" << m << "' in: " << r.err;
  EXPECT_EQ(r.err.find("unexpected error"), std::string::npos) << r.err;
}

std::vector<std::string> files_named(const std::string& folder, const std::vector<std::string>& names) {
  std::vector<std::string> found;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(folder, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
    if (std::find(names.begin(), names.end(), it->path().filename().string()) != names.end()) found.push_back(it->path().string());
  return found;
}

std::vector<std::string> partial_files(const std::string& folder) {
  std::vector<std::string> found;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(folder, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
    if (it->path().extension() == ".partial") found.push_back(it->path().string());
  return found;
}

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

int start_haptex(const std::vector<std::string>& args, const std::string& stdout_path, const std::string& stderr_path, int ignored) {
  std::vector<std::string> all = {haptex_binary()};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t child = fork();
  if (child == 0) {
    if (!std::freopen(stdout_path.c_str(), "w", stdout) || !std::freopen(stderr_path.c_str(), "w", stderr)) _exit(126);
    if (ignored != 0) std::signal(ignored, SIG_IGN);
    execv(argv[0], argv.data());
    _exit(127);
  }
  return child;
}

int wait_for(int pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return status;
}

}  // namespace haptex::test
