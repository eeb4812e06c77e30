#pragma once
// The pixel size of a PNG or JPEG file, read from its header without decoding it, so a reader can
// refuse an absurdly large image before OpenCV allocates gigabytes for it.
#include <cstdint>
#include <optional>
#include <span>
#include <string>

namespace haptex {

struct ImageSize {
  std::uint32_t width = 0, height = 0;
};

// nullopt when the file is neither PNG nor JPEG or its header is damaged (let the decoder judge it).
std::optional<ImageSize> image_header_size(const std::string& path);
// The same for an image in memory.
std::optional<ImageSize> image_header_size(std::span<const std::uint8_t> bytes);

}  // namespace haptex
