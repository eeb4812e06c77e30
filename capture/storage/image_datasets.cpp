#include "capture/storage/image_datasets.hpp"

#include <cstring>
#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "dataset/channel_order.hpp"
#include "dataset/layout.hpp"

namespace haptex::capture {
namespace {

h5::DatasetOptions per_image_chunks(const cv::Mat& image, std::size_t leading) {
  h5::DatasetOptions options;
  options.gzip_level = 1;
  options.chunk = {hsize_t(image.rows), hsize_t(image.cols), 3};
  if (leading) options.chunk.insert(options.chunk.begin(), 1);
  return options;
}

void state_order(h5::Dataset& d) {
  d.set_attr(dataset::layout::kChannelOrder, dataset::channel_order_name(dataset::kWrittenChannelOrder));
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
  state_order(d);
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
