#include "core/signal/dft321.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <complex>
#include <string>

#include "core/error.hpp"
#include "core/signal/fft.hpp"
#include "core/signal/stft.hpp"

namespace haptex::signal {
namespace {

void check_lengths(std::size_t x, std::size_t y, std::size_t z) {
  if (y != x || z != x)
    throw failure("DFT321: the acceleration axes have different lengths (" + std::to_string(x) + ", " + std::to_string(y) + ", " +
                  std::to_string(z) + " samples)");
}

// The three axes' spectra of one frame (or of the whole recording).
struct AxisSpectra {
  std::span<const std::complex<double>> x, y, z;
};

// The frame's covariance of the axes: Re(sum over bins of U U^H).
Eigen::Matrix3d covariance(const AxisSpectra& u) {
  Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
  for (std::size_t k = 0; k < u.x.size(); ++k) {
    const std::complex<double> v[3] = {u.x[k], u.y[k], u.z[k]};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) c(i, j) += (v[i] * std::conj(v[j])).real();
  }
  return c;
}

// Per bin: the energy of all three axes, and the phase of the axes combined with `weights`.
void combine(const AxisSpectra& u, const Eigen::Vector3d& weights, std::span<std::complex<double>> out) {
  for (std::size_t k = 0; k < out.size(); ++k) {
    const double magnitude = std::sqrt(std::norm(u.x[k]) + std::norm(u.y[k]) + std::norm(u.z[k]));
    out[k] = std::polar(magnitude, std::arg(weights[0] * u.x[k] + weights[1] * u.y[k] + weights[2] * u.z[k]));
  }
}

// The phase weights of every frame. They start as the plain sum of the axes (Landin's) and move toward
// the frame's principal direction (sign: the one closer to the weights before) as far as that direction
// stands out: all the way for one vibration seen through the axes (the largest eigenvalue alone),
// not at all for independent noise of equal size on each axis (two equal largest eigenvalues), where a
// direction that jumped from frame to frame would make overlapping frames disagree.
std::vector<Eigen::Vector3d> phase_weights(const std::vector<Eigen::Matrix3d>& frame_covariance) {
  std::vector<Eigen::Vector3d> weights;
  Eigen::Vector3d w = Eigen::Vector3d::Ones().normalized();
  for (const Eigen::Matrix3d& c : frame_covariance) {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(c);
    const Eigen::Vector3d& lambda = solver.eigenvalues();  // ascending
    Eigen::Vector3d v = solver.eigenvectors().col(2);
    if (v.dot(w) < 0) v = -v;
    const double clarity = lambda[2] > 0 ? (lambda[2] - lambda[1]) / lambda[2] : 0.0;
    w = ((1 - clarity) * w + clarity * v).normalized();
    weights.push_back(w);
  }
  return weights;
}

}  // namespace

std::vector<double> dft321(std::span<const double> x, std::span<const double> y, std::span<const double> z, const Dft321Frames& frames) {
  check_lengths(x.size(), y.size(), z.size());
  if (x.empty()) return {};
  const StftConfig config{frames.window, frames.hop, true};
  const Spectrogram X = stft(x, config), Y = stft(y, config), Z = stft(z, config);
  auto frame = [&](const Spectrogram& S, std::size_t m) { return std::span(S.values).subspan(m * S.bins, S.bins); };
  std::vector<Eigen::Matrix3d> frame_covariance;
  for (std::size_t m = 0; m < X.frames; ++m) frame_covariance.push_back(covariance({frame(X, m), frame(Y, m), frame(Z, m)}));
  const std::vector<Eigen::Vector3d> weights = phase_weights(frame_covariance);
  Spectrogram out = X;
  for (std::size_t m = 0; m < X.frames; ++m)
    combine({frame(X, m), frame(Y, m), frame(Z, m)}, weights[m], std::span(out.values).subspan(m * out.bins, out.bins));
  return istft(out, x.size(), config);
}

std::vector<double> dft321_whole_recording(std::span<const double> x, std::span<const double> y, std::span<const double> z) {
  check_lengths(x.size(), y.size(), z.size());
  const std::size_t n = x.size();
  if (n == 0) return {};
  const auto& fft = real_fft<double>(n);
  std::vector<std::complex<double>> X(fft.bins()), Y(fft.bins()), Z(fft.bins());
  fft.forward(x, X);
  fft.forward(y, Y);
  fft.forward(z, Z);
  combine({X, Y, Z}, Eigen::Vector3d::Ones(), X);  // Landin's phase of the plain sum
  std::vector<double> out(n);
  fft.inverse(X, out);
  return out;
}

}  // namespace haptex::signal
