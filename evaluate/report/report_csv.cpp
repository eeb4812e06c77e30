#include "evaluate/report/report_csv.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/durable_file.hpp"
#include "core/error.hpp"
#include "core/signal/spectrum.hpp"
#include "core/text/utf8.hpp"
#include "dataset/window.hpp"
#include "evaluate/report/results_json.hpp"

namespace haptex::evaluate {
namespace {

using dataset::kBinHz, dataset::kSampleRateHz;

std::string safe_stem(std::string_view id) {
  std::string s(id);
  for (char& c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '_' || c == '-')) c = '_';
  return s.empty() ? "unnamed" : s;
}

std::string unique_name(const std::string& stem, std::set<std::string>& used) {
  std::string name = stem;
  for (int k = 2; !used.insert(name).second; ++k) name = stem + "-" + std::to_string(k);
  return name;
}

// A CSV file built in memory and written, checked, by close().
class CsvFile {
 public:
  CsvFile(std::string path, std::string_view header) : path_(std::move(path)) { out_ << header << '\n'; }
  template <typename... Fields>
  void row(const Fields&... fields) {
    bool first = true;
    ((out_ << (first ? "" : ",") << fields, first = false), ...);
    out_ << '\n';
  }
  const std::string& close() {
    write_whole_file(path_, out_.str());
    return path_;
  }

 private:
  std::string path_;
  std::ostringstream out_;
};

std::string cell(const std::vector<double>& v, std::size_t i) { return i < v.size() ? csv_number(v[i]) : ""; }

// One row per index up to the longest series; x(i) gives the first column, then truth, model,
// baseline and one column per predictions file, `external-NAME` (its experiment's id).
template <typename X>
std::string write_series(const std::string& path, std::string_view header, X x, const std::vector<double>& truth,
                         const std::vector<double>& model, const std::vector<double>& baseline, const std::vector<NamedSeries>& external) {
  std::string columns(header);
  std::size_t n = std::max({truth.size(), model.size(), baseline.size()});
  for (const NamedSeries& s : external) columns += "," + csv_field("external-" + s.name), n = std::max(n, s.values.size());
  CsvFile out(path, columns);
  for (std::size_t i = 0; i < n; ++i) {
    std::string more;
    for (const NamedSeries& s : external) more += "," + cell(s.values, i);
    out.row(csv_number(x(i)), cell(truth, i), cell(model, i), cell(baseline, i) + more);
  }
  return out.close();
}

std::string write_experiment(const std::string& path, const Experiment& x) {
  CsvFile out(path, kExperimentColumns);
  for (const MaterialComparison& m : x.materials)
    out.row(csv_field(m.id), csv_field(m.name), m.windows, csv_number(m.model), csv_number(m.baseline),
            csv_number(m.difference.q1), csv_number(m.difference.median), csv_number(m.difference.q3), csv_number(m.test.t),
            csv_number(m.test.df), csv_number(m.test.p), m.test.n_a, m.test.n_b, int(m.better()), int(m.significant()),
            csv_measured(m.model_lsd_db), csv_measured(m.baseline_lsd_db), csv_measured(m.floor),
            csv_measured(m.floor_ratio()), csv_measured(m.mean_spectrum), csv_measured(m.mean_spectrum_ratio()),
            int(m.below_floor));
  return out.close();
}

std::string write_speed(const std::string& path, const std::vector<SpeedPoint>& points) {
  CsvFile out(path, kSpeedColumns);
  for (const SpeedPoint& s : points)
    out.row(csv_field(s.method), csv_field(s.setting), csv_number(s.seconds_per_second), csv_number(s.distance),
            csv_field(s.kind), csv_measured(s.section_lsd_db), csv_measured(s.spread_ratio));
  return out.close();
}

std::string write_latents(const std::string& path, const std::vector<LatentPoint>& points) {
  CsvFile out(path, kLatentColumns);
  for (const LatentPoint& p : points)
    out.row(csv_field(p.id), csv_field(p.name), csv_field(p.kind), csv_number(p.x), csv_number(p.y));
  return out.close();
}

std::string write_floors(const std::string& path, const std::vector<MaterialFloor>& floors) {
  CsvFile out(path, kFloorColumns);
  for (const MaterialFloor& f : floors)
    out.row(csv_field(f.id), csv_field(f.name), csv_field(f.kind), csv_field(f.method), f.windows, csv_measured(f.distance),
            csv_measured(f.lsd_db), csv_measured(f.closed_form), csv_measured(f.monte_carlo),
            csv_measured(closed_form_gap_percent(f)), csv_measured(f.rendered), csv_measured(rendered_ratio(f)),
            csv_measured(f.estimate), csv_measured(f.baseline_expected), csv_measured(f.input_floor));
  return out.close();
}

std::string write_realism(const std::string& path, const std::vector<Realism>& realism) {
  CsvFile out(path, kRealismColumns);
  for (const Realism& r : realism)
    for (const MaterialRealism& m : r.materials)
      out.row(csv_field(r.method), csv_field(r.setting), csv_field(m.id), csv_field(m.name), csv_measured(m.section_lsd_db),
              csv_measured(m.spread_ratio), csv_measured(m.distance), csv_measured(m.floor_ratio), csv_measured(m.rendered_floor_ratio));
  return out.close();
}

}  // namespace

ReportLayout report_layout(const Evaluation& e) {
  std::set<std::string> used{std::string(kSpeedStem), std::string(kLatentsStem), std::string(kExamplesStem),
                             std::string(kFloorsStem), std::string(kRealismStem)};
  ReportLayout layout;
  for (const Experiment& x : e.experiments) layout.experiments.push_back(unique_name("experiment-" + safe_stem(x.id), used));
  for (const Example& x : e.examples) layout.examples.push_back(unique_name("example-" + safe_stem(x.id), used));
  return layout;
}

std::string csv_field(std::string_view raw) {
  const std::string text = text::printable(raw);  // as in report.md: a newline or tab too, so no line splits where a name does
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::string csv_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, end);
}

std::string csv_measured(double x) { return std::isnan(x) ? "" : csv_number(x); }

std::vector<std::string> write_report_csvs(const Evaluation& e, const ReportLayout& layout, const std::string& directory) {
  namespace fs = std::filesystem;
  const auto path = [&](const std::string& name) { return (fs::path(directory) / name).string(); };
  const auto csv = [&](std::string_view stem) { return path(std::string(stem) + ".csv"); };
  std::vector<std::string> written;
  for (std::size_t i = 0; i < e.experiments.size(); ++i) written.push_back(write_experiment(csv(layout.experiments[i]), e.experiments[i]));
  written.push_back(write_speed(csv(kSpeedStem), e.speed));
  written.push_back(write_latents(csv(kLatentsStem), e.latents));
  written.push_back(write_floors(csv(kFloorsStem), e.floors));
  written.push_back(write_realism(csv(kRealismStem), e.realism));
  for (std::size_t i = 0; i < e.examples.size(); ++i) {
    const Example& x = e.examples[i];
    written.push_back(write_series(path(layout.examples[i] + "-spectra.csv"), kSpectraColumns,
                                   [](std::size_t k) { return double(k + 1) * kBinHz; }, x.truth_spectrum,
                                   x.model_spectrum, x.baseline_spectrum, x.external_spectra));
    written.push_back(write_series(path(layout.examples[i] + "-signals.csv"), kSignalColumns,
                                   [](std::size_t k) { return double(k) / kSampleRateHz; }, x.truth_signal,
                                   x.model_signal, x.baseline_signal, x.external_signals));
  }
  return written;
}

}  // namespace haptex::evaluate
