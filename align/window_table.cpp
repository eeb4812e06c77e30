#include "align/window_table.hpp"

#include "core/parallel.hpp"
#include "core/signal/spectrum.hpp"

namespace haptex::align {
namespace {

WindowTable windows_of(const RecordingSignals& r, std::size_t stride) {
  WindowTable table;
  table.start = window_starts(r.accel.size(), stride);
  const std::size_t w = table.size();
  table.material.assign(w, r.material);
  table.recording.assign(w, r.recording);
  table.action.resize(w * kActionValues);
  table.target.resize(w * kTargetBins);
  std::vector<double> window(kWindowSamples), spectrum(kTargetBins);
  for (std::size_t i = 0; i < w; ++i) {
    const std::size_t t = std::size_t(table.start[i]), first = std::size_t(window_action_first(table.start[i]));
    float* action = &table.action[i * kActionValues];
    for (std::size_t k = 0; k < kActionSamples; ++k) {
      action[k] = r.force_lp[first + k];
      action[kActionSamples + k] = r.speed_lp[first + k];
    }
    for (std::size_t k = 0; k < kWindowSamples; ++k) window[k] = r.accel[t + k];
    signal::amplitude_spectrum(window, spectrum);
    for (std::size_t k = 0; k < kTargetBins; ++k) table.target[i * kTargetBins + k] = float(spectrum[k]);
  }
  return table;
}

template <typename T>
void append(std::vector<T>& to, const std::vector<T>& from) {
  to.insert(to.end(), from.begin(), from.end());
}

}  // namespace

std::string window_place(std::size_t w, std::string_view material, std::int64_t recording, std::int64_t start) {
  return "/windows[" + std::to_string(w) + "] (" + std::string(material) + ", recording " + std::to_string(recording) +
         ", start " + std::to_string(start) + ")";
}

std::vector<std::int64_t> window_starts(std::size_t samples, std::size_t stride) {
  std::vector<std::int64_t> starts;
  for (std::size_t t = 0; t + kWindowSamples <= samples; t += stride) starts.push_back(std::int64_t(t));
  return starts;
}

WindowTable build_windows(const std::vector<RecordingSignals>& recordings, std::size_t stride) {
  std::vector<WindowTable> parts(recordings.size());
  parallel_for(recordings.size(), [&](std::size_t i) { parts[i] = windows_of(recordings[i], stride); });
  WindowTable all;
  for (const WindowTable& part : parts) {
    append(all.material, part.material);
    append(all.recording, part.recording);
    append(all.start, part.start);
    append(all.action, part.action);
    append(all.target, part.target);
  }
  return all;
}

}  // namespace haptex::align
