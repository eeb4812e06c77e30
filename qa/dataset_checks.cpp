// dataset.*: the window table follows its documented rule, and its cached action and target are
// what the recordings give (docs/qa.md, "Dataset files"; docs/predict.md, "The model's sample").
#include <algorithm>
#include <cmath>
#include <optional>
#include <set>

#include "core/parallel.hpp"
#include "core/signal/spectrum.hpp"
#include "dataset/layout.hpp"
#include "dataset/object_paths.hpp"
#include "dataset/window.hpp"
#include "qa/checkers.hpp"
#include "qa/recording_data.hpp"
#include "qa/thresholds.hpp"
#include "qa/window_table.hpp"

namespace haptex::qa {

namespace layout = dataset::layout;
namespace {

std::string window_where(const WindowTable& t, std::size_t w) {
  const auto m = t.material[w];
  const std::string id = m >= 0 && std::size_t(m) < t.materials.size() ? t.materials[std::size_t(m)] : "#" + std::to_string(m);
  return dataset::window_place(w, id, t.recording[w], t.start[w]);
}

struct Finding {
  std::string where, what;
};

// The windows of one recording, in table order, and how they break the table's rule (nullopt: they
// keep it). Judged once: dataset.windows reports the breaks, dataset.cache skips those recordings.
struct WindowRun {
  std::int32_t material, recording;
  std::vector<std::size_t> windows;
  std::optional<Finding> problem;
};

// The table is ordered by material and recording, each recording's windows contiguous, and they
// start at t = 0, stride, ... while t + window_samples <= samples.
std::optional<Finding> run_problem(const h5::Group& root, const WindowTable& t, const std::vector<WindowRun>& runs,
                                   std::size_t i, std::set<std::pair<std::int32_t, std::int32_t>>& seen) {
  const WindowRun& run = runs[i];
  const std::string where = window_where(t, run.windows.front());
  if (i > 0 && std::pair(run.material, run.recording) < std::pair(runs[i - 1].material, runs[i - 1].recording))
    return Finding{where, "the table is not ordered by material and recording"};
  if (!seen.insert({run.material, run.recording}).second) return Finding{where, "the recording's windows are not contiguous"};
  if (run.material < 0 || std::size_t(run.material) >= t.materials.size())
    return Finding{where, "material index " + std::to_string(run.material) + " is outside /windows/materials"};
  const std::string& id = t.materials[std::size_t(run.material)];
  const auto samples = recording_samples(root, id, run.recording);
  if (!samples)
    return Finding{where, dataset::recording_path(id, int(run.recording)) + " does not exist (or has no samples attribute)"};
  const std::int64_t t0 = 0;
  const std::int64_t expected = *samples < t0 + t.window_samples ? 0 : (*samples - t0 - t.window_samples) / std::int64_t(t.stride) + 1;
  if (std::int64_t(run.windows.size()) != expected)
    return Finding{where, std::to_string(run.windows.size()) + " windows; a recording of " + std::to_string(*samples) +
                              " samples at stride " + std::to_string(t.stride) + " has " + std::to_string(expected) +
                              ", starting at " + std::to_string(t0) + " every " + std::to_string(t.stride) + " samples"};
  std::size_t k = 0;
  while (k < run.windows.size() && t.start[run.windows[k]] == t0 + std::int64_t(k) * std::int64_t(t.stride)) ++k;
  if (k < run.windows.size())
    return Finding{window_where(t, run.windows[k]),
                   "window " + std::to_string(k) + " of its recording starts at sample " +
                       std::to_string(t.start[run.windows[k]]) + ", expected " +
                       std::to_string(t0 + std::int64_t(k) * std::int64_t(t.stride)) + " (" + std::to_string(t0) + " + " +
                       std::to_string(k) + " x stride " + std::to_string(t.stride) + ")"};
  return std::nullopt;
}

std::vector<WindowRun> window_runs(const h5::Group& root, const WindowTable& t) {
  std::vector<WindowRun> runs;
  for (std::size_t w = 0; w < t.size(); ++w) {
    if (runs.empty() || runs.back().material != t.material[w] || runs.back().recording != t.recording[w])
      runs.push_back({t.material[w], t.recording[w], {}, std::nullopt});
    runs.back().windows.push_back(w);
  }
  std::set<std::pair<std::int32_t, std::int32_t>> seen;
  for (std::size_t i = 0; i < runs.size(); ++i) runs[i].problem = run_problem(root, t, runs, i, seen);
  return runs;
}

// The window geometry the model was built for (docs/predict.md, "The model's sample").
void check_geometry(const WindowTable& t, CheckTally& tally) {
  if (t.action_samples != std::int64_t(kActionSamples) || t.window_samples != std::int64_t(kWindowSamples) ||
      t.action_end != std::int64_t(kActionEnd) || t.action_step != std::int64_t(kActionStep))
    tally.fail("/windows", "action_samples " + std::to_string(t.action_samples) + ", window_samples " +
                               std::to_string(t.window_samples) + ", action_end " + std::to_string(t.action_end) + " and action_step " +
                               std::to_string(t.action_step) + ", expected " + std::to_string(kActionSamples) + ", " +
                               std::to_string(kWindowSamples) + ", " + std::to_string(kActionEnd) + " and " + std::to_string(kActionStep) +
                               " (docs/predict.md, \"The model's sample\")");
}

// Every material of the file has windows, listed once.
void check_material_list(const h5::Group& root, const WindowTable& t, CheckTally& tally) {
  std::set<std::string> listed;
  for (const auto& id : t.materials)
    if (!listed.insert(id).second) tally.fail("/windows/materials", "'" + id + "' is listed twice");
  if (root.has_group(layout::kMaterials))
    for (const auto& id : root.open_group(layout::kMaterials).children())
      if (!listed.count(id)) tally.fail(dataset::material_path(id), "has no windows in /windows");
}

double max_abs(const std::vector<double>& x) {
  double m = 0;
  for (double v : x) m = std::max(m, std::abs(v));
  return m;
}

// What a recording's cached windows are compared with, and how far a float32 copy may be off.
struct CacheSource {
  const Signal &force, &speed, &accel;
  double force_tolerance, speed_tolerance, target_tolerance;
};

// How window w's cached action or target differs from its recomputation; empty when they agree.
std::string cache_mismatch(const WindowTable& t, std::size_t w, const CacheSource& s) {
  const std::size_t a = std::size_t(t.action_samples);
  const std::size_t start = std::size_t(t.start[w]);
  const float* action = &t.action[w * t.action_width];
  for (std::size_t j = 0; j < a; ++j) {
    const std::size_t sample = start + std::size_t(t.action_end) - (a - 1 - j) * std::size_t(t.action_step);
    if (!(std::abs(action[j] - s.force.values[sample]) <= s.force_tolerance))
      return "action[" + std::to_string(j) + "] is " + number(action[j]) + ", force_normal_lp[" + std::to_string(sample) +
             "] is " + number(s.force.values[sample]);
    if (!(std::abs(action[a + j] - s.speed.values[sample]) <= s.speed_tolerance))
      return "action[" + std::to_string(a + j) + "] is " + number(action[a + j]) + ", speed_lp[" + std::to_string(sample) +
             "] is " + number(s.speed.values[sample]);
  }
  std::vector<double> spectrum(kTargetBins);
  signal::amplitude_spectrum(std::span(s.accel.values).subspan(start, std::size_t(t.window_samples)), spectrum, 1);
  const float* target = &t.target[w * t.target_width];
  for (std::size_t b = 0; b < kTargetBins; ++b)
    if (!(std::abs(target[b] - spectrum[b]) <= s.target_tolerance))
      return "target[" + std::to_string(b) + "] (" + std::to_string(10 * (b + 1)) + " Hz) is " + number(target[b]) +
             ", the spectrum of accel gives " + number(spectrum[b]);
  return "";
}

// dataset.cache for the windows of one recording.
void judge_cache(const h5::Group& root, const WindowTable& t, const WindowRun& run, CheckTally& tally) {
  const std::string path = dataset::recording_path(t.materials[std::size_t(run.material)], int(run.recording));
  const LoadedRecording r = load_recording(root, path);
  const Signal &force = r.signals.at(layout::kForceNormalLp), &speed = r.signals.at(layout::kSpeedLp), &accel = r.signals.at(layout::kAccel);
  if (!force.ok() || !speed.ok() || !accel.ok()) return tally.skip(path + ": force_normal_lp, speed_lp or accel unreadable");
  const auto tolerance = [](const Signal& s) { return kCacheTolerance * std::max(1e-12, max_abs(s.values)); };
  const CacheSource source{force, speed, accel, tolerance(force), tolerance(speed), tolerance(accel)};
  std::vector<std::string> findings(run.windows.size());
  parallel_for(run.windows.size(), [&](std::size_t k) { findings[k] = cache_mismatch(t, run.windows[k], source); });
  for (std::size_t k = 0; k < run.windows.size(); ++k)
    if (findings[k].empty()) tally.pass();
    else tally.fail(window_where(t, run.windows[k]), findings[k]);
}

CheckResult check_dataset_windows(const h5::Group& root, const WindowTable& t, const std::vector<WindowRun>& runs) {
  CheckTally tally("dataset.windows", "recordings' windows");
  check_geometry(t, tally);
  check_material_list(root, t, tally);
  for (const WindowRun& run : runs)
    if (run.problem) tally.fail(run.problem->where, run.problem->what);
    else tally.pass();
  return tally.result();
}

// Recomputed from the recordings' signals, for the recordings whose windows keep the table's rule.
CheckResult check_dataset_cache(const h5::Group& root, const WindowTable& t, const std::vector<WindowRun>& runs) {
  CheckTally tally("dataset.cache", "windows");
  if (t.action.empty() || t.target.empty() || t.action_width != 2 * std::size_t(t.action_samples) ||
      t.target_width != kTargetBins) {
    tally.skip("/windows/action or /windows/target is missing or misshapen");
    return tally.result();
  }
  for (const WindowRun& run : runs)
    if (run.problem) tally.skip(window_where(t, run.windows.front()) + ": its recording's windows are invalid (dataset.windows)");
    else judge_cache(root, t, run, tally);
  return tally.result();
}

}  // namespace

std::vector<CheckResult> check_dataset(const h5::Group& root) {
  std::string problem;
  const std::optional<WindowTable> table = load_window_table(root, problem);
  // A dataset file without a readable window table breaks its format: every reader refuses it.
  if (!table)
    return {make_result("dataset.windows", Status::fail, problem, {root.file() + ":/windows"}),
            make_result("dataset.cache", Status::skip, problem)};
  const std::vector<WindowRun> runs = window_runs(root, *table);
  return {check_dataset_windows(root, *table, runs), check_dataset_cache(root, *table, runs)};
}

}  // namespace haptex::qa
