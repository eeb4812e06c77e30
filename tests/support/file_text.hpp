#pragma once
// A whole file's bytes, for tests that compare what a command or a writer left on disk.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace haptex::test {

inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace haptex::test
