#pragma once
// gzip (RFC 1952) for haptex's own text outputs and the inputs users compress: the whole text in
// memory, in one call. Compression is deterministic (no name, mtime 0), so a seed still gives
// byte-identical files.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace haptex::gzip {

// True when `bytes` start with gzip's magic number (1f 8b).
bool is_gzip(std::span<const char> bytes);

// One gzip member holding `text`, at zlib level 1..9.
std::string compress(std::string_view text, int level);

// The concatenated contents of every member in `compressed`. Throws haptex::Error (bad_input) naming
// `source` when the data is damaged or cut short, when bytes follow that are not another member, or
// when the contents would exceed `max_bytes` (then before more than that is held in memory).
std::vector<char> decompress(std::span<const char> compressed, std::uintmax_t max_bytes, const std::string& source);

}  // namespace haptex::gzip
