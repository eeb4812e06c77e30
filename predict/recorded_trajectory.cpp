#include "predict/recorded_trajectory.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.hpp"
#include "core/text/format.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"
#include "dataset/object_paths.hpp"
#include "dataset/recordings_file.hpp"
#include "dataset/window.hpp"

namespace haptex::predict {

dataset::OpenedFile open_trajectory_source(const std::string& path) {
  constexpr std::array kinds{dataset::Kind::recordings, dataset::Kind::dataset};
  return dataset::open_any(path, kinds, "trajectory reads", "Give a recordings file (haptex convert) or a dataset (haptex align)");
}

Trajectory recorded_trajectory(const dataset::OpenedFile& source, const RecordedStretch& stretch) {
  const std::string& path = source.file.path();
  const h5::Group materials = source.file.root().open_group(dataset::layout::kMaterials);
  // An id, not a path into the file (review 13, F2: "/materials/x" and "x/" were followed).
  const bool an_id = !stretch.material.empty() && stretch.material.find('/') == std::string::npos && stretch.material != "." &&
                     stretch.material != "..";
  if (!an_id || !materials.has_group(stretch.material))
    throw input_error(path, dataset::material_path(stretch.material), "no such material",
                      "Use one of its ids: " + text::listed(materials.children()));
  const h5::Group recordings = materials.open_group(stretch.material).open_group(dataset::layout::kRecordings);
  const std::string k = std::to_string(stretch.recording);
  if (stretch.recording < 0 || !recordings.has_group(k))
    throw input_error(path, dataset::recording_path(stretch.material, k), "no such recording",
                      "Give --recording 0 to " + std::to_string(int(recordings.children().size()) - 1));
  const dataset::RecordingSignals signals = dataset::read_recording_signals(recordings.open_group(k));
  const std::size_t total = signals.force_lp.size();
  const double rate = dataset::kSampleRateHz;
  // The sample at or after --start, so a start within the last sample's 0.1 ms is that sample (review 13, C1).
  // Compared as doubles: a start or length beyond 2^64 samples does not wrap to 0 (review 19, F1).
  const double first_sample = std::max(0.0, std::ceil(stretch.start_s * rate - 1e-9));
  if (!(first_sample < double(total)))
    throw input_error(path, dataset::recording_path(stretch.material, k),
                      text::format("starts at %g s, after its last sample (at %.4f s)", stretch.start_s, double(total - 1) / rate),
                      "Give --start before its end");
  const std::size_t first = std::size_t(first_sample);
  const double left = double(total - first);
  const double wanted = stretch.seconds > 0 ? std::min(left, std::round(stretch.seconds * rate)) : left;
  const std::size_t end = first + std::size_t(wanted);
  // What render and play need (review 13, F1: --seconds 1e-9 wrote a CSV of no sample, exit 0).
  if (end - first < kMinTrajectorySamples)
    throw input_error(path, dataset::recording_path(stretch.material, k),
                      text::format("holds %zu samples from %g s for %g s, fewer than the %zu (%.1f ms) a trajectory needs", end - first,
                                   stretch.start_s, stretch.seconds, kMinTrajectorySamples, 1000.0 * double(kMinTrajectorySamples) / rate),
                      "Give a longer --seconds, or an earlier --start");
  Trajectory t;
  t.force.assign(signals.force_lp.begin() + std::ptrdiff_t(first), signals.force_lp.begin() + std::ptrdiff_t(end));
  t.speed.assign(signals.speed_lp.begin() + std::ptrdiff_t(first), signals.speed_lp.begin() + std::ptrdiff_t(end));
  // The low-pass rings a little below 0 where a stroke starts or stops; a trajectory holds no negative
  // force or speed (read_trajectory refuses them), and the model saturates below its range anyway.
  for (std::vector<float>* v : {&t.force, &t.speed})
    for (float& x : *v) x = std::max(x, 0.0f);
  return t;
}

}  // namespace haptex::predict
