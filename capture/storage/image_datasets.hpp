#pragma once
// A press file's no-contact reference (schemas/hdf5-layout.md, "Press file"): uint8 H x W x 3 in RGB
// order (what h5py, PIL and matplotlib users expect; the dataset says so in its channel_order
// attribute, dataset/channel_order.hpp), one image per chunk, gzip level 1 (images barely compress
// further, and writing a 3280 x 2464 frame at level 4 would take longer than a frame period). In
// memory, OpenCV's BGR. Gelsight and dataset files store encoded images instead (dataset/press_images.hpp).
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/h5/node.hpp"
#include "dataset/channel_order.hpp"

namespace haptex::capture {

h5::Dataset write_image(h5::Group& group, const std::string& name, const cv::Mat& bgr, const std::string& description);
// The image `name` of `press` (a press group, or a press file's root) as BGR, whatever order the
// press states. Throws haptex::Error (bad_input) naming the object when it is no H x W x 3 uint8
// image or its order is unknown (dataset::read_channel_order).
cv::Mat read_image(const h5::Group& press, const std::string& name);
// Pixels read in `order`, as BGR: the image itself when they already are, else a converted copy.
cv::Mat to_bgr(const cv::Mat& image, dataset::ChannelOrder order);

}  // namespace haptex::capture
