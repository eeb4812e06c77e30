#pragma once
// Welch's two-sided t-test for two independent samples with unequal variances: is the evaluator's
// loss on one model different from another's (e.g. haptex's predictor against the HaTT AR models)?
#include <cstddef>
#include <span>

namespace haptex::evaluate {

struct WelchTest {
  double t = 0.0;   // (mean_a - mean_b) / sqrt(var_a / n_a + var_b / n_b), sample variances (n - 1)
  double df = 0.0;  // Welch-Satterthwaite degrees of freedom
  double p = 1.0;   // two-sided: 2 P(T_df > |t|)
  double mean_a = 0.0, mean_b = 0.0;
  std::size_t n_a = 0, n_b = 0;
};

// scipy.stats.ttest_ind(a, b, equal_var=False), with the degenerate cases defined:
// - both samples without spread (zero variance) and equal means: scipy gives t = p = nan; here
//   t = 0 and p = 1 (nothing tells the samples apart);
// - both without spread and different means: t = +-infinity and p = 0, as scipy (the samples are
//   separated with no overlap at all; callers writing JSON must map the infinity themselves);
// - both without spread: the Welch-Satterthwaite formula is 0/0; df = 1, scipy's placeholder.
// Throws haptex::Error when a sample has fewer than 2 values or a value that is not finite.
WelchTest welch_t_test(std::span<const double> a, std::span<const double> b);

}  // namespace haptex::evaluate
