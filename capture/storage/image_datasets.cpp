#include "capture/storage/image_datasets.hpp"

#include <cstring>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "dataset/channel_order.hpp"
#include "dataset/description.hpp"
#include "dataset/layout.hpp"

namespace haptex::capture {
namespace {

// One chunk: the image.
h5::DatasetOptions one_chunk(const cv::Mat& image) {
  h5::DatasetOptions options;
  options.gzip_level = 1;
  options.chunk = {hsize_t(image.rows), hsize_t(image.cols), 3};
  return options;
}

}  // namespace

h5::Dataset write_image(h5::Group& group, const std::string& name, const cv::Mat& bgr, const std::string& description) {
  CV_Assert(bgr.type() == CV_8UC3);
  cv::Mat rgb;
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  if (!rgb.isContinuous()) rgb = rgb.clone();
  h5::Dataset d = group.write_array<std::uint8_t>(name, std::span<const std::uint8_t>(rgb.data, rgb.total() * 3),
                                                  {hsize_t(bgr.rows), hsize_t(bgr.cols), 3}, one_chunk(bgr));
  dataset::describe(d, "", description);
  d.set_attr(dataset::layout::kChannelOrder, dataset::channel_order_name(dataset::kWrittenChannelOrder));
  return d;
}

cv::Mat to_bgr(const cv::Mat& image, dataset::ChannelOrder order) {
  if (order == dataset::ChannelOrder::bgr) return image;
  cv::Mat bgr;
  cv::cvtColor(image, bgr, cv::COLOR_RGB2BGR);
  return bgr;
}

cv::Mat read_image(const h5::Group& press, const std::string& name) {
  const dataset::ChannelOrder order = dataset::read_channel_order(press, name);
  const h5::Dataset d = press.open_dataset(name);
  const h5::Shape shape = d.shape();
  if (shape.size() != 3 || shape[2] != 3 || d.dtype() != "uint8")
    throw input_error(d.file(), d.object_path(), "expected an H x W x 3 uint8 image", "Was the file written by haptex?");
  const std::vector<std::uint8_t> pixels = d.read<std::uint8_t>();
  cv::Mat image(static_cast<int>(shape[0]), static_cast<int>(shape[1]), CV_8UC3);
  std::memcpy(image.data, pixels.data(), pixels.size());
  return to_bgr(image, order);
}

}  // namespace haptex::capture
