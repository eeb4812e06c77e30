#pragma once
// Training targets averaged over neighbouring bins (docs/predict.md, "Smoothed training targets").
// A window's amplitude spectrum scatters around its expectation by about half its value in every bin,
// and with a rectangular window neighbouring bins scatter nearly independently. The model is to learn
// the expectation, so each training target is replaced by a weighted mean of its neighbouring bins:
// less scatter, at the price of the expected spectrum's bend within those bins. Validation and every
// evaluation keep the windows' own spectra.
#include <Eigen/Core>
#include <cstddef>
#include <vector>

namespace haptex::predict {

// A copy of `targets` (bins x windows) whose `columns` are each replaced by their triangular moving
// mean over `bins` (odd) neighbouring bins, centred (3: weights 1, 2, 1; 5: 1, 2, 3, 2, 1); at the band's
// ends over the neighbours there are, weights renormalised. bins = 1 copies. Throws haptex::Error when
// bins is even or not positive.
Eigen::MatrixXf smoothed_targets(const Eigen::MatrixXf& targets, const std::vector<std::size_t>& columns, int bins);

}  // namespace haptex::predict
