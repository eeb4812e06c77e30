#pragma once
// All-pole synthesis y[n] = e[n] - sum_{i=1..p} a_i y[n-i], one sample at a time, with the output
// history kept across calls so the coefficients may change from sample to sample (HaTT rendering).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace haptex::ar {

class AllPoleFilter {
 public:
  AllPoleFilter() = default;

  // a = [1, a1, ..., ap]; a0 is taken as 1 whatever it holds. The history grows to the largest p
  // seen (zeros before the first sample), so switching orders needs no reset.
  double step(std::span<const double> a, double excitation);

  // Forget the history (back to rest).
  void reset();

  // history()[i] is y[n-1-i] for the last returned y[n-1].
  std::span<const double> history() const { return history_; }

 private:
  std::vector<double> history_;
};

// Filter a whole excitation with fixed coefficients, from rest (scipy.signal.lfilter([1], a, e)
// for a0 == 1).
std::vector<double> all_pole_filter(std::span<const double> a, std::span<const double> excitation);

// n samples of the AR process with white Gaussian excitation of the given variance, from rest,
// excitation drawn from GaussianNoise(seed). Throws haptex::Error for a negative or non-finite
// variance or a filter that is not strictly stable.
std::vector<double> synthesize_ar(std::span<const double> a, double variance, std::size_t n, std::uint64_t seed);

}  // namespace haptex::ar
