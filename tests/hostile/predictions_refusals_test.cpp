// haptex evaluate --predictions refuses what it cannot score (exit code 2, naming the file and the
// object) and writes no report then: another format, dataset, split or grid; wrong types and shapes;
// non-finite or negative values; bad compute times and signals; names the report cannot use.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>

#include <hdf5.h>

#include "core/h5/file.hpp"
#include "tests/hostile/hostile_support.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/predictions_files.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

const GridTable& grid() {
  static const GridTable g = [] {
    const TempDir dir;
    const SmallPipeline& p = small_pipeline();
    const CommandResult r = run_haptex({"windows", p.dataset, "--split", p.split, "-o", dir.file("windows.h5")});
    if (r.exit_code != 0) throw std::runtime_error("haptex windows failed: " + r.err);
    return read_grid(dir.file("windows.h5"));
  }();
  return g;
}

CommandResult evaluate(const TempDir& dir, const std::vector<std::string>& predictions) {
  const SmallPipeline& p = small_pipeline();
  std::vector<std::string> args{"evaluate", p.dataset, "--split", p.split, "--repeats", "2", "--reconstruct", "none", "-o", dir.file("report")};
  for (const std::string& argument : predictions) args.insert(args.end(), {"--predictions", argument});
  return run_haptex(args);
}

struct Case {
  std::string what;
  std::function<void(Predictions&)> change;
  std::vector<std::string> mentions;  // besides the file
};

const float kNaN = std::numeric_limits<float>::quiet_NaN();

std::vector<Case> cases() {
  const std::size_t rows = grid().rows();
  return {
      {"another format", [](Predictions& p) { p.format = "predictions/0"; }, {"/@predictions_format", "predictions/1"}},
      {"another dataset", [](Predictions& p) { p.dataset_sha256 = std::string(64, 'a'); }, {"/@dataset_sha256", "another dataset"}},
      {"another split", [](Predictions& p) { p.split_sha256 = std::string(64, 'b'); }, {"/@split_sha256", "another split"}},
      {"another grid (a row short)", [rows](Predictions& p) { p.spectra.resize((rows - 1) * 100), p.shape = {rows - 1, 100}; },
       {"/spectra", "another grid", std::to_string(rows) + " windows"}},
      {"one dimension", [rows](Predictions& p) { p.shape = {rows * 100}; }, {"/spectra", "has shape"}},
      {"99 bins", [rows](Predictions& p) { p.spectra.resize(rows * 99), p.shape = {rows, 99}; }, {"/spectra", "100-bin"}},
      {"three dimensions", [rows](Predictions& p) { p.shape = {rows, 10, 10}; }, {"/spectra", "has shape"}},
      {"NaN", [](Predictions& p) { p.spectra[250] = kNaN; }, {"/spectra", "row 2, bin 50", "nan"}},
      {"infinity", [](Predictions& p) { p.spectra[3] = std::numeric_limits<float>::infinity(); }, {"/spectra", "row 0, bin 3", "inf"}},
      {"a negative amplitude", [](Predictions& p) { p.spectra[101] = -0.5f; }, {"/spectra", "row 1, bin 1", "clamp"}},
      {"an amplitude beyond any vibration", [](Predictions& p) { p.spectra[7] = 3e37f; }, {"/spectra", "row 0, bin 7", "1e6"}},
      {"a NaN compute time", [](Predictions& p) { p.query_seconds = std::nan(""); }, {"/@query_seconds", "above 0"}},
      {"a negative compute time", [](Predictions& p) { p.query_seconds = -1; }, {"/@query_seconds", "above 0"}},
      {"a signal too few", [](Predictions& p) { p.signals.pop_back(); }, {"/signals", "one per grid section"}},
      {"a signal too short", [](Predictions& p) { p.signals[0].resize(p.signals[0].size() - 1); }, {"/signals/0", "samples"}},
      {"a signal far too long", [](Predictions& p) { p.signals[1].resize(50'000'000); }, {"/signals/1", "samples"}},
      {"a NaN sample", [](Predictions& p) { p.signals[0][7] = kNaN; }, {"/signals/0", "sample 7"}},
      {"a sample beyond any vibration", [](Predictions& p) { p.signals[1][3] = -2e6f; }, {"/signals/1", "sample 3"}},
  };
}

Predictions good() {
  Predictions p = perfect_predictions(grid());
  for (const GridSpan& s : grid_spans(grid())) p.signals.push_back(std::vector<float>(s.covered, 0.1f));
  return p;
}

TEST(PredictionsRefusals, EachBrokenFileIsRefusedNamingTheFileAndTheObject) {
  for (const Case& c : cases()) {
    SCOPED_TRACE(c.what);
    const TempDir dir;
    Predictions p = good();
    c.change(p);
    const std::string file = dir.file("p'r \"`x`\".h5");
    write_predictions(file, p);
    std::vector<std::string> mentions = c.mentions;
    mentions.push_back(file);
    expect_refusal(evaluate(dir, {"mine=" + file}), mentions);
    EXPECT_FALSE(fs::exists(dir.file("report")));
  }
}

// The untouched file (under the same hostile name) is scored: the refusals above are each one change.
// A source of several lines stays one CSV row, or gnuplot would read the speed chart's rows wrong.
TEST(PredictionsRefusals, TheGoodFileUnderAHostileNameIsScored) {
  const TempDir dir;
  const std::string file = dir.file("p'r \"`x`\".h5");
  Predictions p = good();
  p.source = "made\nby `me`\r\n\"twice\"";
  write_predictions(file, p);
  const CommandResult r = evaluate(dir, {"mine=" + file});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir.file("report/experiment-stitched-external-mine.csv")));
  const std::string speed = file_bytes(dir.file("report/speed.csv"));
  EXPECT_NE(speed.find("made by `me`"), std::string::npos) << speed;
  EXPECT_EQ(speed.find('\r'), std::string::npos) << speed;
}

// Puts /spectra of `file` behind an external link to /spectra in `target`.
bool link_spectra(const std::string& file, const std::string& target) {
  h5::File f = h5::File::open(file, true);
  const bool made = H5Lcreate_external(target.c_str(), "/spectra", f.root().id(), "spectra", H5P_DEFAULT, H5P_DEFAULT) >= 0;
  f.close();
  return made;
}

// Links are refused: an external link would score data the file's SHA-256 in the report does not cover.
TEST(PredictionsRefusals, LinksInPlaceOfDataAreRefused) {
  const TempDir dir;
  write_predictions(dir.file("target.h5"), good());
  Predictions p = good();
  p.shape.clear();
  const std::string file = dir.file("linked.h5");
  write_predictions(file, p);
  ASSERT_TRUE(link_spectra(file, dir.file("target.h5")));
  expect_refusal(evaluate(dir, {"x=" + file}), {file, "/spectra", "link"});
  EXPECT_FALSE(fs::exists(dir.file("report")));
  // Review 5: an external link to a FIFO hung evaluate, which followed it while looking /spectra up.
  ASSERT_EQ(::mkfifo(dir.file("fifo").c_str(), 0600), 0);
  const std::string to_fifo = dir.file("to_fifo.h5");
  write_predictions(to_fifo, p);
  ASSERT_TRUE(link_spectra(to_fifo, dir.file("fifo")));
  expect_refusal(evaluate(dir, {"x=" + to_fifo}), {to_fifo, "/spectra", "external link"});
}

TEST(PredictionsRefusals, AttributesOfAnotherTypeAreRefusedWithThisFilesFix) {
  const TempDir dir;
  const std::string file = dir.file("p.h5");
  Predictions p = good();
  p.query_seconds.reset();
  write_predictions(file, p);
  {
    h5::File f = h5::File::open(file, true);
    f.root().set_attr("query_seconds", "fast");
    f.close();
  }
  expect_refusal(evaluate(dir, {"x=" + file}), {file, "/@query_seconds", "one number", "hdf5-layout.md"});
}

TEST(PredictionsRefusals, FilesThatAreNoPredictionsAreRefused) {
  const TempDir dir;
  std::ofstream(dir.file("text.h5")) << "not HDF5";
  write_predictions(dir.file("whole.h5"), good());
  const std::string whole = file_bytes(dir.file("whole.h5"));
  std::ofstream(dir.file("truncated.h5"), std::ios::binary) << whole.substr(0, whole.size() / 2);
  {  // An HDF5 file of another kind.
    h5::File f = h5::File::create(dir.file("other.h5"));
    f.root().set_attr("haptex_format", "windows/1");
    f.close();
  }
  for (const auto& [name, mention] : std::vector<std::pair<std::string, std::string>>{
           {"text.h5", ""}, {"truncated.h5", ""}, {"other.h5", "/@predictions_format"}}) {
    SCOPED_TRACE(name);
    const std::string file = dir.file(name);
    expect_refusal(evaluate(dir, {"x=" + file}), mention.empty() ? std::vector<std::string>{file} : std::vector<std::string>{file, mention});
    EXPECT_FALSE(fs::exists(dir.file("report")));
  }
}

// Review 31, F2: a damaged predictions file was told "is not an HDF5 file haptex can read ... write the
// file as the layout says", hiding the place and what HDF5 found; only a file that is not HDF5 is told so.
TEST(PredictionsRefusals, DamageIsToldAsDamageNotAsAnotherLayout) {
  const TempDir dir;
  write_predictions(dir.file("whole.h5"), good());
  const std::string damaged = dir.file("damaged.h5"), text = dir.file("text.h5");
  copy_with_damaged_attribute(dir.file("whole.h5"), "predictions_format", damaged);
  std::ofstream(text) << "not HDF5";
  const CommandResult r = evaluate(dir, {"x=" + damaged});
  expect_refusal(r, {damaged, "damaged"});
  EXPECT_EQ(r.err.find("lays it out"), std::string::npos) << r.err;
  expect_refusal(evaluate(dir, {"x=" + text}), {text, "is not an HDF5 file", "lays it out"});
  EXPECT_FALSE(fs::exists(dir.file("report")));
}

TEST(PredictionsRefusals, SpectraOfAnotherTypeAreRefused) {
  const TempDir dir;
  for (const std::string type : {"int32", "string"}) {
    SCOPED_TRACE(type);
    const std::string file = dir.file(type + ".h5");
    Predictions p = good();
    p.shape.clear();
    write_predictions(file, p);  // no /spectra yet: written below in the wrong type
    {
      h5::File f = h5::File::open(file, true);
      if (type == "int32")
        f.root().write_array<std::int32_t>("spectra", std::vector<std::int32_t>(grid().rows() * 100, 1), {grid().rows(), 100});
      else
        f.root().write_strings("spectra", std::vector<std::string>(grid().rows(), "1.0"));
      f.close();
    }
    expect_refusal(evaluate(dir, {"x=" + file}), {file, "/spectra", "float32 or float64"});
  }
}

TEST(PredictionsRefusals, NamesTheReportCannotUseAreRefused) {
  const TempDir dir;
  const std::string file = dir.file("p.h5");
  write_predictions(file, good());
  for (const std::string& argument : std::vector<std::string>{
           "=" + file, "knn", "knn=", "a b=" + file, "it's=" + file, "`x`=" + file, "\"q\"=" + file, "x-vs-y=" + file,
           "-dash=" + file, std::string(41, 'n') + "=" + file, "caf\xff=" + file}) {
    SCOPED_TRACE(argument);
    expect_refusal(evaluate(dir, {argument}), {"--predictions"});
    EXPECT_FALSE(fs::exists(dir.file("report")));
  }
  const CommandResult binary = evaluate(dir, {"caf\xff=" + file});
  EXPECT_EQ(binary.err.find('\xff'), std::string::npos) << "the message echoes a byte that is not UTF-8";
  // Review 8: control and text-reordering characters were shown as '?', so the wrong one could not be told.
  expect_refusal(evaluate(dir, {"x\ny=" + file}), {"'x\\x0ay'"});
  expect_refusal(evaluate(dir, {"r\u202eevil=" + file}), {"'r\\u202eevil'"});
  expect_refusal(evaluate(dir, {"same=" + file, "same=" + file}), {"named 'same'"});
  expect_refusal(evaluate(dir, {"knn=" + file, "KNN=" + file}), {"alike but for case"});
  // The report folder may not be one of the inputs.
  const SmallPipeline& p = small_pipeline();
  expect_refusal(run_haptex({"evaluate", p.dataset, "--split", p.split, "--predictions", "x=" + file, "-o", file, "--force"}), {file});
  EXPECT_EQ(file_bytes(file).substr(1, 3), "HDF");
  expect_refusal(run_haptex({"evaluate", p.dataset, "--split", p.split, "-o", dir.file("report")}), {"--predictions"});
}

}  // namespace
}  // namespace haptex::test
