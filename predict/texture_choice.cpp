#include "dataset/object_paths.hpp"
#include "predict/texture_choice.hpp"

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "core/input_file.hpp"
#include "core/image_header.hpp"
#include "dataset/decode_image.hpp"

namespace haptex::predict {
namespace {

void check_pixels(const std::string& path, std::uint64_t width, std::uint64_t height) {
  if (width * height > kMaxImagePixels)
    throw input_error(path, "", "the image is " + std::to_string(width) + " x " + std::to_string(height) +
                                    " pixels, over the limit of 64 megapixels for a press image",
                      "Scale it down (haptex describes it at 256 x 256 anyway), e.g. convert IMG -resize 2048x2048 SMALL.png");
}

// RGB, the order texture_descriptor takes (OpenCV decodes PNG and JPEG as BGR).
cv::Mat read_rgb(const std::string& path) {
  require_regular_file(path);  // a FIFO would block the header read below
  if (const auto size = image_header_size(path)) check_pixels(path, size->width, size->height);
  cv::Mat image = dataset::read_image_file(path);
  if (image.empty()) throw input_error(path, "", "not an image haptex can read", "Give a PNG or JPEG frame of the sensor");
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
      throw input_error(model_path, dataset::model_material_ids_path(), "no material '" + choice.material + "'", "Use one of the ids haptex info lists");
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
