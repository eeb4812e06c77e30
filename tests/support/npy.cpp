#include "tests/support/npy.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace haptex::test {

std::string golden_path(const std::string& name) { return std::string(HAPTEX_GOLDEN_DIR) + "/" + name; }

std::string shared_data_dir() {
  const char* env = std::getenv("HAPTEX_SHARED_DATA");
  std::string dir = env ? env : HAPTEX_SHARED_DATA_DIR;
  return std::filesystem::is_directory(dir) ? dir : std::string();
}

std::vector<std::complex<double>> NpyArray::as_complex() const {
  std::vector<std::complex<double>> out(data.size() / 2);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = {data[2 * i], data[2 * i + 1]};
  return out;
}

static std::vector<std::size_t> parse_shape(const std::string& header) {
  auto open = header.find('(', header.find("'shape'"));
  auto close = header.find(')', open);
  std::vector<std::size_t> shape;
  std::string inside = header.substr(open + 1, close - open - 1);
  std::size_t pos = 0;
  while (pos < inside.size()) {
    auto comma = inside.find(',', pos);
    std::string item = inside.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    if (item.find_first_of("0123456789") != std::string::npos) shape.push_back(std::stoul(item));
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  return shape;
}

NpyArray load_golden(const std::string& name) {
  const std::string path = golden_path(name);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("golden file missing: " + path + " (run make golden)");
  char magic[8];
  in.read(magic, 8);
  if (std::memcmp(magic, "\x93NUMPY", 6) != 0) throw std::runtime_error("not a .npy file: " + path);
  std::size_t header_len = 0;
  if (magic[6] == 1) {
    unsigned char len[2];
    in.read(reinterpret_cast<char*>(len), 2);
    header_len = len[0] | (len[1] << 8);
  } else {
    unsigned char len[4];
    in.read(reinterpret_cast<char*>(len), 4);
    header_len = len[0] | (len[1] << 8) | (len[2] << 16) | (static_cast<std::size_t>(len[3]) << 24);
  }
  std::string header(header_len, '\0');
  in.read(header.data(), static_cast<std::streamsize>(header_len));
  NpyArray array;
  if (header.find("'<f8'") != std::string::npos) {
    array.is_complex = false;
  } else if (header.find("'<c16'") != std::string::npos) {
    array.is_complex = true;
  } else {
    throw std::runtime_error("golden file is not float64/complex128: " + path);
  }
  if (header.find("'fortran_order': False") == std::string::npos)
    throw std::runtime_error("golden file is Fortran-ordered: " + path);
  array.shape = parse_shape(header);
  std::size_t count = 1;
  for (auto d : array.shape) count *= d;
  if (array.is_complex) count *= 2;
  array.data.resize(count);
  in.read(reinterpret_cast<char*>(array.data.data()), static_cast<std::streamsize>(count * sizeof(double)));
  if (!in) throw std::runtime_error("golden file truncated: " + path);
  return array;
}

double max_scaled_error(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return INFINITY;
  double scale = 0, err = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    scale = std::max(scale, std::abs(b[i]));
    err = std::max(err, std::abs(a[i] - b[i]));
  }
  return scale > 0 ? err / scale : err;
}

}  // namespace haptex::test
