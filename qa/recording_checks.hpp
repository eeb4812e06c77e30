#pragma once
// signal.*, filter.* and recordings.duplicate (docs/qa.md, "Recordings"): the checks run recording by
// recording over a recordings or dataset file, one recording in memory at a time. Each check_*
// function is one check of the catalog: it adds one recording's findings to the check's tally.
// Checks whose pass message quotes what they measured keep its extremes over the recordings in a Seen.
#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "qa/check.hpp"
#include "qa/recording_data.hpp"

namespace haptex::qa {

// The lowest and highest value a check measured so far.
struct Seen {
  double low = INFINITY, high = -INFINITY;
  void add(double value) {
    low = std::min(low, value);
    high = std::max(high, value);
  }
};

void check_signal_nan(const LoadedRecording& r, CheckTally& tally);
void check_signal_sample_rate(const LoadedRecording& r, CheckTally& tally);
void check_signal_duration(const LoadedRecording& r, CheckTally& tally);
void check_signal_short(const LoadedRecording& r, CheckTally& tally);
void check_signal_clipping(const LoadedRecording& r, CheckTally& tally, Seen& flat_share);
void check_signal_force_range(const LoadedRecording& r, CheckTally& tally, Seen& force);
void check_signal_speed_range(const LoadedRecording& r, CheckTally& tally, Seen& speed);
void check_signal_accel_spectrum(const LoadedRecording& r, CheckTally& tally, Seen& band_share);
void check_signal_reduction_energy(const LoadedRecording& r, CheckTally& tally, Seen& energy_ratio);

void check_filter_lowpass(const LoadedRecording& r, CheckTally& tally, Seen& share_above);
void check_filter_raw(const LoadedRecording& r, CheckTally& tally, Seen& share_above);
void check_filter_stated(const LoadedRecording& r, CheckTally& tally);

// Source and acceleration-data hashes of the recordings seen so far, each with the first recording
// that had it.
struct SeenHashes {
  std::vector<std::pair<std::string, std::string>> source, data;  // hash, path
};
void check_recordings_duplicate(const LoadedRecording& r, CheckTally& tally, SeenHashes& seen);

}  // namespace haptex::qa
