#include "tests/support/temp_dir.hpp"

#include <cstdlib>
#include <stdexcept>

namespace haptex::test {

TempDir::TempDir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "haptex-test-XXXXXX").string();
  if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
  path_ = pattern;
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::permissions(path_, std::filesystem::perms::owner_all, ignored);
  std::filesystem::remove_all(path_, ignored);
}

}  // namespace haptex::test
