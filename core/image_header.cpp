#include "core/image_header.hpp"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace haptex {

namespace {

constexpr unsigned char kPngSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

std::uint32_t big_endian(const unsigned char* p, int bytes) {
  std::uint32_t v = 0;
  for (int i = 0; i < bytes; ++i) v = (v << 8) | p[i];
  return v;
}

// PNG: the 8-byte signature, then the IHDR chunk whose data opens with width and height.
std::optional<ImageSize> png_size(std::istream& in) {
  std::array<unsigned char, 24> head{};
  if (!in.read(reinterpret_cast<char*>(head.data()), head.size())) return std::nullopt;
  if (!std::equal(kPngSignature, kPngSignature + 8, head.begin()) || std::string(head.begin() + 12, head.begin() + 16) != "IHDR")
    return std::nullopt;
  return ImageSize{big_endian(&head[16], 4), big_endian(&head[20], 4)};
}

// JPEG: segments after SOI until a start-of-frame marker (C0..CF but C4, C8, CC), which holds
// precision, height and width.
std::optional<ImageSize> jpeg_size(std::istream& in) {
  unsigned char soi[2] = {};
  if (!in.read(reinterpret_cast<char*>(soi), 2) || soi[0] != 0xFF || soi[1] != 0xD8) return std::nullopt;
  for (int segments = 0; segments < 1000; ++segments) {
    if (in.get() != 0xFF) return std::nullopt;
    int type = in.get();
    while (type == 0xFF) type = in.get();  // fill bytes before a marker, which libjpeg accepts
    unsigned char size[2] = {};
    if (type == std::char_traits<char>::eof() || !in.read(reinterpret_cast<char*>(size), 2)) return std::nullopt;
    const std::uint32_t length = big_endian(size, 2);
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

std::string image_format(std::span<const std::uint8_t> b) {
  if (b.size() >= 3 && b[0] == 0xFF && b[1] == 0xD8 && b[2] == 0xFF) return "jpeg";
  if (b.size() >= 8 && std::equal(kPngSignature, kPngSignature + 8, b.begin())) return "png";
  return "";
}

PngPixels png_pixels(std::span<const std::uint8_t> png) {
  if (png.size() < 26 || image_format(png) != "png" || std::string(png.begin() + 12, png.begin() + 16) != "IHDR") return {};
  return {png[24], png[25]};
}

bool is_plain_rgb_png(std::span<const std::uint8_t> png) {
  const PngPixels pixels = png_pixels(png);
  return pixels.bit_depth == 8 && pixels.colour_type == 2;
}

bool is_complete_jpeg(std::span<const std::uint8_t> jpeg) {
  if (jpeg.size() < 4 || jpeg[0] != 0xFF || jpeg[1] != 0xD8) return false;
  const std::size_t tail = std::min<std::size_t>(jpeg.size(), 4096);
  for (std::size_t i = jpeg.size() - 1; i + tail > jpeg.size() && i > 0; --i)
    if (jpeg[i - 1] == 0xFF && jpeg[i] == 0xD9) return true;
  return false;
}

bool is_complete_png(std::span<const std::uint8_t> png) {
  if (png.size() < 8 || !std::equal(kPngSignature, kPngSignature + 8, png.begin())) return false;
  for (std::size_t at = 8; png.size() - at >= 12;) {
    const std::uint32_t length = big_endian(&png[at], 4);
    if (length > png.size() - at - 12) return false;
    const std::uint32_t stored = big_endian(&png[at + 8 + length], 4);
    if (crc32(0, &png[at + 4], uInt(length + 4)) != stored) return false;
    const bool end = std::equal(&png[at + 4], &png[at + 8], "IEND");
    at += 12 + std::size_t(length);
    if (end) return at == png.size();
  }
  return false;
}

bool is_complete_image(std::span<const std::uint8_t> bytes) {
  const std::string format = image_format(bytes);
  return format == "jpeg" ? is_complete_jpeg(bytes) : format == "png" && is_complete_png(bytes);
}

}  // namespace haptex
