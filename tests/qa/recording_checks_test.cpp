// Each recording check fires, alone, on a copy of the good recordings file with one defect.
#include <gtest/gtest.h>

#include <cmath>

#include "core/signal/butterworth.hpp"
#include "core/signal/dft321.hpp"
#include "core/signal/sosfilt.hpp"
#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "qa/integrity.hpp"
#include "qa/run_qa.hpp"
#include "tests/support/mutations.hpp"
#include "tests/qa/qa_fixture.hpp"

namespace haptex::test {
namespace {

const std::string kRecording = "materials/sandpaper_1/recordings/0";
const std::string kOther = "materials/woven_1/recordings/0";

class RecordingsMutation : public ::testing::Test {
 protected:
  qa::Report qa() const { return qa::run_qa({file_, {}}); }
  TempDir dir_;  // before file_: members are made in this order
  std::string file_ = copy_into(dir_, small_pipeline().recordings, "recordings.h5");
};

TEST_F(RecordingsMutation, MissingDatasetIsLayoutRequired) {
  Edit(file_).remove(kRecording + "/speed_lp");
  const qa::Report r = qa();
  expect_only(r, "layout.required");
  EXPECT_NE(r.find("layout.required")->message.find("/" + kRecording + "/speed_lp: missing"), std::string::npos)
      << r.find("layout.required")->message;
  // The filter check could not look at it, and says so.
  EXPECT_NE(r.find("filter.lowpass")->message.find("not checked"), std::string::npos);
}

TEST_F(RecordingsMutation, MissingRootAttributeIsLayoutRequired) {
  Edit(file_).remove("@created_utc");
  expect_only(qa(), "layout.required");
}

TEST_F(RecordingsMutation, Float64AccelerationIsLayoutDtype) {
  {
    Edit e(file_);
    const auto accel = e.dataset(kRecording + "/accel").read<double>();
    e.replace<double>(kRecording + "/accel", accel, {accel.size()});
  }
  const qa::Report r = qa();
  expect_only(r, "layout.dtype");
  EXPECT_NE(r.find("layout.dtype")->message.find("dtype float64, expected float32"), std::string::npos);
}

TEST_F(RecordingsMutation, IntegerSampleRateAttributeIsLayoutDtype) {
  Edit(file_).group(kRecording).set_attr("sample_rate_hz", std::int64_t(10000));
  expect_only(qa(), "layout.dtype");
}

// Review 17, F7: an array of one string is one value, as every reader takes it; an array of two is not.
TEST_F(RecordingsMutation, AnAttributeIsOneValueWhenItsArrayHoldsOne) {
  const std::string created = h5::File::open(file_).root().attr_string("created_utc");
  {
    Edit e(file_);
    e.remove("@created_utc");
    e.write_fixed_strings("@created_utc", {created}, true);
  }
  EXPECT_EQ(qa().find("layout.dtype")->status, qa::Status::pass) << qa().find("layout.dtype")->message;
  {
    Edit e(file_);
    e.remove("@created_utc");
    e.write_fixed_strings("@created_utc", {created, created});
  }
  const qa::Report r = qa();
  expect_only(r, "layout.dtype");
  EXPECT_NE(r.find("layout.dtype")->message.find("/@created_utc: holds 2 values, expected one string"), std::string::npos)
      << r.find("layout.dtype")->message;
}

TEST_F(RecordingsMutation, TwoColumnPositionIsLayoutShape) {
  {
    Edit e(file_);
    const auto position = e.dataset(kRecording + "/position").read<float>();
    std::vector<float> xy;
    for (std::size_t i = 0; i < position.size(); i += 3) xy.insert(xy.end(), {position[i], position[i + 1]});
    e.replace<float>(kRecording + "/position", xy, {xy.size() / 2, 2});
  }
  const qa::Report r = qa();
  expect_only(r, "layout.shape");
  EXPECT_NE(r.find("layout.shape")->message.find("expected (30000, 3) = (N, 3)"), std::string::npos)
      << r.find("layout.shape")->message;
}

TEST_F(RecordingsMutation, AccelerationInGIsLayoutUnits) {
  Edit(file_).dataset(kRecording + "/accel").set_attr("units", "g");
  const qa::Report r = qa();
  expect_only(r, "layout.units");
  EXPECT_NE(r.find("layout.units")->message.find("units 'g', expected 'm/s^2'"), std::string::npos);
}

TEST_F(RecordingsMutation, NaNInOneAxisIsSignalNan) {
  Edit(file_).change_floats(kRecording + "/accel_xyz", [](std::vector<float>& v) { v[3 * 100 + 1] = NAN; });
  const qa::Report r = qa();
  expect_only(r, "signal.nan");
  EXPECT_NE(r.find("signal.nan")->message.find("accel_xyz has 1 NaN/Inf values, the first at sample 100"),
            std::string::npos)
      << r.find("signal.nan")->message;
}

TEST_F(RecordingsMutation, InfInForceIsSignalNan) {
  Edit(file_).change_floats(kRecording + "/force_tangential", [](std::vector<float>& v) { v[7] = INFINITY; });
  expect_only(qa(), "signal.nan");
}

TEST_F(RecordingsMutation, FiveKilohertzIsSignalSampleRate) {
  {
    Edit e(file_);
    h5::Group g = e.group(kRecording);
    g.set_attr("sample_rate_hz", 5000.0);
    g.set_attr("duration_s", double(g.attr_int("samples")) / 5000.0);  // consistent with its own rate
  }
  expect_only(qa(), "signal.sample_rate");
}

TEST_F(RecordingsMutation, WrongDurationIsSignalDuration) {
  Edit(file_).group(kRecording).set_attr("duration_s", 6.0);
  const qa::Report r = qa();
  expect_only(r, "signal.duration");
  EXPECT_NE(r.find("signal.duration")->message.find("30000 samples at 10000 Hz last 3 s"), std::string::npos)
      << r.find("signal.duration")->message;
}

TEST_F(RecordingsMutation, TwoSecondRecordingIsSignalShortAWarning) {
  constexpr std::size_t kKeep = 20000;
  {
    Edit e(file_);
    h5::Group g = e.group(kRecording);
    for (const auto& name : g.children()) {
      const h5::Dataset d = g.open_dataset(name);
      h5::Shape shape = d.shape();
      const std::size_t columns = shape.size() == 2 ? shape[1] : 1;
      std::vector<float> values = d.read<float>();
      values.resize(kKeep * columns);
      shape[0] = kKeep;
      e.replace<float>(kRecording + "/" + name, values, shape);
    }
    g.set_attr("samples", std::int64_t(kKeep));
    g.set_attr("duration_s", double(kKeep) / 10000.0);
  }
  const qa::Report r = qa();
  expect_only(r, "signal.short");
  EXPECT_EQ(r.find("signal.short")->severity, qa::Severity::warning);
  EXPECT_EQ(r.verdict(), "warnings");
  EXPECT_EQ(r.errors(), 0);
}

// accel made again from the (edited) axes, as convert would make it.
void reduce_again(Edit& e, const std::string& recording) {
  const std::vector<float> xyz = e.dataset(recording + "/accel_xyz").read<float>();
  std::vector<double> axis[3];
  for (std::size_t i = 0; i < xyz.size(); ++i) axis[i % 3].push_back(xyz[i]);
  const std::vector<double> reduced = signal::dft321(axis[0], axis[1], axis[2]);
  e.change_floats(recording + "/accel", [&](std::vector<float>& v) { v.assign(reduced.begin(), reduced.end()); });
}

TEST_F(RecordingsMutation, RailedAxisIsSignalClipping) {
  {
    Edit e(file_);
    e.change_floats(kRecording + "/accel_xyz", [](std::vector<float>& v) {
      float peak = 0;
      for (std::size_t i = 0; i < v.size(); i += 3) peak = std::max(peak, std::abs(v[i]));
      const float rail = 0.3f * peak;  // an accelerometer range far too small for the stroke
      for (std::size_t i = 0; i < v.size(); i += 3) v[i] = std::clamp(v[i], -rail, rail);
    });
    reduce_again(e, kRecording);
  }
  const qa::Report r = qa();
  expect_only(r, "signal.clipping");
  EXPECT_NE(r.find("signal.clipping")->message.find("accel_xyz[:, 0]"), std::string::npos) << r.find("signal.clipping")->message;
}

TEST_F(RecordingsMutation, ForceInGramsIsSignalForceRange) {
  {
    Edit e(file_);
    for (const char* name : {"/force_normal", "/force_normal_lp"})
      e.change_floats(kRecording + name, [](std::vector<float>& v) {
        for (float& x : v) x *= 1000 / 9.81f;
      });
  }
  const qa::Report r = qa();
  expect_only(r, "signal.force_range");
  EXPECT_NE(r.find("signal.force_range")->message.find("above 20 N"), std::string::npos);
}

TEST_F(RecordingsMutation, SpeedInMetresPerSecondIsSignalSpeedRange) {
  {
    Edit e(file_);
    for (const char* name : {"/speed", "/speed_lp"})
      e.change_floats(kRecording + name, [](std::vector<float>& v) {
        for (float& x : v) x /= 1000;
      });
  }
  const qa::Report r = qa();
  expect_only(r, "signal.speed_range");
  EXPECT_NE(r.find("signal.speed_range")->message.find("never reaching 5 mm/s"), std::string::npos);
}

TEST_F(RecordingsMutation, AccelerationLowPassedAt50HzIsSignalAccelSpectrum) {
  {
    Edit e(file_);
    e.change_floats(kRecording + "/accel_xyz", [](std::vector<float>& v) {
      const auto sos = signal::butter_lowpass_hz(4, 50, 10000);
      for (std::size_t c = 0; c < 3; ++c) {
        std::vector<double> axis;
        for (std::size_t i = c; i < v.size(); i += 3) axis.push_back(v[i]);
        const auto filtered = signal::sosfiltfilt(sos, axis);
        for (std::size_t i = 0; i < filtered.size(); ++i) v[3 * i + c] = float(filtered[i]);
      }
    });
    reduce_again(e, kRecording);
  }
  expect_only(qa(), "signal.accel_spectrum");
}

TEST_F(RecordingsMutation, UnfilteredLowPassIsFilterLowpass) {
  {
    Edit e(file_);
    const auto raw = e.dataset(kRecording + "/force_normal").read<float>();
    e.change_floats(kRecording + "/force_normal_lp", [&](std::vector<float>& v) { v = raw; });
  }
  const qa::Report r = qa();
  expect_only(r, "filter.lowpass");
  EXPECT_NE(r.find("filter.lowpass")->message.find("force_normal_lp"), std::string::npos);
}

TEST_F(RecordingsMutation, LowPassedRawSpeedIsFilterRaw) {
  {
    Edit e(file_);
    const auto lp = e.dataset(kRecording + "/speed_lp").read<float>();
    e.change_floats(kRecording + "/speed", [&](std::vector<float>& v) { v = lp; });
  }
  const qa::Report r = qa();
  expect_only(r, "filter.raw");
  EXPECT_NE(r.find("filter.raw")->message.find("/speed: only"), std::string::npos) << r.find("filter.raw")->message;
}

// Review 8, #9: a recording stating a 1e300 Hz low-pass passed qa, merge and align.
TEST_F(RecordingsMutation, AnotherStatedFilterIsFilterStated) {
  Edit(file_).group(kRecording).set_attr("lowpass_cutoff_hz", 1e300);
  Edit(file_).group(kOther).set_attr("accel_reduction_hop", std::int64_t(512));
  const qa::Report r = qa();
  expect_only(r, "filter.stated");
  const std::string& message = r.find("filter.stated")->message;
  EXPECT_NE(message.find("/" + kRecording + ": lowpass_cutoff_hz is 1e+300, not 20"), std::string::npos) << message;
  EXPECT_NE(message.find("(and 1 more)"), std::string::npos) << message << ": the other recording's hop of 512";
  ASSERT_EQ(r.find("filter.stated")->where.size(), 2u);
  EXPECT_NE(r.find("filter.stated")->where[1].find(kOther), std::string::npos) << r.find("filter.stated")->where[1];
  EXPECT_THROW(qa::require_integrity(h5::File::open(file_).root(), dataset::Kind::recordings), Error) << "merge and align refuse it too";
}

// Review 9, F5: a dataset declaring a chunk far larger than itself (4 GiB for 30 000 samples) passed
// qa "clean" after inflating it, and merge copied it. 32 MiB stands in for it here.
TEST_F(RecordingsMutation, AChunkLargerThanItsDatasetIsLayoutLinks) {
  {
    Edit e(file_);
    const std::vector<float> accel = e.dataset(kRecording + "/accel").read<float>();
    e.remove(kRecording + "/accel");
    const hsize_t dims[1] = {accel.size()}, unlimited[1] = {H5S_UNLIMITED}, chunk[1] = {hsize_t(8) << 20};
    h5::Handle space(H5Screate_simple(1, dims, unlimited)), list(H5Pcreate(H5P_DATASET_CREATE));
    H5Pset_chunk(list.get(), 1, chunk);
    H5Pset_deflate(list.get(), 4);
    h5::Handle d(H5Dcreate2(e.group(kRecording).id(), "accel", H5T_NATIVE_FLOAT, space.get(), H5P_DEFAULT, list.get(), H5P_DEFAULT));
    ASSERT_GE(H5Dwrite(d.get(), H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, accel.data()), 0);
    e.dataset(kRecording + "/accel").set_attr("units", std::string("m/s^2"));
  }
  const qa::Report r = qa();
  const auto* links = r.find("layout.links");
  ASSERT_EQ(links->status, qa::Status::fail) << links->message;
  EXPECT_NE(links->message.find("/" + kRecording + "/accel: is stored in chunks of 32 MiB"), std::string::npos) << links->message;
  EXPECT_THROW(qa::require_integrity(h5::File::open(file_).root(), dataset::Kind::recordings), Error) << "merge and align refuse it too";
}

TEST_F(RecordingsMutation, CopiedRecordingIsRecordingsDuplicate) {
  Edit(file_).copy(kRecording, "materials/woven_1/recordings/1");
  const qa::Report r = qa();
  expect_only(r, "recordings.duplicate");
  EXPECT_NE(r.find("recordings.duplicate")->message.find("the same source file"), std::string::npos);
}

TEST_F(RecordingsMutation, SameSourceHashIsRecordingsDuplicate) {
  {
    Edit e(file_);
    e.group(kOther).set_attr("source_sha256", e.group(kRecording).attr_string("source_sha256"));
  }
  expect_only(qa(), "recordings.duplicate");
}

// A window whose reduced signal lost or gained energy against the axes, as a whole-recording DFT321
// of a turning tool leaves them (issue 12, section 0).
TEST_F(RecordingsMutation, AWindowOffTheAxesEnergyIsSignalReductionEnergy) {
  Edit(file_).change_floats(kRecording + "/accel", [](std::vector<float>& v) {
    for (std::size_t i = 2000; i < 3000; ++i) v[i] *= 0.5f;
  });
  const qa::Report r = qa();
  expect_only(r, "signal.reduction_energy");
  EXPECT_NE(r.find("signal.reduction_energy")->message.find("window at sample 2000 holds 0.25"), std::string::npos)
      << r.find("signal.reduction_energy")->message;
}

TEST_F(RecordingsMutation, SameSamplesUnderAnotherSourceIsRecordingsDuplicate) {
  {
    Edit e(file_);
    e.copy(kRecording, "materials/woven_1/recordings/1");
    e.group("materials/woven_1/recordings/1").set_attr("source_sha256", std::string(64, 'f'));
  }
  const qa::Report r = qa();
  expect_only(r, "recordings.duplicate");
  EXPECT_NE(r.find("recordings.duplicate")->message.find("the same acceleration samples"), std::string::npos);
}

}  // namespace
}  // namespace haptex::test
