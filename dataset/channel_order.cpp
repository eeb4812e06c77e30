#include "dataset/channel_order.hpp"

#include <optional>
#include <string>
#include <utility>

#include "core/error.hpp"
#include "dataset/layout.hpp"

namespace haptex::dataset {
namespace {

constexpr const char* kFix = "Set it to RGB or BGR, the order of the stored pixels (h5py: obj.attrs['channel_order'] = 'RGB')";

// "/materials/x/presses/0/@channel_order", "/@channel_order" for a file's root.
std::string attribute_place(const h5::Node& node) {
  return (node.object_path() == "/" ? std::string() : node.object_path()) + "/@" + layout::kChannelOrder;
}

// The order `node` states, nullopt when it has no channel_order attribute.
std::optional<ChannelOrder> stated(const h5::Node& node) {
  if (!node.has_attr(layout::kChannelOrder)) return std::nullopt;
  const std::string text = node.attr_string(layout::kChannelOrder);
  for (ChannelOrder order : {ChannelOrder::rgb, ChannelOrder::bgr})
    if (text == channel_order_name(order)) return order;
  throw input_error(node.file(), attribute_place(node),
                    "unknown channel order '" + text.substr(0, 40) + "'", kFix);
}

}  // namespace

const char* channel_order_name(ChannelOrder order) { return order == ChannelOrder::rgb ? "RGB" : "BGR"; }

ChannelOrder read_channel_order(const h5::Group& press, std::string_view image) {
  const std::optional<ChannelOrder> of_press = stated(press);
  std::optional<ChannelOrder> of_image;
  if (press.has_dataset(image)) {
    const h5::Dataset d = press.open_dataset(image);
    of_image = stated(d);
    if (of_press && of_image && *of_press != *of_image)
      throw input_error(press.file(), attribute_place(d),
                        std::string("says ") + channel_order_name(*of_image) + " but its press says " +
                            channel_order_name(*of_press) + " (" + attribute_place(press) + ")",
                        "Make both name the order of the stored pixels");
  }
  if (of_press) return *of_press;
  if (of_image) return *of_image;
  throw input_error(press.file(), attribute_place(press),
                    "missing: the order of the colour channels of its images is unknown", kFix);
}

void reorder_channels(std::span<std::uint8_t> pixels, ChannelOrder from, ChannelOrder to) {
  if (from == to) return;
  for (std::size_t i = 0; i + 2 < pixels.size(); i += 3) std::swap(pixels[i], pixels[i + 2]);
}

}  // namespace haptex::dataset
