#pragma once
// Reads the .npy files that tests/golden/*.py write with numpy.save (little-endian float64,
// C order), so the tests compare against scipy/numpy without needing Python at test time.
#include <complex>
#include <cstddef>
#include <string>
#include <vector>

namespace haptex::test {

struct NpyArray {
  std::vector<std::size_t> shape;
  std::vector<double> data;  // complex arrays are stored as interleaved (re, im)
  bool is_complex = false;

  std::size_t rows() const { return shape.empty() ? 1 : shape[0]; }
  std::size_t cols() const { return shape.size() < 2 ? 1 : shape[1]; }
  double at(std::size_t r, std::size_t c) const { return data[r * cols() + c]; }
  std::vector<std::complex<double>> as_complex() const;
};

// NAME is relative to tests/golden; throws std::runtime_error when missing or not f8/c16.
NpyArray load_golden(const std::string& name);

std::string golden_path(const std::string& name);
// ../shared/data (or $HAPTEX_SHARED_DATA); empty when the folder is absent.
std::string shared_data_dir();

// max |a - b| / max |b|: the error relative to the reference's scale.
double max_scaled_error(const std::vector<double>& a, const std::vector<double>& b);

}  // namespace haptex::test
