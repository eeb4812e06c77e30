#pragma once
// The pixel size of a PNG or JPEG file, read from its header without decoding it, so a reader can
// refuse an absurdly large image before OpenCV allocates gigabytes for it; and whether one is whole.
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

// A whole JPEG starts with SOI (FF D8) and ends with EOI (FF D9), perhaps followed by padding some
// cameras add. A cut-off frame lacks EOI; libjpeg would still "decode" it, the missing part grey,
// and that would score as contact.
bool is_complete_jpeg(std::span<const std::uint8_t> jpeg);
// A whole PNG: the signature, then chunks whose CRCs hold, up to IEND at the very end. libpng would
// print its complaint about anything less to stderr (libraries here never print) before failing.
bool is_complete_png(std::span<const std::uint8_t> png);

}  // namespace haptex
