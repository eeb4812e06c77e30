#pragma once
// Every threshold `haptex qa` applies, with the reason for its value. docs/qa.md quotes them.
#include <cstddef>

#include "dataset/window.hpp"

namespace haptex::qa {

// ---- recordings (docs/convert.md)

// The only rate the model, the filters and the window table are defined for, and one model window:
// 1000 samples, its action inside them (dataset/window.hpp).
using dataset::kSampleRateHz, dataset::kWindowSamples;
// `haptex split` cuts every recording into 25 sections (docs/split.md); a window must fit in one.
inline constexpr std::size_t kDefaultSections = 25;
// A recording shorter than this cannot hold a single window in one of the 25 sections.
inline constexpr std::size_t kShortRecordingSamples = kDefaultSections * kWindowSamples;

// Clipping: an accelerometer driven past its range repeats its rail value. A flat top is a run of at
// least this many identical samples at the channel's maximum or minimum; free vibration at 10 kHz
// reaches its extreme in one or two samples.
inline constexpr std::size_t kClipRunSamples = 3;
// ... and the channel is clipped when more than this share of its samples sit in flat tops
// (0.1%: 10 samples per second of recording, many separate rail hits, not one coincidence).
inline constexpr double kClipMaxShare = 0.001;

// Normal force of a hand-held tool stroke: HaTT strokes stay under about 5 N. Below -0.5 N is a load
// cell offset or sign error; above 20 N is a units mistake (gram-force, kN) more than a stroke; a
// recording that never exceeds 0.05 N never touched the surface.
inline constexpr double kForceMinN = -0.5;
inline constexpr double kForceMaxN = 20.0;
inline constexpr double kForcePeakAtLeastN = 0.05;
// Tangential speed is a magnitude: below -1 mm/s is a sign error; HaTT strokes stay under about
// 600 mm/s and 2000 mm/s is beyond any hand stroke; a peak under 5 mm/s means no stroke (or m/s).
inline constexpr double kSpeedMinMmS = -1.0;
inline constexpr double kSpeedMaxMmS = 2000.0;
inline constexpr double kSpeedPeakAtLeastMmS = 5.0;

// Acceleration above 100 Hz is what the model predicts (its bins reach 1000 Hz). The band 100-1000 Hz
// must hold at least 1% of the acceleration's power (texture vibration puts tens of percent there) and
// at least 0.001 m/s^2 RMS (a MEMS accelerometer's noise floor alone gives ~0.01 m/s^2).
inline constexpr double kAccelBandLowHz = 100.0;
inline constexpr double kAccelBandHighHz = 1000.0;
inline constexpr double kAccelBandMinShare = 0.01;
inline constexpr double kAccelBandMinRms = 0.001;

// DFT321 frame by frame keeps each 100 ms window's energy: within 0.1 % for a turning tool, 5 to 25 %
// under where the three axes hold mostly independent noise; a reduction over the whole recording moves
// energy between moments. On the 60 HaTT-model-driven materials (10 959 windows louder than 1 % of their
// recording's mean): frame by frame 0.85 to 1.002, over the whole recording 0.009 to 25.7 (9 903 outside
// 0.8 to 1.25). Quieter windows (the sensor's floor at a stroke's turn) are not judged.
inline constexpr std::size_t kReductionWindowSamples = 1000;
inline constexpr double kReductionEnergyLow = 0.8;
inline constexpr double kReductionEnergyHigh = 1.25;
inline constexpr double kReductionQuiet = 0.01;

// Low-pass filtering (4th-order Butterworth at 20 Hz, zero phase): above 40 Hz it removes at least
// 48 dB of power (|H|^4 <= 1.5e-5 at 40 Hz, far less higher up). The low-passed signal's power above
// 40 Hz must be at most 1e-5 of its own power (mean removed).
inline constexpr double kFilterCheckHz = 40.0;
inline constexpr double kLowpassMaxShare = 1e-5;
// The raw signals must keep what the filter removes: a measured force or speed has sensor noise and
// vibration ripple above 40 Hz of at least 1e-8 of its power (a 0.1 N rms force with 10 uN of noise,
// far below any load cell's; the 20 Hz filter leaves ~1e-10);
// a raw signal with less was low-passed itself.
inline constexpr double kRawMinShare = 1e-8;

// ---- GelSight presses

// The reference must show no contact: its contact score against the median of all references of the
// same size (same sensor) stays under the press's own contact trigger (stored as `trigger`).
// At least this many presses are needed for a meaningful median.
inline constexpr std::size_t kMinReferencesForMedian = 3;
// The peak frame, scored again against the stored reference with the press's pixel threshold, must
// reach the press's contact trigger, which stands at least 1.5 times the footage's no-contact level
// (docs/capture.md, "The thresholds"): a peak under it could not have started the
// press, so the reference or the peak is not the one the press was cut with. 0.9, not 1: the stored
// reference is the reference frames' mean rounded to 8 bits.
inline constexpr double kPeakOverTrigger = 0.9;
// A frame is saturated when more than 2% of its pixels have a channel at 255 (overexposed LEDs
// flatten the shading that encodes the surface).
inline constexpr int kSaturatedLevel = 255;
inline constexpr double kSaturatedMaxShare = 0.02;
// A frame is blurred when the variance of its grey Laplacian is under half the median over the
// file's no-contact references of the same size (same optics): contact only adds edges, so a sharp
// press frame never falls that low; motion blur or a lost focus does.
inline constexpr double kBlurMinRatio = 0.5;
// ... provided the references have detail to compare with: a smooth reference (a flat, marker-less gel
// seen through MJPG) has a Laplacian variance of about 1.4, what 8-bit rounding of a smooth image
// leaves, and a frame blurred to the same smoothness cannot fall far below that. Real backgrounds in
// ../shared/data have 10 (GelSight Mini) and 165 (GelSlim); under 3 the check says it cannot judge
// instead of passing.
inline constexpr double kBlurMinReferenceSharpness = 3.0;
// Presses per material: 3 train, 1 val, 1 test (docs/split.md).
inline constexpr std::size_t kPressesPerMaterial = 5;

// ---- dataset and split

using dataset::kActionSamples, dataset::kActionEnd, dataset::kActionStep, dataset::kTargetBins;
// Cached action and target values are float32 copies of computations on the stored signals: they
// must agree to 1e-5 of the largest magnitude of the recording's signal (float32 rounding is 6e-8;
// the margin allows for spectra computed in float32).
inline constexpr double kCacheTolerance = 1e-5;
// Val and test windows are checked for coverage against the manifest's own min_coverage; the
// coverage the manifest records must match the recomputed one to this much (the split tool and qa
// may break ties on the hull's edge differently).
inline constexpr double kCoverageRecordedTolerance = 0.02;

}  // namespace haptex::qa
