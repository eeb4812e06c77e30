#pragma once
// Reading a whole input file into memory, after checking it is not larger than the user allows.
#include <cstdint>
#include <string>
#include <vector>

namespace haptex::convert {

inline constexpr std::uintmax_t kDefaultMaxBytes = std::uintmax_t(1) << 30;  // 1 GiB

// The file's bytes. Refuses, before reading,
// a file over max_bytes, naming the limit and --max-bytes.
std::vector<char> read_whole_file(const std::string& path, std::uintmax_t max_bytes);

// A file that may be gzip-compressed (known by its magic number, whatever its name): its contents,
// decompressed when compressed (no more than max_bytes of them either), and their SHA-256, which is
// what provenance names: a recording keeps its hash through gzip and gunzip.
struct InputFile {
  std::vector<char> contents;
  std::string sha256;
};
InputFile read_input_file(const std::string& path, std::uintmax_t max_bytes);

}  // namespace haptex::convert
