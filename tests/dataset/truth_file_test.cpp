// truth.h5 (truth/2): what generated each synthetic recording, written and read back, and every
// damaged or foreign file refused with a message naming the file, the object and the fix.
#include "dataset/truth_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>

#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/sha256.hpp"
#include "core/text/utf8.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::dataset {
namespace {
namespace fs = std::filesystem;

constexpr const char* kRerun = ". Run haptex synth again to write a new truth.h5";

// Values exact in float32, so the actions survive the file unchanged.
dataset::TruthRecording recording(int index, std::size_t samples) {
  dataset::TruthRecording r{index, std::string(64, char('a' + index)), {}, {}};
  for (std::size_t i = 0; i < samples; ++i) {
    r.speed_mm_s.push_back(0.25 * double(i));
    r.force_n.push_back(1 + 0.125 * double(i));
  }
  return r;
}

// One material of each generator. The model text is over 64 KiB, as the published models are
// (70 to 80 KB): more than an HDF5 attribute stored in its object header could hold.
dataset::Truth sample_truth() {
  const std::string xml = "<?xml version=\"1.0\"?>\n<model>\n  <!-- " + std::string(100'000, '.') + " -->\n  <mu>0.4</mu>\n</model>\n";
  dataset::MaterialTruth book{"Book", "hatt-model", xml, "", std::nullopt, {recording(0, 6), recording(1, 4)}};
  std::vector<double> spectra(3 * 2 * 100);
  for (std::size_t i = 0; i < spectra.size(); ++i) spectra[i] = 0.001 * double(i);
  dataset::MaterialTruth woven{"Woven 1", "synth-material", "", R"({"name":"Woven 1","family":"Woven"})",
                      dataset::TruthGrid{{10, 20, 40}, {0.5, 1}, spectra}, {recording(0, 5)}};
  return {10000, 0.02, {book, woven}};
}

void expect_same(const dataset::TruthRecording& a, const dataset::TruthRecording& b) {
  EXPECT_EQ(a.index, b.index);
  EXPECT_EQ(a.source_sha256, b.source_sha256);
  EXPECT_EQ(a.speed_mm_s, b.speed_mm_s);
  EXPECT_EQ(a.force_n, b.force_n);
}

void expect_same(const dataset::Truth& a, const dataset::Truth& b) {
  EXPECT_EQ(a.sample_rate_hz, b.sample_rate_hz);
  EXPECT_EQ(a.accel_noise_m_s2, b.accel_noise_m_s2);
  ASSERT_EQ(a.materials.size(), b.materials.size());
  for (std::size_t m = 0; m < a.materials.size(); ++m) {
    const dataset::MaterialTruth &x = a.materials[m], &y = b.materials[m];
    SCOPED_TRACE(x.name);
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.generator, y.generator);
    EXPECT_EQ(x.model_xml, y.model_xml);
    EXPECT_EQ(x.recipe_json, y.recipe_json);
    ASSERT_EQ(x.grid.has_value(), y.grid.has_value());
    if (x.grid) {
      EXPECT_EQ(x.grid->speeds_mm_s, y.grid->speeds_mm_s);
      EXPECT_EQ(x.grid->forces_n, y.grid->forces_n);
      EXPECT_EQ(x.grid->spectra, y.grid->spectra);
    }
    ASSERT_EQ(x.recordings.size(), y.recordings.size());
    for (std::size_t k = 0; k < x.recordings.size(); ++k) expect_same(x.recordings[k], y.recordings[k]);
  }
}

// dataset::read_truth_file's refusal: always bad input (exit code 2); the message, to compare exactly.
std::string refusal(const std::string& path) {
  try {
    dataset::read_truth_file(path);
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "read_truth_file accepted " << path;
  return "";
}

class TruthFile : public ::testing::Test {
 protected:
  // The sample truth, written, then changed by `change` (through core/h5, as a damaged copy would be).
  std::string written(const std::function<void(test::Edit&)>& change = {}, const dataset::Truth& truth = sample_truth()) {
    dataset::write_truth_file(path_, truth, "test");
    if (change) {
      test::Edit edit(path_);
      change(edit);
    }
    return path_;
  }

  test::TempDir dir_;
  std::string path_ = dir_.file("truth.h5");
};

TEST_F(TruthFile, BothGeneratorsRoundTrip) {
  const dataset::Truth truth = sample_truth();
  const dataset::Truth read = dataset::read_truth_file(written());
  expect_same(read, truth);
  ASSERT_NE(read.find("woven_1"), nullptr);
  EXPECT_EQ(read.find("woven_1")->name, "Woven 1");
  EXPECT_EQ(read.find("book"), &read.materials[0]);
  EXPECT_EQ(read.find("cork"), nullptr);
  EXPECT_DOUBLE_EQ(*read.find("woven_1")->grid->spectrum(2, 1), 0.001 * 500);

  const h5::File file = h5::File::open(path_);
  EXPECT_EQ(file.root().attr_string("haptex_format"), "truth/2");
  const h5::Group book = file.root().open_group("materials/book");
  EXPECT_EQ(book.attr_string("model_sha256"), sha256_hex(truth.materials[0].model_xml));
  EXPECT_EQ(book.open_dataset("recordings/0/speed").dtype(), "float32");
  EXPECT_EQ(book.open_dataset("recordings/0/force").attr_string("units"), "N");
  EXPECT_EQ(file.root().open_dataset("materials/woven_1/spectrum").attr_string("units"), "m/s^2");
}

TEST_F(TruthFile, APathWithQuotesBackQuotesSpacesAndNonUtf8BytesRoundTrips) {
  path_ = dir_.file("truth \"of\" 'it' `all` $(x) \xff\xfe.h5");
  expect_same(dataset::read_truth_file(written()), sample_truth());
  written([](test::Edit& e) { e.root().set_attr("haptex_format", "truth/1"); });
  // The name is shown escaped (core/error.hpp): its bytes that are not UTF-8 are written \xff.
  EXPECT_EQ(refusal(path_), text::printable(path_) + ": /@haptex_format: is truth/1, written by an older haptex: it does not record what "
                                    "generated each recording. Run haptex synth again to write truth/2");
}

TEST_F(TruthFile, RefusesWhatIsNotHdf5OrIsTruncated) {
  std::ofstream(path_) << "speed,force\n1,2\n";
  EXPECT_EQ(refusal(path_), path_ + ": not an HDF5 file. Give a file written by haptex (recordings, gelsight, dataset or model)");

  fs::remove(path_);  // --force would not replace the user's text file
  written();
  fs::resize_file(path_, fs::file_size(path_) / 2);
  const std::string message = refusal(path_);
  EXPECT_EQ(message.rfind(path_ + ": HDF5 could not open the file", 0), 0u) << message;
  EXPECT_NE(message.find("The file is truncated, damaged or not what haptex wrote there"), std::string::npos) << message;
}

TEST_F(TruthFile, RefusesOtherFormats) {
  written([](test::Edit& e) { e.root().set_attr("haptex_format", "truth/1"); });
  // The name is shown escaped (core/error.hpp): its bytes that are not UTF-8 are written \xff.
  EXPECT_EQ(refusal(path_), text::printable(path_) + ": /@haptex_format: is truth/1, written by an older haptex: it does not record what "
                                    "generated each recording. Run haptex synth again to write truth/2");
  written([](test::Edit& e) { e.root().set_attr("haptex_format", "recordings/1"); });
  EXPECT_EQ(refusal(path_), path_ + ": /@haptex_format: is 'recordings/1': a recordings file (haptex convert writes those), not a truth file "
                                    "(truth/2). Give the file haptex synth wrote");
}

TEST_F(TruthFile, RefusesMissingMembers) {
  written([](test::Edit& e) { e.remove("materials/book/recordings/0/speed"); });
  EXPECT_EQ(refusal(path_), path_ + ": /materials/book/recordings/0/speed: is missing" + kRerun);
  written([](test::Edit& e) { e.remove("materials/book@model_xml"); });
  EXPECT_EQ(refusal(path_), path_ + ": /materials/book/@model_xml: is missing" + kRerun);
  written([](test::Edit& e) { e.remove("materials/woven_1/speeds"); });  // a synthetic material without its grid
  EXPECT_EQ(refusal(path_), path_ + ": /materials/woven_1/speeds: is missing" + kRerun);
}

TEST_F(TruthFile, RefusesSpeedAndForceOfDifferentLengths) {
  written([](test::Edit& e) { e.replace<float>("materials/book/recordings/0/force", {1, 2, 3, 4}, {4}); });
  EXPECT_EQ(refusal(path_), path_ + ": /materials/book/recordings/0/force: has shape (4), expected (6): one value per speed sample" +
                                kRerun);
}

TEST_F(TruthFile, RefusesNaNInSpeed) {
  dataset::Truth truth = sample_truth();
  truth.materials[1].recordings[0].speed_mm_s[2] = std::numeric_limits<double>::quiet_NaN();
  written({}, truth);
  EXPECT_EQ(refusal(path_), path_ + ": /materials/woven_1/recordings/0/speed: value 2 is nan, expected a finite number of 0 or more up to 1e+06" +
                                kRerun);
}

// Review 9, F4: a recording's speed of 3e38 mm/s (or a force of 1e30 N) moved the oracle floor, unremarked.
TEST_F(TruthFile, RefusesASpeedOrForceNoStrokeComesNear) {
  dataset::Truth truth = sample_truth();
  truth.materials[1].recordings[0].speed_mm_s[2] = 3e38;
  written({}, truth);
  EXPECT_NE(refusal(path_).find("/materials/woven_1/recordings/0/speed: value 2 is 3e+38, expected a finite number of 0 or more up to 1e+06"),
            std::string::npos) << refusal(path_);
  truth = sample_truth();
  truth.materials[1].recordings[0].force_n[0] = 1e30;
  written({}, truth);
  EXPECT_NE(refusal(path_).find("/materials/woven_1/recordings/0/force: value 0 is 1e+30"), std::string::npos) << refusal(path_);
}

TEST_F(TruthFile, RefusesNegativeAccelNoise) {
  dataset::Truth truth = sample_truth();
  truth.accel_noise_m_s2 = -0.02;
  written({}, truth);
  EXPECT_EQ(refusal(path_), path_ + ": /@accel_noise_m_s2: is -0.02, expected a finite number of 0 or more up to 1e+06" + kRerun);
}

TEST_F(TruthFile, RefusesASpectrumOfTheWrongShape) {
  written([](test::Edit& e) { e.replace<double>("materials/woven_1/spectrum", std::vector<double>(3 * 2 * 99, 0.1), {3, 2, 99}); });
  EXPECT_EQ(refusal(path_), path_ + ": /materials/woven_1/spectrum: has shape (3, 2, 99), expected (3, 2, 100) (speeds, forces, 100 bins)" +
                                kRerun);
}

TEST_F(TruthFile, RefusesAGridThatDoesNotAscend) {
  dataset::Truth truth = sample_truth();
  truth.materials[1].grid->speeds_mm_s = {10, 40, 20};
  written({}, truth);
  EXPECT_EQ(refusal(path_), path_ + ": /materials/woven_1/speeds: value 2 is 20, not above the one before it (40): the grid's axes "
                                    "must ascend" + kRerun);
}

TEST_F(TruthFile, RefusesAnUnknownGeneratorAndADamagedModel) {
  written([](test::Edit& e) { e.group("materials/book").set_attr("generator", "magic"); });
  EXPECT_EQ(refusal(path_), path_ + ": /materials/book/@generator: is 'magic', expected hatt-model or synth-material" + kRerun);
  written([](test::Edit& e) { e.group("materials/book").set_attr("model_xml", "<model/>"); });
  EXPECT_EQ(refusal(path_), path_ + ": /materials/book/@model_sha256: is not the SHA-256 of @model_xml: the model text is damaged" +
                                kRerun);
}

TEST_F(TruthFile, RefusesAMistypedAction) {
  written([](test::Edit& e) { e.replace<double>("materials/book/recordings/1/speed", {1, 2, 3, 4}, {4}); });
  EXPECT_EQ(refusal(path_), path_ + ": /materials/book/recordings/1/speed: holds float64, expected float32" + kRerun);
}

}  // namespace
}  // namespace haptex::dataset
