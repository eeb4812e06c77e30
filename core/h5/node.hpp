#pragma once
// Groups and datasets of an HDF5 file, with their attributes. Paths in error messages read
// "FILE:/group/dataset" so a user can find the object with h5ls or h5py.
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/h5/handle.hpp"
#include "core/h5/types.hpp"

namespace haptex::h5 {

using Shape = std::vector<hsize_t>;
// The most bytes one dataset or attribute may hold to be read at once: far beyond any haptex file's
// (a file declaring more, in a few bytes of chunks, is refused instead of exhausting memory).
inline constexpr std::uint64_t kMostBytesRead = std::uint64_t(4) << 30;
// The longest fixed-length string (a name, a label, a format) haptex reads.
inline constexpr std::size_t kLongestFixedString = std::size_t(64) << 10;
// The longest variable-length string: the longest text haptex writes is a `source` command line, which
// Linux caps at 2 MiB of arguments (review 20, F1: a 60 MB name cost 2.5 GB as readers copied it).
inline constexpr std::size_t kLongestText = std::size_t(4) << 20;
// The longest list of names (material ids, names) haptex reads, in strings and in bytes.
inline constexpr std::size_t kMostTexts = 1000000;
inline constexpr std::size_t kLongestTexts = std::size_t(64) << 20;
// haptex writes chunks of about 64 KiB; h5py's own are at most 1 MiB.
inline constexpr std::uint64_t kLargestChunkBytes = std::uint64_t(16) << 20;
// Throws haptex::Error (bad_input) naming `where` in `file` when count values of `element_size` bytes exceed it.
void require_readable_size(double count, std::size_t element_size, const std::string& file, const std::string& where);
// "(3, 4)": a shape in messages.
std::string shape_text(const Shape& shape);
// The objects Group::copy_from copied out of one source file: the path each was first copied from, by address.
using CopiedObjects = std::map<haddr_t, std::string>;

// Anything that carries attributes.
class Node {
 public:
  Node(Handle handle, std::string file, std::string object_path)
      : handle_(std::move(handle)), file_(std::move(file)), object_path_(std::move(object_path)) {
    silence_library_errors();  // in the thread that uses it (HDF5's error printing is per thread)
  }

  const std::string& file() const { return file_; }
  const std::string& object_path() const { return object_path_; }
  std::string where() const { return file_ + ":" + object_path_; }
  hid_t id() const { return handle_.get(); }

  void set_attr(std::string_view name, double value);
  void set_attr(std::string_view name, std::int64_t value);
  void set_attr(std::string_view name, int value) { set_attr(name, static_cast<std::int64_t>(value)); }
  void set_attr(std::string_view name, std::string_view value);  // variable-length UTF-8
  void set_attr(std::string_view name, const char* value) { set_attr(name, std::string_view(value)); }
  void set_attr(std::string_view name, std::span<const double> values);

  bool has_attr(std::string_view name) const;
  std::vector<std::string> attr_names() const;
  // Readers throw haptex::Error (bad_input) naming the object when the attribute is missing or of another kind.
  double attr_double(std::string_view name) const;
  std::int64_t attr_int(std::string_view name) const;
  std::string attr_string(std::string_view name) const;  // UTF-8 text, else an error naming the byte
  // A string attribute's bytes as stored, ASCII or UTF-8, valid or not: for showing what a file holds
  // (haptex info escapes what is not printable); readers that use the text take attr_string.
  std::string attr_bytes(std::string_view name) const;
  std::vector<double> attr_doubles(std::string_view name) const;
  // The attribute as T (double, std::int64_t or std::string), or nullopt when it is missing or does
  // not read as T: for checks and summaries that report such an attribute themselves.
  template <typename T>
  std::optional<T> try_attr(std::string_view name) const;

 protected:
  // A fixed-length string of `type` without its padding; refuses a NUL inside it (`what` names it).
  std::string fixed_length_text(std::string stored, hid_t type, const std::string& what) const;
  // A fixed-length string type's size; refuses (bad_input) one over kLongestFixedString (`what`
  // names an attribute; empty for the dataset itself).
  std::size_t fixed_length_size(hid_t type, const std::string& what) const;
  // Refuses (bad_input) text of more than kLongestText bytes (`what`: "attribute 'x'", "an element").
  void require_short_text(std::size_t bytes, const std::string& what) const;

  Handle handle_;
  std::string file_;
  std::string object_path_;

 private:
  Handle open_attr(std::string_view name) const;
  Handle open_scalar_attr(std::string_view name) const;
  void write_attr(std::string_view name, hid_t type, hid_t space, const void* data);
};

class Dataset : public Node {
 public:
  using Node::Node;
  Shape shape() const;
  std::size_t elements() const;
  // "float64", "float32", "int64", "uint8", "string", ... (numpy's names)
  std::string dtype() const;

  template <typename T>
  std::vector<T> read() const {
    std::vector<T> out(elements_to_read(sizeof(T)));
    read_raw(native_type<T>(), out.data());
    return out;
  }
  // Variable- or fixed-length strings (h5py writes numpy bytes arrays as fixed-length), each UTF-8.
  std::vector<std::string> read_strings() const;
  // Refuses (bad_input) a dataset stored in chunks of over kLargestChunkBytes that hold more than the
  // whole dataset: reading one value would inflate the whole chunk (review 9, F5: a 4 GiB chunk for
  // 30 000 samples took 4.3 GB and 20 s). read() and read_strings() call it.
  // Also refuses a dataset compressed with a filter this HDF5 lacks, naming it (require_available_filters).
  void require_sensible_chunks() const;
  void require_available_filters() const;
  // What require_sensible_chunks refuses ("is stored in chunks of ..."), or empty (qa's layout.shape).
  std::string chunk_problem() const;
  // When the dataset declares more than haptex reads at once (kMostBytesRead) of its stored type,
  // what is wrong ("declares N values of B bytes, ..."); else empty. Reads no value.
  std::string size_problem() const;

 private:
  // elements(), after a refusal (bad_input) of a dataset too large to read at once (kMostBytesRead).
  std::size_t elements_to_read(std::size_t element_size) const;
  // elements_to_read for a list of strings (fixed_size 0: variable-length), refused over kMostTexts
  // strings or kLongestTexts bytes.
  std::size_t text_elements(std::size_t fixed_size) const;
  void read_raw(hid_t memory_type, void* out) const;
  std::vector<std::string> read_variable_strings(hid_t stored) const;
  std::vector<std::string> read_fixed_strings(hid_t stored) const;
};

struct DatasetOptions {
  bool compress = true;   // gzip + shuffle (readable by h5py and MATLAB without plugins)
  int gzip_level = 4;
  Shape chunk;            // empty: about 64 KiB chunks along the first axis
};

class Group : public Node {
 public:
  using Node::Node;
  Group create_group(std::string_view name);
  Group require_group(std::string_view name);  // opens or creates
  Group open_group(std::string_view name) const;
  Dataset open_dataset(std::string_view name) const;

  bool has(std::string_view name) const;
  bool has_group(std::string_view name) const;
  bool has_dataset(std::string_view name) const;
  // Member names, numbers in numeric order ("2" before "10"), others alphabetically.
  std::vector<std::string> children() const;

  template <typename T>
  Dataset write_array(std::string_view name, std::span<const T> data, const Shape& shape,
                      const DatasetOptions& options = {}) {
    return write_raw(name, native_type<T>(), sizeof(T), data.data(), data.size(), shape, options);
  }
  template <typename T>
  Dataset write(std::string_view name, const std::vector<T>& data, const DatasetOptions& options = {}) {
    return write_array<T>(name, std::span<const T>(data), Shape{data.size()}, options);
  }
  Dataset write_strings(std::string_view name, const std::vector<std::string>& values);
  // Copies source's member `name` (a group with everything below it, or a dataset, with attributes)
  // into this group as `new_name`; the source may be in another file. `copied` remembers every object
  // copied out of one source file across calls, so that an object linked twice (one material
  // hard-linked under two names) is refused, not copied twice; pass one per source file.
  void copy_from(const Group& source, std::string_view name, std::string_view new_name, CopiedObjects& copied);
  void copy_from(const Group& source, std::string_view name, std::string_view new_name);

 private:
  std::string child_path(std::string_view name) const;
  Dataset write_raw(std::string_view name, hid_t type, std::size_t element_size, const void* data, std::size_t count,
                    const Shape& shape, const DatasetOptions& options);
};

}  // namespace haptex::h5
