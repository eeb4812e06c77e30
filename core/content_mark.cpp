#include "core/content_mark.hpp"

#include <fcntl.h>
#include <sys/xattr.h>
#include <unistd.h>

#include <array>
#include <cstdint>

#include "core/error.hpp"
#include "core/sha256.hpp"

namespace haptex {
namespace {

// The hex SHA-256 of fd's bytes, read with pread from the start; empty when they cannot be read.
std::string hash_of(int fd) {
  Sha256 hash;
  std::array<std::uint8_t, 1 << 16> buffer{};
  for (off_t at = 0;;) {
    const ssize_t got = ::pread(fd, buffer.data(), buffer.size(), at);
    if (got < 0) return "";
    if (got == 0) return hash.hex_digest();
    hash.update(std::span<const std::uint8_t>(buffer.data(), std::size_t(got)));
    at += got;
  }
}

bool carries_content_mark(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) return false;
  std::array<char, 65> stored{};
  const ssize_t size = ::fgetxattr(fd, kContentMarkAttribute, stored.data(), stored.size());
  const bool marked = size == 64 && std::string(stored.data(), 64) == hash_of(fd);
  ::close(fd);
  return marked;
}

}  // namespace

void mark_content(int fd) {
  const std::string hex = hash_of(fd);
  if (!hex.empty()) ::fsetxattr(fd, kContentMarkAttribute, hex.data(), hex.size(), 0);  // unsupported: left unmarked
}

void require_content_mark(const std::string& path) {
  if (carries_content_mark(path)) return;
  throw input_error(path, "",
                    "its bytes are not those haptex wrote there (a file of yours in the same format, or haptex's edited, copied "
                    "or moved from a file system without extended attributes since: haptex keeps the SHA-256 of what it wrote in "
                    "the attribute " + std::string(kContentMarkAttribute) + "), so --force does not replace it",
                    "Choose another output name, or move the file away yourself");
}

}  // namespace haptex
