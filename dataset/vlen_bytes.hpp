#pragma once
// A growing 1-D HDF5 dataset whose elements are byte strings of any length (variable-length uint8):
// how press files keep MJPG frames exactly as the sensor sent them, and gelsight and dataset files
// their images (dataset/press_images.hpp). h5py reads each element as a
// numpy uint8 array; cv2.imdecode turns it into the image.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/h5/node.hpp"

namespace haptex::dataset {

class VlenBytesWriter {
 public:
  VlenBytesWriter(h5::Group& group, const std::string& name);
  void append(std::span<const std::uint8_t> bytes);
  std::size_t size() const { return size_; }
  h5::Dataset& dataset() { return dataset_; }

 private:
  h5::Dataset dataset_;
  h5::Handle type_;
  std::size_t size_ = 0;
};

// Element `index` of such a dataset. Throws haptex::Error (bad_input) naming the dataset when it is
// not variable-length uint8 or the index is out of range.
std::vector<std::uint8_t> read_vlen_bytes(const h5::Dataset& dataset, std::size_t index);
bool is_vlen_bytes(const h5::Dataset& dataset);

}  // namespace haptex::dataset
