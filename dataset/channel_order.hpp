#pragma once
// The order of the colour channels of the images a haptex file stores: a press file's uint8 H x W x 3
// reference, and encoded images once decoded (a press file's frames; a gelsight or dataset press's
// `reference`, `peak`, `frames`). The press that holds them states it in its `channel_order`
// attribute (a gelsight or dataset press group, a press file's root; schemas/hdf5-layout.md), and each
// image dataset haptex writes repeats it. haptex writes RGB, what h5py, PIL and matplotlib users
// expect; readers take RGB or BGR and convert to what their consumer expects. An order taken for the
// other does not fail anywhere: it silently changes the grey image and every colour-derived feature,
// so an order a reader does not know is refused.
#include <cstdint>
#include <span>
#include <string_view>

#include "core/h5/node.hpp"

namespace haptex::dataset {

enum class ChannelOrder { rgb, bgr };

inline constexpr ChannelOrder kWrittenChannelOrder = ChannelOrder::rgb;

const char* channel_order_name(ChannelOrder order);  // "RGB", "BGR"

// The order of the images of `press`, from its @channel_order; where the press has none (press files
// written before it had one), from its dataset `image`'s own. Throws haptex::Error (bad_input) naming
// the file and the attribute when neither states an order, when one names an order other than RGB or
// BGR, or when the two disagree.
ChannelOrder read_channel_order(const h5::Group& press, std::string_view image);

// Interleaved 3-channel pixels from `from` into `to`: the first and third channel of every pixel
// swap places when the orders differ.
void reorder_channels(std::span<std::uint8_t> pixels, ChannelOrder from, ChannelOrder to);

}  // namespace haptex::dataset
