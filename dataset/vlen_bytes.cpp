#include "dataset/vlen_bytes.hpp"

#include "core/bounded_call.hpp"
#include "core/error.hpp"
#include "core/h5/structure_probe.hpp"

namespace haptex::dataset {
namespace {

h5::Handle byte_string_type() { return h5::Handle(H5Tvlen_create(H5T_NATIVE_UINT8)); }

h5::Dataset create_growing(h5::Group& group, const std::string& name, hid_t type) {
  const hsize_t dims[1] = {0}, max_dims[1] = {H5S_UNLIMITED}, chunk[1] = {64};
  h5::Handle space(H5Screate_simple(1, dims, max_dims));
  h5::Handle list(H5Pcreate(H5P_DATASET_CREATE));
  H5Pset_chunk(list.get(), 1, chunk);
  H5Pset_obj_track_times(list.get(), false);  // same content, same bytes
  const std::string path = (group.object_path() == "/" ? "/" : group.object_path() + "/") + name;
  h5::Handle dataset(h5::check(H5Dcreate2(group.id(), name.c_str(), type, space.get(), H5P_DEFAULT, list.get(), H5P_DEFAULT),
                               "create dataset", group.file() + ":" + path));
  return h5::Dataset(std::move(dataset), group.file(), path);
}

}  // namespace

VlenBytesWriter::VlenBytesWriter(h5::Group& group, const std::string& name)
    : dataset_(create_growing(group, name, byte_string_type().get())), type_(byte_string_type()) {}

void VlenBytesWriter::append(std::span<const std::uint8_t> bytes) {
  const hsize_t new_size[1] = {size_ + 1}, start[1] = {size_}, one[1] = {1};
  h5::check_status(H5Dset_extent(dataset_.id(), new_size), "grow dataset", dataset_.where());
  h5::Handle file_space(H5Dget_space(dataset_.id()));
  H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, one, nullptr);
  h5::Handle memory_space(H5Screate_simple(1, one, nullptr));
  hvl_t element{bytes.size(), const_cast<std::uint8_t*>(bytes.data())};
  h5::check_status(H5Dwrite(dataset_.id(), type_.get(), memory_space.get(), file_space.get(), H5P_DEFAULT, &element),
                   "write frame", dataset_.where());
  ++size_;
}

bool is_vlen_bytes(const h5::Dataset& dataset) {
  h5::Handle type(H5Dget_type(dataset.id()));
  if (H5Tget_class(type.get()) != H5T_VLEN) return false;
  h5::Handle base(H5Tget_super(type.get()));
  return H5Tget_class(base.get()) == H5T_INTEGER && H5Tget_size(base.get()) == 1;
}

std::vector<std::uint8_t> read_vlen_bytes(const h5::Dataset& dataset, std::size_t index) {
  if (!is_vlen_bytes(dataset))
    throw input_error(dataset.file(), dataset.object_path(), "expected variable-length uint8 (one encoded image or frame per element)",
                      "Was the file written by haptex? Write it again with the haptex command that makes it");
  dataset.require_sensible_chunks();
  h5::probe_values(dataset.id(), dataset.file());
  if (dataset.shape().size() != 1 || index >= dataset.shape()[0])
    throw input_error(dataset.file(), dataset.object_path(), "element " + std::to_string(index) + " does not exist",
                      "The file is damaged; write it again with the haptex command that makes it");
  const hsize_t start[1] = {index}, one[1] = {1};
  h5::Handle file_space(H5Dget_space(dataset.id()));
  H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, one, nullptr);
  h5::Handle memory_space(H5Screate_simple(1, one, nullptr));
  h5::Handle type = byte_string_type();
  hvl_t element{0, nullptr};
  const BoundedCall bounded(dataset.file(), dataset.object_path() + ", element " + std::to_string(index));
  // A damaged file (its global heap overwritten) is bad input, named with the element (review 14, F10).
  if (H5Dread(dataset.id(), type.get(), memory_space.get(), file_space.get(), H5P_DEFAULT, &element) < 0)
    throw input_error(dataset.file(), dataset.object_path() + ", element " + std::to_string(index),
                      "HDF5 could not read it (" + h5::last_library_error() + ")",
                      "The file is damaged: copy it again, or make it again with the haptex command that wrote it");
  const auto* p = static_cast<const std::uint8_t*>(element.p);
  std::vector<std::uint8_t> bytes(p, p + element.len);
  H5Dvlen_reclaim(type.get(), memory_space.get(), H5P_DEFAULT, &element);
  return bytes;
}

}  // namespace haptex::dataset
