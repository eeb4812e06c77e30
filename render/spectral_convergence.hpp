#pragma once
// How consistent a reconstruction is with its target magnitudes: spectral convergence as the
// PhaseRet/LTFAT toolboxes define it (magnitudeerrdb, frsynabs' relres),
//   SC = 20 log10( || |STFT(x)| - s ||_F / || s ||_F )  dB,
// over the reconstruction frames (render/target_magnitudes.hpp). Lower is better; an exact
// reconstruction gives -infinity.
#include <span>

#include "render/target_magnitudes.hpp"

namespace haptex::render {

// |STFT(x)| with the reconstruction frames: 1 + (n - 1000) / 100 frames x 501 bins.
MagnitudeFrames stft_magnitudes(std::span<const double> x);

// SC of two magnitude arrays of the same shape. When s is all zero: -infinity if the reconstruction
// is too, +infinity otherwise. Throws haptex::Error when the shapes differ.
double spectral_convergence_db(const MagnitudeFrames& reconstructed, const MagnitudeFrames& s);

// SC of a signal against s: the signal's first s.frames frames are compared (x must cover them,
// covered_samples(s.frames) samples or more; haptex::Error otherwise).
double spectral_convergence_db(std::span<const double> x, const MagnitudeFrames& s);

}  // namespace haptex::render
