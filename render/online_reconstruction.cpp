#include "render/online_reconstruction.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "dataset/window.hpp"
#include "render/griffin_lim.hpp"

namespace haptex::render {
namespace {

using dataset::kWindowSamples;

constexpr std::size_t kHop = kReconstructionHop;
// Earlier frames that still overlap a frame: ceil(1000 / 100) - 1. The slot after them holds the
// frame being finished; the look-ahead frames follow.
constexpr std::size_t kLookback = (kWindowSamples + kHop - 1) / kHop - 1;

std::size_t check_iterations(std::size_t iterations) {
  if (iterations == 0) throw failure("online reconstruction: iterations must be at least 1");
  return iterations;
}

// The newest frame has no successors yet: its overlay is the earlier frames' tails, complete at
// its start and empty towards its end. PhaseRet weights it not by the Hann window but by the summed
// windows of the frames still to come (specg1; specg2 adds the frame's own window once it has an
// estimate), which makes the effective window over the partial signal roughly centred. On the
// texture signal this is ~3 dB better than the plain window.
std::vector<double> successors_window(const std::vector<double>& window, bool with_own) {
  std::vector<double> out = with_own ? window : std::vector<double>(window.size(), 0.0);
  for (std::size_t i = 1; i <= kLookback; ++i)
    for (std::size_t j = i * kHop; j < window.size(); ++j) out[j] += window[j - i * kHop];
  return out;
}

}  // namespace

OnlineReconstruction::OnlineReconstruction(const OnlineReconstructionOptions& options)
    : look_ahead_(options.look_ahead),
      iterations_(check_iterations(options.iterations)),
      slots_(kLookback + 1 + options.look_ahead),
      fft_(signal::real_fft<double>(kWindowSamples)),
      window_(signal::hann_periodic(kWindowSamples)),
      first_pass_window_(successors_window(window_, false)),
      later_pass_window_(successors_window(window_, true)),
      frames_(slots_ * kWindowSamples, 0.0),
      magnitudes_((options.look_ahead + 1) * kReconstructionBins, 0.0),
      overlay_(kWindowSamples, 0.0),
      output_(options.look_ahead * kHop + kWindowSamples - kHop, 0.0),
      spectrum_(kReconstructionBins),
      scatter_(options.scatter),
      noise_(options.seed),
      scattered_(kReconstructionBins) {
  fft_.inverse(spectrum_, overlay_);  // sizes FFTW's per-thread scratch on this thread now
}

void OnlineReconstruction::reset() {
  std::fill(frames_.begin(), frames_.end(), 0.0);
  std::fill(magnitudes_.begin(), magnitudes_.end(), 0.0);
  shifts_ = received_ = emitted_ = 0;
  flushing_ = false;
  noise_.restart();
}

std::span<const double> OnlineReconstruction::push(std::span<const double> magnitudes) {
  check_magnitude_frame(magnitudes, "online reconstruction");
  shift_in(scatter_ ? scattered(magnitudes) : magnitudes);
  ++received_;
  refine();
  if (frame_at(kLookback) < 0) return {};
  write_finished(std::span(output_).first(kHop));
  ++emitted_;
  return std::span(output_).first(kHop);
}

std::span<const double> OnlineReconstruction::flush() {
  std::size_t produced = 0;
  if (received_ > 0) {
    flushing_ = true;
    while (emitted_ < received_) {
      shift_in({});
      refine();
      if (frame_at(kLookback) < 0) continue;
      write_finished(std::span(output_).subspan(produced, kHop));
      ++emitted_;
      produced += kHop;
    }
    write_finished(std::span(output_).subspan(produced, kWindowSamples - kHop));  // the last frame's tail
    produced += kWindowSamples - kHop;
  }
  reset();
  return std::span(output_).first(produced);
}

std::span<const double> OnlineReconstruction::scattered(std::span<const double> magnitudes) {
  const std::span<const std::complex<double>> noise = noise_.next();
  for (std::size_t k = 0; k < kReconstructionBins; ++k) scattered_[k] = magnitudes[k] * std::abs(noise[k]) * noise_.unit_gain();
  return scattered_;
}

// One slot to the left; the new last slot is empty, its target `magnitudes` (zeros when empty).
void OnlineReconstruction::shift_in(std::span<const double> magnitudes) {
  std::copy(frames_.begin() + kWindowSamples, frames_.end(), frames_.begin());
  std::fill(frames_.end() - kWindowSamples, frames_.end(), 0.0);
  std::copy(magnitudes_.begin() + kReconstructionBins, magnitudes_.end(), magnitudes_.begin());
  const auto last = magnitudes_.end() - kReconstructionBins;
  if (magnitudes.empty())
    std::fill(last, magnitudes_.end(), 0.0);
  else
    std::copy(magnitudes.begin(), magnitudes.end(), last);
  ++shifts_;
}

// The frame a slot holds; negative before the stream's first frame.
long OnlineReconstruction::frame_at(std::size_t slot) const {
  return static_cast<long>(shifts_ + slot) - static_cast<long>(slots_);
}

void OnlineReconstruction::refine() {
  for (std::size_t pass = 0; pass < iterations_; ++pass)
    for (std::size_t ahead = look_ahead_ + 1; ahead-- > 0;) {
      const std::size_t slot = kLookback + ahead;
      const long frame = frame_at(slot);
      if (frame < 0 || frame >= static_cast<long>(received_)) continue;
      const bool newest = ahead == look_ahead_ && !flushing_;
      update_slot(slot, !newest ? window_ : pass == 0 ? first_pass_window_ : later_pass_window_);
    }
}

void OnlineReconstruction::update_slot(std::size_t slot, std::span<const double> analysis_window) {
  std::fill(overlay_.begin(), overlay_.end(), 0.0);
  for (std::size_t q = 0; q < slots_; ++q) {
    const long shift = (static_cast<long>(q) - static_cast<long>(slot)) * static_cast<long>(kHop);
    const std::size_t distance = static_cast<std::size_t>(std::abs(shift));
    if (distance >= kWindowSamples) continue;
    const double* other = frames_.data() + q * kWindowSamples;
    // Frame q starts `shift` samples after this one.
    for (std::size_t j = 0; j + distance < kWindowSamples; ++j) {
      if (shift >= 0)
        overlay_[j + distance] += other[j];
      else
        overlay_[j] += other[j + distance];
    }
  }
  for (std::size_t j = 0; j < kWindowSamples; ++j) overlay_[j] *= analysis_window[j];
  fft_.forward(overlay_, spectrum_);
  const std::size_t row = slot - kLookback;
  impose_magnitude(spectrum_, std::span(magnitudes_).subspan(row * kReconstructionBins, kReconstructionBins));
  fft_.inverse(spectrum_, overlay_);
  double* stored = frames_.data() + slot * kWindowSamples;
  for (std::size_t j = 0; j < kWindowSamples; ++j) stored[j] = window_[j] * overlay_[j];
}

// The samples from the first one not yet returned on, which only the finished frame (slot
// kLookback) and the frames before it overlap, least-squares normalised: the sum of the stored
// window-weighted frames times synthesis_gain.
void OnlineReconstruction::write_finished(std::span<double> out) const {
  const long finished = frame_at(kLookback);
  const std::size_t first = emitted_ * kHop;  // the first sample not yet returned
  for (std::size_t r = 0; r < out.size(); ++r) {
    const std::size_t n = first + r;
    double sum = 0.0;
    for (std::size_t back = 0; back <= kLookback && static_cast<long>(back) <= finished; ++back) {
      const std::size_t start = static_cast<std::size_t>(finished - static_cast<long>(back)) * kHop;
      if (n - start < kWindowSamples) sum += frames_[(kLookback - back) * kWindowSamples + (n - start)];
    }
    out[r] = sum * synthesis_gain(window_, n, static_cast<std::size_t>(finished) + 1);
  }
}

}  // namespace haptex::render
