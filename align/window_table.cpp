#include "align/window_table.hpp"

#include "core/parallel.hpp"
#include "core/signal/spectrum.hpp"

namespace haptex::align {
namespace {

using namespace dataset;

WindowTable windows_of(const WindowSource& source, std::size_t stride) {
  const RecordingSignals& r = source.signals;
  WindowTable table;
  table.start = window_starts(r.accel.size(), stride);
  const std::size_t w = table.size();
  table.material.assign(w, source.material);
  table.recording.assign(w, source.recording);
  table.action.resize(w * kActionValues);
  table.target.resize(w * kTargetBins);
  std::vector<double> window(kWindowSamples), spectrum(kTargetBins);
  for (std::size_t i = 0; i < w; ++i) {
    const std::size_t t = std::size_t(table.start[i]);
    action_ending_at<float>(r.force_lp, r.speed_lp, t + kActionEnd, std::span(table.action).subspan(i * kActionValues, kActionValues));
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

WindowTable build_windows(const std::vector<WindowSource>& sources, std::size_t stride) {
  std::vector<WindowTable> parts(sources.size());
  parallel_for(sources.size(), [&](std::size_t i) { parts[i] = windows_of(sources[i], stride); });
  WindowTable all;
  all.stride = stride;
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
