#include "dataset/decode_image.hpp"

#include <csetjmp>
#include <cstdio>  // jpeglib.h needs FILE
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <vector>

#include <jpeglib.h>
#include <jerror.h>

#include "core/error.hpp"
#include "core/image_header.hpp"
#include "core/input_file.hpp"
#include "media/codecs.hpp"

namespace haptex::dataset {
namespace {

// libjpeg reports an error by calling error_exit, which must not return; it jumps back into the call
// below that started the work, keeping its text. Warnings reach emit_message, which prints nothing,
// counts them and keeps the text of the first that tells of damaged image data.
struct JpegState {
  jpeg_decompress_struct info{};
  jpeg_error_mgr errors{};
  std::jmp_buf jump{};
  bool created = false;
  char damage[JMSG_LENGTH_MAX] = {}, first_warning[JMSG_LENGTH_MAX] = {};
};

void jump_back(j_common_ptr info) {
  auto* s = static_cast<JpegState*>(info->client_data);
  if (s->damage[0] == 0) info->err->format_message(info, s->damage);
  std::longjmp(s->jump, 1);
}

// Bits that are no Huffman (or arithmetic) code, a lost restart marker, a scan that breaks the
// sequence: the coded data was changed, and libjpeg draws garbage where it was. "Premature end of data
// segment" is damage only when the marker that ended the data early is not the image's end: OpenCV's
// MJPG encoder and many webcams close whole frames a few bits short of their end marker
// (decode_image.hpp), while bytes changed mid-scan make a marker of their own there (review 4: a
// JPEG with 200 bytes overwritten passed). "Extraneous bytes before marker" is never damage.
bool tells_of_damage(j_common_ptr info) {
  constexpr int kEndOfImage = 0xD9;
  const int code = info->err->msg_code;
  if (code == JWRN_HIT_MARKER) return reinterpret_cast<j_decompress_ptr>(info)->unread_marker != kEndOfImage;
  return code == JWRN_HUFF_BAD_CODE || code == JWRN_ARITH_BAD_CODE || code == JWRN_MUST_RESYNC || code == JWRN_NOT_SEQUENTIAL ||
         code == JWRN_BOGUS_PROGRESSION || code == JWRN_JPEG_EOF;
}

void count_warning(j_common_ptr info, int level) {
  if (level >= 0) return;  // trace messages
  ++info->err->num_warnings;
  auto* s = static_cast<JpegState*>(info->client_data);
  if (s->first_warning[0] == 0) info->err->format_message(info, s->first_warning);
  if (s->damage[0] == 0 && tells_of_damage(info)) info->err->format_message(info, s->damage);
}

// The two functions that call libjpeg hold no C++ object of their own, so the jump skips no destructor.
bool start(JpegState& s, std::span<const std::uint8_t> jpeg, DecodedColour colour, int reduction) {
  if (setjmp(s.jump)) return false;
  jpeg_create_decompress(&s.info);
  s.created = true;
  s.info.client_data = &s;
  jpeg_mem_src(&s.info, jpeg.data(), static_cast<unsigned long>(jpeg.size()));
  if (jpeg_read_header(&s.info, TRUE) != JPEG_HEADER_OK) return false;
  // The stated size, not the scaled one: a progressive JPEG holds every coefficient at full size
  // however small it is decoded, so a 30 KB file stating 60000 x 60000 would take gigabytes.
  if (std::uint64_t(s.info.image_width) * s.info.image_height > kMaxImagePixels) return false;
  if (s.info.num_components != 1 && s.info.num_components != 3) return false;  // CMYK or worse: no sensor sends it
  // As OpenCV asks for it, so the pixels are the same: the codec's own BGR or grey, scaled in the DCT.
  s.info.scale_num = 1;
  s.info.scale_denom = static_cast<unsigned>(reduction);
  s.info.out_color_space = colour == DecodedColour::grey ? JCS_GRAYSCALE : JCS_EXT_BGR;
  jpeg_start_decompress(&s.info);
  return true;
}

bool read_rows(JpegState& s, std::uint8_t* pixels, std::size_t step) {
  if (setjmp(s.jump)) return false;
  while (s.info.output_scanline < s.info.output_height) {
    JSAMPROW row = pixels + step * s.info.output_scanline;
    jpeg_read_scanlines(&s.info, &row, 1);
  }
  jpeg_finish_decompress(&s.info);
  return true;
}

cv::Mat png_decode(std::span<const std::uint8_t> bytes, DecodedColour colour) {
  const cv::Mat wrapped(1, int(bytes.size()), CV_8U, const_cast<std::uint8_t*>(bytes.data()));
  try {
    return media::decode_image(wrapped, (colour == DecodedColour::grey ? cv::IMREAD_GRAYSCALE : cv::IMREAD_COLOR) | cv::IMREAD_IGNORE_ORIENTATION);
  } catch (const cv::Exception&) {
    return {};
  }
}

}  // namespace

cv::Mat decode_jpeg(std::span<const std::uint8_t> jpeg, DecodedColour colour, int reduction, JpegReport* report) {
  if (reduction != 1 && reduction != 2 && reduction != 4 && reduction != 8) return {};
  if (!is_complete_jpeg(jpeg)) return {};  // libjpeg would draw the missing part grey, which scores as contact
  auto s = std::make_unique<JpegState>();
  s->info.err = jpeg_std_error(&s->errors);
  s->errors.error_exit = jump_back;
  s->errors.emit_message = count_warning;
  s->info.client_data = s.get();
  struct Destroy {
    JpegState& s;
    ~Destroy() {
      if (s.created) jpeg_destroy_decompress(&s.info);
    }
  } destroy{*s};
  if (!start(*s, jpeg, colour, reduction)) return {};
  cv::Mat image(int(s->info.output_height), int(s->info.output_width), colour == DecodedColour::grey ? CV_8UC1 : CV_8UC3);
  const bool read = read_rows(*s, image.data, image.step);
  if (report) *report = {int(s->errors.num_warnings), s->damage, s->first_warning};
  if (!read || s->damage[0] != 0) return {};
  return image;
}

cv::Mat decode_image(std::span<const std::uint8_t> bytes, DecodedColour colour) {
  const std::string format = image_format(bytes);
  if (format == "jpeg") return decode_jpeg(bytes, colour);
  if (format == "png" && is_complete_png(bytes)) return png_decode(bytes, colour);
  return {};
}

cv::Mat read_image_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec))) return {};  // the caller says "cannot read"
  require_regular_file(path);  // a FIFO or a device would block: refused by name
  std::ifstream in(path, std::ios::binary);
  std::vector<std::uint8_t> head(8);
  if (!in.read(reinterpret_cast<char*>(head.data()), std::streamsize(head.size()))) return {};
  if (image_format(head).empty()) {
    try {
      return media::read_image(path, cv::IMREAD_COLOR | cv::IMREAD_IGNORE_ORIENTATION);
    } catch (const cv::Exception&) {
      return {};
    }
  }
  std::error_code error;
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (error || size > 4 * kMaxImagePixels) return {};
  // A 1 MB PNG may state 20000 x 20000 pixels: refused from its header before 1.6 GB is decoded (review 12, F1).
  if (const auto stated = image_header_size(path); stated && std::uint64_t(stated->width) * stated->height > kMaxImagePixels)
    throw input_error(path, "", "its header states " + std::to_string(stated->width) + " x " + std::to_string(stated->height) +
                                    " pixels, over 64 megapixels",
                      "Scale it down (haptex describes a press at 256 x 256), e.g. convert IMG -resize 2048x2048 SMALL.png");
  in.seekg(0);
  const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return decode_image(bytes);
}

}  // namespace haptex::dataset
