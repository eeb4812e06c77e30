#pragma once
// One home for turning a press image's bytes (a JPEG or a PNG: a camera's MJPG frame, a press file's
// frame, a file in a folder) into pixels. JPEGs are decoded with libjpeg directly rather than through
// cv::imdecode, because libjpeg prints its warnings to stderr and OpenCV gives no way to stop it: OpenCV's
// own MJPG encoder (`haptex synth`'s videos) and many webcams write frames that decode whole but draw
// "Corrupt JPEG data: premature end of data segment" or "extraneous bytes before marker", and a
// library here never prints (docs/architecture.md). The pixels are cv::imdecode's, bit for bit (a
// test holds it), except that EXIF orientation is never applied: a sensor frame's pixel grid is the
// sensor's.
#include <cstdint>
#include <span>
#include <string>

#include <opencv2/core/mat.hpp>

namespace haptex::dataset {

enum class DecodedColour { bgr, grey };

// What libjpeg said while decoding, never printed: how many warnings, and its error or the first
// warning that tells of damaged coded data ("Corrupt JPEG data: bad Huffman code"; empty when none).
struct JpegReport {
  int warnings = 0;
  std::string damage;
  std::string first_warning;  // the text of the first warning, damage or not
};

// A JPEG decoded at 1/reduction of its size (1, 2, 4 or 8: libjpeg's DCT-domain scaling, OpenCV's
// IMREAD_REDUCED_*) as 8-bit BGR or grey, what libjpeg said in `report` when given; empty when it is
// cut off (is_complete_jpeg), does not decode, its coded data is damaged (JpegReport::damage: libjpeg
// would draw garbage there), it states more than kMaxImagePixels (core/image_header.hpp) whatever the
// reduction, or is CMYK (no GelSight-type camera sends it). A frame cut off and closed with an end
// marker still decodes, its missing part grey, with a warning ("premature end of data segment"):
// OpenCV's own MJPG encoder closes whole frames the same way, so the two cannot be told apart. Nor can
// a changed byte that still reads as valid codes: libjpeg decodes what it finds.
cv::Mat decode_jpeg(std::span<const std::uint8_t> jpeg, DecodedColour colour = DecodedColour::bgr, int reduction = 1,
                    JpegReport* report = nullptr);

// A JPEG (decode_jpeg) or a PNG (cv::imdecode, 8-bit BGR; is_complete_png checked first, so libpng
// finds nothing to complain of) at full size; empty for anything else or when it does not decode.
cv::Mat decode_image(std::span<const std::uint8_t> bytes, DecodedColour colour = DecodedColour::bgr);

// An image file as 8-bit BGR: a JPEG or PNG through decode_image (a file over 256 MiB, four bytes
// per pixel of kMaxImagePixels, is not read), any other format OpenCV reads through cv::imread, EXIF
// orientation never applied; empty when it cannot be read. Throws haptex::Error (bad_input) when a
// JPEG's or PNG's header states over 64 megapixels (core/image_header.hpp).
cv::Mat read_image_file(const std::string& path);

}  // namespace haptex::dataset
