#include "capture/storage/image_datasets.hpp"

#include <cstring>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"

namespace haptex::capture {
namespace {

h5::DatasetOptions per_image_chunks(const cv::Mat& image, std::size_t leading) {
  h5::DatasetOptions options;
  options.gzip_level = 1;
  options.chunk = {hsize_t(image.rows), hsize_t(image.cols), 3};
  if (leading) options.chunk.insert(options.chunk.begin(), 1);
  return options;
}

void append_rgb(const cv::Mat& bgr, std::vector<std::uint8_t>& out) {
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  if (!rgb.isContinuous()) rgb = rgb.clone();
  out.insert(out.end(), rgb.data, rgb.data + rgb.total() * 3);
}

}  // namespace

h5::Dataset write_image(h5::Group& group, const std::string& name, const cv::Mat& bgr, const std::string& description) {
  CV_Assert(bgr.type() == CV_8UC3);
  std::vector<std::uint8_t> rgb;
  append_rgb(bgr, rgb);
  h5::Dataset d = group.write_array<std::uint8_t>(name, rgb, {hsize_t(bgr.rows), hsize_t(bgr.cols), 3},
                                                  per_image_chunks(bgr, 0));
  d.set_attr("description", description);
  d.set_attr("channel_order", "RGB");
  return d;
}

h5::Dataset write_image_stack(h5::Group& group, const std::string& name, const std::vector<cv::Mat>& bgr,
                              const std::string& description) {
  CV_Assert(!bgr.empty());
  std::vector<std::uint8_t> rgb;
  rgb.reserve(bgr.size() * bgr.front().total() * 3);
  for (const auto& image : bgr) {
    CV_Assert(image.type() == CV_8UC3 && image.size() == bgr.front().size());
    append_rgb(image, rgb);
  }
  const cv::Mat& first = bgr.front();
  h5::Dataset d = group.write_array<std::uint8_t>(
      name, rgb, {hsize_t(bgr.size()), hsize_t(first.rows), hsize_t(first.cols), 3}, per_image_chunks(first, 1));
  d.set_attr("description", description);
  d.set_attr("channel_order", "RGB");
  return d;
}

cv::Mat read_image(const h5::Dataset& dataset) {
  const h5::Shape shape = dataset.shape();
  if (shape.size() != 3 || shape[2] != 3 || dataset.dtype() != "uint8")
    throw input_error(dataset.file(), dataset.object_path(), "expected an H x W x 3 uint8 image",
                      "Was the file written by haptex?");
  const std::vector<std::uint8_t> rgb = dataset.read<std::uint8_t>();
  cv::Mat image(static_cast<int>(shape[0]), static_cast<int>(shape[1]), CV_8UC3);
  std::memcpy(image.data, rgb.data(), rgb.size());
  cv::cvtColor(image, image, cv::COLOR_RGB2BGR);
  return image;
}

}  // namespace haptex::capture
