#include "capture/storage/avi_frame_rate.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string_view>
#include <vector>

namespace haptex::capture {
namespace {

// The headers sit before the frames ("movi"), in the first kilobytes; this much is read at most.
constexpr std::size_t kHeaderBytes = 1 << 20;

std::uint32_t le32(std::string_view bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = value << 8 | static_cast<unsigned char>(bytes[at + std::size_t(i)]);
  return value;
}

struct StatedRates {
  double stream = 0, main = 0;
  bool stream_seen = false;
};

// Walks the chunks in bytes[begin, end): avih and the first video strh, descending into the
// header lists (hdrl, strl). Chunks are padded to even sizes (RIFF).
void walk(std::string_view bytes, std::size_t begin, std::size_t end, StatedRates& rates) {
  for (std::size_t at = begin; at + 8 <= end;) {
    const std::string_view id = bytes.substr(at, 4);
    const std::size_t size = le32(bytes, at + 4), body = at + 8;
    if (size > end - body) return;  // cut off: what was read so far stands
    if (id == "LIST" && size >= 4) {
      const std::string_view type = bytes.substr(body, 4);
      if (type == "movi") return;
      if (type == "hdrl" || type == "strl") walk(bytes, body + 4, body + size, rates);
    } else if (id == "avih" && size >= 4) {
      const std::uint32_t micros = le32(bytes, body);
      if (micros > 0) rates.main = 1e6 / micros;
    } else if (id == "strh" && size >= 28 && !rates.stream_seen && bytes.substr(body, 4) == "vids") {
      rates.stream_seen = true;
      const std::uint32_t scale = le32(bytes, body + 20), rate = le32(bytes, body + 24);
      if (scale > 0 && rate > 0) rates.stream = double(rate) / scale;
    }
    at = body + size + (size & 1);
  }
}

}  // namespace

std::optional<double> avi_frame_rate(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes(kHeaderBytes, '\0');
  in.read(bytes.data(), std::streamsize(bytes.size()));
  bytes.resize(std::size_t(in.gcount()));
  if (bytes.size() < 12 || bytes.compare(0, 4, "RIFF") != 0 || bytes.compare(8, 4, "AVI ") != 0) return std::nullopt;
  StatedRates rates;
  walk(bytes, 12, bytes.size(), rates);
  return rates.stream > 0 ? rates.stream : rates.main;
}

}  // namespace haptex::capture
