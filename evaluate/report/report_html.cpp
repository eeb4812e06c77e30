#include "evaluate/report/report_html.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/signal/resample.hpp"
#include "core/text/base64.hpp"
#include "core/text/format.hpp"
#include "core/text/markdown_html.hpp"
#include "core/text/utf8.hpp"
#include "render/wav_writer.hpp"

namespace haptex::evaluate {
namespace {

constexpr int kPageRate = 48000;  // every browser plays it

constexpr const char* kStyle = R"(body{font-family:sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;line-height:1.45;color:#222}
table{border-collapse:collapse;margin:1em 0;font-size:.9em}th,td{border:1px solid #ccc;padding:.25em .5em;text-align:left}
th{background:#f3f3f3;cursor:pointer}th.sorted-up::after{content:" \25B2"}th.sorted-down::after{content:" \25BC"}
code{background:#f5f5f5;padding:0 .2em}figure{margin:1em 0}img{max-width:100%}
.material{border-top:1px solid #ddd;padding:.5em 0}.material .row{display:flex;gap:1.5em;flex-wrap:wrap;align-items:flex-start}
.material svg{background:#fafafa;border:1px solid #ddd}#load-check{display:none})";

// Sorting by the column clicked (numbers as numbers), and the load check the tests read.
constexpr const char* kScript = R"(document.querySelectorAll("table.sortable th").forEach(function(th){th.addEventListener("click",function(){
var table=th.closest("table"),body=table.tBodies[0],i=Array.prototype.indexOf.call(th.parentNode.children,th);
var up=!th.classList.contains("sorted-up");table.querySelectorAll("th").forEach(function(h){h.classList.remove("sorted-up","sorted-down")});
th.classList.add(up?"sorted-up":"sorted-down");var key=function(r){var t=r.children[i]?r.children[i].textContent.trim():"";var n=parseFloat(t);return isNaN(n)?t:n};
Array.prototype.slice.call(body.rows).sort(function(a,b){var x=key(a),y=key(b);var c=(typeof x==typeof y)?(x<y?-1:x>y?1:0):(typeof x=="number"?-1:1);return up?c:-c}).forEach(function(r){body.appendChild(r)})})});
(function(){var check={images:0,image_errors:[],audio:[],audio_errors:[]};var out=document.getElementById("load-check");
var images=document.querySelectorAll("img"),audio=document.querySelectorAll("audio"),waiting=images.length+audio.length;
function done(){if(--waiting<=0){out.textContent=JSON.stringify(check);out.setAttribute("data-done","1")}}
if(waiting==0){out.textContent=JSON.stringify(check);out.setAttribute("data-done","1")}
images.forEach(function(img){function ok(){check.images++;done()}function bad(){check.image_errors.push(img.alt);done()}
if(img.complete){img.naturalWidth>0?ok():bad()}else{img.addEventListener("load",ok);img.addEventListener("error",bad)}});
audio.forEach(function(a){function ok(){check.audio.push({title:a.title,seconds:a.duration});done()}function bad(){check.audio_errors.push(a.title);done()}
if(a.readyState>=1){ok()}else{a.addEventListener("loadedmetadata",ok);a.addEventListener("error",bad)}a.load()})})();)";

std::string file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// A chart of the folder as a data: URI; empty when it was not drawn.
std::string embedded_png(const std::string& folder, const std::string& file) {
  const std::filesystem::path path = std::filesystem::path(folder) / file;
  if (file.find('/') != std::string::npos || !std::filesystem::is_regular_file(path)) return "";
  return "data:image/png;base64," + text::base64(file_bytes(path.string()));
}

// A clip at the page's rate, in 16 bits of `full_scale`, as an embedded WAV.
std::string audio_source(const std::vector<double>& clip, double full_scale, const std::string& title) {
  const std::vector<double> resampled = signal::resample_poly(clip, kPageRate, 10000);
  std::vector<std::int16_t> pcm(resampled.size());
  for (std::size_t i = 0; i < pcm.size(); ++i) pcm[i] = std::int16_t(std::lrint(std::clamp(resampled[i] / full_scale, -1.0, 1.0) * 32767));
  render::WavOptions options;
  options.full_scale_m_s2 = full_scale;
  options.title = title;
  return "data:audio/wav;base64," + text::base64(render::wav_bytes(pcm, kPageRate, options));
}

// The three spectra (10..1000 Hz, 100 bins) as lines on a log amplitude axis.
std::string spectra_svg(const MaterialClip& c) {
  const std::vector<std::pair<const std::vector<double>*, const char*>> lines = {
      {&c.recorded_spectrum, "#222"}, {&c.model_spectrum, "#d62728"}, {&c.baseline_spectrum, "#1f77b4"}};
  double low = INFINITY, high = 0;
  for (const auto& [v, colour] : lines)
    for (const double a : *v)
      if (a > 0) low = std::min(low, a), high = std::max(high, a);
  if (!(high > low)) return "";
  const double w = 360, h = 200, l0 = std::log10(low), l1 = std::log10(high);
  std::string svg = text::format("<svg width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" role=\"img\" aria-label=\"spectra\">", w, h + 20, w, h + 20);
  for (const auto& [v, colour] : lines) {
    std::string points;
    for (std::size_t k = 0; k < v->size(); ++k) {
      const double y = (*v)[k] > 0 ? h - (std::log10((*v)[k]) - l0) / (l1 - l0) * (h - 10) - 5 : h;
      points += text::format("%.1f,%.1f ", double(k) / double(std::max<std::size_t>(1, v->size() - 1)) * (w - 10) + 5, y);
    }
    svg += std::string("<polyline fill=\"none\" stroke=\"") + colour + "\" stroke-width=\"1.5\" points=\"" + points + "\"/>";
  }
  svg += text::format("<text x=\"5\" y=\"%.0f\" font-size=\"11\">10 Hz</text><text x=\"%.0f\" y=\"%.0f\" font-size=\"11\" text-anchor=\"end\">1000 Hz"
                      "</text><text x=\"5\" y=\"12\" font-size=\"11\">%.3g m/s^2</text></svg>",
                      h + 15, w - 5, h + 15, high);
  return svg;
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
    s += "<figure><img alt=\"test press of " + name + "\" src=\"data:image/png;base64," +
         text::base64(std::string(c.press_png.begin(), c.press_png.end())) + "\"><figcaption>test press, peak frame</figcaption></figure>";
  s += "<figure>" + spectra_svg(c) +
       "<figcaption>middle window's spectra: <span style=\"color:#222\">recorded</span>, <span style=\"color:#d62728\">model</span>, "
       "<span style=\"color:#1f77b4\">AR baseline</span></figcaption></figure><table><thead><tr><th>signal</th><th>listen</th></tr></thead><tbody>";
  for (const auto& [label, clip] : {std::pair{"recorded", &c.recorded}, {"model (stitched)", &c.model}, {"AR baseline (rendered)", &c.baseline}}) {
    if (clip->empty()) continue;
    const std::string title = printable + ": " + label;
    s += "<tr><td>" + std::string(label) + "</td><td><audio controls preload=\"metadata\" title=\"" + text::html_escaped(title) + "\" src=\"" +
         audio_source(*clip, full_scale, title) + "\"></audio></td></tr>";
  }
  s += "</tbody></table></div><p>" +
       text::format("%.2f s from the start of the first test section, 48 kHz, 16 bits; full scale %.3g m/s^2 (the loudest of the three)",
                    double(c.recorded.size()) / 10000.0, full_scale) +
       ".</p></section>\n";
  return s;
}

}  // namespace

std::string report_html(const Evaluation& e, const std::string& markdown, const std::string& folder) {
  std::string page = std::string("<!doctype html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>haptex evaluation report</title><style>") +
                     kStyle + "</style></head><body>\n";
  if (!e.clips.empty()) page += "<p><a href=\"#listen\">Listen to every material</a>: recorded, model and baseline.</p>\n";
  page += text::markdown_html(markdown, [&](const std::string& file) { return embedded_png(folder, file); });
  if (!e.clips.empty()) {
    page += "<h2 id=\"listen\">Listen</h2>\n<p>Per material, the start of its first test section as recorded, as the model's stitched "
            "signal and as the AR baseline rendered it. The three clips of a material share one full scale; each material has its own, "
            "so quiet ones are audible. Over a voice-coil actuator on a sound card they are felt as well as heard.</p>\n";
    for (const MaterialClip& c : e.clips) page += material_section(c);
  }
  page += "<pre id=\"load-check\"></pre>\n<script>" + std::string(kScript) + "</script>\n</body></html>\n";
  return page;
}

}  // namespace haptex::evaluate
