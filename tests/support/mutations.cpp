#include "tests/support/mutations.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "dataset/vlen_bytes.hpp"

namespace haptex::test {

h5::Group Edit::group(const std::string& path) const { return path.empty() ? root() : root().open_group(path); }

h5::Dataset Edit::dataset(const std::string& path) const {
  const auto slash = path.rfind('/');
  return group(slash == std::string::npos ? "" : path.substr(0, slash)).open_dataset(path.substr(slash + 1));
}

void Edit::remove(const std::string& path) {
  const auto at = path.find('@');
  if (at != std::string::npos) {
    const std::string owner = path.substr(0, at).empty() ? "/" : "/" + path.substr(0, at);
    if (H5Adelete_by_name(root().id(), owner.c_str(), path.substr(at + 1).c_str(), H5P_DEFAULT) < 0)
      throw std::runtime_error("cannot delete attribute " + path);
    return;
  }
  if (H5Ldelete(root().id(), ("/" + path).c_str(), H5P_DEFAULT) < 0) throw std::runtime_error("cannot delete " + path);
}

void Edit::write_fixed_strings(const std::string& path, const std::vector<std::string>& texts, bool array, bool space_padded) {
  std::size_t size = 1;
  for (const auto& t : texts) size = std::max(size, t.size() + (space_padded ? 3 : 0));
  std::string bytes;
  for (const auto& t : texts) bytes += t + std::string(size - t.size(), space_padded ? ' ' : '\0');
  const hid_t type = H5Tcopy(H5T_C_S1);
  H5Tset_size(type, size);
  H5Tset_strpad(type, space_padded ? H5T_STR_SPACEPAD : H5T_STR_NULLPAD);
  const hsize_t count[1] = {texts.size()};
  const auto at = path.find('@');
  const hid_t space = at == std::string::npos || array || texts.size() != 1 ? H5Screate_simple(1, count, nullptr)
                                                                            : H5Screate(H5S_SCALAR);
  herr_t status = -1;
  if (at != std::string::npos) {
    const std::string owner = path.substr(0, at).empty() ? "/" : "/" + path.substr(0, at);
    const hid_t object = H5Oopen(root().id(), owner.c_str(), H5P_DEFAULT);
    const hid_t attr = H5Acreate2(object, path.substr(at + 1).c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT);
    status = H5Awrite(attr, type, bytes.data());
    H5Aclose(attr), H5Oclose(object);
  } else {
    const hid_t d = H5Dcreate2(root().id(), ("/" + path).c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    status = H5Dwrite(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data());
    H5Dclose(d);
  }
  H5Sclose(space), H5Tclose(type);
  if (status < 0) throw std::runtime_error("cannot write fixed-length strings at " + path);
}

void Edit::copy(const std::string& from, const std::string& to) {
  if (H5Ocopy(root().id(), ("/" + from).c_str(), root().id(), ("/" + to).c_str(), H5P_DEFAULT, H5P_DEFAULT) < 0)
    throw std::runtime_error("cannot copy " + from + " to " + to);
}

void Edit::change_floats(const std::string& path, const std::function<void(std::vector<float>&)>& change) {
  const h5::Dataset d = dataset(path);
  std::vector<float> values = d.read<float>();
  change(values);
  if (H5Dwrite(d.id(), H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    throw std::runtime_error("cannot write " + path);
}

void Edit::change_bytes(const std::string& path, const std::function<void(std::vector<std::uint8_t>&)>& change) {
  const h5::Dataset d = dataset(path);
  std::vector<std::uint8_t> values = d.read<std::uint8_t>();
  change(values);
  if (H5Dwrite(d.id(), H5T_NATIVE_UINT8, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
    throw std::runtime_error("cannot write " + path);
}

void Edit::change_image(const std::string& path, std::size_t index, const std::function<void(std::vector<std::uint8_t>&)>& change) {
  std::vector<std::vector<std::uint8_t>> images;
  for (std::size_t i = 0; i < dataset(path).shape()[0]; ++i) images.push_back(dataset::read_vlen_bytes(dataset(path), i));
  change(images.at(index));
  const auto attrs = string_attrs(dataset(path));
  remove(path);
  const auto slash = path.rfind('/');
  h5::Group parent = slash == std::string::npos ? root() : group(path.substr(0, slash));
  dataset::VlenBytesWriter writer(parent, slash == std::string::npos ? path : path.substr(slash + 1));
  for (const auto& image : images) writer.append(image);
  restore(writer.dataset(), attrs);
}

std::vector<std::pair<std::string, std::string>> Edit::string_attrs(const h5::Dataset& d) const {
  std::vector<std::pair<std::string, std::string>> attrs;
  for (const auto& name : d.attr_names()) attrs.emplace_back(name, d.attr_string(name));
  return attrs;
}

void Edit::restore(h5::Dataset d, const std::vector<std::pair<std::string, std::string>>& attrs) const {
  for (const auto& [name, value] : attrs) d.set_attr(name, value);
}

nlohmann::json read_json(const std::string& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

void write_json(const std::string& path, const nlohmann::json& doc) { std::ofstream(path) << doc.dump(2); }

void copy_with_damaged_attribute(const std::string& file, const std::string& name, const std::string& copy) {
  std::ifstream in(file, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string stored = name + '\0';
  for (std::size_t at = bytes.find(stored); at != std::string::npos; at = bytes.find(stored, at + 1)) {
    if (at < 8 || bytes[at - 8] != 1 || bytes[at - 7] != 0 || std::size_t(std::uint8_t(bytes[at - 6])) != stored.size() || bytes[at - 5] != 0)
      continue;
    bytes[at - 5] = char(175);
    std::ofstream(copy, std::ios::binary) << bytes;
    return;
  }
  throw std::runtime_error("no attribute message for " + name + " in " + file);
}

void copy_with_damaged_heap(const std::string& file, const std::string& copy) {
  std::ifstream in(file, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t heap = bytes.find("GCOL");
  if (heap == std::string::npos) throw std::runtime_error("no global heap in " + file);
  const std::size_t size_field = heap + 16 + 8;  // the collection's 16-byte header, then the object's index, count, reserve
  const std::uint64_t claimed = 16384;
  for (int byte = 0; byte < 8; ++byte) bytes[size_field + std::size_t(byte)] = char((claimed >> (8 * byte)) & 0xff);
  std::ofstream(copy, std::ios::binary) << bytes;
}

bool copy_with_damaged_float_size(const std::string& file, std::size_t nth, const std::string& copy) {
  std::ifstream in(file, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // The float class's size, then its properties: bit offset 0, precision 32, exponent at 23 of 8 bits,
  // mantissa at 0 of 23 bits, exponent bias 127 (the HDF5 file format's datatype message).
  const std::string float32("\x04\0\0\0\0\0\x20\0\x17\x08\0\x17\x7f\0\0\0", 16);
  std::size_t at = bytes.find(float32);
  for (std::size_t k = 0; k < nth && at != std::string::npos; ++k) at = bytes.find(float32, at + 1);
  if (at == std::string::npos) return false;
  bytes[at] = char(255);
  std::ofstream(copy, std::ios::binary) << bytes;
  return true;
}

}  // namespace haptex::test
