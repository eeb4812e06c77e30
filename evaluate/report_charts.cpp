#include "evaluate/report_charts.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/plot/gnuplot.hpp"
#include "evaluate/results_json.hpp"

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
    << "set title " << gnuplot::text(x.title + "\nbaseline - model over the test windows: median (bar) and quartiles; "
                                                "> 0: the model is closer") << "\n"
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
    << "size screen 0.008,90 lc rgb 'black' notitle, \\\n"
    << "     NaN with boxes lc rgb '" << kBetter << "' title 'model significantly better (p < " << kSignificanceLevel << ")', \\\n"
    << "     NaN with boxes lc rgb '" << kNotSignificant << "' title 'not significant', \\\n"
    << "     NaN with boxes lc rgb '" << kWorse << "' title 'model significantly worse'\n";
  return s.str();
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
  for (const auto& row : rows) {
    s << "set xlabel '" << row[2] << "'\nset ylabel '" << row[3] << "'\n";
    for (std::size_t k = 0; k < shown.size(); ++k) {
      const Example& x = e.examples[shown[k]];
      s << "set title " << gnuplot::text(label_of(x.name, x.id) + row[1]) << "\n" << (k == 0 ? "set key top right font ',8' opaque\n" : "unset key\n")
        << "plot " << gnuplot::file(layout.examples[shown[k]] + row[0]) << " using " << row[4] << ":'truth' with lines lc rgb 'black' title 'recorded', \\\n"
        << "     '' using " << row[4] << ":'model' with lines lc rgb '" << kPalette[0] << "' title 'model', \\\n"
        << "     '' using " << row[4] << ":'baseline' with lines lc rgb '" << kPalette[1] << "' title 'baseline'\n";
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

std::string speed_script(const std::vector<SpeedPoint>& points, const std::string& terminal) {
  const bool log_x = std::any_of(points.begin(), points.end(),
                                 [](const SpeedPoint& p) { return std::isfinite(p.seconds_per_second) && p.seconds_per_second > 0; });
  std::ostringstream s;
  s << header(terminal, kSpeedStem, 1100, 700, "speed against accuracy")
    << "set title 'Speed against accuracy: one point per method and setting (lower left is better)'\n"
    << "set xlabel 'compute time per second of rendered vibration (s, one core)" << (log_x ? ", log scale" : "") << "'\n"
    << "set ylabel 'mean spectral distance (m/s^2)'\n"
    << (log_x ? "set logscale x\nset format x '%g'\n" : "") << "set key outside right top\nset grid\n"
    << "set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05\n"
    << "set arrow from 1, graph 0 to 1, graph 1 nohead dt 2 lc rgb '#666666'\n"
    << "set label 'real time' at 1, graph 0.5 rotate by 90 offset char -1,0 center tc rgb '#666666'\n";
  std::vector<std::string> methods;
  for (const SpeedPoint& p : points) {
    if (std::find(methods.begin(), methods.end(), p.method) == methods.end()) methods.push_back(p.method);
    if (std::isfinite(p.seconds_per_second) && std::isfinite(p.distance) && (!log_x || p.seconds_per_second > 0))
      s << "set label " << gnuplot::text(p.setting) << " at " << csv_number(p.seconds_per_second) << ","
        << csv_number(p.distance) << " offset char 0.8,0.4 font ',8'\n";
  }
  s << "plot ";
  for (std::size_t m = 0; m < methods.size(); ++m) {
    std::string rows;
    for (std::size_t i = 0; i < points.size(); ++i)
      if (points[i].method == methods[m]) rows += (rows.empty() ? "$0==" : "||$0==") + std::to_string(i);
    s << (m ? ", \\\n     " : "") << "'" << kSpeedStem << ".csv' using ((" << rows
      << ") ? column('seconds_per_second') : NaN):'distance' with points pt " << 5 + 2 * (m / std::size(kPalette) % 3)
      << " ps 1.6 lc rgb '" << kPalette[m % std::size(kPalette)] << "' title " << gnuplot::text(methods[m]);
  }
  s << "\n";
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
  if (!e.speed.empty()) charts.emplace_back(kSpeedStem, speed_script(e.speed, terminal));

  ChartResult result;
  std::string failed;
  for (const auto& [stem, script] : charts) {
    write_text_file((fs::path(directory) / (stem + ".gnuplot")).string(), script);
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
