// All recording checks (signal.*, filter.*, recordings.duplicate) over every recording of a
// recordings or dataset file, one recording in memory at a time.
#include "qa/checkers.hpp"
#include "qa/recording_checks.hpp"

namespace haptex::qa {
namespace {

// Each recording check's tally, and what its pass message quotes, across the recordings of a file.
struct RecordingTallies {
  CheckTally nan{"signal.nan", "recordings"};
  CheckTally sample_rate{"signal.sample_rate", "recordings"};
  CheckTally duration{"signal.duration", "recordings"};
  CheckTally short_recording{"signal.short", "recordings"};
  CheckTally clipping{"signal.clipping", "acceleration channels"};
  CheckTally force_range{"signal.force_range", "recordings"};
  CheckTally speed_range{"signal.speed_range", "recordings"};
  CheckTally accel_spectrum{"signal.accel_spectrum", "recordings"};
  CheckTally reduction_energy{"signal.reduction_energy", "recordings"};
  CheckTally lowpass{"filter.lowpass", "low-passed signals"};
  CheckTally raw{"filter.raw", "raw signals"};
  CheckTally stated{"filter.stated", "recordings"};
  CheckTally duplicate{"recordings.duplicate", "recordings"};
  Seen flat_share, force, speed, band_share, lowpass_share, raw_share;
  Seen energy_ratio{INFINITY, 0};  // a ratio of energies: never below 0
  SeenHashes hashes;
};

}  // namespace

std::vector<CheckResult> check_recordings(const h5::Group& root) {
  RecordingTallies t;
  for (const auto& path : recording_paths(root)) {
    const LoadedRecording r = load_recording(root, path);
    check_signal_nan(r, t.nan);
    check_signal_sample_rate(r, t.sample_rate);
    check_signal_duration(r, t.duration);
    check_signal_short(r, t.short_recording);
    check_signal_clipping(r, t.clipping, t.flat_share);
    check_signal_force_range(r, t.force_range, t.force);
    check_signal_speed_range(r, t.speed_range, t.speed);
    check_signal_accel_spectrum(r, t.accel_spectrum, t.band_share);
    check_signal_reduction_energy(r, t.reduction_energy, t.energy_ratio);
    check_filter_lowpass(r, t.lowpass, t.lowpass_share);
    check_filter_raw(r, t.raw, t.raw_share);
    check_filter_stated(r, t.stated);
    check_recordings_duplicate(r, t.duplicate, t.hashes);
  }
  return {t.nan.result(),
          t.sample_rate.result(),
          t.duration.result(),
          t.short_recording.result(),
          t.clipping.result(),
          t.force_range.result(),
          t.speed_range.result(),
          t.accel_spectrum.result(),
          t.reduction_energy.result(),
          t.lowpass.result(),
          t.raw.result(),
          t.stated.result(),
          t.duplicate.result()};
}

}  // namespace haptex::qa
