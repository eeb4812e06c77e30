#include "dataset/object_paths.hpp"
#include "predict/texture_choice.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "core/text/format.hpp"
#include "core/input_file.hpp"
#include "core/image_header.hpp"
#include "dataset/decode_image.hpp"

namespace haptex::predict {
namespace {

// The least side and the most width-to-height ratio of a press image: a GelSight-type frame is 4:3
// or so and hundreds of pixels wide; a 1 x 1 or 1 x 20000 image is none (haptex describes it at
// 256 x 256, which would stretch it beyond recognition).
constexpr std::uint64_t kLeastSide = 32;
constexpr double kMostAspect = 4;

void check_pixels(const std::string& path, std::uint64_t width, std::uint64_t height) {
  const std::string size = std::to_string(width) + " x " + std::to_string(height) + " pixels";
  if (width * height > kMaxImagePixels)
    throw input_error(path, "", "the image is " + size + ", over the limit of 64 megapixels for a press image",
                      "Scale it down (haptex describes it at 256 x 256 anyway), e.g. convert IMG -resize 2048x2048 SMALL.png");
  if (std::min(width, height) < kLeastSide || double(std::max(width, height)) > kMostAspect * double(std::min(width, height)))
    throw input_error(path, "", "the image is " + size + ": no sensor frame (at least " + std::to_string(kLeastSide) +
                                    " pixels a side, at most " + std::to_string(int(kMostAspect)) + " times as wide as high or high as wide)",
                      "Give the sensor's whole frame, as it recorded it");
}

std::vector<std::uint8_t> file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), {});
  if (!in.eof() && in.fail()) throw input_error(path, "", "cannot be read", "Check the file's permissions");
  return bytes;
}

// RGB, the order texture_descriptor takes (OpenCV decodes PNG and JPEG as BGR). Only PNG and JPEG,
// the formats a sensor's frames come in, and a JPEG only when libjpeg decodes it without a warning:
// one that warns (data ending early or changed) would be described from grey or garbage pixels
// (review 4: a JPEG with 200 bytes overwritten was taken without a word).
cv::Mat read_rgb(const std::string& path) {
  require_regular_file(path);  // a FIFO would block the reads below
  const auto size = image_header_size(path);
  if (size) check_pixels(path, size->width, size->height);
  // Judged from its first bytes, before the whole file is read (review 14, F2: a 2 GB file of zeros).
  std::vector<std::uint8_t> head(16);
  std::ifstream(path, std::ios::binary).read(reinterpret_cast<char*>(head.data()), std::streamsize(head.size()));
  const std::string format = image_format(head);
  if (format != "png" && format != "jpeg")
    throw input_error(path, "", "is not a PNG or JPEG image", "Save the sensor frame as PNG (lossless) or JPEG");
  const std::vector<std::uint8_t> bytes = file_bytes(path);
  dataset::JpegReport report;
  cv::Mat image = format == "jpeg" ? dataset::decode_jpeg(bytes, dataset::DecodedColour::bgr, 1, &report) : dataset::decode_image(bytes);
  if (!report.first_warning.empty() || image.empty())
    throw input_error(path, "", "the image does not decode whole" + (report.first_warning.empty() ? "" : " (libjpeg: " + report.first_warning + ")") +
                                    ": its data is cut short or was changed",
                      "Give the frame as the sensor sent it, or save it again from a copy that is whole");
  check_pixels(path, std::uint64_t(image.cols), std::uint64_t(image.rows));
  cv::cvtColor(image, image, cv::COLOR_BGR2RGB);
  return image;
}

}  // namespace

TextureCode choose_texture(const Predictor& predictor, const std::string& model_path, const TextureChoice& choice,
                           std::vector<float>* descriptor) {
  const Model& model = predictor.model();
  if (!choice.material.empty()) {
    const int m = model.material_index(choice.material);
    if (m < 0)
      throw input_error(model_path, dataset::model_material_ids_path(), "no material '" + choice.material + "'",
                        "Use one of its " + std::to_string(model.material_ids.size()) + " ids: " + text::listed(model.material_ids) +
                            " (haptex info lists them with their names)");
    return predictor.material_code(m);
  }
  if (choice.image.empty())
    throw Error(Error::Kind::bad_input, "give a press image (--image, with --reference) or a training material (--material)");
  if (model.variant != Variant::unified)
    throw input_error(model_path, "/", "a per-material model has no texture encoder", "Give --material ID instead of --image");
  const cv::Mat peak = read_rgb(choice.image);
  std::vector<float> d;
  if (choice.reference.empty()) {
    d = texture_descriptor_self_referenced(peak, model.descriptor);
  } else {
    const cv::Mat reference = read_rgb(choice.reference);
    if (reference.size() != peak.size())
      throw input_error(choice.reference, "", "the reference is not the size of the image", "Give the no-contact frame of the same sensor");
    d = texture_descriptor(peak, reference, model.descriptor);
  }
  const TextureCode code = predictor.encode_descriptor(d);
  if (descriptor) *descriptor = std::move(d);
  return code;
}

}  // namespace haptex::predict
