#include "convert/convert_recordings.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "convert/preprocess.hpp"
#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/signal/fft.hpp"
#include "core/temporary_name.hpp"
#include "convert/input_limits.hpp"
#include "tests/support/no_free_descriptor.hpp"
#include "tests/support/sample_recording.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::convert {
namespace {

using test::SampleRecordingSpec;
using test::TempDir;

void write_sample(const TempDir& dir, const std::string& name, const std::string& material, std::uint64_t seed) {
  SampleRecordingSpec spec;
  spec.material = material;
  spec.seed = seed;
  spec.seconds = 1.0;
  test::write_text_file(dir.file(name), test::sample_recording_xml(spec));
}

// Share of a signal's energy (mean removed) above a frequency, from its Hann-windowed spectrum
// (the window keeps leakage from the strong low-frequency stroke out of the high bins).
double energy_share_above(const std::vector<float>& x, double hz) {
  std::vector<double> v(x.begin(), x.end());
  double mean = 0;
  for (double s : v) mean += s / double(v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    v[i] = (v[i] - mean) * (0.5 - 0.5 * std::cos(2 * M_PI * double(i) / double(v.size())));
  std::vector<std::complex<double>> X(v.size() / 2 + 1);
  signal::real_fft<double>(v.size()).forward(v, X);
  double above = 0, total = 0;
  for (std::size_t k = 1; k < X.size(); ++k) {
    const double e = std::norm(X[k]);
    total += e;
    if (double(k) * 10000.0 / double(v.size()) > hz) above += e;
  }
  return above / total;
}

TEST(ConvertRecordings, WritesTheDocumentedLayout) {
  TempDir in, out;
  write_sample(in, "canvas_a.xml", "Sample Canvas", 1);
  const std::string output = out.file("recordings.h5");
  const ConvertResult result = convert_recordings({in.path().string()}, output, {});
  ASSERT_EQ(result.recordings.size(), 1u);

  const h5::Group root = h5::File::open(output).root();
  EXPECT_EQ(root.attr_string("haptex_format"), "recordings/1");
  EXPECT_FALSE(root.attr_string("haptex_version").empty());
  const h5::Group material = root.open_group("materials").open_group("sample_canvas");
  EXPECT_EQ(material.attr_string("name"), "Sample Canvas");
  const h5::Group rec = material.open_group("recordings").open_group("0");
  EXPECT_EQ(rec.attr_double("sample_rate_hz"), 10000.0);
  EXPECT_EQ(rec.attr_double("lowpass_cutoff_hz"), 20.0);
  EXPECT_EQ(rec.attr_int("lowpass_order"), 4);
  EXPECT_EQ(rec.attr_string("source_sha256").size(), 64u);
  for (const char* name : {"accel", "force_normal", "force_normal_lp", "speed", "speed_lp", "force_tangential"}) {
    const h5::Dataset d = rec.open_dataset(name);
    EXPECT_EQ(d.shape(), (h5::Shape{10000})) << name;
    EXPECT_EQ(d.dtype(), "float32") << name;
    EXPECT_TRUE(d.has_attr("units")) << name;
  }
  EXPECT_EQ(rec.open_dataset("accel_xyz").shape(), (h5::Shape{10000, 3}));
  EXPECT_EQ(rec.open_dataset("position").shape(), (h5::Shape{10000, 3}));
  EXPECT_EQ(rec.open_dataset("accel").attr_string("units"), "m/s^2");
  EXPECT_EQ(rec.open_dataset("speed_lp").attr_string("units"), "mm/s");
}

TEST(ConvertRecordings, LowPassRemovesRippleAndKeepsRawSignals) {
  TempDir in, out;
  write_sample(in, "a.xml", "Canvas", 3);
  const std::string output = out.file("r.h5");
  convert_recordings({in.file("a.xml")}, output, {});
  const h5::Group rec = h5::File::open(output).root().open_group("materials").open_group("canvas")
                            .open_group("recordings").open_group("0");
  // The sample force carries an 85 Hz ripple and the speed a 120 Hz one (tests/support/sample_recording.cpp).
  EXPECT_GT(energy_share_above(rec.open_dataset("force_normal").read<float>(), 40), 1e-4);
  EXPECT_LT(energy_share_above(rec.open_dataset("force_normal_lp").read<float>(), 40), 1e-7);
  EXPECT_GT(energy_share_above(rec.open_dataset("speed").read<float>(), 40), 1e-4);
  EXPECT_LT(energy_share_above(rec.open_dataset("speed_lp").read<float>(), 40), 1e-7);
}

TEST(ConvertRecordings, Dft321KeepsTheEnergyOfTheThreeAxes) {
  TempDir in, out;
  write_sample(in, "a.xml", "Canvas", 4);
  const std::string output = out.file("r.h5");
  convert_recordings({in.file("a.xml")}, output, {});
  const h5::Group rec = h5::File::open(output).root().open_group("materials").open_group("canvas")
                            .open_group("recordings").open_group("0");
  const auto accel = rec.open_dataset("accel").read<float>();
  const auto xyz = rec.open_dataset("accel_xyz").read<float>();
  double one = 0, three = 0;
  for (float a : accel) one += double(a) * a;
  for (float a : xyz) three += double(a) * a;
  EXPECT_NEAR(one / three, 1.0, 1e-4);
}

TEST(ConvertRecordings, SeveralFilesPerMaterialBecomeNumberedRecordings) {
  TempDir in, out;
  write_sample(in, "book_1.xml", "Book", 1);
  write_sample(in, "book_2.xml", "Book", 2);
  write_sample(in, "brick.xml", "Brick 2", 3);
  const std::string output = out.file("r.h5");
  const ConvertResult result = convert_recordings({in.path().string()}, output, {});
  ASSERT_EQ(result.recordings.size(), 3u);
  const h5::Group materials = h5::File::open(output).root().open_group("materials");
  EXPECT_EQ(materials.children(), (std::vector<std::string>{"book", "brick_2"}));
  EXPECT_EQ(materials.open_group("book").open_group("recordings").children(), (std::vector<std::string>{"0", "1"}));
  EXPECT_EQ(materials.open_group("book").open_group("recordings").open_group("1").attr_string("source_file"),
            in.file("book_2.xml"));
}

TEST(ConvertRecordings, SpellingsOfOneNameAreOneMaterialAndNamelessOnesAreRefused) {
  TempDir in, out;
  write_sample(in, "a.xml", "Brick 2", 1);
  write_sample(in, "b.xml", "brick-2", 2);
  const std::string output = out.file("r.h5");
  convert_recordings({in.path().string()}, output, {});
  const h5::Group brick = h5::File::open(output).root().open_group("materials").open_group("brick_2");
  EXPECT_EQ(brick.attr_string("name"), "Brick 2");  // the first spelling
  EXPECT_EQ(brick.open_group("recordings").children().size(), 2u);

  TempDir odd;
  write_sample(odd, "c.xml", "\u2014 !", 3);  // a dash and a bang: no letter
  try {
    convert_recordings({odd.file("c.xml")}, out.file("odd.h5"), {});
    FAIL() << "a material without an id was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find(odd.file("c.xml")), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("no letter or digit"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(out.file("odd.h5")));
}

TEST(ConvertRecordings, AnyBadFileLeavesNoOutput) {
  TempDir in, out;
  write_sample(in, "a.xml", "Book", 1);
  test::write_text_file(in.file("b.xml"), "<recordedData><material>Book</material>");
  const std::string output = out.file("r.h5");
  EXPECT_THROW(convert_recordings({in.path().string()}, output, {}), Error);
  EXPECT_FALSE(std::filesystem::exists(output));
  EXPECT_TRUE(temporaries_of(output).empty());
}

TEST(ConvertRecordings, DirectoryWithoutRecordingsIsRefused) {
  TempDir in, out;
  EXPECT_THROW(expand_inputs({in.path().string()}), Error);
  EXPECT_THROW(expand_inputs({in.file("missing.xml")}), Error);
}

// Review 25, F3: out of file descriptors, a good recording "could not be read completely. Check the disk
// and permissions" (exit 2); the limit is the machine's: exit 1 naming it.
TEST(ConvertRecordings, OutOfDescriptorsIsTheLimitNotTheFile) {
  const TempDir dir;
  { std::ofstream(dir.file("rig_0.csv")) << "time_s,accelX\n0,1\n"; }
  try {
    const test::NoFreeDescriptor none;
    read_whole_file(dir.file("rig_0.csv"), 1 << 20);
    FAIL() << "read without a descriptor";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::failed) << e.what();
    EXPECT_NE(std::string(e.what()).find("ulimit -n"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_whole_file(dir.file("rig_0.csv"), 1 << 20).size(), std::filesystem::file_size(dir.file("rig_0.csv")));
}

}  // namespace
}  // namespace haptex::convert
