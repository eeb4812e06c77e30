#include "core/image_header.hpp"

#include <algorithm>
#include <array>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace haptex {

namespace {

std::uint32_t big_endian(const unsigned char* p, int bytes) {
  std::uint32_t v = 0;
  for (int i = 0; i < bytes; ++i) v = (v << 8) | p[i];
  return v;
}

// PNG: the 8-byte signature, then the IHDR chunk whose data opens with width and height.
std::optional<ImageSize> png_size(std::istream& in) {
  std::array<unsigned char, 24> head{};
  if (!in.read(reinterpret_cast<char*>(head.data()), head.size())) return std::nullopt;
  static constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (!std::equal(kSignature, kSignature + 8, head.begin()) || std::string(head.begin() + 12, head.begin() + 16) != "IHDR")
    return std::nullopt;
  return ImageSize{big_endian(&head[16], 4), big_endian(&head[20], 4)};
}

// JPEG: segments after SOI until a start-of-frame marker (C0..CF but C4, C8, CC), which holds
// precision, height and width.
std::optional<ImageSize> jpeg_size(std::istream& in) {
  unsigned char soi[2] = {};
  if (!in.read(reinterpret_cast<char*>(soi), 2) || soi[0] != 0xFF || soi[1] != 0xD8) return std::nullopt;
  for (int segments = 0; segments < 1000; ++segments) {
    unsigned char marker[4] = {};
    if (!in.read(reinterpret_cast<char*>(marker), 4) || marker[0] != 0xFF) return std::nullopt;
    const unsigned char type = marker[1];
    const std::uint32_t length = big_endian(&marker[2], 2);
    if (length < 2) return std::nullopt;
    if (type >= 0xC0 && type <= 0xCF && type != 0xC4 && type != 0xC8 && type != 0xCC) {
      unsigned char frame[5] = {};
      if (!in.read(reinterpret_cast<char*>(frame), 5)) return std::nullopt;
      return ImageSize{big_endian(&frame[3], 2), big_endian(&frame[1], 2)};
    }
    in.seekg(std::streamoff(length - 2), std::ios::cur);
  }
  return std::nullopt;
}

std::optional<ImageSize> header_size(std::istream& in) {
  if (auto size = png_size(in)) return size;
  in.clear();
  in.seekg(0);
  return jpeg_size(in);
}

}  // namespace

std::optional<ImageSize> image_header_size(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  return header_size(in);
}

std::optional<ImageSize> image_header_size(std::span<const std::uint8_t> bytes) {
  std::istringstream in(std::string(bytes.begin(), bytes.end()), std::ios::binary);
  return header_size(in);
}

}  // namespace haptex
