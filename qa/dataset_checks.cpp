// dataset.*: the window table follows its documented rule, and its cached action and target are
// what the recordings give (DESIGN.md section 3).
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "align/window_table.hpp"
#include "core/parallel.hpp"
#include "core/signal/spectrum.hpp"
#include "qa/checkers.hpp"
#include "qa/recording_data.hpp"
#include "qa/thresholds.hpp"
#include "qa/window_table.hpp"

namespace haptex::qa {
namespace {

std::string window_where(const WindowTable& t, std::size_t w) {
  const auto m = t.material[w];
  const std::string id = m >= 0 && std::size_t(m) < t.materials.size() ? t.materials[std::size_t(m)] : "#" + std::to_string(m);
  return align::window_place(w, id, t.recording[w], t.start[w]);
}

struct Run {  // the windows of one recording
  std::int32_t material, recording;
  std::vector<std::size_t> windows;
};

double max_abs(const std::vector<double>& x) {
  double m = 0;
  for (double v : x) m = std::max(m, std::abs(v));
  return m;
}

}  // namespace

std::vector<CheckResult> check_dataset(const h5::Group& root) {
  CheckTally windows("dataset.windows", "recordings' windows"), cache("dataset.cache", "windows");
  std::string problem;
  const auto table = load_window_table(root, problem);
  if (!table) {
    windows.skip(problem);
    cache.skip(problem);
    return {windows.result(), cache.result()};
  }
  const WindowTable& t = *table;
  std::vector<char> valid(t.size(), 0);

  if (t.action_samples != std::int64_t(kActionSamples) || t.window_samples != std::int64_t(kTargetSamples) ||
      t.action_end != std::int64_t(kActionEnd))
    windows.fail("/windows", "action_samples " + std::to_string(t.action_samples) + ", window_samples " +
                                 std::to_string(t.window_samples) + " and action_end " + std::to_string(t.action_end) + ", expected " +
                                 std::to_string(kActionSamples) + ", " + std::to_string(kTargetSamples) + " and " +
                                 std::to_string(kActionEnd) + " (docs/predict.md, \"The model's sample\")");

  // Every material of the file has windows, listed once.
  std::set<std::string> listed;
  for (const auto& id : t.materials)
    if (!listed.insert(id).second) windows.fail("/windows/materials", "'" + id + "' is listed twice");
  if (root.has_group("materials"))
    for (const auto& id : root.open_group("materials").children())
      if (!listed.count(id)) windows.fail("/materials/" + id, "has no windows in /windows");

  // Runs of windows per recording, in table order; the table must be ordered by material, recording, start.
  std::vector<Run> runs;
  for (std::size_t w = 0; w < t.size(); ++w) {
    if (runs.empty() || runs.back().material != t.material[w] || runs.back().recording != t.recording[w])
      runs.push_back({t.material[w], t.recording[w], {}});
    runs.back().windows.push_back(w);
  }
  std::set<std::pair<std::int32_t, std::int32_t>> seen;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const Run& run = runs[i];
    const std::size_t first = run.windows.front();
    const std::string where = window_where(t, first);
    if (i > 0 && std::pair(run.material, run.recording) < std::pair(runs[i - 1].material, runs[i - 1].recording)) {
      windows.fail(where, "the table is not ordered by material and recording");
      continue;
    }
    if (!seen.insert({run.material, run.recording}).second) {
      windows.fail(where, "the recording's windows are not contiguous");
      continue;
    }
    if (run.material < 0 || std::size_t(run.material) >= t.materials.size()) {
      windows.fail(where, "material index " + std::to_string(run.material) + " is outside /windows/materials");
      continue;
    }
    const std::string& id = t.materials[std::size_t(run.material)];
    const auto samples = recording_samples(root, id, run.recording);
    if (!samples) {
      windows.fail(where, "/materials/" + id + "/recordings/" + std::to_string(run.recording) +
                              " does not exist (or has no samples attribute)");
      continue;
    }
    // Starts t = 0, stride, ... while t + window_samples <= samples.
    const std::int64_t t0 = 0;
    const std::int64_t expected = *samples < t0 + t.window_samples ? 0 : (*samples - t0 - t.window_samples) / t.stride + 1;
    if (std::int64_t(run.windows.size()) != expected) {
      windows.fail(where, std::to_string(run.windows.size()) + " windows; a recording of " + std::to_string(*samples) +
                              " samples at stride " + std::to_string(t.stride) + " has " + std::to_string(expected) +
                              ", starting at " + std::to_string(t0) + " every " + std::to_string(t.stride) + " samples");
      continue;
    }
    std::size_t k = 0;
    while (k < run.windows.size() && t.start[run.windows[k]] == t0 + std::int64_t(k) * t.stride) ++k;
    if (k < run.windows.size()) {
      windows.fail(window_where(t, run.windows[k]), "window " + std::to_string(k) + " of its recording starts at sample " +
                                                        std::to_string(t.start[run.windows[k]]) + ", expected " +
                                                        std::to_string(t0 + std::int64_t(k) * t.stride) + " (" +
                                                        std::to_string(t0) + " + " + std::to_string(k) + " x stride " +
                                                        std::to_string(t.stride) + ")");
      continue;
    }
    for (auto w : run.windows) valid[w] = 1;
    windows.pass();
  }

  // Cached action and target, recomputed from the recording's signals.
  if (t.action.empty() || t.target.empty() || t.action_width != 2 * std::size_t(t.action_samples) ||
      t.target_width != kTargetBins) {
    cache.skip("/windows/action or /windows/target is missing or misshapen");
    return {windows.result(), cache.result()};
  }
  for (const Run& run : runs) {
    if (!valid[run.windows.front()]) {
      cache.skip(window_where(t, run.windows.front()) + ": its recording's windows are invalid (dataset.windows)");
      continue;
    }
    const std::string path =
        "/materials/" + t.materials[std::size_t(run.material)] + "/recordings/" + std::to_string(run.recording);
    const LoadedRecording r = load_recording(root, path);
    const Signal &force = r.signals.at("force_normal_lp"), &speed = r.signals.at("speed_lp"), &accel = r.signals.at("accel");
    if (!force.ok() || !speed.ok() || !accel.ok()) {
      cache.skip(path + ": force_normal_lp, speed_lp or accel unreadable");
      continue;
    }
    const double force_tol = kCacheTolerance * std::max(1e-12, max_abs(force.values));
    const double speed_tol = kCacheTolerance * std::max(1e-12, max_abs(speed.values));
    const double target_tol = kCacheTolerance * std::max(1e-12, max_abs(accel.values));
    const std::size_t a = std::size_t(t.action_samples);
    std::vector<std::string> findings(run.windows.size());
    parallel_for(run.windows.size(), [&](std::size_t k) {
      const std::size_t w = run.windows[k];
      const std::size_t start = std::size_t(t.start[w]);
      const float* action = &t.action[w * t.action_width];
      for (std::size_t j = 0; j < a; ++j) {
        const std::size_t sample = start + std::size_t(t.action_end) + 1 - a + j;
        if (!(std::abs(action[j] - force.values[sample]) <= force_tol)) {
          findings[k] = "action[" + std::to_string(j) + "] is " + number(action[j]) + ", force_normal_lp[" +
                        std::to_string(sample) + "] is " + number(force.values[sample]);
          return;
        }
        if (!(std::abs(action[a + j] - speed.values[sample]) <= speed_tol)) {
          findings[k] = "action[" + std::to_string(a + j) + "] is " + number(action[a + j]) + ", speed_lp[" +
                        std::to_string(sample) + "] is " + number(speed.values[sample]);
          return;
        }
      }
      std::vector<double> spectrum(kTargetBins);
      signal::amplitude_spectrum(std::span(accel.values).subspan(start, std::size_t(t.window_samples)), spectrum, 1);
      const float* target = &t.target[w * t.target_width];
      for (std::size_t b = 0; b < kTargetBins; ++b)
        if (!(std::abs(target[b] - spectrum[b]) <= target_tol)) {
          findings[k] = "target[" + std::to_string(b) + "] (" + std::to_string(10 * (b + 1)) + " Hz) is " +
                        number(target[b]) + ", the spectrum of accel gives " + number(spectrum[b]);
          return;
        }
    });
    for (std::size_t k = 0; k < run.windows.size(); ++k) {
      if (findings[k].empty()) cache.pass();
      else cache.fail(window_where(t, run.windows[k]), findings[k]);
    }
  }
  return {windows.result(), cache.result()};
}

}  // namespace haptex::qa
