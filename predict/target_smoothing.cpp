#include "predict/target_smoothing.hpp"

#include <algorithm>
#include <string>

#include "core/error.hpp"

namespace haptex::predict {

Eigen::MatrixXf smoothed_targets(const Eigen::MatrixXf& targets, const std::vector<std::size_t>& columns, int bins) {
  if (bins < 1 || bins % 2 == 0) throw failure("train: target smoothing must be an odd number of bins, not " + std::to_string(bins));
  Eigen::MatrixXf out = targets;
  const Eigen::Index half = bins / 2, rows = targets.rows();
  for (std::size_t c : columns)
    for (Eigen::Index b = 0; b < rows; ++b) {
      float sum = 0, weight = 0;
      for (Eigen::Index j = std::max<Eigen::Index>(0, b - half); j <= std::min(rows - 1, b + half); ++j) {
        const float w = float(half + 1 - std::abs(j - b));
        sum += w * targets(j, Eigen::Index(c)), weight += w;
      }
      out(b, Eigen::Index(c)) = sum / weight;
    }
  return out;
}

}  // namespace haptex::predict
