#include "evaluate/report/report_html.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/text/format.hpp"
#include "core/text/markdown_html.hpp"
#include "core/text/utf8.hpp"
#include "dataset/window.hpp"
#include "page/html_page.hpp"
#include "page/media.hpp"
#include "render/wav_writer.hpp"

namespace haptex::evaluate {
namespace {

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A chart of the folder as a data: URI; empty when it was not drawn.
std::string embedded_png(const std::string& folder, const std::string& file) {
  const std::filesystem::path path = std::filesystem::path(folder) / file;
  if (file.find('/') != std::string::npos || !std::filesystem::is_regular_file(path)) return "";
  const std::string png = file_bytes(path.string());
  return page::png_source({reinterpret_cast<const std::uint8_t*>(png.data()), png.size()});
}

std::string material_section(const MaterialClip& c) {
  double peak = 0;
  for (const std::vector<double>* clip : {&c.recorded, &c.model, &c.baseline})
    for (const double a : *clip) peak = std::max(peak, std::abs(a));
  const double full_scale = render::rounded_full_scale(peak);
  // As report.md writes names (README, "promises"): control and reordering characters escaped, then as HTML text.
  const std::string printable = text::printable(c.name), name = text::html_escaped(printable), id = text::html_escaped(text::printable(c.id));
  std::string s = "<section class=\"material\" id=\"listen-" + id + "\"><h3>" + name + " (<code>" + id + "</code>)</h3><div class=\"row\">";
  if (!c.press_png.empty())
    s += "<figure><img alt=\"test press of " + name + "\" src=\"" + page::png_source(c.press_png) +
         "\"><figcaption>test press, peak frame</figcaption></figure>";
  s += "<figure>" + page::spectra_svg({{c.recorded_spectrum, "#222"}, {c.model_spectrum, "#d62728"}, {c.baseline_spectrum, "#1f77b4"}}) +
       "<figcaption>middle window's spectra: <span style=\"color:#222\">recorded</span>, <span style=\"color:#d62728\">model</span>, "
       "<span style=\"color:#1f77b4\">AR baseline</span></figcaption></figure><table><thead><tr><th>signal</th><th>listen</th></tr></thead><tbody>";
  for (const auto& [label, clip] : {std::pair{"recorded", &c.recorded}, {"model (stitched)", &c.model}, {"AR baseline (rendered)", &c.baseline}}) {
    if (clip->empty()) continue;
    const std::string title = printable + ": " + label;
    s += "<tr><td>" + std::string(label) + "</td><td>" + page::audio_player(*clip, full_scale, title) + "</td></tr>";
  }
  s += "</tbody></table></div><p>" +
       text::format("%.2f s: %zu test section%s in order, joined by %.0f ms cross-fades; 48 kHz, 16 bits; full scale %.3g m/s^2 "
                    "(the loudest of the three)",
                    double(c.recorded.size()) / dataset::kSampleRateHz, c.sections, c.sections == 1 ? "" : "s",
                    1000.0 * double(kClipFadeSamples) / dataset::kSampleRateHz, full_scale) +
       ".</p></section>\n";
  return s;
}

}  // namespace

std::string report_html(const Evaluation& e, const std::string& markdown, const std::string& folder) {
  std::string body;
  if (!e.clips.empty()) body += "<p><a href=\"#listen\">Listen to every material</a>: recorded, model and baseline.</p>\n";
  body += text::markdown_html(markdown, [&](const std::string& file) { return embedded_png(folder, file); });
  if (!e.clips.empty()) {
    body += "<h2 id=\"listen\">Listen</h2>\n<p>Per material, its test sections one after another (up to 3 s) as recorded, as the model's "
            "stitched signal and as the AR baseline rendered it. The three clips of a material share one full scale; each material has its own, "
            "so quiet ones are audible. Over a voice-coil actuator on a sound card they are felt as well as heard.</p>\n";
    for (const MaterialClip& c : e.clips) body += material_section(c);
  }
  return page::html_page("haptex evaluation report", body);
}

}  // namespace haptex::evaluate
