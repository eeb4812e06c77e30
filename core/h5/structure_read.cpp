#include "core/h5/structure_probe.hpp"

#include <ostream>
#include <vector>

#include "core/error.hpp"
#include "core/h5/handle.hpp"
#include "core/h5/link_rule.hpp"
#include "core/h5/node.hpp"
#include "core/h5/stored_type.hpp"

// haptex-h5-probe's reading (core/h5/structure_probe.hpp): every place it reads is written to `out`
// first, so that when HDF5 crashes the reader of the pipe knows where.
namespace haptex::h5 {
namespace {

// An attribute haptex writes holds a few bytes; the longest, a `source` command line, at most 2 MiB
// (kLongestText). The probe reads values up to this size and only opens larger ones.
constexpr std::uint64_t kMostAttributeBytesRead = std::uint64_t(16) << 20;

// Reads the value of attribute `name` of `object` as its own native type, when it is of a class haptex's
// readers read (integer, float, string), then frees what HDF5 allocated for a variable-length string.
void read_attribute(hid_t object, const std::string& name, const std::string& where, const std::string& file) {
  Handle attr(check_input(H5Aopen(object, name.c_str(), H5P_DEFAULT), "open the attribute " + where, file));
  Handle stored(check_input(H5Aget_type(attr.get()), "read the type of " + where, file));
  Handle space(check_input(H5Aget_space(attr.get()), "read the shape of " + where, file));
  require_sound_number_type(stored.get(), file, where);
  const H5T_class_t kind = H5Tget_class(stored.get());
  if (kind != H5T_INTEGER && kind != H5T_FLOAT && kind != H5T_STRING) return;  // what haptex's readers read
  Handle memory(check_input(H5Tget_native_type(stored.get(), H5T_DIR_DEFAULT), "read the type of " + where, file));
  const hssize_t values = H5Sget_simple_extent_npoints(space.get());
  const std::size_t size = H5Tget_size(memory.get());
  if (values < 0 || size == 0) check_input(H5I_INVALID_HID, "read the shape of " + where, file);
  if (double(values) * double(size) > double(kMostAttributeBytesRead)) return;
  std::vector<unsigned char> value(std::size_t(values) * size);
  check_input_status(H5Aread(attr.get(), memory.get(), value.data()), "read " + where, file);
  if (H5Tis_variable_str(memory.get()) > 0)
    H5Dvlen_reclaim(memory.get(), space.get(), H5P_DEFAULT, value.data());
}

// Variable-length values (encoded images and frames, names) live in the file's global heap, whose
// sizes HDF5 1.10 trusts: a damaged one crashes the read (memcpy past the heap) or loops in it. Those of
// `depth` (strings for the structure, byte sequences for the values) are read one element at a time,
// as dataset::read_vlen_bytes does, when the readers would read them (a dataset they refuse for its
// size or chunks is left to them).
void read_variable_length_values(const Dataset& dataset, ProbeDepth depth, std::ostream& progress) {
  const std::string& file = dataset.file();
  const std::string& path = dataset.object_path();
  Handle stored(check_input(H5Dget_type(dataset.id()), "read the type of " + path, file));
  const bool strings = H5Tis_variable_str(stored.get()) > 0, sequences = H5Tget_class(stored.get()) == H5T_VLEN;
  if (!(depth == ProbeDepth::structure ? strings : sequences)) return;
  if (dataset.shape().size() != 1 || !dataset.size_problem().empty() || !dataset.chunk_problem().empty()) return;
  Handle memory(check_input(H5Tget_native_type(stored.get(), H5T_DIR_DEFAULT), "read the type of " + path, file));
  const hsize_t one[1] = {1};
  Handle memory_space(H5Screate_simple(1, one, nullptr));
  Handle file_space(check_input(H5Dget_space(dataset.id()), "read the shape of " + path, file));
  std::vector<unsigned char> element(H5Tget_size(memory.get()));
  for (hsize_t index = 0; index < dataset.shape()[0]; ++index) {
    const std::string where = path + ", element " + std::to_string(index);
    progress << where << '\0' << std::flush;
    H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, &index, nullptr, one, nullptr);
    if (H5Dread(dataset.id(), memory.get(), memory_space.get(), file_space.get(), H5P_DEFAULT, element.data()) < 0)
      throw input_error(file, where, "HDF5 could not read it (" + last_library_error() + ")",
                        "The file is damaged: copy it again, or make it again with the haptex command that wrote it");
    H5Dvlen_reclaim(memory.get(), memory_space.get(), H5P_DEFAULT, element.data());
  }
}

void read_attributes(hid_t object, const std::string& path, const std::string& file, std::ostream& progress) {
  progress << path << '\0' << std::flush;  // the pipe's reader keeps the last path: where a crash was
  H5O_info_t info;
  check_input_status(H5Oget_info2(object, &info, H5O_INFO_NUM_ATTRS), "read the attributes of " + path, file);
  if (info.num_attrs > kMostAttributes) return;  // check_links refuses it, without reading them
  for (const std::string& name : attribute_names(object, path, file)) read_attribute(object, name, path + "@" + name, file);
}

// check_links's walk (core/h5/link_rule.cpp): every object reached by a hard link, once, groups to
// kDeepestGroups; what breaks the link rule is skipped, for the readers to refuse.
void read_members(hid_t group, const std::string& path, const std::string& file, CopiedObjects& seen, ProbeDepth values,
                  std::ostream& progress, int depth = 1) {
  for (const std::string& name : link_names(group, path, file)) {
    const std::string member = member_path(path, name);
    H5O_info_t info;
    if (follow_link(group, name, member, file, seen, info)) continue;
    if (info.type == H5O_TYPE_GROUP && depth <= kDeepestGroups) {
      Handle child(check_input(H5Gopen2(group, name.c_str(), H5P_DEFAULT), "open " + member, file));
      read_attributes(child.get(), member, file, progress);
      read_members(child.get(), member, file, seen, values, progress, depth + 1);
    } else if (info.type == H5O_TYPE_DATASET) {
      progress << member << '\0' << std::flush;
      const Dataset dataset(Handle(check_input(H5Dopen2(group, name.c_str(), H5P_DEFAULT), "open " + member, file)), file, member);
      Handle type(check_input(H5Dget_type(dataset.id()), "read the type of " + member, file));
      require_sound_number_type(type.get(), file, member);
      Handle space(check_input(H5Dget_space(dataset.id()), "read the shape of " + member, file));
      Handle creation(check_input(H5Dget_create_plist(dataset.id()), "read the layout of " + member, file));
      read_attributes(dataset.id(), member, file, progress);
      read_variable_length_values(dataset, values, progress);
    }
  }
}

}  // namespace

int read_structure(const std::string& path, ProbeDepth depth, std::ostream& out,
                   const std::function<void(std::uint64_t end_of_address)>& opened) {
  out << '\0' << std::flush;  // started (AddressSanitizer's runtime, when preloaded, could not stop it)
  silence_library_errors();
  const hid_t id = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (id < 0) return kProbeNotOpened;  // File::open says why
  haddr_t end_of_address = 0;
  if (opened && H5Fget_eoa(id, &end_of_address) >= 0) opened(end_of_address);
  try {
    {
      Handle root(check_input(H5Gopen2(id, "/", H5P_DEFAULT), "open the root group", path));
      CopiedObjects seen;
      H5O_info_t info;
      check_input_status(H5Oget_info2(root.get(), &info, H5O_INFO_BASIC), "read /", path);
      seen.emplace(info.addr, "/");
      read_attributes(root.get(), "/", path, out);
      read_members(root.get(), "/", path, seen, depth, out);
    }
    out << '\0' << std::flush;  // an empty place: the file as a whole
    H5Fclose(id);  // where HDF5 1.10 crashes after a read it did not refuse
    return kProbeRead;
  } catch (const Error& refused) {
    // Not closed: HDF5 1.10 may crash closing it.
    out << refused.where() << '\0' << refused.finding() << '\0' << refused.fix() << '\0' << std::flush;
    return kProbeRefused;
  }
}

}  // namespace haptex::h5
