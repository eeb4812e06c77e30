#pragma once
// SHA-256 (FIPS 180-4) for provenance: every converted source file and every split input is hashed.
#include <array>
#include <cstdint>
#include <span>
#include <string>

namespace haptex {

class Sha256 {
 public:
  Sha256();
  void update(std::span<const std::uint8_t> bytes);
  void update(std::string_view text);
  std::array<std::uint8_t, 32> digest();  // finishes; the object must not be updated afterwards
  std::string hex_digest();
  // The x86 SHA extensions are used when the CPU has them; tests switch them off to check the portable path.
  static bool use_cpu_extensions;
  static bool cpu_extensions_available();

 private:
  void compress(const std::uint8_t* block);
  std::array<std::uint32_t, 8> state_;
  std::array<std::uint8_t, 64> buffer_{};
  std::size_t buffered_ = 0;
  std::uint64_t total_bytes_ = 0;
};

std::string sha256_hex(std::span<const char> bytes);
// Hex SHA-256 of a file's bytes; throws haptex::Error (bad_input) when it cannot be read.
std::string sha256_file(const std::string& path);

}  // namespace haptex
