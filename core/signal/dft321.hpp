#pragma once
// DFT321 (Landin et al. 2010): three acceleration axes to one signal with the same spectral energy,
// frame by frame (docs/convert.md, "Acceleration"). A hand-held tool turns while it strokes; one
// DFT321 over a whole recording takes its phase from the sum of axes whose weights change sign as
// the tool turns, and so moves energy between moments (a 100 ms window off by 0.3x to 20x). Frames of
// about 0.1 s, over which the orientation is nearly constant, keep each moment's energy.
#include <cstddef>
#include <span>
#include <vector>

namespace haptex::signal {

// The reduction's frames: periodic Hann, centred, 1024 samples (0.1 s at 10 kHz), hop 256. The
// recordings file stores these beside the signal (schemas/hdf5-layout.md).
struct Dft321Frames {
  std::size_t window = 1024;
  std::size_t hop = 256;
};
inline constexpr Dft321Frames kDft321Frames{};

// Per STFT frame and bin: |Y| = sqrt(sum_k |U_k|^2), and the phase of the axes combined with weights
// that follow the frame's principal direction as far as it stands out (docs/convert.md). Landin's
// phase of the plain sum fails where the axes' weights sum to zero, which a turning tool passes
// through: there the phase is the noise's, overlapping frames disagree and up to 30 % of a 100 ms
// window's energy cancels. y = inverse STFT by window-weighted overlap-add. All three axes must have
// the same length. With a fixed orientation (every axis a multiple of one signal whose weights do not
// sum to zero) it equals dft321_whole_recording.
std::vector<double> dft321(std::span<const double> x, std::span<const double> y, std::span<const double> z,
                           const Dft321Frames& frames = kDft321Frames);

// The same over the whole recording at once (per rfft bin; y = irfft(Y, n)): right only when the
// orientation never changes. Kept as the reference the frame-wise reduction must agree with then.
std::vector<double> dft321_whole_recording(std::span<const double> x, std::span<const double> y, std::span<const double> z);

}  // namespace haptex::signal
