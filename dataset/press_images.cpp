#include "dataset/press_images.hpp"

#include <optional>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "core/image_header.hpp"
#include "dataset/channel_order.hpp"
#include "dataset/description.hpp"
#include "dataset/decode_image.hpp"
#include "dataset/layout.hpp"
#include "dataset/vlen_bytes.hpp"
#include "media/codecs.hpp"

namespace haptex::dataset {
namespace {

Error bad_image(const h5::Dataset& d, std::size_t i, const std::string& what) {
  return input_error(d.file(), d.object_path() + "[" + std::to_string(i) + "]", what,
                     "Write the file again with haptex capture extract (and align)");
}

// A JPEG's coded data read through at an eighth of its size (libjpeg's DCT scaling: every code is
// read, few pixels drawn), so damage libjpeg can see is found at a fraction of a full decode's cost.
void require_undamaged_jpeg(const h5::Dataset& d, std::size_t i, const EncodedImage& bytes) {
  JpegReport report;
  if (decode_jpeg(bytes, DecodedColour::grey, 8, &report).empty())
    throw bad_image(d, i, "does not decode (a damaged JPEG" + (report.damage.empty() ? std::string() : ": " + report.damage) + ")");
}

// An image's bytes are decoded only once its header has been read and states the press's size (so no
// hostile header makes OpenCV allocate more), and only when whole (so libjpeg conceals nothing and
// libpng prints no complaint).
void require_whole(const h5::Dataset& d, std::size_t i, const EncodedImage& bytes, std::optional<cv::Size> expected) {
  const std::string encoding = image_format(bytes);
  if (encoding.empty()) throw bad_image(d, i, "is neither a JPEG nor a PNG image");
  const std::optional<ImageSize> size = image_header_size(bytes);
  if (!size) throw bad_image(d, i, "has a damaged " + encoding + " header");
  const std::string stated = std::to_string(size->width) + " x " + std::to_string(size->height);
  if (std::uint64_t(size->width) * size->height > kMaxImagePixels) throw bad_image(d, i, "its header states " + stated + " pixels, over 64 megapixels");
  if (expected && cv::Size(int(size->width), int(size->height)) != *expected)
    throw bad_image(d, i, "its header states " + stated + " pixels, the press's width and height " + std::to_string(expected->width) +
                              " x " + std::to_string(expected->height));
  if (!is_complete_image(bytes))
    throw bad_image(d, i, "does not decode (a damaged or cut-off " + encoding + ")");
  if (encoding == "png" && !is_plain_rgb_png(bytes)) {
    const PngPixels pixels = png_pixels(bytes);
    throw bad_image(d, i, "is a PNG of " + std::to_string(pixels.bit_depth) + " bits, colour type " + std::to_string(pixels.colour_type) +
                              "; haptex stores 8-bit RGB PNGs (colour type 2) only, which every reader decodes alike");
  }
}

// Orientation tags are ignored, as any other reader of the bytes would.
cv::Mat decode(const h5::Dataset& d, std::size_t i, const EncodedImage& bytes, std::optional<cv::Size> expected) {
  require_whole(d, i, bytes, expected);
  const cv::Mat image = decode_image(bytes);
  if (image.empty()) throw bad_image(d, i, "does not decode (a damaged image)");
  return image;
}

// The press's stated image size, when it states one.
std::optional<cv::Size> size_stated_by(const h5::Group& press) {
  try {
    if (press.has_attr("width") && press.has_attr("height"))
      return cv::Size(int(press.attr_int("width")), int(press.attr_int("height")));
  } catch (const Error&) {
  }
  return std::nullopt;
}

h5::Dataset open_images(const h5::Group& press, const std::string& name) {
  h5::Dataset d = press.open_dataset(name);
  if (!is_vlen_bytes(d) || d.shape().size() != 1 || d.shape()[0] == 0)
    throw input_error(d.file(), d.object_path(), "expected a 1-D dataset of encoded images (variable-length uint8)",
                      "Files from before gelsight/2 stored pixels; run haptex capture extract (and align) again");
  return d;
}

}  // namespace

EncodedImage encode_png(const cv::Mat& bgr) {
  CV_Assert(bgr.type() == CV_8UC3);
  EncodedImage png;
  // OpenCV's default settings are its fast path (SUB filter, zlib level 1); setting a compression level
  // would make libpng try every filter, twice as slow for nothing on sensor noise.
  if (!media::encode_image(".png", bgr, png)) throw failure("cannot encode an image as PNG");
  return png;
}

h5::Dataset write_press_images(h5::Group& press, const std::string& name, const std::vector<EncodedImage>& images,
                               const std::string& description) {
  CV_Assert(!images.empty());
  const std::string encoding = image_format(images.front());
  VlenBytesWriter writer(press, name);
  for (const EncodedImage& image : images) {
    if (image_format(image) != encoding || encoding.empty())
      throw failure(writer.dataset().where() + ": images must all be JPEG or all PNG");
    writer.append(image);
  }
  h5::Dataset& d = writer.dataset();
  describe(d, "", description);
  d.set_attr(layout::kEncoding, encoding);
  d.set_attr(layout::kChannelOrder, channel_order_name(kWrittenChannelOrder));
  return d;
}

std::vector<cv::Mat> read_press_images(const h5::Group& press, const std::string& name, bool stated_size) {
  const ChannelOrder order = read_channel_order(press, name);
  const h5::Dataset d = open_images(press, name);
  const std::optional<cv::Size> expected = stated_size ? size_stated_by(press) : std::nullopt;
  cv::Size largest;  // without the size check, the most an image may state: the press's size (0 x 0: none)
  if (!stated_size)
    if (const std::optional<cv::Size> stated = size_stated_by(press)) largest = *stated;
  std::vector<cv::Mat> images;
  for (std::size_t i = 0; i < d.shape()[0]; ++i) {
    const EncodedImage bytes = read_vlen_bytes(d, i);
    // Without the size check, an image is still never decoded at more pixels than the press states:
    // a dozen frames whose headers claim 64 megapixels each took qa 3.6 GB (review 15, R12).
    if (const std::optional<ImageSize> header = image_header_size(bytes);
        largest.area() > 0 && header && double(header->width) * header->height > double(largest.area()))
      throw bad_image(d, i, "its header states " + std::to_string(header->width) + " x " + std::to_string(header->height) +
                                " pixels, more than the press's width and height " + std::to_string(largest.width) + " x " +
                                std::to_string(largest.height));
    cv::Mat image = decode(d, i, bytes, expected);
    if (order == ChannelOrder::bgr) cv::cvtColor(image, image, cv::COLOR_RGB2BGR);  // the stored pixels were blue first
    images.push_back(image);
  }
  return images;
}

cv::Mat read_press_image(const h5::Group& press, const std::string& name) { return read_press_images(press, name).front(); }

void require_whole_press_images(const h5::Group& press, const std::string& name) {
  const h5::Dataset d = open_images(press, name);
  const std::string label = d.has_attr(layout::kEncoding) ? d.attr_string(layout::kEncoding) : "";
  const std::optional<cv::Size> stated = size_stated_by(press);
  for (std::size_t i = 0; i < d.shape()[0]; ++i) {
    const EncodedImage bytes = read_vlen_bytes(d, i);
    if (!label.empty() && image_format(bytes) != label)
      throw bad_image(d, i, "is " + (image_format(bytes).empty() ? std::string("no image") : "a " + image_format(bytes)) +
                                ", but the dataset's encoding says " + label);
    require_whole(d, i, bytes, stated);
    if (image_format(bytes) == "jpeg") require_undamaged_jpeg(d, i, bytes);
  }
}

}  // namespace haptex::dataset
