#include "core/h5/node.hpp"


#include <type_traits>

#include <algorithm>
#include <cctype>
#include <cstring>

#include "core/bounded_call.hpp"
#include "core/error.hpp"
#include "core/h5/link_rule.hpp"
#include "core/h5/stored_type.hpp"
#include "core/text/format.hpp"
#include "core/text/utf8.hpp"

namespace haptex::h5 {
namespace {

// Variable-length strings in `cset`. Reads use the file's own character set: HDF5 converts no string
// between ASCII and UTF-8, and older h5py and other tools write ASCII (review 16, F6).
Handle string_type(H5T_cset_t cset = H5T_CSET_UTF8) {
  Handle type(H5Tcopy(H5T_C_S1));
  H5Tset_size(type.get(), H5T_VARIABLE);
  H5Tset_cset(type.get(), cset);
  return type;
}

Handle string_type_of(hid_t stored) { return string_type(H5Tget_cset(stored)); }

// Object creation without timestamps, so the same content gives the same bytes.
Handle untimed_creation_list(hid_t list_class) {
  Handle list(H5Pcreate(list_class));
  H5Pset_obj_track_times(list.get(), false);
  return list;
}

bool all_digits(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

Shape automatic_chunk(const Shape& shape, std::size_t element_size) {
  Shape chunk = shape;
  std::size_t row_bytes = element_size;
  for (std::size_t i = 1; i < shape.size(); ++i) row_bytes *= shape[i];
  const hsize_t rows = std::max<hsize_t>(1, (64 * 1024) / std::max<std::size_t>(1, row_bytes));
  chunk[0] = std::min<hsize_t>(shape[0], rows);
  return chunk;
}

}  // namespace

// ---- attributes

void Node::write_attr(std::string_view name, hid_t type, hid_t space, const void* data) {
  const std::string n(name);
  if (H5Aexists(id(), n.c_str()) > 0) H5Adelete(id(), n.c_str());
  Handle attr(check(H5Acreate2(id(), n.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), "create attribute " + n,
                    where()));
  check_status(H5Awrite(attr.get(), type, data), "write attribute " + n, where());
}

void Node::set_attr(std::string_view name, double value) {
  Handle space(H5Screate(H5S_SCALAR));
  write_attr(name, H5T_NATIVE_DOUBLE, space.get(), &value);
}

void Node::set_attr(std::string_view name, std::int64_t value) {
  Handle space(H5Screate(H5S_SCALAR));
  write_attr(name, H5T_NATIVE_INT64, space.get(), &value);
}

void Node::set_attr(std::string_view name, std::string_view value) {
  Handle space(H5Screate(H5S_SCALAR));
  Handle type = string_type();
  const std::string copy(value);
  const char* pointer = copy.c_str();
  write_attr(name, type.get(), space.get(), &pointer);
}

void Node::set_attr(std::string_view name, std::span<const double> values) {
  const hsize_t dims[1] = {values.size()};
  Handle space(H5Screate_simple(1, dims, nullptr));
  write_attr(name, H5T_NATIVE_DOUBLE, space.get(), values.data());
}

bool Node::has_attr(std::string_view name) const { return H5Aexists(id(), std::string(name).c_str()) > 0; }

std::vector<std::string> Node::attr_names() const {
  std::vector<std::string> names;
  H5Aiterate2(
      id(), H5_INDEX_NAME, H5_ITER_INC, nullptr,
      [](hid_t, const char* name, const H5A_info_t*, void* out) -> herr_t {
        static_cast<std::vector<std::string>*>(out)->emplace_back(name);
        return 0;
      },
      &names);
  return names;
}

Handle Node::open_attr(std::string_view name) const {
  const std::string n(name);
  if (!has_attr(name))
    throw input_error(file_, object_path_, "attribute '" + n + "' is missing",
                      "Was the file written by haptex? Check it with 'haptex qa'");
  return Handle(check_input(H5Aopen(id(), n.c_str(), H5P_DEFAULT), "open attribute " + n, where()));
}

Handle Node::open_scalar_attr(std::string_view name) const {
  Handle attr = open_attr(name);
  Handle space(H5Aget_space(attr.get()));
  if (const hssize_t values = H5Sget_simple_extent_npoints(space.get()); values != 1)
    throw input_error(file_, object_path_,
                      "attribute '" + std::string(name) + "' holds " + std::to_string(values) + " values, expected one",
                      "Rewrite the file with haptex");
  return attr;
}

void Node::require_short_text(std::size_t bytes, const std::string& what) const {
  if (bytes > kLongestText)
    throw input_error(file_, object_path_,
                      what + " holds " + std::to_string(bytes) + " bytes of text, over the " + std::to_string(kLongestText >> 20) +
                          " MiB the longest text haptex writes may take",
                      "The file is damaged or not what haptex wrote: make it again with the haptex command that wrote it");
}

// Names and labels are short: a fixed-length string type declaring more is refused before its
// buffer is made (review 18, F8: 2 x 1 GiB declared in a 19 MB file ran out of memory).
std::size_t Node::fixed_length_size(hid_t type, const std::string& what) const {
  const std::size_t size = H5Tget_size(type);
  if (size > kLongestFixedString)
    throw input_error(file_, object_path_,
                      (what.empty() ? "" : what + " ") + "declares fixed-length strings of " + std::to_string(size) + " bytes each, over the " +
                          std::to_string(kLongestFixedString >> 10) + " KiB a name or label may take",
                      "The file is damaged or not what haptex wrote: make it again with the haptex command that wrote it");
  return size;
}

// One fixed-length string as stored: padding is NULs to the end (spaces, for a space-padded type:
// Fortran and MATLAB write them); text after a NUL would be cut off unseen (issue 32), so it is refused.
std::string Node::fixed_length_text(std::string stored, hid_t type, const std::string& what) const {
  if (H5Tget_strpad(type) == H5T_STR_SPACEPAD) stored.erase(stored.find_last_not_of(' ') + 1);
  const std::size_t end = std::min(stored.size(), stored.find('\0'));
  if (stored.find_first_not_of('\0', end) != std::string::npos)
    throw input_error(file_, object_path_, what + " holds a NUL byte inside its text",
                      "Write it without NUL bytes (haptex writes names as UTF-8 text)");
  stored.resize(end);
  return stored;
}

double Node::attr_double(std::string_view name) const {
  Handle attr = open_scalar_attr(name);
  Handle type(H5Aget_type(attr.get()));
  const H5T_class_t type_class = H5Tget_class(type.get());
  if (type_class != H5T_FLOAT && type_class != H5T_INTEGER)
    throw input_error(file_, object_path_, "attribute '" + std::string(name) + "' is not a number",
                      "Rewrite the file with haptex");
  double value = 0;
  check_input_status(H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &value), "read attribute", where());
  return value;
}

std::int64_t Node::attr_int(std::string_view name) const {
  Handle attr = open_scalar_attr(name);
  Handle type(H5Aget_type(attr.get()));
  if (H5Tget_class(type.get()) != H5T_INTEGER)
    throw input_error(file_, object_path_, "attribute '" + std::string(name) + "' is not an integer",
                      "Rewrite the file with haptex");
  std::int64_t value = 0;
  check_input_status(H5Aread(attr.get(), H5T_NATIVE_INT64, &value), "read attribute", where());
  return value;
}

std::string Node::attr_bytes(std::string_view name) const {
  Handle attr = open_scalar_attr(name);
  Handle type(H5Aget_type(attr.get()));
  if (H5Tget_class(type.get()) != H5T_STRING)
    throw input_error(file_, object_path_, "attribute '" + std::string(name) + "' is not a string",
                      "Rewrite the file with haptex");
  if (H5Tis_variable_str(type.get()) > 0) {
    Handle memory = string_type_of(type.get());
    char* text = nullptr;
    {
      const BoundedCall bounded(file_, object_path_ + " attribute '" + std::string(name) + "'");
      check_input_status(H5Aread(attr.get(), memory.get(), &text), "read attribute", where());
    }
    std::string value = text ? text : "";
    Handle space(H5Aget_space(attr.get()));
    H5Dvlen_reclaim(memory.get(), space.get(), H5P_DEFAULT, &text);
    require_short_text(value.size(), "attribute '" + std::string(name) + "'");
    return value;
  }
  const std::string what = "attribute '" + std::string(name) + "'";
  std::string value(fixed_length_size(type.get(), what), '\0');  // fixed-length strings, as other tools write them
  check_input_status(H5Aread(attr.get(), type.get(), value.data()), "read attribute", where());
  return fixed_length_text(value, type.get(), what);
}

std::string Node::attr_string(std::string_view name) const {
  std::string value = attr_bytes(name);
  text::require_utf8(value, file_, object_path_ + " attribute '" + std::string(name) + "'");
  return value;
}

template <typename T>
std::optional<T> Node::try_attr(std::string_view name) const {
  if (!has_attr(name)) return std::nullopt;
  try {
    if constexpr (std::is_same_v<T, double>) return attr_double(name);
    else if constexpr (std::is_same_v<T, std::int64_t>) return attr_int(name);
    else return attr_string(name);
  } catch (const Error&) {
    return std::nullopt;
  }
}
template std::optional<double> Node::try_attr<double>(std::string_view) const;
template std::optional<std::int64_t> Node::try_attr<std::int64_t>(std::string_view) const;
template std::optional<std::string> Node::try_attr<std::string>(std::string_view) const;

std::vector<double> Node::attr_doubles(std::string_view name) const {
  Handle attr = open_attr(name);
  Handle space(H5Aget_space(attr.get()));
  std::vector<double> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space.get())));
  check_input_status(H5Aread(attr.get(), H5T_NATIVE_DOUBLE, values.data()), "read attribute", where());
  return values;
}

// ---- datasets

Shape Dataset::shape() const {
  Handle space(H5Dget_space(id()));
  const int rank = H5Sget_simple_extent_ndims(space.get());
  Shape dims(static_cast<std::size_t>(std::max(rank, 0)));
  H5Sget_simple_extent_dims(space.get(), dims.data(), nullptr);
  return dims;
}

std::size_t Dataset::elements() const {
  std::size_t n = 1;
  for (auto d : shape()) n *= d;
  return n;
}

namespace {

std::string oversize(double count, std::size_t element_size) {
  if (count * double(element_size) <= double(kMostBytesRead)) return "";
  return "declares " + text::format("%.0f", count) + " values of " + std::to_string(element_size) + " bytes, more than haptex reads at once (" +
         std::to_string(kMostBytesRead >> 30) + " GiB)";
}

}  // namespace

void require_readable_size(double count, std::size_t element_size, const std::string& file, const std::string& where) {
  if (const std::string problem = oversize(count, element_size); !problem.empty())
    throw input_error(file, where, problem, "The file is damaged or not what haptex wrote: make it again with the haptex command that wrote it");
}

std::string Dataset::size_problem() const {
  Handle type(H5Dget_type(id()));
  double count = 1;
  for (auto d : shape()) count *= double(d);
  return oversize(count, H5Tget_size(type.get()));
}

std::string Dataset::chunk_problem() const {
  Handle list(H5Dget_create_plist(id()));
  if (H5Pget_layout(list.get()) != H5D_CHUNKED) return "";
  const int rank = H5Pget_chunk(list.get(), 0, nullptr);
  if (rank <= 0) return "";
  std::vector<hsize_t> chunk(static_cast<std::size_t>(rank));
  H5Pget_chunk(list.get(), rank, chunk.data());
  Handle type(H5Dget_type(id()));
  double chunk_bytes = double(H5Tget_size(type.get())), data_bytes = chunk_bytes;
  for (const hsize_t c : chunk) chunk_bytes *= double(c);
  for (const auto d : shape()) data_bytes *= double(d);
  if (chunk_bytes <= double(kLargestChunkBytes) || chunk_bytes <= data_bytes) return "";
  return text::format("is stored in chunks of %.0f MiB, for %.3g MiB of data: reading any value would inflate a whole chunk",
                      chunk_bytes / double(1 << 20), data_bytes / double(1 << 20));
}

// A filter the file names that this HDF5 lacks (h5py's lzf, hdf5plugin's blosc or zstd) fails every read
// with HDF5's plugin search, which reads like damage (review 15, R3): it is named instead.
void Dataset::require_available_filters() const {
  Handle list(H5Dget_create_plist(id()));
  const int filters = H5Pget_nfilters(list.get());
  for (int i = 0; i < filters; ++i) {
    unsigned flags = 0, config = 0;
    std::size_t values = 0;
    char name[64] = {};
    const H5Z_filter_t filter = H5Pget_filter2(list.get(), unsigned(i), &flags, &values, nullptr, sizeof name, name, &config);
    if (filter >= 0 && H5Zfilter_avail(filter) <= 0)
      throw input_error(file_, object_path_,
                        "is compressed with HDF5 filter " + std::to_string(filter) + (name[0] ? " (" + text::printable(name) + ")" : "") +
                            ", which haptex's HDF5 library cannot read",
                        "Store it with gzip (h5py: compression='gzip') or without compression");
  }
}

void Dataset::require_sensible_chunks() const {
  require_available_filters();
  if (const std::string problem = chunk_problem(); !problem.empty())
    throw input_error(file_, object_path_, problem,
                    "Rewrite the file with chunks of at most " + std::to_string(kLargestChunkBytes >> 20) +
                        " MiB (h5repack -l CHUNK=...), or make it again with the haptex command that wrote it");
}

std::size_t Dataset::elements_to_read(std::size_t element_size) const {
  require_sensible_chunks();
  double count = 1;
  for (auto d : shape()) count *= double(d);
  require_readable_size(count, element_size, file_, object_path_);
  return elements();
}

// A list of names is short: one of more than kMostTexts, or of more than kLongestTexts bytes of
// fixed-length text, is refused from its shape before any is read (review 21, F3: 3.5 million names of
// 1 KiB declared in 340 KB of unwritten chunks ran out of memory).
std::size_t Dataset::text_elements(std::size_t fixed_size) const {
  const std::size_t count = elements_to_read(std::max<std::size_t>(fixed_size, sizeof(char*)));
  if (count > kMostTexts || double(count) * double(fixed_size) > double(kLongestTexts))
    throw input_error(file_, object_path_,
                      "holds " + std::to_string(count) + " strings" + (fixed_size ? " of " + std::to_string(fixed_size) + " bytes" : "") +
                          ", more than a list of names haptex writes (" + std::to_string(kMostTexts) + " at most, " +
                          std::to_string(kLongestTexts >> 20) + " MiB in all)",
                      "The file is damaged or not what haptex wrote: make it again with the haptex command that wrote it");
  return count;
}

std::string Dataset::dtype() const {
  Handle type(H5Dget_type(id()));
  const std::size_t bytes = H5Tget_size(type.get());
  switch (H5Tget_class(type.get())) {
    case H5T_FLOAT: return "float" + std::to_string(8 * bytes);
    case H5T_INTEGER:
      return std::string(H5Tget_sign(type.get()) == H5T_SGN_NONE ? "uint" : "int") + std::to_string(8 * bytes);
    case H5T_STRING: return "string";
    case H5T_VLEN: return "vlen";
    default: return "other";
  }
}

void Dataset::read_raw(hid_t memory_type, void* out) const {
  const Handle stored(check_input(H5Dget_type(id()), "read the type of " + object_path_, file_));
  require_sound_number_type(stored.get(), file_, object_path_);
  check_input_status(H5Dread(id(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out), "read dataset", where());
}

std::vector<std::string> Dataset::read_strings() const {
  Handle stored(H5Dget_type(id()));
  std::vector<std::string> values =
      H5Tis_variable_str(stored.get()) > 0 ? read_variable_strings(stored.get()) : read_fixed_strings(stored.get());
  for (std::size_t i = 0; i < values.size(); ++i) text::require_utf8(values[i], file_, object_path_ + "[" + std::to_string(i) + "]");
  return values;
}

std::vector<std::string> Dataset::read_fixed_strings(hid_t stored) const {
  if (H5Tget_class(stored) != H5T_STRING)
    throw input_error(file_, object_path_, "holds " + dtype() + " values, not text", "Write the names as strings");
  const std::size_t size = fixed_length_size(stored, "");
  std::string raw(text_elements(size) * size, '\0');
  {
    const BoundedCall bounded(file_, object_path_);
    check_input_status(H5Dread(id(), stored, H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.data()), "read strings", where());
  }
  std::vector<std::string> values;
  for (std::size_t at = 0; at < raw.size(); at += size)
    values.push_back(fixed_length_text(raw.substr(at, size), stored, "element " + std::to_string(at / size)));
  return values;
}

std::vector<std::string> Dataset::read_variable_strings(hid_t stored) const {
  Handle memory = string_type_of(stored);
  std::vector<char*> pointers(text_elements(0), nullptr);
  {
    const BoundedCall bounded(file_, object_path_);
    check_input_status(H5Dread(id(), memory.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()), "read strings", where());
  }
  std::vector<std::string> values;
  std::size_t longest = 0;
  for (const char* p : pointers) longest = std::max(longest, p ? std::strlen(p) : 0);
  if (longest <= kLongestText)
    for (const char* p : pointers) values.emplace_back(p ? p : "");
  Handle space(H5Dget_space(id()));
  H5Dvlen_reclaim(memory.get(), space.get(), H5P_DEFAULT, pointers.data());
  require_short_text(longest, "an element");
  return values;
}

std::string shape_text(const Shape& shape) {
  std::string text = "(";
  for (std::size_t i = 0; i < shape.size(); ++i) text += (i ? ", " : "") + std::to_string(shape[i]);
  return text + ")";
}

// ---- groups

std::string Group::child_path(std::string_view name) const {
  return (object_path_ == "/" ? "/" : object_path_ + "/") + std::string(name);
}

Group Group::create_group(std::string_view name) {
  const std::string path = child_path(name);
  Handle list = untimed_creation_list(H5P_GROUP_CREATE);
  Handle group(check(H5Gcreate2(id(), std::string(name).c_str(), H5P_DEFAULT, list.get(), H5P_DEFAULT),
                     "create group", file_ + ":" + path));
  return Group(std::move(group), file_, path);
}

Group Group::require_group(std::string_view name) {
  return has_group(name) ? open_group(name) : create_group(name);
}

static void require_hard_link(hid_t group, std::string_view name, const std::string& file, const std::string& path) {
  if (const std::optional<LinkFault> fault = soft_or_external(group, std::string(name), path, file))
    throw input_error(file, path, fault->what, fault->fix);
}

Group Group::open_group(std::string_view name) const {
  const std::string path = child_path(name);
  if (!has_group(name))
    throw input_error(file_, path, "group is missing", "Check the file's layout with 'haptex info' or 'haptex qa'");
  require_hard_link(id(), name, file_, path);
  return Group(Handle(check_input(H5Gopen2(id(), std::string(name).c_str(), H5P_DEFAULT), "open group", file_ + ":" + path)),
               file_, path);
}

Dataset Group::open_dataset(std::string_view name) const {
  const std::string path = child_path(name);
  if (!has_dataset(name))
    throw input_error(file_, path, "dataset is missing", "Check the file's layout with 'haptex info' or 'haptex qa'");
  require_hard_link(id(), name, file_, path);
  Handle dataset(check_input(H5Dopen2(id(), std::string(name).c_str(), H5P_DEFAULT), "open dataset", file_ + ":" + path));
  if (const std::optional<LinkFault> fault = stored_outside(dataset.get(), path, file_)) throw input_error(file_, path, fault->what, fault->fix);
  return Dataset(std::move(dataset), file_, path);
}

bool Group::has(std::string_view name) const {
  return H5Lexists(id(), std::string(name).c_str(), H5P_DEFAULT) > 0;
}

static bool has_object_of_type(hid_t group, std::string_view name, H5O_type_t type) {
  const std::string n(name);
  if (H5Lexists(group, n.c_str(), H5P_DEFAULT) <= 0) return false;
  H5O_info_t info;
  if (H5Oget_info_by_name(group, n.c_str(), &info, H5P_DEFAULT) < 0) return false;
  return info.type == type;
}

bool Group::has_group(std::string_view name) const { return has_object_of_type(id(), name, H5O_TYPE_GROUP); }
bool Group::has_dataset(std::string_view name) const { return has_object_of_type(id(), name, H5O_TYPE_DATASET); }

std::vector<std::string> Group::children() const {
  std::vector<std::string> names;
  H5Literate(
      id(), H5_INDEX_NAME, H5_ITER_INC, nullptr,
      [](hid_t, const char* name, const H5L_info_t*, void* out) -> herr_t {
        static_cast<std::vector<std::string>*>(out)->emplace_back(name);
        return 0;
      },
      &names);
  for (const std::string& name : names) text::require_utf8(name, file_, child_path(name));
  std::stable_sort(names.begin(), names.end(), [](const std::string& a, const std::string& b) {
    if (all_digits(a) && all_digits(b) && a.size() != b.size()) return a.size() < b.size();
    return a < b;
  });
  return names;
}

Dataset Group::write_raw(std::string_view name, hid_t type, std::size_t element_size, const void* data,
                         std::size_t count, const Shape& shape, const DatasetOptions& options) {
  const std::string path = child_path(name);
  std::size_t expected = 1;
  for (auto d : shape) expected *= d;
  if (expected != count)
    throw failure(file_ + ":" + path + ": internal: " + std::to_string(count) + " values for a shape of " +
                  std::to_string(expected));
  Handle space(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr));
  Handle list = untimed_creation_list(H5P_DATASET_CREATE);
  if (options.compress && count > 0 && !shape.empty()) {
    const Shape chunk = options.chunk.empty() ? automatic_chunk(shape, element_size) : options.chunk;
    H5Pset_chunk(list.get(), static_cast<int>(chunk.size()), chunk.data());
    H5Pset_shuffle(list.get());
    H5Pset_deflate(list.get(), static_cast<unsigned>(options.gzip_level));
  }
  Handle dataset(check(H5Dcreate2(id(), std::string(name).c_str(), type, space.get(), H5P_DEFAULT, list.get(),
                                  H5P_DEFAULT),
                       "create dataset", file_ + ":" + path));
  if (count > 0)
    check_status(H5Dwrite(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), "write dataset",
                 file_ + ":" + path);
  return Dataset(std::move(dataset), file_, path);
}

Dataset Group::write_strings(std::string_view name, const std::vector<std::string>& values) {
  const std::string path = child_path(name);
  const hsize_t dims[1] = {values.size()};
  Handle space(H5Screate_simple(1, dims, nullptr));
  Handle type = string_type();
  Handle list = untimed_creation_list(H5P_DATASET_CREATE);
  Handle dataset(check(H5Dcreate2(id(), std::string(name).c_str(), type.get(), space.get(), H5P_DEFAULT, list.get(),
                                  H5P_DEFAULT),
                       "create dataset", file_ + ":" + path));
  std::vector<const char*> pointers;
  for (const auto& v : values) pointers.push_back(v.c_str());
  if (!values.empty())
    check_status(H5Dwrite(dataset.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, pointers.data()),
                 "write strings", file_ + ":" + path);
  return Dataset(std::move(dataset), file_, path);
}

}  // namespace haptex::h5
