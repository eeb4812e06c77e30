#include "evaluate/report/report_charts.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/durable_file.hpp"
#include "core/plot/gnuplot.hpp"
#include "core/text/format.hpp"
#include "evaluate/report/results_json.hpp"

namespace haptex::evaluate {
namespace fs = std::filesystem;

namespace {

constexpr std::size_t kExamplesShown = 4;  // Fig. 5: a 2 x 4 grid
constexpr const char* kPalette[] = {"#0072b2", "#e69f00", "#009e73", "#cc79a7", "#56b4e9", "#d55e00", "#000000", "#999999"};
constexpr const char* kBetter = "#009e73";
constexpr const char* kWorse = "#d55e00";
constexpr const char* kNotSignificant = "#b0b0b0";

std::string label_of(const std::string& name, const std::string& id) { return name.empty() ? id : name; }

std::string header(const std::string& terminal, std::string_view stem, int width, int height, std::string_view what) {
  std::ostringstream s;
  s << "# haptex evaluate: " << what << ".\n"
    << "# To draw " << stem << ".png again, run in the report folder: gnuplot " << stem << ".gnuplot\n"
    << "set terminal " << terminal << " noenhanced size " << width << "," << height
    << (terminal == "pngcairo" ? " font ',10'" : "") << "\n"
    << "set output '" << stem << ".png'\n"
    << "set datafile separator ','\n"
    << "set datafile columnheaders\n";
  return s.str();
}

// Fig. 4: baseline - model per material, median and quartiles, coloured by the test.
std::string bars_script(const Experiment& x, const std::string& stem, const std::string& terminal) {
  const std::size_t n = x.materials.size();
  std::ostringstream s;
  s << header(terminal, stem, int(std::clamp<std::size_t>(160 + 18 * n, 800, 6000)), 620,
              "baseline minus model per material (the paper's Fig. 4)")
    // Two lines joined in gnuplot (`.` and a "\n" of the script's own): the title as it is, then how to read the bars.
    << "set title " << gnuplot::text(x.title) << ".\"\\n\"."
    << gnuplot::text("bars: median of baseline - model per test window; whiskers: quartiles; above 0 the model is closer", 160)
    << "\n"
    << "set ylabel 'baseline - model spectral distance (m/s^2)'\n"
    << "set xrange [-0.6:" << double(n) - 0.4 << "]\n"
    << "set xtics nomirror rotate by 60 right font ',8' (";
  for (std::size_t i = 0; i < n; ++i) s << (i ? ", " : "") << gnuplot::text(label_of(x.materials[i].name, x.materials[i].id)) << " " << i;
  s << ")\n"
    << "set xzeroaxis lt -1\nset grid ytics\nset key outside bottom center horizontal\n"
    << "set offsets 0, 0, graph 0.05, graph 0.05\n"
    << "set boxwidth 0.7\nset style fill solid 0.8 noborder\n"
    << "colour(better, significant) = significant != 0 ? (better != 0 ? 0x" << (kBetter + 1) << " : 0x" << (kWorse + 1) << ") : 0x"
    << (kNotSignificant + 1) << "\n"
    << "plot '" << stem << ".csv' using 0:'difference_median':(colour(column('better'), column('significant'))) "
    << "with boxes lc rgb variable notitle, \\\n"
    << "     '' using 0:'difference_q1':(0):(column('difference_q3') - column('difference_q1')) with vectors heads "
    << "size screen 0.008,90 lc rgb 'black' notitle";
  // The key lists the colours drawn, no other.
  const auto drawn = [&](bool significant, bool better) {
    return std::any_of(x.materials.begin(), x.materials.end(),
                       [&](const MaterialComparison& m) { return m.significant() == significant && (!significant || m.better() == better); });
  };
  if (drawn(true, true)) s << ", \\\n     NaN with boxes lc rgb '" << kBetter << "' title 'model significantly better (p < " << kSignificanceLevel << ")'";
  if (drawn(false, false)) s << ", \\\n     NaN with boxes lc rgb '" << kNotSignificant << "' title 'not significant'";
  if (drawn(true, false)) s << ", \\\n     NaN with boxes lc rgb '" << kWorse << "' title 'model significantly worse'";
  s << "\n";
  return s.str();
}

// A predictions file's colour in Fig. 5, the same in both rows: the palette without the recording's
// black and the model's and baseline's colours, by the file's place among the predictions.
const char* external_colour(const Evaluation& e, const std::string& name) {
  const char* const kExternal[] = {kPalette[2], kPalette[3], kPalette[4], kPalette[5], kPalette[7]};
  std::size_t i = 0;
  while (i < e.predictions.size() && e.predictions[i].name != name) ++i;
  return kExternal[i % std::size(kExternal)];
}

// Fig. 5: spectra above, signals below, one column per example (those with data, at most four).
std::string examples_script(const Evaluation& e, const ReportLayout& layout, const std::string& terminal) {
  std::vector<std::size_t> shown;
  for (std::size_t i = 0; i < e.examples.size() && shown.size() < kExamplesShown; ++i)
    if (!e.examples[i].truth_spectrum.empty() && !e.examples[i].truth_signal.empty()) shown.push_back(i);
  if (shown.empty()) return "";
  std::ostringstream s;
  s << header(terminal, kExamplesStem, int(420 * shown.size()), 760,
              "recorded, model and baseline vibration of up to four materials (the paper's Fig. 5)")
    << "set multiplot layout 2," << shown.size() << " title 'Recorded, model and baseline vibration'\n"
    << "set grid\n";
  const char* rows[2][5] = {{"-spectra.csv", ": spectra of one test window", "frequency (Hz)", "amplitude (m/s^2)", "1"},
                            {"-signals.csv", ": start of a test section", "time (ms)", "acceleration (m/s^2)", "($1*1000)"}};
  for (std::size_t r = 0; r < 2; ++r) {
    const auto& row = rows[r];
    s << "set xlabel '" << row[2] << "'\nset ylabel '" << row[3] << "'\n";
    for (std::size_t k = 0; k < shown.size(); ++k) {
      const Example& x = e.examples[shown[k]];
      s << "set title " << gnuplot::text(label_of(x.name, x.id) + row[1]) << "\n" << (k == 0 ? "set key top right font ',8' opaque\n" : "unset key\n")
        << "plot " << gnuplot::file(layout.examples[shown[k]] + row[0]) << " using " << row[4] << ":'truth' with lines lc rgb 'black' title 'recorded', \\\n"
        << "     '' using " << row[4] << ":'model' with lines lc rgb '" << kPalette[0] << "' title 'model', \\\n"
        << "     '' using " << row[4] << ":'baseline' with lines lc rgb '" << kPalette[1] << "' title 'baseline'";
      for (const NamedSeries& series : r == 0 ? x.external_spectra : x.external_signals)
        s << ", \\\n     '' using " << row[4] << ":" << gnuplot::text("external-" + series.name) << " with lines lc rgb '"
          << external_colour(e, series.name) << "' title " << gnuplot::text(series.name + " (external)");
      s << "\n";
    }
  }
  s << "unset multiplot\n";
  return s.str();
}

std::string latents_script(const std::vector<LatentPoint>& points, const std::string& terminal) {
  std::ostringstream s;
  s << header(terminal, kLatentsStem, 1000, 800, "texture latents, 2-D PCA")
    << "set title " << gnuplot::text("Texture latents: 2-D PCA of the unified model's latents") << "\n"
    << "set xlabel 'first principal component'\nset ylabel 'second principal component'\n"
    << "set key outside top center horizontal\nset grid\n"
    << "set offsets graph 0.05, graph 0.1, graph 0.05, graph 0.05\n";
  for (const LatentPoint& p : points)
    if (std::isfinite(p.x) && std::isfinite(p.y))
      s << "set label " << gnuplot::text(label_of(p.name, p.id)) << " at " << csv_number(p.x) << ","
        << csv_number(p.y) << " offset char 0.5,0.4 font ',7' tc rgb '" << kPalette[p.kind == "training" ? 0 : 5] << "'\n";
  s << "plot '" << kLatentsStem << ".csv' using 'x':(strcol('kind') eq 'training' ? column('y') : NaN) with points pt 7 "
    << "ps 1.2 lc rgb '" << kPalette[0] << "' title 'material (mean training latent)', \\\n"
    << "     '' using 'x':(strcol('kind') eq 'training' ? NaN : column('y')) with points pt 5 ps 1.0 lc rgb '" << kPalette[5]
    << "' title 'test press'\n";
  return s.str();
}

// The speed chart's panels: the accuracy of spectrum predictors, the realism of rendered signals.
struct SpeedPanel {
  std::string_view kind, title, ylabel, column;
};
constexpr SpeedPanel kSpeedPanels[] = {
    {"spectrum", "Spectrum accuracy (lower left is better)", "mean spectral distance (m/s^2)", "distance"},
    {"signal", "Signal realism (1: as steady as the recording)", "spread ratio (rendered / recorded)", "spread_ratio"},
};

double panel_y(const SpeedPoint& p, const SpeedPanel& panel) { return panel.column == "distance" ? p.distance : p.spread_ratio; }

bool on_panel(const SpeedPoint& p, const SpeedPanel& panel, bool log_x) {
  return p.kind == panel.kind && std::isfinite(p.seconds_per_second) && std::isfinite(panel_y(p, panel)) &&
         (!log_x || p.seconds_per_second > 0);
}

bool any_finite_floor(const std::vector<MaterialFloor>& floors) {
  return std::any_of(floors.begin(), floors.end(), [](const MaterialFloor& f) { return std::isfinite(f.distance); });
}

// The panel's horizontal line, plotted as a constant over the whole x range: the mean floor distance
// (the gnuplot variable `floor`, from floors.csv) or the recording's spread ratio 1; empty without one.
std::string reference_line(const SpeedPanel& panel, const Evaluation& e) {
  if (panel.column != "distance") return ", \\\n     1 with lines dt 2 lc rgb 'black' title 'the recording (1)'";
  if (!any_finite_floor(e.floors)) return "";
  const std::string label = e.floor_kind == "oracle" ? "oracle" : e.floor_kind == "estimate" ? "floor (estimate)" : "floor";
  return ", \\\n     floor with lines dt 2 lc rgb '#666666' title " + gnuplot::text(label);
}

// Where each point's label goes, in text lines below its place beside the point: a label that would
// cover one placed before (two methods at one speed and distance, as unified-new-actions and
// unified-new-presses when every press is recognised) moves down a line until it is clear. Positions
// are fractions of the panel (x in decades when log_x), a label's box its characters at about 1/140
// of the width and a line at 1/40 of the height (8-point text on an 800 x 720 panel).
std::vector<int> label_lines(const std::vector<SpeedPoint>& points, const SpeedPanel& panel, bool log_x) {
  constexpr double kCharWidth = 1.0 / 140, kLineHeight = 1.0 / 40;
  std::vector<int> lines(points.size(), 0);
  double x_min = INFINITY, x_max = -INFINITY, y_min = INFINITY, y_max = -INFINITY;
  const auto x_of = [&](const SpeedPoint& p) { return log_x ? std::log10(p.seconds_per_second) : p.seconds_per_second; };
  for (const SpeedPoint& p : points)
    if (on_panel(p, panel, log_x))
      x_min = std::min(x_min, x_of(p)), x_max = std::max(x_max, x_of(p)), y_min = std::min(y_min, panel_y(p, panel)),
      y_max = std::max(y_max, panel_y(p, panel));
  const double x_span = std::max(x_max - x_min, 1e-12), y_span = std::max(y_max - y_min, 1e-12);
  struct Box {
    double x, y, width;
  };
  std::vector<Box> placed;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!on_panel(points[i], panel, log_x)) continue;
    const double x = (x_of(points[i]) - x_min) / x_span, width = kCharWidth * double(points[i].setting.size());
    const auto covers = [&](double y) {
      return std::any_of(placed.begin(), placed.end(), [&](const Box& b) {
        return std::abs(b.y - y) < kLineHeight && x < b.x + b.width && b.x < x + width;
      });
    };
    double y = (panel_y(points[i], panel) - y_min) / y_span;
    while (covers(y) && lines[i] < 20) ++lines[i], y -= kLineHeight;
    placed.push_back({x, y, width});
  }
  return lines;
}

// One panel: its points coloured by method (colours shared by both panels), labelled with their setting.
void speed_panel(std::ostringstream& s, const Evaluation& e, const SpeedPanel& panel, const std::vector<std::string>& methods,
                 bool log_x) {
  const std::vector<SpeedPoint>& points = e.speed;
  s << "unset label\n"
    << (log_x ? "set label 'real time' at 1, graph 0.5 rotate by 90 offset char -1,0 center tc rgb '#666666'\n" : "")
    << "set title " << gnuplot::text(std::string(panel.title)) << "\nset ylabel " << gnuplot::text(std::string(panel.ylabel)) << "\n";
  const std::vector<int> lines = label_lines(points, panel, log_x);
  for (std::size_t i = 0; i < points.size(); ++i)
    if (on_panel(points[i], panel, log_x))
      s << "set label " << gnuplot::text(points[i].setting) << " at " << csv_number(points[i].seconds_per_second) << ","
        << csv_number(panel_y(points[i], panel)) << " offset char 0.8," << text::format("%.1f", 0.4 - lines[i]) << " font ',8'\n";
  s << "plot ";
  bool first = true;
  for (std::size_t m = 0; m < methods.size(); ++m) {
    std::string rows;
    for (std::size_t i = 0; i < points.size(); ++i)
      if (points[i].method == methods[m] && on_panel(points[i], panel, log_x)) rows += (rows.empty() ? "$0==" : "||$0==") + std::to_string(i);
    if (rows.empty()) continue;
    s << (first ? "" : ", \\\n     ") << "'" << kSpeedStem << ".csv' using ((" << rows << ") ? column('seconds_per_second') : NaN):'"
      << panel.column << "' with points pt " << 5 + 2 * (m / std::size(kPalette) % 3) << " ps 1.6 lc rgb '"
      << kPalette[m % std::size(kPalette)] << "' title " << gnuplot::text(methods[m]);
    first = false;
  }
  s << reference_line(panel, e) << "\n";
}

// Two panels side by side (those with points): spectrum accuracy and signal realism against compute
// time; "" when neither has a point to draw.
std::string speed_script(const Evaluation& e, const std::string& terminal) {
  const std::vector<SpeedPoint>& points = e.speed;
  const bool log_x = std::any_of(points.begin(), points.end(),
                                 [](const SpeedPoint& p) { return std::isfinite(p.seconds_per_second) && p.seconds_per_second > 0; });
  std::vector<const SpeedPanel*> panels;
  for (const SpeedPanel& panel : kSpeedPanels)
    if (std::any_of(points.begin(), points.end(), [&](const SpeedPoint& p) { return on_panel(p, panel, log_x); })) panels.push_back(&panel);
  if (panels.empty()) return "";
  std::vector<std::string> methods;
  for (const SpeedPoint& p : points)
    if (std::find(methods.begin(), methods.end(), p.method) == methods.end()) methods.push_back(p.method);
  std::ostringstream s;
  s << header(terminal, kSpeedStem, int(800 * panels.size()), 720, "speed against spectrum accuracy and signal realism");
  s << "finite(x) = abs(x) < 1e300 ? x : NaN  # inf and nan left out\n";
  if (any_finite_floor(e.floors))
    // Weighted by windows, as every point's distance pools its windows over the materials.
    s << "stats '" << kFloorsStem << ".csv' using (finite(column('distance')) * column('windows')) nooutput prefix 'FLOORW'\n"
      << "stats '" << kFloorsStem << ".csv' using (finite(column('distance')) * 0 + column('windows')) nooutput prefix 'WINDOWS'\n"
      << "floor = FLOORW_sum / WINDOWS_sum\n";
  // On the log axis, from half the fastest time to twice the slowest or real time (1 s), whichever is
  // slower, over the times that are positive and finite.
  if (log_x)
    s << "stats '" << kSpeedStem << ".csv' using (column('seconds_per_second') > 0 ? finite(column('seconds_per_second')) : NaN) "
      << "nooutput prefix 'TIME'\n"
      << "set logscale x\nset format x '%g'\nset xrange [TIME_min / 2 : (TIME_max > 1 ? TIME_max : 1) * 2]\n"
      << "set arrow from 1, graph 0 to 1, graph 1 nohead dt 2 lc rgb '#666666'\n";
  s << "set multiplot layout 1," << panels.size() << " title 'Speed against accuracy: one point per method and setting'\n"
    << "set xlabel 'compute time per second of rendered vibration (s, one core)" << (log_x ? ", log scale" : "") << "'\n"
    << "set key below\nset grid\nset offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\n";
  for (const SpeedPanel* panel : panels) speed_panel(s, e, *panel, methods, log_x);
  s << "unset multiplot\n";
  return s.str();
}

}  // namespace

ChartResult write_report_charts(const Evaluation& e, const ReportLayout& layout, const std::string& directory) {
  const std::string found = gnuplot::png_terminal();
  const std::string terminal = found.empty() ? "pngcairo" : found;
  std::vector<std::pair<std::string, std::string>> charts;  // stem, script
  for (std::size_t i = 0; i < e.experiments.size(); ++i)
    if (!e.experiments[i].materials.empty())
      charts.emplace_back(layout.experiments[i], bars_script(e.experiments[i], layout.experiments[i], terminal));
  if (std::string s = examples_script(e, layout, terminal); !s.empty()) charts.emplace_back(kExamplesStem, s);
  if (!e.latents.empty()) charts.emplace_back(kLatentsStem, latents_script(e.latents, terminal));
  if (std::string s = speed_script(e, terminal); !s.empty()) charts.emplace_back(kSpeedStem, s);

  ChartResult result;
  std::string failed;
  for (const auto& [stem, script] : charts) {
    write_whole_file((fs::path(directory) / (stem + ".gnuplot")).string(), script);
    result.scripts.push_back(stem + ".gnuplot");
    if (found.empty()) continue;
    if (gnuplot::draw(directory, stem + ".gnuplot", stem + ".png")) result.images.push_back(stem + ".png");
    else failed += (failed.empty() ? "" : ", ") + stem + ".gnuplot";
  }
  if (found.empty() && !charts.empty())
    result.note = "gnuplot is not installed, so the charts were not drawn; their data (CSV) and gnuplot scripts are in the "
                  "report folder: install gnuplot (Debian: gnuplot-nox) and run `gnuplot NAME.gnuplot` there";
  else if (!failed.empty())
    result.note = "gnuplot failed on " + failed + ", so those charts were not drawn; run the scripts in the report folder to see why";
  return result;
}

}  // namespace haptex::evaluate
