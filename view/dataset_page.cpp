#include "view/dataset_page.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "core/error.hpp"
#include "core/text/format.hpp"
#include "core/text/markdown_html.hpp"
#include "core/text/utf8.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"
#include "dataset/object_paths.hpp"
#include "dataset/press_images.hpp"
#include "dataset/recordings_file.hpp"
#include "dataset/window.hpp"
#include "page/html_page.hpp"
#include "page/media.hpp"
#include "qa/integrity.hpp"
#include "render/wav_writer.hpp"

namespace haptex::view {
namespace {

namespace layout = dataset::layout;

constexpr const char* kSetNames[] = {"train", "validation", "test"};
constexpr const char* kSetColours[] = {"#1f77b4", "#ff7f0e", "#2ca02c"};
constexpr const char* kNoSetColour = "#aaaaaa";

// The dataset's /windows: which material each window is, its newest action and its target spectrum.
struct Windows {
  std::vector<std::string> materials;
  std::vector<std::int32_t> material;
  std::vector<float> action, target;  // W x 20, W x 100
};

Windows read_windows(const h5::Group& root) {
  const h5::Group w = root.open_group(layout::kWindows);
  return {w.open_dataset(layout::kWindowMaterials).read_strings(), w.open_dataset(layout::kWindowMaterial).read<std::int32_t>(),
          w.open_dataset(layout::kWindowAction).read<float>(), w.open_dataset(layout::kWindowTarget).read<float>()};
}

std::string thumbnail(const cv::Mat& bgr, int width, const std::string& alt) {
  cv::Mat small = bgr;
  if (bgr.cols > width) cv::resize(bgr, small, cv::Size(width, std::max(1, bgr.rows * width / bgr.cols)), 0, 0, cv::INTER_AREA);
  return "<img alt=\"" + text::html_escaped(alt) + "\" src=\"" + page::png_source(dataset::encode_png(small)) + "\">";
}

// Each press: its peak frame, then its frames around the peak (the contact sheet).
std::string presses_html(const h5::Group& material, const std::string& name) {
  if (!material.has_group(layout::kPresses)) return "<p>No presses.</p>";
  const h5::Group presses = material.open_group(layout::kPresses);
  std::string s;
  for (const std::string& j : presses.children()) {
    const h5::Group press = presses.open_group(j);
    s += "<div class=\"row\"><figure>" + thumbnail(dataset::read_press_image(press, layout::kPeak), kPeakWidth, name + ", press " + j + ", peak") +
         "<figcaption>press " + text::html_escaped(j) + ", peak frame</figcaption></figure><figure>";
    if (press.has_dataset(layout::kFrames))
      for (const cv::Mat& frame : dataset::read_press_images(press, layout::kFrames)) s += thumbnail(frame, kFrameWidth, name + ", press " + j + ", frame");
    s += "<figcaption>its frames around the peak</figcaption></figure></div>";
  }
  return s;
}

// Force against speed of the newest action of each window, coloured by its set.
std::string coverage_svg(const Windows& w, const std::vector<std::size_t>& rows, const split::MaterialSets* sets) {
  std::vector<int> set_of(rows.empty() ? 0 : *std::max_element(rows.begin(), rows.end()) + 1, -1);
  if (sets)
    for (std::size_t s = 0; s < 3; ++s)
      for (const std::size_t r : sets->rows[s]) if (r < set_of.size()) set_of[r] = int(s);
  const auto force = [&](std::size_t r) { return double(w.action[r * dataset::kActionValues + dataset::kActionSamples - 1]); };
  const auto speed = [&](std::size_t r) { return double(w.action[r * dataset::kActionValues + dataset::kActionValues - 1]); };
  double top_force = 1e-9, top_speed = 1e-9;
  for (const std::size_t r : rows) top_force = std::max(top_force, force(r)), top_speed = std::max(top_speed, speed(r));
  const double width = 360, height = 220;
  std::string svg = text::format("<svg width=\"%.0f\" height=\"%.0f\" role=\"img\" aria-label=\"coverage\">", width, height + 20);
  const std::size_t step = std::max<std::size_t>(1, rows.size() / kMostPoints);
  for (std::size_t i = 0; i < rows.size(); i += step) {
    const std::size_t r = rows[i];
    const int s = r < set_of.size() ? set_of[r] : -1;
    svg += text::format("<circle cx=\"%.1f\" cy=\"%.1f\" r=\"1.6\" fill=\"%s\"/>", 5 + speed(r) / top_speed * (width - 10),
                        height - 5 - force(r) / top_force * (height - 10), s >= 0 ? kSetColours[s] : kNoSetColour);
  }
  svg += text::format("<text x=\"5\" y=\"%.0f\" font-size=\"11\">speed 0 to %.4g mm/s; force 0 to %.3g N</text></svg>", height + 15, top_speed, top_force);
  return svg;
}

std::vector<double> mean_target(const Windows& w, const std::vector<std::size_t>& rows) {
  std::vector<double> mean(dataset::kTargetBins, 0.0);
  for (const std::size_t r : rows)
    for (std::size_t k = 0; k < dataset::kTargetBins; ++k) mean[k] += w.target[r * dataset::kTargetBins + k] / double(rows.size());
  return mean;
}

// The start of each recording's acceleration, all on the material's one full scale.
std::string recordings_html(const h5::Group& material, const std::string& name) {
  if (!material.has_group(layout::kRecordings)) return "<p>No recordings.</p>";
  const h5::Group recordings = material.open_group(layout::kRecordings);
  std::vector<std::pair<std::string, std::vector<double>>> clips;
  double peak = 0;
  for (const std::string& k : recordings.children()) {
    const std::vector<float> accel = dataset::read_recording_signals(recordings.open_group(k)).accel;
    std::vector<double> clip(accel.begin(), accel.begin() + std::ptrdiff_t(std::min(accel.size(), kClipSamples)));
    for (const double a : clip) peak = std::max(peak, std::abs(a));
    clips.emplace_back(k, std::move(clip));
  }
  const double full_scale = render::rounded_full_scale(peak);
  std::string s = "<table><thead><tr><th>recording</th><th>listen</th></tr></thead><tbody>";
  for (const auto& [k, clip] : clips)
    s += "<tr><td>" + text::html_escaped(k) + text::format(" (%.2f s)", double(clip.size()) / dataset::kSampleRateHz) + "</td><td>" +
         page::audio_player(clip, full_scale, name + ": recording " + k) + "</td></tr>";
  return s + "</tbody></table>" + text::format("<p>The first %.0f s of each recording, 48 kHz, 16 bits; full scale %.3g m/s^2 (this material's loudest).</p>",
                                               double(kClipSamples) / dataset::kSampleRateHz, full_scale);
}

std::string material_html(const h5::Group& root, const Windows& w, std::size_t m, const split::MaterialSets* sets) {
  const std::string id = w.materials[m];
  const h5::Group material = root.open_group(dataset::material_path(id).substr(1));
  const std::string name = text::printable(material.attr_string(layout::kName)), html_name = text::html_escaped(name);
  std::vector<std::size_t> rows;
  for (std::size_t r = 0; r < w.material.size(); ++r)
    if (w.material[r] == std::int32_t(m)) rows.push_back(r);
  std::string s = "<section class=\"material\" id=\"" + text::html_escaped(text::printable(id)) + "\"><h2>" + html_name + " (<code>" +
                  text::html_escaped(text::printable(id)) + "</code>)</h2>";
  s += text::format("<p>%zu windows", rows.size());
  if (sets)
    for (std::size_t k = 0; k < 3; ++k) s += text::format("; %s %zu", kSetNames[k], sets->rows[k].size());
  s += ".</p><div class=\"row\"><figure>" + coverage_svg(w, rows, sets) + "<figcaption>force against speed of each window's newest action" +
       (sets ? std::string(": <span style=\"color:#1f77b4\">train</span>, <span style=\"color:#ff7f0e\">validation</span>, "
                           "<span style=\"color:#2ca02c\">test</span>, <span style=\"color:#aaaaaa\">none</span> (crossing a section's edge)")
             : std::string(" (give --split to colour them by set)")) +
       "</figcaption></figure><figure>";
  const std::vector<double> mean = mean_target(w, rows);
  s += page::spectra_svg({{mean, "#222"}}) + "<figcaption>mean spectrum of its windows, 10 to 1000 Hz</figcaption></figure></div>";
  s += "<h3>Presses</h3>" + presses_html(material, name) + "<h3>Recordings</h3>" + recordings_html(material, name) + "</section>\n";
  return s;
}

}  // namespace

std::string dataset_page(const std::string& dataset_path, const std::optional<split::DatasetSplit>& split) {
  const h5::File file = dataset::open_checked(dataset_path, dataset::Kind::dataset);
  const h5::Group root = file.root();
  // Read as strictly as merge and align read their inputs (review 11, F3: a recording of 7 samples
  // where its group states 30 000 was shown, which qa fails).
  qa::require_integrity(root, dataset::Kind::dataset);
  const Windows w = read_windows(root);
  std::string body = "<h1>" + text::html_escaped(text::printable(dataset_path)) + "</h1><p>" +
                     text::format("%zu materials, %zu windows", w.materials.size(), w.material.size()) +
                     (split ? "; split " + text::html_escaped(text::printable(split->manifest_path)) : std::string("; no split given")) +
                     ".</p><table class=\"sortable\"><thead><tr><th>material</th><th>id</th><th>windows</th></tr></thead><tbody>";
  for (std::size_t m = 0; m < w.materials.size(); ++m) {
    const std::size_t windows = std::size_t(std::count(w.material.begin(), w.material.end(), std::int32_t(m)));
    const std::string id = text::html_escaped(text::printable(w.materials[m]));
    body += "<tr><td><a href=\"#" + id + "\">" +
            text::html_escaped(text::printable(root.open_group(dataset::material_path(w.materials[m]).substr(1)).attr_string(layout::kName))) +
            "</a></td><td><code>" + id + "</code></td><td>" + std::to_string(windows) + "</td></tr>";
  }
  body += "</tbody></table>\n";
  for (std::size_t m = 0; m < w.materials.size(); ++m) {
    const split::MaterialSets* sets = nullptr;
    if (split)
      for (const split::MaterialSets& s : split->materials)
        if (s.id == w.materials[m]) sets = &s;
    body += material_html(root, w, m, sets);
  }
  return page::html_page("haptex view: " + text::printable(dataset_path), body);
}

}  // namespace haptex::view
