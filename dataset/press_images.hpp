#pragma once
// The images of a press in gelsight (`gelsight/2`) and dataset (`dataset/4`) files: `reference`, `peak`
// and `frames`, each a 1-D dataset of encoded images (variable-length uint8, dataset/vlen_bytes.hpp),
// JPEG or PNG, with an `encoding` attribute. JPEG frames are the bytes the sensor sent (an MJPG video or
// press file), so storing them loses nothing and costs a tenth of the decoded pixels; the reference
// (a mean of frames) and frames of other sources are PNG, lossless. Decoded, an image's channels are
// in the press's `channel_order` (dataset/channel_order.hpp): haptex writes images whose decoded
// colours are true (RGB). schemas/hdf5-layout.md, "GelSight file", has the layout.
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/h5/node.hpp"

namespace haptex::dataset {

using EncodedImage = std::vector<std::uint8_t>;

// A BGR image as a PNG (zlib level 1: the sensor's noise does not compress further).
EncodedImage encode_png(const cv::Mat& bgr);

// Writes `images` (all one encoding, all the same size once decoded) as dataset `name` of `press`,
// with its description, encoding and channel order (RGB).
h5::Dataset write_press_images(h5::Group& press, const std::string& name, const std::vector<EncodedImage>& images,
                               const std::string& description);

// Every image of dataset `name` of `press`, decoded, in BGR whatever order the press states. Throws
// haptex::Error (bad_input) naming the file and the object when the dataset is not encoded images,
// an element is neither JPEG nor PNG, its header is damaged, states over 64 megapixels or another
// size than the press's `width` and `height` (unless `stated_size` is false: qa compares them itself,
// but even then an image that states more pixels than the press is refused, never decoded), or it
// does not decode.
std::vector<cv::Mat> read_press_images(const h5::Group& press, const std::string& name, bool stated_size = true);
// The one image of a dataset that holds one (`reference`, `peak`).
cv::Mat read_press_image(const h5::Group& press, const std::string& name);
// Throws as read_press_images does for everything short of decoding: each image is a JPEG or PNG as
// the dataset's `encoding` says, with a readable header stating the press's width and height (at
// most 64 megapixels), and whole: every PNG chunk's CRC holds and it is 8-bit; each JPEG ends with its
// end marker and its coded data reads without damage (decode_jpeg at an eighth of its size, about a
// tenth of a full decode, so merge and align afford it on every image they copy). A changed byte that
// still reads as valid codes is not found (dataset/decode_image.hpp).
void require_whole_press_images(const h5::Group& press, const std::string& name);

}  // namespace haptex::dataset
