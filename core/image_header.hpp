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

// The largest image haptex decodes as a press: 8192 x 8192 (64 megapixels), twice the largest
// GelSight-type frame known (a 3280 x 2464 GelSight Mini frame is 8 MP); the texture descriptor works
// at 256 x 256, so a larger image only costs time and memory.
inline constexpr std::uint64_t kMaxImagePixels = std::uint64_t(1) << 26;

// "jpeg" or "png" from the bytes' signature; "" for anything else.
std::string image_format(std::span<const std::uint8_t> bytes);

// nullopt when the file is neither PNG nor JPEG or its header is damaged (let the decoder judge it).
std::optional<ImageSize> image_header_size(const std::string& path);
// The same for an image in memory.
std::optional<ImageSize> image_header_size(std::span<const std::uint8_t> bytes);

// A PNG's IHDR: bit depth per channel and colour type (2 is RGB); zeros when the bytes are no PNG.
struct PngPixels {
  int bit_depth = 0, colour_type = 0;
};
PngPixels png_pixels(std::span<const std::uint8_t> png);
// An 8-bit RGB PNG, the only PNG haptex stores: every reader decodes it to the same three channels
// (OpenCV and PIL differ on 16 bits; PIL gives grey as one channel and keeps alpha).
bool is_plain_rgb_png(std::span<const std::uint8_t> png);

// A whole JPEG starts with SOI (FF D8) and ends with EOI (FF D9), perhaps followed by padding some
// cameras add. A cut-off frame lacks EOI; libjpeg would still "decode" it, the missing part grey,
// and that would score as contact.
bool is_complete_jpeg(std::span<const std::uint8_t> jpeg);
// A whole PNG: the signature, then chunks whose CRCs hold, up to IEND at the very end. libpng would
// print its complaint about anything less to stderr (libraries here never print) before failing.
bool is_complete_png(std::span<const std::uint8_t> png);
// is_complete_jpeg or is_complete_png, by the bytes' signature; false for any other format.
bool is_complete_image(std::span<const std::uint8_t> bytes);

}  // namespace haptex
