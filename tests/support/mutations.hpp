#pragma once
// Small edits of a copied haptex file through core/h5 (plus the two HDF5 calls core/h5 has no
// wrapper for: deleting and copying objects), and of a copied split manifest.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/h5/file.hpp"

namespace haptex::test {

// Opens a file for writing; everything is flushed when the object goes.
class Edit {
 public:
  explicit Edit(const std::string& path) : file_(h5::File::open(path, true)) {}
  ~Edit() { file_.close(); }
  h5::Group root() const { return file_.root(); }
  h5::Group group(const std::string& path) const;  // path without the leading '/'
  h5::Dataset dataset(const std::string& path) const;

  void remove(const std::string& path);                    // unlinks a group, dataset or attribute ("a/b@name")
  void copy(const std::string& from, const std::string& to);  // a group or dataset, with everything in it
  // Reads a numeric dataset as float (or uint8), lets `change` edit the values, writes them back in place.
  void change_floats(const std::string& path, const std::function<void(std::vector<float>&)>& change);
  void change_bytes(const std::string& path, const std::function<void(std::vector<std::uint8_t>&)>& change);
  // Lets `change` edit the encoded bytes of image `index` of an image dataset (a press's reference,
  // peak or frames), written back with the dataset's string attributes.
  void change_image(const std::string& path, std::size_t index, const std::function<void(std::vector<std::uint8_t>&)>& change);
  // Fixed-length NUL-padded strings as other tools write them (h5py: numpy bytes), holding exactly
  // `texts` (NULs included; as long as the longest): at `path` "a/b@name" an attribute (scalar unless
  // `array` or several texts), else a new dataset (always an array).
  // `space_padded`: padded with spaces and typed so (H5T_STR_SPACEPAD, as Fortran and MATLAB write).
  void write_fixed_strings(const std::string& path, const std::vector<std::string>& texts, bool array = false,
                           bool space_padded = false);
  // Replaces a dataset by new values and shape (and dtype T), keeping its string attributes.
  template <typename T>
  void replace(const std::string& path, const std::vector<T>& values, const h5::Shape& shape);

 private:
  std::vector<std::pair<std::string, std::string>> string_attrs(const h5::Dataset& d) const;
  void restore(h5::Dataset d, const std::vector<std::pair<std::string, std::string>>& attrs) const;
  h5::File file_;
};

template <typename T>
void Edit::replace(const std::string& path, const std::vector<T>& values, const h5::Shape& shape) {
  const auto attrs = string_attrs(dataset(path));
  remove(path);
  const auto slash = path.rfind('/');
  h5::Group parent = slash == std::string::npos ? root() : group(path.substr(0, slash));
  restore(parent.write_array<T>(slash == std::string::npos ? path : path.substr(slash + 1), values, shape), attrs);
}

// A copy of `file` as `copy` in which the stored name length of the first attribute `name` (a version 1
// attribute message: version 1, a reserved 0, the name's length with its NUL, as haptex's files hold
// them) reads 44 800 bytes longer, as one flipped byte on a disk makes it: libhdf5 1.10 crashes reading
// some such files (review 27, F1). Throws std::runtime_error when no such message is found.
void copy_with_damaged_attribute(const std::string& file, const std::string& name, const std::string& copy);
// A copy of `file` whose first global heap collection's first object claims 16 KiB, more than the
// collection holds: libhdf5 1.10 copies past the heap reading it (review 30, F2).
void copy_with_damaged_heap(const std::string& file, const std::string& copy);
// A copy of `file` whose `nth` (from 0) little-endian float32 datatype message says its elements are 255
// bytes (review 31, F4: HDF5 copies past its buffers reading them); false when the file has fewer.
bool copy_with_damaged_float_size(const std::string& file, std::size_t nth, const std::string& copy);

nlohmann::json read_json(const std::string& path);
void write_json(const std::string& path, const nlohmann::json& doc);

}  // namespace haptex::test
