// Group::copy_from: a member of one file copied into another by reading every attribute and every
// dataset's values and writing them again, instead of H5Ocopy. Two reasons (issue 32): the copy reads
// its source as strictly as any reader (a chunk that does not inflate, a soft or external link, an
// object that is neither group nor dataset is an error naming the source file and object, never
// copied on), and a failed write (a full disk) comes back as an error: HDF5 1.10's H5Ocopy crashes on
// one. Datasets keep their type, shape, chunking and filters (the source's creation properties).
#include <hdf5.h>

#include <algorithm>
#include <map>
#include <vector>

#include "core/bounded_call.hpp"
#include "core/error.hpp"
#include "core/h5/link_rule.hpp"
#include "core/h5/structure_probe.hpp"
#include "core/h5/node.hpp"
#include "core/h5/stored_type.hpp"

namespace haptex::h5 {
namespace {

// Whether values of the type hold pointers to memory HDF5 allocates (variable-length sequences or strings).
bool variable_length(hid_t type) {
  return H5Tdetect_class(type, H5T_VLEN) > 0 || (H5Tget_class(type) == H5T_STRING && H5Tis_variable_str(type) > 0);
}

// The type values of the stored `type` are read into and written from. Variable-length values are
// read as the native type, as haptex-h5-probe reads them (core/h5/structure_probe.hpp): read as the
// stored type, a damaged datatype message made HDF5 1.10 convert them into the file's own heap (a
// crash in H5HG_insert; found by a fuzz of review 27's kind).
Handle memory_type(hid_t type, const std::string& where, const std::string& file) {
  return Handle(check_input(variable_length(type) ? H5Tget_native_type(type, H5T_DIR_DEFAULT) : H5Tcopy(type), "read the type of " + where, file));
}

// Holds a buffer read with `type` over `space` and frees what variable-length values allocated in it.
class Values {
 public:
  Values(hid_t type, hid_t space) : type_(type), space_(space) {
    const hssize_t points = H5Sget_simple_extent_npoints(space);
    bytes_.resize(std::size_t(points > 0 ? points : 0) * H5Tget_size(type));
  }
  ~Values() {
    if (read_ && variable_length(type_)) H5Dvlen_reclaim(type_, space_, H5P_DEFAULT, bytes_.data());
  }
  Values(const Values&) = delete;
  Values& operator=(const Values&) = delete;
  void* data() { return bytes_.data(); }
  bool empty() const { return bytes_.empty(); }
  void mark_read() { read_ = true; }

 private:
  hid_t type_, space_;
  std::vector<unsigned char> bytes_;
  bool read_ = false;
};

struct Copy {
  std::string source_file, target_file;
  CopiedObjects& seen;  // every object copied, by address (core/h5/link_rule.hpp)

  // Copied, a reference would point nowhere (or anywhere) in the output.
  void require_plain_type(hid_t type, const std::string& where) const {
    if (const std::optional<LinkFault> fault = holds_references(type)) throw input_error(source_file, where, fault->what, fault->fix);
  }

  void require_readable(hid_t type, hid_t space, const std::string& where) const {
    require_plain_type(type, where);
    require_readable_size(double(std::max<hssize_t>(0, H5Sget_simple_extent_npoints(space))), H5Tget_size(type), source_file, where);
    require_sound_number_type(type, source_file, where);
  }

  void attributes(hid_t from, hid_t to, const std::string& source_path, const std::string& target_path) const {
    for (const std::string& name : attribute_names(from, source_path, source_file)) {
      const std::string where = source_path + "@" + name;
      Handle attr(check_input(H5Aopen(from, name.c_str(), H5P_DEFAULT), "open " + where, source_file));
      Handle type(check_input(H5Aget_type(attr.get()), "read the type of " + where, source_file));
      Handle space(check_input(H5Aget_space(attr.get()), "read the shape of " + where, source_file));
      require_readable(type.get(), space.get(), where);
      const Handle memory = memory_type(type.get(), where, source_file);
      Values values(memory.get(), space.get());
      if (!values.empty()) {
        const BoundedCall bounded(source_file, where);
        check_input_status(H5Aread(attr.get(), memory.get(), values.data()), "read " + where, source_file);
        values.mark_read();
      }
      Handle copy(check(H5Acreate2(to, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT),
                        "create attribute " + name, target_file + ":" + target_path));
      if (!values.empty())
        check_status(H5Awrite(copy.get(), memory.get(), values.data()), "write attribute " + name, target_file + ":" + target_path);
    }
  }

  void dataset(hid_t from_parent, const std::string& name, hid_t to_parent, const std::string& new_name,
               const std::string& source_path, const std::string& target_path) const {
    Handle from(check_input(H5Dopen2(from_parent, name.c_str(), H5P_DEFAULT), "open " + source_path, source_file));
    Handle type(check_input(H5Dget_type(from.get()), "read the type of " + source_path, source_file));
    Handle space(check_input(H5Dget_space(from.get()), "read the shape of " + source_path, source_file));
    if (const std::optional<LinkFault> fault = stored_outside(from.get(), source_path, source_file))
      throw input_error(source_file, source_path, fault->what, fault->fix);
    Handle creation(check_input(H5Dget_create_plist(from.get()), "read the layout of " + source_path, source_file));
    require_readable(type.get(), space.get(), source_path);
    if (variable_length(type.get())) probe_values(from.get(), source_file);
    const Handle memory = memory_type(type.get(), source_path, source_file);
    Values values(memory.get(), space.get());
    if (!values.empty()) {
      const BoundedCall bounded(source_file, source_path);
      check_input_status(H5Dread(from.get(), memory.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "read " + source_path,
                         source_file);
      values.mark_read();
    }
    Handle to(check(H5Dcreate2(to_parent, new_name.c_str(), type.get(), space.get(), H5P_DEFAULT, creation.get(), H5P_DEFAULT),
                    "create dataset", target_file + ":" + target_path));
    if (values.empty()) {
    } else if (H5Pget_layout(creation.get()) == H5D_CHUNKED && !variable_length(type.get())) {
      chunks(from.get(), to.get(), source_path, target_path);  // read above, so each one inflates
    } else {
      check_status(H5Dwrite(to.get(), memory.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), "write dataset",
                   target_file + ":" + target_path);
    }
    attributes(from.get(), to.get(), source_path, target_path);
  }

  // A chunked dataset's chunks copied as stored (compressed), once the whole dataset has been read: as
  // fast as H5Ocopy, without compressing again.
  void chunks(hid_t from, hid_t to, const std::string& source_path, const std::string& target_path) const {
    Handle space(check_input(H5Dget_space(from), "read the shape of " + source_path, source_file));
    hsize_t count = 0;
    check_input_status(H5Dget_num_chunks(from, space.get(), &count), "list the chunks of " + source_path, source_file);
    std::vector<hsize_t> offset(std::size_t(std::max(1, H5Sget_simple_extent_ndims(space.get()))));
    std::vector<unsigned char> bytes;
    for (hsize_t i = 0; i < count; ++i) {
      unsigned mask = 0;
      haddr_t address = 0;
      hsize_t size = 0;
      check_input_status(H5Dget_chunk_info(from, space.get(), i, offset.data(), &mask, &address, &size),
                         "read chunk " + std::to_string(i) + " of " + source_path, source_file);
      bytes.resize(std::size_t(size));
      check_input_status(H5Dread_chunk(from, H5P_DEFAULT, offset.data(), &mask, bytes.data()),
                         "read chunk " + std::to_string(i) + " of " + source_path, source_file);
      check_status(H5Dwrite_chunk(to, H5P_DEFAULT, mask, offset.data(), std::size_t(size), bytes.data()), "write dataset",
                   target_file + ":" + target_path);
    }
  }

  void group(hid_t from_parent, const std::string& name, hid_t to_parent, const std::string& new_name,
             const std::string& source_path, const std::string& target_path) {
    Handle from(check_input(H5Gopen2(from_parent, name.c_str(), H5P_DEFAULT), "open " + source_path, source_file));
    Handle creation(check_input(H5Gget_create_plist(from.get()), "read the layout of " + source_path, source_file));
    Handle to(check(H5Gcreate2(to_parent, new_name.c_str(), H5P_DEFAULT, creation.get(), H5P_DEFAULT), "create group",
                    target_file + ":" + target_path));
    attributes(from.get(), to.get(), source_path, target_path);
    for (const std::string& member : link_names(from.get(), source_path, source_file))
      object(from.get(), member, to.get(), member, member_path(source_path, member), member_path(target_path, member));
  }

  void object(hid_t from_parent, const std::string& name, hid_t to_parent, const std::string& new_name,
              const std::string& source_path, const std::string& target_path) {
    H5O_info_t info;
    if (const std::optional<LinkFault> fault = follow_link(from_parent, name, source_path, source_file, seen, info))
      throw input_error(source_file, source_path, fault->what, fault->fix);
    if (info.type == H5O_TYPE_GROUP) group(from_parent, name, to_parent, new_name, source_path, target_path);
    else if (info.type == H5O_TYPE_DATASET) dataset(from_parent, name, to_parent, new_name, source_path, target_path);
    else {
      const LinkFault fault = neither_group_nor_dataset();
      throw input_error(source_file, source_path, fault.what, fault.fix);
    }
  }
};

}  // namespace

void Group::copy_from(const Group& source, std::string_view name, std::string_view new_name) {
  CopiedObjects copied;
  copy_from(source, name, new_name, copied);
}

void Group::copy_from(const Group& source, std::string_view name, std::string_view new_name, CopiedObjects& copied) {
  Copy copy{source.file(), file_, copied};
  copy.object(source.id(), std::string(name), id(), std::string(new_name), member_path(source.object_path(), std::string(name)),
              child_path(new_name));
}

}  // namespace haptex::h5
