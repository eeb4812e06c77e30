#include "page/media.hpp"

#include <algorithm>
#include <cmath>

#include "core/signal/resample.hpp"
#include "core/text/base64.hpp"
#include "core/text/format.hpp"
#include "core/text/markdown_html.hpp"
#include "dataset/window.hpp"
#include "render/wav_writer.hpp"

namespace haptex::page {
namespace {

constexpr int kPageRate = 48000;  // every browser plays it

}  // namespace

std::string png_source(std::span<const std::uint8_t> png) {
  return "data:image/png;base64," + text::base64(std::string_view(reinterpret_cast<const char*>(png.data()), png.size()));
}

std::string wav_source(std::span<const double> signal_m_s2, double full_scale_m_s2, const std::string& title) {
  const std::vector<double> resampled = signal::resample_poly(signal_m_s2, kPageRate, int(dataset::kSampleRateHz));
  std::vector<std::int16_t> pcm(resampled.size());
  for (std::size_t i = 0; i < pcm.size(); ++i)
    pcm[i] = std::int16_t(std::lrint(std::clamp(resampled[i] / full_scale_m_s2, -1.0, 1.0) * 32767));
  render::WavOptions options;
  options.full_scale_m_s2 = full_scale_m_s2;
  options.title = title;
  return "data:audio/wav;base64," + text::base64(render::wav_bytes(pcm, kPageRate, options));
}

std::string audio_player(std::span<const double> signal_m_s2, double full_scale_m_s2, const std::string& title) {
  return "<audio controls preload=\"metadata\" title=\"" + text::html_escaped(title) + "\" src=\"" +
         wav_source(signal_m_s2, full_scale_m_s2, title) + "\"></audio>";
}

std::string spectra_svg(const std::vector<Line>& lines) {
  double low = INFINITY, high = 0;
  for (const Line& line : lines)
    for (const double a : line.values)
      if (a > 0) low = std::min(low, a), high = std::max(high, a);
  if (!(high > low)) return "";
  const double w = 360, h = 200, l0 = std::log10(low), l1 = std::log10(high);
  std::string svg = text::format("<svg width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" role=\"img\" aria-label=\"spectra\">", w, h + 20, w, h + 20);
  for (const Line& line : lines) {
    std::string points;
    const std::size_t n = line.values.size();
    for (std::size_t k = 0; k < n; ++k) {
      const double a = line.values[k], y = a > 0 ? h - (std::log10(a) - l0) / (l1 - l0) * (h - 10) - 5 : h;
      points += text::format("%.1f,%.1f ", double(k) / double(std::max<std::size_t>(1, n - 1)) * (w - 10) + 5, y);
    }
    svg += std::string("<polyline fill=\"none\" stroke=\"") + line.colour + "\" stroke-width=\"1.5\" points=\"" + points + "\"/>";
  }
  svg += text::format("<text x=\"5\" y=\"%.0f\" font-size=\"11\">10 Hz</text><text x=\"%.0f\" y=\"%.0f\" font-size=\"11\" text-anchor=\"end\">1000 Hz"
                      "</text><text x=\"5\" y=\"12\" font-size=\"11\">%.3g m/s^2</text></svg>",
                      h + 15, w - 5, h + 15, high);
  return svg;
}

}  // namespace haptex::page
