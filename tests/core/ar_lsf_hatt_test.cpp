// LSF conversion on the published HaTT models (../shared/data/hatt/models): skipped when absent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "convert/hatt_model_reader.hpp"
#include "core/ar/lsf.hpp"
#include "tests/support/npy.hpp"

namespace haptex::ar {
namespace {

std::vector<std::filesystem::path> hatt_model_files() {
  std::vector<std::filesystem::path> files;
  const std::string shared = test::shared_data_dir();
  if (shared.empty()) return files;
  const std::filesystem::path dir = std::filesystem::path(shared) / "hatt" / "models";
  if (!std::filesystem::is_directory(dir)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().extension() == ".xml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
  return worst;
}

// Every model of every file: ARlsf -> polynomial -> LSF within 1e-9, and ARcoeff reproduced from
// the stored (6-decimal) ARlsf within 5e-5; ARcoeff -> LSF lands within the stored rounding.
TEST(ArLsfHatt, EveryPublishedModel) {
  const auto files = hatt_model_files();
  if (files.empty()) GTEST_SKIP() << "../shared/data/hatt/models is absent: HaTT LSF checks skipped";
  EXPECT_EQ(files.size(), 60u);
  double worst_round_trip = 0.0, worst_coeff = 0.0, worst_from_coeff = 0.0;
  std::string worst_coeff_at;
  for (const auto& file : files) {
    const ModelSet set = convert::read_hatt_model(file);
    for (const ArModel& model : set.models) {
      SCOPED_TRACE(file.filename().string() + " model " + std::to_string(model.number));
      const auto a = lsf_to_poly(model.ar_lsf);
      worst_round_trip = std::max(worst_round_trip, max_abs_diff(poly_to_lsf(a), model.ar_lsf));
      const double coeff = max_abs_diff(a, model.ar_coeff);
      if (coeff > worst_coeff) {
        worst_coeff = coeff;
        worst_coeff_at = file.filename().string() + " model " + std::to_string(model.number);
      }
      worst_from_coeff = std::max(worst_from_coeff, max_abs_diff(poly_to_lsf(model.ar_coeff), model.ar_lsf));
    }
  }
  std::printf("HaTT LSF round trip worst %.3g; ARcoeff from ARlsf worst %.3g (%s); ARlsf from ARcoeff worst %.3g\n",
              worst_round_trip, worst_coeff, worst_coeff_at.c_str(), worst_from_coeff);
  EXPECT_LT(worst_round_trip, 1e-9);
  EXPECT_LT(worst_coeff, 5e-5);
  EXPECT_LT(worst_from_coeff, 5e-7 + 1e-9);  // the files round LSFs to 6 decimals
}

}  // namespace
}  // namespace haptex::ar
