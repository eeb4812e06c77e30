// All recording checks (signal.*, filter.*, recordings.duplicate) over every recording of a
// recordings or dataset file, one recording in memory at a time.
#include "qa/checkers.hpp"

namespace haptex::qa {

std::vector<CheckResult> check_recordings(const h5::Group& root) {
  SignalChecks signals;
  FilterChecks filters;
  DuplicateCheck duplicates;
  for (const auto& path : recording_paths(root)) {
    const LoadedRecording r = load_recording(root, path);
    signals.add(r);
    filters.add(r);
    duplicates.add(r);
  }
  std::vector<CheckResult> out = signals.results();
  for (auto&& r : filters.results()) out.push_back(std::move(r));
  for (auto&& r : duplicates.results()) out.push_back(std::move(r));
  return out;
}

}  // namespace haptex::qa
