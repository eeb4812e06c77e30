#include "evaluate/report/report_writer.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/file.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/process/run_program.hpp"
#include "core/error.hpp"
#include "core/json/schema.hpp"
#include "core/temporary_name.hpp"
#include "evaluate/report/report_csv.hpp"
#include "evaluate/report/report_markdown.hpp"
#include "evaluate/report/results_json.hpp"
#include "tests/support/temp_dir.hpp"
#include "tests/support/file_text.hpp"

namespace haptex::evaluate {
namespace {

namespace fs = std::filesystem;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = kNotMeasured;

MaterialComparison material(const std::string& id, const std::string& name, double model, double baseline,
                            Quartiles difference, double t, double p) {
  MaterialComparison m{id, name, 120, model, baseline, difference, {}};
  m.test = {t, 150.25, p, model, baseline, 120, 1200};
  return m;
}

// The measures beside the distance: log-spectral distances, the noise floor, the mean spectrum.
MaterialComparison measured(MaterialComparison m, double model_lsd_db, double baseline_lsd_db, double floor,
                            double mean_spectrum, bool below_floor = false) {
  m.model_lsd_db = model_lsd_db, m.baseline_lsd_db = baseline_lsd_db, m.floor = floor;
  m.mean_spectrum = mean_spectrum, m.below_floor = below_floor;
  return m;
}

Example example(const std::string& id, const std::string& name, std::size_t model_samples) {
  Example x{id, name, {}, {}, {}, {}, {}, {}, {}, {}};
  for (int k = 0; k < 100; ++k) {
    x.truth_spectrum.push_back(0.1 / (1 + k));
    x.model_spectrum.push_back(0.11 / (1 + k));
    x.baseline_spectrum.push_back(0.09 / (1 + k) + 0.001);
  }
  for (int i = 0; i < 500; ++i) {
    x.truth_signal.push_back(std::sin(0.05 * i));
    x.baseline_signal.push_back(0.8 * std::sin(0.05 * i + 0.3));
  }
  for (std::size_t i = 0; i < model_samples; ++i) x.model_signal.push_back(0.9 * std::cos(0.05 * double(i)));
  return x;
}

// Against the mean training spectrum: better on Book, significantly worse on Brick, 2 and Cork.
Experiment mean_spectrum_experiment() {
  Experiment x{"unified-new-actions-vs-mean-spectrum", "Unified model against the mean training spectrum", "unified model",
               "mean training spectrum", {}};
  x.materials = {material("book", "Book", 0.5, 0.8, {0.1, 0.3, 0.5}, -6.0, 1e-5),
                 material("brick_2", "Brick, 2", 1.1, 0.9, {-0.4, -0.2, 0.0}, 2.5, 0.013),
                 material("cork", "Cork", 0.61, 0.5, {-0.2, -0.1, 0.0}, 2.2, 0.03),
                 material("glass", "Glass \"smooth\"", 0.4, 0.38, {-0.1, -0.02, 0.1}, 0.5, 0.6)};
  return x;
}

// The noise floor: an oracle per material, one not measured (Brick, 2).
std::vector<MaterialFloor> sample_floors() {
  MaterialFloor book{"book", "Book", "oracle", "closed form", 120, 0.48, 2.5, 0.48, 0.5, 0.72, 0.5, 0.625, 0.012, 0.52};
  MaterialFloor brick{"brick_2", "Brick, 2", "oracle", "Monte Carlo", 120};
  MaterialFloor felt{"felt", "Felt", "oracle", "closed form", 120, 0.21, 1.75, 0.21, 0.2, 0.35, kNaN, 0.3};
  return {book, brick, felt};
}

// Realism: the AR baseline as steady as the recording, FGLA too steady; Felt not measured.
std::vector<Realism> sample_realism() {
  return {{"AR baseline", "ar-refit", {{"book", "Book", 3.25, 1.25}, {"brick_2", "Brick, 2", 2.75, 0.75}, {"felt", "Felt", kNaN, kNaN}}},
          {"unified + FGLA", "100 iterations", {{"book", "Book", 1.5, 0.375, 0.9, 1.5, 1.1}, {"brick_2", "Brick, 2", 2.5, 0.625, 1.0, 1.8, 1.3}}}};
}

// Five materials in the paper's experiment: better and significant (Book; Felt with t = -infinity),
// significantly worse (Brick, 2), better and worse without significance; totals 3, 2, 1. Against the
// floor (0.48, not measured, 0.21, 0.35, 0.5): ratios 1.042, -, 0.952 (below the floor), 1.143,
// 1.22: within 10 % on 2 of 4, within 15 % on 3, median 1.092, worst 1.22.
Evaluation sample_evaluation() {
  Evaluation e;
  e.dataset = {"data/dataset.h5", std::string(64, 'a')};
  e.split = {"data/split.json", std::string(64, 'b')};
  e.models = {{"models/unified.h5", std::string(64, 'c')}, {"models/small.h5", std::string(64, 'd')}};
  e.baseline = "ar-refit";
  e.reconstruct = "fgla";
  e.repeats = 10;
  e.seconds = 123.456;
  Experiment actions{"unified-new-actions", "Unified model on new actions", "unified model models/unified.h5", "ar-refit", {}};
  actions.materials = {measured(material("book", "Book", 0.5, 0.9, {0.1, 0.35, 0.6}, -8.25, 1e-6), 4.5, 6.25, 0.48, 0.8),
                       measured(material("brick_2", "Brick, 2", 1.1, 0.7, {-0.6, -0.4, -0.1}, 3.1, 0.0021), 7.0, 5.5, kNaN, 0.9),
                       measured(material("felt", "Felt", 0.2, 0.3, {0.1, 0.1, 0.1}, -kInf, 0.0), 3.0, 4.0, 0.21, kNaN, true),
                       measured(material("glass", "Glass \"smooth\"", 0.4, 0.42, {-0.2, 0.02, 0.25}, -0.9, 0.37), kNaN, kNaN, 0.35, 0.38),
                       measured(material("cork", "Cork", 0.61, 0.6, {-0.3, -0.01, 0.2}, 0.2, 0.84), 5.0, 5.0, 0.5, 0.5)};
  Experiment stitched{"stitched-fgla", "Stitched signals, fast Griffin-Lim", "unified model", "ar-refit", {}};
  stitched.materials = {material("book", "Book", 0.7, 0.9, {0.0, 0.2, 0.4}, -4.0, 0.0001),
                        material("felt", "Felt", 0.35, 0.3, {-0.1, -0.05, 0.0}, 1.2, 0.23)};
  Experiment per_material{"per-material (small.h5)", "Per-material models on new actions", "per-material", "ar-refit", {}};
  per_material.materials = {material("book", "Book", 0.45, 0.9, {0.2, 0.45, 0.7}, -9.0, 2e-9)};
  Experiment presses{"unified-new-presses", "Unified model on a new press", "unified model", "ar-refit", {}};
  Experiment expected{"unified-new-actions-vs-expected-ar", "Unified model against the AR expected spectrum", "unified model",
                      "ar-refit, expected spectrum", {}};
  expected.materials = {material("book", "Book", 0.5, 0.55, {0.0, 0.05, 0.1}, -2.5, 0.013)};
  e.experiments = {actions, stitched, per_material, presses, mean_spectrum_experiment(), expected};
  e.speed = {{"AR baseline", "ar-refit", 0.002, 0.9, "signal", 3.0, 1.0},
             {"AR baseline", "expected spectrum", 0.0004, 0.52},
             {"per-material", "small.h5, 64 hidden", 0.0005, 0.55},
             {"unified", "unified.h5, 64 hidden", 0.0008, 0.5},
             {"unified", "big.h5, 256 hidden", 0.003, 0.45},
             {"unified + FGLA", "0 iterations", 0.0026, 0.8, "signal", kNaN, kNaN},
             {"unified + FGLA", "8 iterations", 0.012, 0.7, "signal", 2.25, 0.5},
             {"unified + FGLA", "32 iterations", 0.04, 0.65, "signal", 2.0, 0.45},
             {"unified + FGLA", "100 iterations", 0.12, 0.6, "signal", 2.0, 0.5},
             {"unified + online (RTISI-LA)", "look-ahead 3", 0.021, 0.66, "signal", 2.5, 0.75}};
  e.floor_kind = "oracle";
  e.floors = sample_floors();
  e.realism = sample_realism();
  e.examples = {example("book", "Book", 500), example("brick_2", "Brick, 2", 400), example("felt", "Felt", 500),
                example("glass", "Glass \"smooth\"", 500)};
  e.latents = {{"book", "Book", "training", 0.5, 0.25},     {"book", "Book", "test press", 0.45, 0.3},
               {"brick_2", "Brick, 2", "training", -1.25, 0.5}, {"brick_2", "Brick, 2", "test press", -1.0, 0.375},
               {"felt", "Felt", "training", 0.125, -2.0},   {"felt", "Felt", "test press", 0.2, -1.5}};
  e.notes = {"material 'velvet' left out: its training sections are too short for the AR fit"};
  return e;
}

// RFC 4180: quoted fields may hold commas, doubled quotes and line breaks.
std::vector<std::vector<std::string>> read_csv(const fs::path& path) {
  const std::string text = test::file_text(path);
  std::vector<std::vector<std::string>> rows(1);
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') field += '"', ++i;
      else if (c == '"') quoted = false;
      else field += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      rows.back().push_back(field), field.clear();
    } else if (c == '\n') {
      rows.back().push_back(field), field.clear();
      rows.emplace_back();
    } else {
      field += c;
    }
  }
  if (rows.back().empty()) rows.pop_back();
  return rows;
}

double number(const std::string& text) {
  char* end = nullptr;
  const double x = std::strtod(text.c_str(), &end);
  EXPECT_TRUE(!text.empty() && *end == '\0') << "not a number: '" << text << "'";
  return x;
}

std::vector<std::string> split_header(std::string_view columns) {
  std::vector<std::string> out(1);
  for (char c : columns) {
    if (c == ',') out.emplace_back();
    else out.back().push_back(c);
  }
  return out;
}

// The data rows of a CSV whose header must be `columns`.
std::vector<std::vector<std::string>> read_table(const fs::path& path, std::string_view columns) {
  std::vector<std::vector<std::string>> rows = read_csv(path);
  if (rows.empty()) {
    ADD_FAILURE() << path << " is empty";
    return rows;
  }
  EXPECT_EQ(rows[0], split_header(columns)) << path;
  rows.erase(rows.begin());
  return rows;
}

// A row read back: its text fields, then its numbers, each exactly as written.
void expect_row(const std::vector<std::string>& row, const std::vector<std::string>& text, const std::vector<double>& numbers) {
  ASSERT_EQ(row.size(), text.size() + numbers.size());
  for (std::size_t i = 0; i < text.size(); ++i) EXPECT_EQ(row[i], text[i]) << "field " << i;
  for (std::size_t i = 0; i < numbers.size(); ++i) EXPECT_EQ(number(row[text.size() + i]), numbers[i]) << "field " << text.size() + i;
}

// The first n cells of a row.
std::vector<std::string> head(const std::vector<std::string>& row, std::size_t n) {
  return {row.begin(), row.begin() + std::ptrdiff_t(std::min(n, row.size()))};
}

// The cells of a row from `first` on to its end: figures that may not have been measured (an empty cell for NaN).
void expect_measured(const std::vector<std::string>& row, std::size_t first, const std::vector<double>& figures) {
  ASSERT_EQ(row.size(), first + figures.size());
  for (std::size_t i = 0; i < figures.size(); ++i) {
    if (std::isnan(figures[i])) EXPECT_EQ(row[first + i], "") << "field " << first + i;
    else EXPECT_EQ(number(row[first + i]), figures[i]) << "field " << first + i;
  }
}

std::vector<std::string> partial_leftovers(const fs::path& dir) {
  std::vector<std::string> found;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (entry.path().string().ends_with(".partial")) found.push_back(entry.path().string());
  return found;
}

// A folder holding one file, as an old report or a killed run leaves it.
void make_folder_with(const std::string& dir, const std::string& file, const std::string& text) {
  fs::create_directories(dir);
  std::ofstream(dir + "/" + file) << text;
}

bool gnuplot_installed() { return process::program_on_path("gnuplot"); }

bool is_png(const fs::path& path) { return test::file_text(path).starts_with(std::string("\x89PNG\r\n\x1a\n", 8)); }

Error::Kind kind_of_failure(const Evaluation& e, const std::string& dir, bool overwrite, std::string* message = nullptr) {
  try {
    write_report(e, dir, overwrite);
  } catch (const Error& error) {
    if (message) *message = error.what();
    return error.kind();
  }
  ADD_FAILURE() << "write_report(" << dir << ") did not throw";
  return Error::Kind::failed;
}

TEST(ReportWriter, WritesEveryFileOfTheReportAndNoPartial) {
  test::TempDir tmp;
  const std::string dir = tmp.file("report");
  const ReportFiles files = write_report(sample_evaluation(), dir, false);
  EXPECT_EQ(files.directory, dir);
  ASSERT_GE(files.files.size(), 3u);
  EXPECT_EQ(files.files[0], dir + "/report.md");
  EXPECT_EQ(files.files[1], dir + "/report.html");
  EXPECT_EQ(files.files[2], dir + "/results.json");
  for (const char* name : {"experiment-unified-new-actions.csv", "experiment-stitched-fgla.csv",
                           "experiment-per-material__small.h5_.csv", "experiment-unified-new-presses.csv", "speed.csv",
                           "latents.csv", "example-book-spectra.csv", "example-brick_2-signals.csv",
                           "experiment-unified-new-actions.gnuplot", "examples.gnuplot", "latents.gnuplot", "speed.gnuplot"}) {
    EXPECT_TRUE(fs::is_regular_file(fs::path(dir) / name)) << name;
    EXPECT_NE(std::find(files.files.begin(), files.files.end(), dir + "/" + name), files.files.end()) << name;
  }
  EXPECT_FALSE(fs::exists(fs::path(dir) / "experiment-unified-new-presses.gnuplot")) << "no chart without materials";
  for (const std::string& f : files.files) EXPECT_TRUE(fs::is_regular_file(f)) << f;
  EXPECT_TRUE(partial_leftovers(tmp.path()).empty());
  EXPECT_TRUE(temporaries_of(dir).empty());
}

TEST(ReportWriter, ResultsJsonFollowsTheSchemaAndCountsTheTotals) {
  test::TempDir tmp;
  const std::string dir = tmp.file("report");
  const Evaluation e = sample_evaluation();
  write_report(e, dir, false);
  const std::string path = dir + "/results.json";
  const nlohmann::json doc = json::read_file(path);
  EXPECT_NO_THROW(json::validate(doc, "results.schema.json", path));
  EXPECT_EQ(doc["format"], "results/2");
  EXPECT_EQ(doc["inputs"]["dataset"]["sha256"], std::string(64, 'a'));
  ASSERT_EQ(doc["experiments"].size(), 6u);
  const nlohmann::json& actions = doc["experiments"][0];
  EXPECT_EQ(actions["totals"]["materials"], 5);
  EXPECT_EQ(actions["totals"]["better"], 3);
  EXPECT_EQ(actions["totals"]["significantly_better"], 2);
  EXPECT_EQ(actions["totals"]["significantly_worse"], 1);
  for (std::size_t i = 0; i < e.experiments.size(); ++i) {
    const nlohmann::json& totals = doc["experiments"][i]["totals"];
    EXPECT_EQ(totals["better"], e.experiments[i].better()) << e.experiments[i].id;
    EXPECT_EQ(totals["significantly_better"], e.experiments[i].significantly_better()) << e.experiments[i].id;
    EXPECT_EQ(totals["significantly_worse"], e.experiments[i].significantly_worse()) << e.experiments[i].id;
  }
  EXPECT_EQ(actions["materials"][2]["test"]["t"], "-inf");
  EXPECT_EQ(actions["materials"][2]["test"]["p"], 0.0);
  EXPECT_EQ(actions["materials"][1]["name"], "Brick, 2");
  EXPECT_EQ(actions["materials"][1]["significant"], true);
  EXPECT_EQ(actions["materials"][1]["better"], false);
  EXPECT_EQ(actions["paper"]["better"], 82);
  EXPECT_EQ(actions["paper"]["significantly_better"], 78);
  EXPECT_EQ(actions["paper"]["materials"], 93);
  EXPECT_EQ(doc["experiments"][1]["paper"]["better_percent"], 86.02);
  EXPECT_EQ(doc["experiments"][1]["paper"]["significantly_better"], 52);
  EXPECT_EQ(doc["experiments"][1]["paper"]["significantly_worse"], 2);
  EXPECT_EQ(doc["experiments"][2]["paper"]["better"], 75) << "per-material, with a model label";
  EXPECT_EQ(doc["experiments"][2]["paper"]["significantly_better"], 65);
  EXPECT_EQ(doc["experiments"][2]["csv"], "experiment-per-material__small.h5_.csv");
  EXPECT_EQ(doc["speed"].size(), e.speed.size());
  EXPECT_EQ(doc["latents"][2]["x"], -1.25);
  EXPECT_EQ(doc["examples"][1]["signals_csv"], "example-brick_2-signals.csv");

  // The schema is not vacuous.
  nlohmann::json bad = doc;
  bad["experiments"][0]["totals"]["better"] = "3";
  EXPECT_THROW(json::validate(bad, "results.schema.json", path), Error);
  bad = doc;
  bad["experiments"][0]["materials"][2]["test"]["t"] = "minus infinity";
  EXPECT_THROW(json::validate(bad, "results.schema.json", path), Error);
  bad = doc;
  bad["inputs"]["split"]["sha256"] = "abc";
  EXPECT_THROW(json::validate(bad, "results.schema.json", path), Error);
}

TEST(ReportWriter, CsvRowsReadBackToTheSameNumbers) {
  test::TempDir tmp;
  const std::string dir = tmp.file("report");
  const Evaluation e = sample_evaluation();
  write_report(e, dir, false);

  const fs::path experiment = fs::path(dir) / "experiment-unified-new-actions.csv";
  EXPECT_NE(test::file_text(experiment).find("\"Brick, 2\""), std::string::npos);
  EXPECT_NE(test::file_text(experiment).find("\"Glass \"\"smooth\"\"\""), std::string::npos);
  const auto rows = read_table(experiment, kExperimentColumns);
  ASSERT_EQ(rows.size(), 5u);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const MaterialComparison& m = e.experiments[0].materials[i];
    expect_row(head(rows[i], 15), {m.id, m.name},
               {double(m.windows), m.model, m.baseline, m.difference.q1, m.difference.median, m.difference.q3, m.test.t,
                m.test.df, m.test.p, double(m.test.n_a), double(m.test.n_b), double(m.better()), double(m.significant())});
    expect_measured(rows[i], 15,
                    {m.model_lsd_db, m.baseline_lsd_db, m.floor, m.floor_ratio(), m.mean_spectrum, m.mean_spectrum_ratio(),
                     double(m.below_floor)});
  }
  EXPECT_EQ(rows[2][8], "-inf");
  EXPECT_EQ(rows[1][13] + rows[1][14], "01") << "Brick, 2: worse, significant";

  const auto speed = read_table(fs::path(dir) / "speed.csv", kSpeedColumns);
  ASSERT_EQ(speed.size(), e.speed.size());
  for (std::size_t i = 0; i < speed.size(); ++i) {
    const SpeedPoint& p = e.speed[i];
    expect_row(head(speed[i], 4), {p.method, p.setting}, {p.seconds_per_second, p.distance});
    EXPECT_EQ(speed[i][4], p.kind);
    expect_measured(speed[i], 5, {p.section_lsd_db, p.spread_ratio});
  }

  const auto latents = read_table(fs::path(dir) / "latents.csv", kLatentColumns);
  ASSERT_EQ(latents.size(), e.latents.size());
  for (std::size_t i = 0; i < latents.size(); ++i)
    expect_row(latents[i], {e.latents[i].id, e.latents[i].name, e.latents[i].kind}, {e.latents[i].x, e.latents[i].y});

  const Example& brick = e.examples[1];
  const auto spectra = read_table(fs::path(dir) / "example-brick_2-spectra.csv", kSpectraColumns);
  ASSERT_EQ(spectra.size(), 100u);
  for (std::size_t k = 0; k < spectra.size(); ++k)
    expect_row(spectra[k], {}, {10.0 * double(k + 1), brick.truth_spectrum[k], brick.model_spectrum[k], brick.baseline_spectrum[k]});
  const auto signals = read_table(fs::path(dir) / "example-brick_2-signals.csv", kSignalColumns);
  ASSERT_EQ(signals.size(), 500u);
  EXPECT_EQ(number(signals[1][0]), 1e-4);
  EXPECT_EQ(number(signals[399][2]), brick.model_signal[399]);
  EXPECT_EQ(signals[400][2], "") << "the model's signal is shorter: its cells stay empty";
  EXPECT_EQ(number(signals[499][1]), brick.truth_signal[499]);
  EXPECT_EQ(number(signals[499][3]), brick.baseline_signal[499]);
}

TEST(ReportWriter, MarkdownGivesTotalsPaperFiguresAndTables) {
  test::TempDir tmp;
  const std::string dir = tmp.file("report");
  const ReportFiles files = write_report(sample_evaluation(), dir, false);
  const std::string md = test::file_text(dir + "/report.md");
  EXPECT_NE(md.find("better on 3 of 5 materials, significantly on 2, significantly worse on 1"), std::string::npos);
  EXPECT_NE(md.find("better on 1 of 2 materials, significantly on 1, significantly worse on 0"), std::string::npos);
  EXPECT_NE(md.find("better on 1 of 1 material, significantly on 1, significantly worse on 0"), std::string::npos);
  EXPECT_NE(md.find("better on 82 of 93 (88.2 %), significantly on 78 (83.9 %)"), std::string::npos);
  EXPECT_NE(md.find("better on 77 of 93 (82.8 %), significantly on 71 (76.3 %)"), std::string::npos);
  EXPECT_NE(md.find("better on 75 of 93 (80.6 %), significantly on 65 (69.9 %)"), std::string::npos);
  EXPECT_NE(md.find("better on 86.02 %, significantly better on 52 of 93 (55.9 %), significantly worse on 2 (2.2 %)"),
            std::string::npos);
  EXPECT_NE(md.find("| 5 | 3 (60 %) | 2 (40 %) | 1 (20 %) |"), std::string::npos) << "totals row of unified-new-actions";
  EXPECT_NE(md.find(std::string(64, 'a')), std::string::npos) << "the dataset's hash";
  EXPECT_NE(md.find("`models/small.h5`"), std::string::npos);
  EXPECT_NE(md.find("| Brick, 2 | 120 | 1.100 | 0.7000 | -0.6000 | -0.4000 | -0.1000 | 3.100 | 0.0021 | worse \\* |"),
            std::string::npos);
  EXPECT_NE(md.find("| Book | 120 | 0.5000 | 0.9000 | 0.1000 | 0.3500 | 0.6000 | -8.250 | 1.00e-06 | better \\* |"),
            std::string::npos);
  EXPECT_NE(md.find("| Felt | 120 | 0.2000 | 0.3000 | 0.1000 | 0.1000 | 0.1000 | -∞ | 0 | better \\* |"), std::string::npos);
  EXPECT_NE(md.find("| Cork | 120 | 0.6100 | 0.6000 | -0.3000 | -0.01000 | 0.2000 | 0.2000 | 0.84 | worse |"),
            std::string::npos);
  EXPECT_NE(md.find("| unified + FGLA | 100 iterations | 120.0 ms | 0.6000 |"), std::string::npos);
  EXPECT_NE(md.find("material 'velvet' left out"), std::string::npos) << "the evaluation's notes";
  EXPECT_NE(md.find("Spectral distance"), std::string::npos);
  EXPECT_NE(md.find("[results.json](results.json)"), std::string::npos);
  if (files.note.empty()) {
    for (const char* link : {"](experiment-unified-new-actions.png)", "](examples.png)", "](latents.png)", "](speed.png)"})
      EXPECT_NE(md.find(link), std::string::npos) << link;
  } else {
    EXPECT_NE(md.find("Chart not drawn"), std::string::npos);
  }
}

// Issue 35: a test press recognised as its own material outright gives unified-new-actions' figures;
// the report says so, per material, instead of presenting recognition as generalisation to a new image.
TEST(ReportWriter, MarkdownSaysWhereNewPressesMeasureRecognition) {
  for (const std::size_t recognised : {std::size_t(2), std::size_t(5)}) {
    Evaluation e = sample_evaluation();
    Experiment& presses = *std::find_if(e.experiments.begin(), e.experiments.end(), [](const Experiment& x) { return x.id == "unified-new-presses"; });
    presses.materials = e.experiments[0].materials;  // unified-new-actions' materials and figures
    for (std::size_t m = recognised; m < presses.materials.size(); ++m) presses.materials[m].model += 0.05;
    test::TempDir tmp;
    write_report(e, tmp.file("report"), false);
    const std::string md = test::file_text(tmp.file("report") + "/report.md");
    if (recognised == 5)
      EXPECT_NE(md.find("every test press was recognised as its own material outright:** these figures equal `unified-new-actions`'s"),
                std::string::npos) << md;
    else
      EXPECT_NE(md.find("On 2 of 5 materials the test press was recognised as its own material outright"), std::string::npos) << md;
  }
  test::TempDir tmp;
  write_report(sample_evaluation(), tmp.file("report"), false);
  EXPECT_EQ(test::file_text(tmp.file("report") + "/report.md").find("recognised as its own material outright:"), std::string::npos)
      << "no note where no figure is the same";
}

TEST(ReportWriter, ResultsJsonHoldsFloorsRealismAndNullWhereNotMeasured) {
  test::TempDir tmp;
  const std::string dir = tmp.file("report");
  write_report(sample_evaluation(), dir, false);
  const std::string path = dir + "/results.json";
  const nlohmann::json doc = json::read_file(path);
  EXPECT_NO_THROW(json::validate(doc, "results.schema.json", path)) << "NaN figures are null";
  const nlohmann::json& actions = doc["experiments"][0];
  EXPECT_EQ(actions["comparison"], "rendered-ar");
  EXPECT_EQ(doc["experiments"][1]["comparison"], "stitched");
  EXPECT_EQ(doc["experiments"][4]["comparison"], "mean-spectrum");
  EXPECT_EQ(doc["experiments"][5]["comparison"], "expected-ar");
  EXPECT_EQ(actions["totals"]["with_floor"], 4);
  EXPECT_EQ(actions["totals"]["within_floor_10_percent"], 2);
  EXPECT_EQ(actions["totals"]["within_floor_15_percent"], 3);
  EXPECT_EQ(actions["totals"]["below_floor"], 1);
  EXPECT_DOUBLE_EQ(actions["median_floor_ratio"].get<double>(), (0.5 / 0.48 + 0.4 / 0.35) / 2);
  EXPECT_DOUBLE_EQ(actions["worst_floor_ratio"].get<double>(), 0.61 / 0.5);
  EXPECT_TRUE(doc["experiments"][3]["median_floor_ratio"].is_null()) << "no materials, no floor";
  const nlohmann::json& book = actions["materials"][0];
  EXPECT_EQ(book["model_lsd_db"], 4.5);
  EXPECT_EQ(book["baseline_lsd_db"], 6.25);
  EXPECT_EQ(book["floor"], 0.48);
  EXPECT_DOUBLE_EQ(book["floor_ratio"].get<double>(), 0.5 / 0.48);
  EXPECT_DOUBLE_EQ(book["mean_spectrum_ratio"].get<double>(), 0.5 / 0.8);
  EXPECT_EQ(book["below_floor"], false);
  EXPECT_TRUE(actions["materials"][1]["floor"].is_null());
  EXPECT_TRUE(actions["materials"][1]["floor_ratio"].is_null());
  EXPECT_EQ(actions["materials"][2]["below_floor"], true);
  EXPECT_TRUE(actions["materials"][3]["model_lsd_db"].is_null());

  EXPECT_EQ(doc["floor_kind"], "oracle");
  ASSERT_EQ(doc["floors"].size(), 3u);
  EXPECT_EQ(doc["floors"][0]["method"], "closed form");
  EXPECT_DOUBLE_EQ(doc["floors"][0]["closed_form_gap_percent"].get<double>(), 1.2);
  EXPECT_DOUBLE_EQ(doc["floors"][0]["rendered_ratio"].get<double>(), 0.72 / 0.48);
  for (const char* key : {"distance", "lsd_db", "closed_form", "monte_carlo", "closed_form_gap_percent", "rendered", "rendered_ratio",
                          "estimate", "baseline_expected", "input_floor"})
    EXPECT_TRUE(doc["floors"][1][key].is_null()) << key;
  EXPECT_EQ(doc["floors"][0]["input_floor"], 0.52);
  EXPECT_TRUE(doc["floors"][2]["estimate"].is_null());
  EXPECT_EQ(doc["floors"][2]["baseline_expected"], 0.3);

  ASSERT_EQ(doc["realism"].size(), 2u);
  EXPECT_EQ(doc["realism"][0]["median_section_lsd_db"], 3.0);
  EXPECT_EQ(doc["realism"][0]["median_spread_ratio"], 1.0);
  EXPECT_TRUE(doc["realism"][0]["materials"][2]["spread_ratio"].is_null());
  EXPECT_EQ(doc["realism"][1]["median_spread_ratio"], 0.5);
  EXPECT_EQ(doc["speed"][0]["kind"], "signal");
  EXPECT_EQ(doc["speed"][0]["spread_ratio"], 1.0);
  EXPECT_EQ(doc["speed"][1]["kind"], "spectrum");
  EXPECT_TRUE(doc["speed"][1]["spread_ratio"].is_null());

  // Strict: a figure not measured is null, never "nan"; no field the schema does not name.
  nlohmann::json bad = doc;
  bad["experiments"][0]["materials"][1]["floor"] = "nan";
  EXPECT_THROW(json::validate(bad, "results.schema.json", path), Error);
  bad = doc;
  bad["floors"][0]["distance"] = -0.5;
  EXPECT_THROW(json::validate(bad, "results.schema.json", path), Error);
  bad = doc;
  bad["realism"][0]["materials"][0]["spread"] = 1.0;
  EXPECT_THROW(json::validate(bad, "results.schema.json", path), Error);
  bad = doc;
  bad["speed"][0]["kind"] = "noise";
  EXPECT_THROW(json::validate(bad, "results.schema.json", path), Error);
  bad = doc;
  bad["floor_kind"] = "guess";
  EXPECT_THROW(json::validate(bad, "results.schema.json", path), Error);
  bad = doc;
  bad["experiments"][0]["totals"].erase("below_floor");
  EXPECT_THROW(json::validate(bad, "results.schema.json", path), Error);
}

TEST(ReportWriter, FloorsAndRealismCsvsReadBack) {
  test::TempDir tmp;
  const std::string dir = tmp.file("report");
  const Evaluation e = sample_evaluation();
  write_report(e, dir, false);
  const auto floors = read_table(fs::path(dir) / "floors.csv", kFloorColumns);
  ASSERT_EQ(floors.size(), e.floors.size());
  for (std::size_t i = 0; i < floors.size(); ++i) {
    const MaterialFloor& f = e.floors[i];
    expect_row(head(floors[i], 5), {f.id, f.name, f.kind, f.method}, {double(f.windows)});
    expect_measured(floors[i], 5,
                    {f.distance, f.lsd_db, f.closed_form, f.monte_carlo, closed_form_gap_percent(f), f.rendered,
                     rendered_ratio(f), f.estimate, f.baseline_expected, f.input_floor});
  }
  EXPECT_EQ(floors[1][5], "") << "Brick, 2: not measured, an empty cell";

  const auto realism = read_table(fs::path(dir) / "realism.csv", kRealismColumns);
  std::size_t row = 0;
  for (const Realism& r : e.realism)
    for (const MaterialRealism& m : r.materials) {
      ASSERT_LT(row, realism.size());
      expect_row(head(realism[row], 4), {r.method, r.setting, m.id, m.name}, {});
      expect_measured(realism[row++], 4, {m.section_lsd_db, m.spread_ratio, m.distance, m.floor_ratio, m.rendered_floor_ratio});
    }
  EXPECT_EQ(row, realism.size());
}

TEST(ReportWriter, MarkdownShowsTheFloorRealismAndWhatEachComparisonAsks) {
  test::TempDir tmp;
  const std::string dir = tmp.file("report");
  write_report(sample_evaluation(), dir, false);
  const std::string md = test::file_text(dir + "/report.md");
  const auto has = [&md](const std::string& text) { return md.find(text) != std::string::npos; };
  // Per experiment: against the floor, the warning, and the materials worse than their mean spectrum.
  EXPECT_TRUE(has("**Against the noise floor (oracle):** within 10 % of the floor on 2 of 4 materials, within 15 % on 3; "
                  "model/floor median 1.092, worst 1.220; below the floor on 1. 1 material without a floor."));
  EXPECT_TRUE(has("the oracle is wrong or the model saw the test data"));
  EXPECT_TRUE(has("**Significantly worse than the material's mean training spectrum** (the model does not gain from the "
                  "actions) on: Brick, 2; Cork."));
  // The material table's new columns: LSD model and baseline, floor, model/floor († below it), model/mean spectrum.
  EXPECT_TRUE(has("| better \\* | 4.500 | 6.250 | 0.4800 | 1.042 | 0.6250 |")) << "Book";
  EXPECT_TRUE(has("| worse \\* | 7.000 | 5.500 | – | – | 1.222 |")) << "Brick, 2: no floor";
  EXPECT_TRUE(has("| better \\* | 3.000 | 4.000 | 0.2100 | 0.9524 † | – |")) << "Felt: below the floor";
  EXPECT_TRUE(has("| 0.5620 | 0.5840 | 1.092 |")) << "the totals table: mean model and baseline, median model/floor";
  // The noise floor, with a floor that was not measured.
  EXPECT_TRUE(has("## Noise floor\n\n**Oracle.**"));
  EXPECT_TRUE(has("| Book | oracle | closed form | 120 | 0.4800 | 2.500 | 0.4800 | 0.5000 | 1.200 % | 0.7200 | 1.500 | 0.5000 | 0.6250 | 0.5200 |"));
  EXPECT_TRUE(has("| Brick, 2 | oracle | Monte Carlo | 120 | – | – | – | – | – | – | – | – | – | – |"));
  EXPECT_TRUE(has("pays the randomness twice"));
  // Realism: medians over the materials where each figure was measured.
  // Spread in range: neither 1.25 nor 0.75 (AR), neither 0.375 nor 0.625; within 25 % of the
  // rendered floor: 1.1 but not 1.3; the AR rows have no distance ("–").
  EXPECT_TRUE(has("| AR baseline | ar-refit | 2 | 3.000 | 1.000 | 0 | – | – | – |"));
  EXPECT_TRUE(has("| unified + FGLA | 100 iterations | 2 | 2.000 | 0.5000 | 0 | 1.650 | 1.200 | 1 |"));
  EXPECT_TRUE(has("about 0.52 (Rayleigh amplitudes)"));
  EXPECT_TRUE(has("| unified + FGLA | 100 iterations | 120.0 ms | 0.6000 | signal | 2.000 | 0.5000 |"));
  EXPECT_TRUE(has("| AR baseline | expected spectrum | 0.4000 ms | 0.5200 | spectrum | – | – |"));
  // Which comparison answers which question, naming this report's experiments.
  EXPECT_TRUE(has("## Which comparison answers which question"));
  EXPECT_TRUE(has("| `unified-new-actions-vs-expected-ar` | Which model knows the texture better? Like for like"));
  EXPECT_TRUE(has("| `unified-new-actions-vs-mean-spectrum` | Does the model use the actions?"));
  EXPECT_TRUE(has("| `stitched-fgla` | Signal against signal"));
  EXPECT_TRUE(has("pays the texture's randomness twice"));
  EXPECT_TRUE(has("`floors.csv`") && has("`realism.csv`"));
}

TEST(ReportWriter, TheSpeedChartReadsTheFloorFromItsCsv) {
  test::TempDir tmp;
  Evaluation e = sample_evaluation();
  write_report(e, tmp.file("oracle"), false);
  const std::string oracle = test::file_text(tmp.file("oracle/speed.gnuplot"));
  EXPECT_NE(oracle.find("set multiplot layout 1,2"), std::string::npos) << oracle;
  EXPECT_NE(oracle.find("stats 'floors.csv' using (finite(column('distance')) * column('windows')) nooutput"), std::string::npos) << oracle;
  EXPECT_NE(oracle.find("floor with lines dt 2 lc rgb '#666666' title 'oracle'"), std::string::npos) << oracle;
  EXPECT_NE(oracle.find(":'spread_ratio' with points"), std::string::npos) << oracle;
  EXPECT_NE(oracle.find("1 with lines dt 2 lc rgb 'black' title 'the recording (1)'"), std::string::npos) << oracle;
  EXPECT_EQ(oracle.find("0.345"), std::string::npos) << "the mean floor is computed by gnuplot, not written into the script";

  e.floor_kind = "estimate";
  write_report(e, tmp.file("estimate"), false);
  EXPECT_NE(test::file_text(tmp.file("estimate/speed.gnuplot")).find("title 'floor (estimate)'"), std::string::npos);

  e.floors.clear();
  for (SpeedPoint& p : e.speed) p.kind = "spectrum";
  write_report(e, tmp.file("none"), false);
  const std::string none = test::file_text(tmp.file("none/speed.gnuplot"));
  EXPECT_NE(none.find("set multiplot layout 1,1"), std::string::npos) << "only the spectrum panel";
  EXPECT_EQ(none.find("floors.csv"), std::string::npos) << "no floor, no line";
  EXPECT_EQ(none.find("floor with lines"), std::string::npos);
  EXPECT_EQ(none.find("spread_ratio"), std::string::npos);
}

// Issue 35: two points at one place had their labels printed over each other; the bar chart's title
// was cut short, and its key listed a colour no bar had.
TEST(ReportWriter, ChartLabelsDoNotCoverEachOtherAndTheKeyListsWhatIsDrawn) {
  test::TempDir tmp;
  Evaluation e = sample_evaluation();
  e.speed.push_back({"unified-new-presses", "unified.h5, 64 hidden", 0.0008, 0.5});  // where "unified" is
  write_report(e, tmp.file("r"), false);
  const std::string speed = test::file_text(tmp.file("r/speed.gnuplot"));
  EXPECT_NE(speed.find("set label 'unified.h5, 64 hidden' at 8e-04,0.5 offset char 0.8,0.4 "), std::string::npos) << speed;
  EXPECT_NE(speed.find("set label 'unified.h5, 64 hidden' at 8e-04,0.5 offset char 0.8,-0.6 "), std::string::npos) << "a line below: " << speed;
  // unified-new-actions: better, not significant and significantly worse materials; stitched-fgla: no worse one.
  const std::string all = test::file_text(tmp.file("r/experiment-unified-new-actions.gnuplot"));
  EXPECT_NE(all.find("title 'model significantly worse'"), std::string::npos) << all;
  const std::string stitched = test::file_text(tmp.file("r/experiment-stitched-fgla.gnuplot"));
  EXPECT_NE(stitched.find("title 'model significantly better"), std::string::npos) << stitched;
  EXPECT_NE(stitched.find("title 'not significant'"), std::string::npos) << stitched;
  EXPECT_EQ(stitched.find("title 'model significantly worse'"), std::string::npos) << "no such bar, no such key: " << stitched;
  EXPECT_NE(stitched.find("set title 'Stitched signals, fast Griffin-Lim'.\"\\n\".'bars: median of baseline - model per test window; "
                          "whiskers: quartiles; above 0 the model is closer'"),
            std::string::npos) << stitched;
}

TEST(ReportWriter, ChartsAreValidPngsWhenGnuplotIsInstalled) {
  if (!gnuplot_installed()) GTEST_SKIP() << "gnuplot is not installed";
  test::TempDir tmp;
  const std::string dir = tmp.file("report");
  const ReportFiles files = write_report(sample_evaluation(), dir, false);
  EXPECT_EQ(files.note, "");
  const std::vector<std::string> expected = {"experiment-unified-new-actions.png", "experiment-stitched-fgla.png",
                                             "experiment-per-material__small.h5_.png",
                                             "experiment-unified-new-actions-vs-mean-spectrum.png",
                                             "experiment-unified-new-actions-vs-expected-ar.png", "examples.png", "latents.png",
                                             "speed.png"};
  EXPECT_EQ(files.charts.size(), expected.size());
  for (const std::string& name : expected) {
    EXPECT_TRUE(is_png(fs::path(dir) / name)) << name;
    EXPECT_NE(std::find(files.charts.begin(), files.charts.end(), dir + "/" + name), files.charts.end()) << name;
  }
}

// PATH without gnuplot for as long as it lives.
class NoGnuplotOnPath {
 public:
  explicit NoGnuplotOnPath(const std::string& empty_dir) : saved_(std::getenv("PATH") ? std::getenv("PATH") : "") {
    setenv("PATH", empty_dir.c_str(), 1);
  }
  ~NoGnuplotOnPath() { setenv("PATH", saved_.c_str(), 1); }

 private:
  std::string saved_;
};

TEST(ReportWriter, WithoutGnuplotTheScriptsAndANoteRemain) {
  test::TempDir tmp;
  const std::string dir = tmp.file("report");
  fs::create_directory(tmp.file("empty"));
  ReportFiles files;
  {
    NoGnuplotOnPath guard(tmp.file("empty"));
    files = write_report(sample_evaluation(), dir, false);
  }
  EXPECT_NE(files.note.find("gnuplot is not installed"), std::string::npos) << files.note;
  EXPECT_TRUE(files.charts.empty());
  EXPECT_TRUE(fs::is_regular_file(fs::path(dir) / "speed.gnuplot"));
  EXPECT_FALSE(fs::exists(fs::path(dir) / "speed.png"));
  const std::string md = test::file_text(dir + "/report.md");
  EXPECT_NE(md.find("gnuplot is not installed"), std::string::npos);
  EXPECT_NE(md.find("Chart not drawn"), std::string::npos);
  EXPECT_EQ(md.find("](speed.png)"), std::string::npos);
}

TEST(ReportWriter, AnExistingFolderIsRefusedWithoutOverwriteAndKept) {
  test::TempDir tmp;
  const std::string dir = tmp.file("report");
  make_folder_with(dir, "old.txt", "the old report");
  std::string message;
  EXPECT_EQ(kind_of_failure(sample_evaluation(), dir, false, &message), Error::Kind::bad_input);
  EXPECT_NE(message.find(dir), std::string::npos) << message;
  EXPECT_NE(message.find("already exists"), std::string::npos) << message;
  EXPECT_EQ(test::file_text(dir + "/old.txt"), "the old report");
  EXPECT_FALSE(fs::exists(dir + "/report.md"));
  EXPECT_TRUE(partial_leftovers(tmp.path()).empty());
  EXPECT_TRUE(temporaries_of(dir).empty());
}

// An earlier report: every file of it listed in haptex-files.json, and one file of its own marked.
void write_old_report(const std::string& dir) {
  Evaluation old = sample_evaluation();
  old.notes.push_back("the old report");
  write_report(old, dir, false);
  ASSERT_TRUE(fs::is_regular_file(dir + "/haptex-files.json"));
}

TEST(ReportWriter, OverwriteReplacesTheOldReport) {
  test::TempDir tmp;
  const std::string dir = tmp.file("report");
  write_old_report(dir);
  const ReportFiles files = write_report(sample_evaluation(), dir + "/", true);
  EXPECT_EQ(files.directory, dir);
  EXPECT_EQ(test::file_text(dir + "/report.md").find("the old report"), std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(dir + "/report.md"));
  EXPECT_TRUE(partial_leftovers(tmp.path()).empty());
  EXPECT_TRUE(temporaries_of(dir).empty());
}

// Issue 11 point 2: overwrite replaces only what haptex wrote.
TEST(ReportWriter, OverwriteRefusesAFolderHoldingAFileItDidNotWrite) {
  test::TempDir tmp;
  const std::string dir = tmp.file("report");
  write_old_report(dir);
  make_folder_with(dir + "/mine", "notes.txt", "my notes");
  std::string message;
  EXPECT_EQ(kind_of_failure(sample_evaluation(), dir, true, &message), Error::Kind::bad_input);
  EXPECT_NE(message.find("mine"), std::string::npos) << message;
  EXPECT_EQ(test::file_text(dir + "/mine/notes.txt"), "my notes");
  EXPECT_NE(test::file_text(dir + "/report.md").find("the old report"), std::string::npos);
  make_folder_with(tmp.file("not_a_report"), "data.csv", "1,2");
  EXPECT_EQ(kind_of_failure(sample_evaluation(), tmp.file("not_a_report"), true, &message), Error::Kind::bad_input);
  EXPECT_NE(message.find("haptex-files.json"), std::string::npos) << message;
  EXPECT_EQ(test::file_text(tmp.file("not_a_report/data.csv")), "1,2");
}

TEST(ReportWriter, AFailureLeavesNoHalfReportAndKeepsTheOldOne) {
  test::TempDir tmp;
  Evaluation broken = sample_evaluation();
  broken.models[1].sha256 = "not a hash";  // results.json fails its schema after the CSVs are written
  const std::string fresh = tmp.file("fresh");
  EXPECT_EQ(kind_of_failure(broken, fresh, false), Error::Kind::failed);
  EXPECT_FALSE(fs::exists(fresh));
  EXPECT_TRUE(temporaries_of(fresh).empty());

  const std::string old = tmp.file("old");
  write_old_report(old);
  EXPECT_EQ(kind_of_failure(broken, old, true), Error::Kind::failed);
  EXPECT_NE(test::file_text(old + "/report.md").find("the old report"), std::string::npos);
  EXPECT_TRUE(partial_leftovers(tmp.path()).empty());
}

TEST(ReportWriter, AFolderOrLinkNamedLikeTheOldTemporaryIsLeftAlone) {
  test::TempDir tmp;
  const std::string dir = tmp.file("report"), thesis = tmp.file("thesis");
  make_folder_with(thesis, "chapter1.tex", "years of work");
  fs::create_directory_symlink(thesis, dir + ".partial");
  write_report(sample_evaluation(), dir, false);
  EXPECT_EQ(test::file_text(thesis + "/chapter1.tex"), "years of work");
  EXPECT_TRUE(fs::is_symlink(dir + ".partial"));
  EXPECT_TRUE(fs::exists(dir + "/report.md"));
  EXPECT_TRUE(temporaries_of(dir).empty());
}

TEST(ReportWriter, AReportAnotherRunIsWritingIsRefusedAndLeftAlone) {
  test::TempDir tmp;
  const std::string dir = tmp.file("report");
  const Temporary other = create_temporary_folder(dir);  // as the other run holds it
  make_folder_with(other.path, "speed.csv", "being written");
  std::string message;
  EXPECT_EQ(kind_of_failure(sample_evaluation(), dir, false, &message), Error::Kind::bad_input);
  EXPECT_NE(message.find("another haptex run"), std::string::npos) << message;
  EXPECT_EQ(test::file_text(other.path + "/speed.csv"), "being written");
  EXPECT_EQ(temporaries_of(dir), std::vector<std::string>{other.path});
  ::close(other.fd);
}

TEST(ReportWriter, NumbersAreFormattedForReading) {
  EXPECT_EQ(format_number(123.456), "123.5");
  EXPECT_EQ(format_number(0.5), "0.5000");
  EXPECT_EQ(format_number(-0.0125), "-0.01250");
  EXPECT_EQ(format_number(42), "42.00");
  EXPECT_EQ(format_number(1234567.0), "1.235e+06");
  EXPECT_EQ(format_number(0.000125), "1.250e-04");
  EXPECT_EQ(format_number(0), "0");
  EXPECT_EQ(format_number(-kInf), "-∞");
  EXPECT_EQ(format_number(std::nan("")), "n/a");
  EXPECT_EQ(format_p(1e-6), "1.00e-06");
  EXPECT_EQ(format_p(0.0312), "0.0312");
  EXPECT_EQ(format_p(0.5), "0.5");
  EXPECT_EQ(format_p(0), "0");
  EXPECT_EQ(csv_field("Brick, 2"), "\"Brick, 2\"");
  EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_field("plain"), "plain");
  EXPECT_EQ(csv_number(0.1), "0.1");
  EXPECT_EQ(csv_number(kInf), "inf");
}

}  // namespace
}  // namespace haptex::evaluate
