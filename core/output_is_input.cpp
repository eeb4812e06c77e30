#include "core/output_is_input.hpp"

#include <sys/stat.h>

#include <filesystem>

#include "core/error.hpp"

namespace haptex {
namespace fs = std::filesystem;

namespace {

bool identity(const std::string& path, struct stat& st) { return !path.empty() && ::stat(path.c_str(), &st) == 0; }

bool same(const struct stat& a, const struct stat& b) { return a.st_dev == b.st_dev && a.st_ino == b.st_ino; }

// Whether path, or a folder above it, is the folder `folder`.
bool inside(const std::string& path, const struct stat& folder) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) return false;
  for (; !p.empty(); p = p.parent_path()) {
    struct stat st;
    if (identity(p.string(), st) && same(st, folder)) return true;
    if (p == p.parent_path()) break;
  }
  return false;
}

}  // namespace

void refuse_output_among_inputs(const std::string& output, const std::vector<std::string>& inputs) {
  struct stat out;
  if (!identity(output, out)) return;
  for (const std::string& input : inputs) {
    struct stat in;
    if (!identity(input, in)) continue;
    if (same(out, in))
      throw input_error(output, "", "this output is also an input of the command (" + (input == kStandardInput ? "standard input" : input) +
                                        "), and writing it would destroy it",
                        "Choose another output name");
    if (S_ISDIR(out.st_mode) && inside(input, out))
      throw input_error(output, "", "this output folder holds an input of the command (" + input + "), which replacing it would delete",
                        "Choose another output folder");
  }
}

bool same_output_path(const std::string& a, const std::string& b) {
  // A path that cannot be resolved (a name over 255 bytes) is compared as written: an error made every
  // two such paths "the same" (review 10, C1).
  const auto resolved = [](const std::string& p) {
    std::error_code ec;
    const std::filesystem::path absolute = std::filesystem::absolute(p, ec).lexically_normal();
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(absolute, ec);
    return ec ? absolute : canonical;
  };
  return resolved(a) == resolved(b);
}

}  // namespace haptex
