#pragma once
// Live phase reconstruction for rendering: Real-Time Iterative Spectrogram Inversion with
// Look-Ahead (RTISI-LA; Zhu, Beauregard, Wyse 2007), on the reconstruction frames of
// render/target_magnitudes.hpp.
//
// Why RTISI-LA and not real-time PGHI (Prusa 2017): PGHI integrates phase gradients estimated from
// log-magnitude derivatives, which assumes a Gaussian-like window and smooth spectra; texture
// vibration is noise-like, its per-bin magnitudes fluctuate from frame to frame, and the predicted
// spectra are noisier still. RTISI-LA instead runs Griffin-Lim's own consistency projection on a
// few frames at a time, so it shares its projection with the offline FGLA, and its look-ahead
// trades latency for accuracy in a way the renderer can choose.
//
// Each new frame is first given the phase of the partial signal the earlier frames already
// overlap it with; then `iterations` passes run over the look-ahead frames (newest first): overlay
// all stored frames on the frame's span, window, FFT, impose the magnitudes, inverse FFT, store the
// Hann-windowed result. The oldest look-ahead frame is then final, and so are the 100 samples where
// it starts: every frame overlapping them is final too.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "core/signal/fft.hpp"
#include "render/noise_frames.hpp"
#include "render/target_magnitudes.hpp"

namespace haptex::render {

struct OnlineReconstructionOptions {
  std::size_t look_ahead = 3;  // frames after the one being finished; latency = look_ahead * 100 samples
  std::size_t iterations = 4;  // passes over the look-ahead frames per new frame, >= 1
  // Draw each frame's targets around the pushed magnitudes with a noise-like texture's spread
  // before finding their phase: every bin times |N_k| / E|N_k| of a white-noise stream's frame
  // (render/noise_frames.hpp; mean 1, Rayleigh, correlated from frame to frame as a recording's
  // windows are). Without it RTISI-LA plays the expected spectrum, steadier than any surface.
  bool scatter = false;
  std::uint64_t seed = 0;  // the scatter's noise
};

// For a haptic loop: construct once, push one magnitude frame every 100 samples (10 ms), play what
// push returns. Allocation-free after construction, except that the first push on a thread other
// than the constructing one sizes FFTW's per-thread scratch once.
class OnlineReconstruction {
 public:
  // Throws haptex::Error when iterations is 0.
  explicit OnlineReconstruction(const OnlineReconstructionOptions& options = {});

  std::size_t look_ahead() const { return look_ahead_; }
  // Samples between a frame's start and the moment its first samples come out of push().
  std::size_t latency_samples() const { return look_ahead_ * kReconstructionHop; }

  // Feeds frame m's 501 Hann-STFT magnitudes (target_magnitude_frame converts the model's 100
  // amplitudes). From the (look_ahead + 1)-th frame on, returns samples [100 (m - look_ahead),
  // 100 (m - look_ahead + 1)) of the signal; before that, an empty span. The span stays valid until
  // the next call. Throws haptex::Error for a wrong size or a negative or non-finite magnitude.
  std::span<const double> push(std::span<const double> magnitudes);

  // Ends the stream: finishes the look-ahead frames and returns every sample not yet returned, up
  // to the end of the last frame (look_ahead * 100 + 900 samples after a long stream). Then the
  // object starts a new stream.
  std::span<const double> flush();

  // Forgets the stream (the scatter goes on with fresh noise).
  void reset();

 private:
  std::span<const double> scattered(std::span<const double> magnitudes);
  void shift_in(std::span<const double> magnitudes);
  void refine();
  void update_slot(std::size_t slot, std::span<const double> analysis_window);
  long frame_at(std::size_t slot) const;
  void write_finished(std::span<double> out) const;

  std::size_t look_ahead_, iterations_, slots_;
  const signal::RealFft<double>& fft_;
  std::vector<double> window_, first_pass_window_, later_pass_window_;
  std::vector<double> frames_;      // slots_ x 1000: each frame's Hann-windowed estimate, oldest first
  std::vector<double> magnitudes_;  // (look_ahead_ + 1) x 501: the look-ahead frames' targets
  std::vector<double> overlay_, output_;
  std::vector<std::complex<double>> spectrum_;
  bool scatter_;
  NoiseFrames noise_;
  std::vector<double> scattered_;  // the newest frame's targets, drawn around the pushed magnitudes
  std::size_t shifts_ = 0, received_ = 0, emitted_ = 0;
  bool flushing_ = false;
};

}  // namespace haptex::render
