#include "render/griffin_lim.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "core/error.hpp"
#include "core/random_seeds.hpp"
#include "core/signal/fft.hpp"
#include "dataset/window.hpp"

namespace haptex::render {
namespace {

using Complex = std::complex<double>;
using dataset::kWindowSamples;

void check_magnitudes(const MagnitudeFrames& s) {
  if (s.frames == 0 || s.bins != kReconstructionBins || s.values.size() != s.frames * s.bins)
    throw failure("Griffin-Lim: the magnitudes are " + std::to_string(s.frames) + " frames x " +
                  std::to_string(s.bins) + " bins (" + std::to_string(s.values.size()) + " values); expected at least " +
                  "one frame of " + std::to_string(kReconstructionBins) + " bins");
  for (std::size_t i = 0; i < s.values.size(); ++i)
    if (!(s.values[i] >= 0.0 && std::isfinite(s.values[i])))
      throw failure("Griffin-Lim: magnitude " + std::to_string(i % s.bins) + " of frame " + std::to_string(i / s.bins) +
                    " is " + std::to_string(s.values[i]) + "; magnitudes must be finite and non-negative");
}

void check_options(const GriffinLimOptions& options) {
  if (!(options.momentum >= 0.0 && options.momentum < 1.0))
    throw failure("Griffin-Lim: momentum " + std::to_string(options.momentum) + " is outside [0, 1)");
}

// The working state of one reconstruction: coefficients t (whose phase is the estimate), the previous
// consistent coefficients c_{n-1}, and the signal. Sized once; the iterations only overwrite.
class FastGriffinLim {
 public:
  explicit FastGriffinLim(const MagnitudeFrames& s)
      : s_(s),
        fft_(signal::real_fft<double>(kWindowSamples)),
        window_(signal::hann_periodic(kWindowSamples)),
        gains_(covered_samples(s.frames)),
        x_(gains_.size()),
        frame_(kWindowSamples),
        t_(s.values.size()),
        previous_(s.values.size()),
        spectrum_(kReconstructionBins) {
    for (std::size_t n = 0; n < gains_.size(); ++n) gains_[n] = synthesis_gain(window_, n, s.frames);
  }

  void start(const GriffinLimOptions& options) {
    std::mt19937_64 engine(options.seed);
    for (std::size_t i = 0; i < t_.size(); ++i) {
      const double phase = options.initial_phase == InitialPhase::random ? 2.0 * std::numbers::pi * unit_draw(engine) : 0.0;
      t_[i] = std::polar(s_.values[i], phase);
    }
  }

  // x = least-squares inverse of s e^{i arg t}.
  void synthesize() {
    std::fill(x_.begin(), x_.end(), 0.0);
    for (std::size_t m = 0; m < s_.frames; ++m) {
      const auto t = frame_coefficients(t_, m);
      impose_magnitude(t, s_.row(m));
      fft_.inverse(t, frame_);
      double* out = x_.data() + m * kReconstructionHop;
      for (std::size_t j = 0; j < kWindowSamples; ++j) out[j] += window_[j] * frame_[j];
    }
    for (std::size_t n = 0; n < x_.size(); ++n) x_[n] *= gains_[n];
  }

  // c_n = STFT(x); t = c_n - beta c_{n-1}.
  void analyse(double beta) {
    for (std::size_t m = 0; m < s_.frames; ++m) {
      const double* in = x_.data() + m * kReconstructionHop;
      for (std::size_t j = 0; j < kWindowSamples; ++j) frame_[j] = window_[j] * in[j];
      fft_.forward(frame_, spectrum_);
      const auto t = frame_coefficients(t_, m);
      const auto previous = frame_coefficients(previous_, m);
      for (std::size_t k = 0; k < kReconstructionBins; ++k) {
        t[k] = spectrum_[k] - beta * previous[k];
        previous[k] = spectrum_[k];
      }
    }
  }

  std::vector<double> signal(std::size_t length) const {
    std::vector<double> out(length, 0.0);
    std::copy_n(x_.begin(), std::min(length, x_.size()), out.begin());
    return out;
  }

 private:
  static std::span<Complex> frame_coefficients(std::vector<Complex>& all, std::size_t m) {
    return std::span(all).subspan(m * kReconstructionBins, kReconstructionBins);
  }

  const MagnitudeFrames& s_;
  const signal::RealFft<double>& fft_;
  std::vector<double> window_, gains_, x_, frame_;
  std::vector<Complex> t_, previous_, spectrum_;
};

}  // namespace

void impose_magnitude(std::span<Complex> X, std::span<const double> s) {
  if (X.size() != s.size())
    throw failure("impose magnitude: " + std::to_string(X.size()) + " coefficients but " + std::to_string(s.size()) +
                  " magnitudes");
  // sqrt(norm) rather than abs (hypot): 10x faster, and the magnitudes here are far from overflow.
  for (std::size_t k = 0; k < X.size(); ++k) {
    const double magnitude = std::sqrt(std::norm(X[k]));
    X[k] = magnitude > 0.0 ? X[k] * (s[k] / magnitude) : Complex(s[k], 0.0);
  }
}

std::vector<double> griffin_lim(const MagnitudeFrames& s, std::size_t length, const GriffinLimOptions& options) {
  check_magnitudes(s);
  check_options(options);
  const double beta = options.momentum / (1.0 + options.momentum);
  FastGriffinLim state(s);
  state.start(options);
  for (std::size_t i = 0; i < options.iterations; ++i) {
    state.synthesize();
    state.analyse(beta);
  }
  state.synthesize();
  return state.signal(length);
}

}  // namespace haptex::render
