#include "synth/gelsight_presses.hpp"

#include <gtest/gtest.h>

#include <set>

#include "tests/support/temp_dir.hpp"
#include "tests/synth/press_frames.hpp"

namespace haptex::synth {
namespace {

// The default 15 mm field of view on a 240 x 180 image: the default press geometry, 16 x fewer pixels.
RendererOptions small_sensor() {
  RendererOptions options;
  options.width = 240;
  options.height = 180;
  return options;
}

SurfaceRecipe recipe(double rms_um, double correlation_mm, Pattern pattern = Pattern::none, double pattern_um = 0) {
  SurfaceRecipe r;
  r.rms_um = rms_um;
  r.correlation_mm = correlation_mm;
  r.pattern = pattern;
  r.pattern_height_um = pattern_um;
  r.pattern_period_mm = 1.2;
  return r;
}

// From nearly polished to pebbled: the peak must be found on the faintest and the roughest.
const std::vector<std::pair<std::string, SurfaceRecipe>>& materials() {
  static const std::vector<std::pair<std::string, SurfaceRecipe>> list = {
      {"Polished", recipe(0.6, 0.5)},
      {"Sandpaper", recipe(14, 0.06)},
      {"Woven", recipe(5, 0.1, Pattern::weave, 60)},
      {"Pebbled", recipe(30, 0.5)},
  };
  return list;
}

HeightField field_of(const SurfaceRecipe& r) { return make_height_field(r, 17, 256, 16.0); }

struct WrittenPress {
  PressSidecar sidecar;
  std::vector<cv::Mat> frames;  // as OpenCV decodes them
};

std::vector<WrittenPress> write_and_read(const SurfaceRecipe& r, const std::string& material, std::uint64_t seed,
                                         const test::TempDir& dir, const RendererOptions& options = small_sensor()) {
  const GelSightRenderer renderer(field_of(r), options);
  std::vector<WrittenPress> presses;
  for (const PressSidecar& sidecar : write_material_presses(renderer, dir.path().string(), material, seed, "test")) {
    const PressSidecar on_disk = read_press_sidecar(press_sidecar_path(dir.path().string(), sidecar.press));
    presses.push_back({on_disk, test::read_press_frames(press_video_path(dir.path().string(), sidecar.press))});
  }
  return presses;
}

TEST(GelSightPresses, DeterministicForASeed) {
  test::TempDir first, second, other;
  const GelSightRenderer renderer(field_of(materials()[2].second), small_sensor());
  MaterialPressOptions two;
  two.presses = 2;
  write_material_presses(renderer, first.path().string(), "Woven", 5, "haptex synth test", two);
  write_material_presses(renderer, second.path().string(), "Woven", 5, "haptex synth test", two);
  write_material_presses(renderer, other.path().string(), "Woven", 6, "haptex synth test", two);
  const auto a = test::tree_contents(first.path()), b = test::tree_contents(second.path());
  ASSERT_EQ(a.size(), 4u);  // two press videos and their sidecars
  EXPECT_TRUE(a == b) << "two runs with one seed wrote different bytes";
  EXPECT_FALSE(a == test::tree_contents(other.path()));
}

TEST(GelSightPresses, FivePressesAtDifferentPlacesReadBack) {
  test::TempDir dir;
  const auto presses = write_and_read(materials()[1].second, "Sandpaper", 3, dir);
  ASSERT_EQ(presses.size(), 5u);
  std::set<std::pair<double, double>> places;
  for (const WrittenPress& p : presses) {
    EXPECT_EQ(int(p.frames.size()), p.sidecar.frames);
    EXPECT_GE(p.sidecar.frames, 31);
    EXPECT_EQ(p.sidecar.fps, 30);
    EXPECT_EQ(p.sidecar.material, "Sandpaper");
    for (const cv::Mat& frame : p.frames) {
      EXPECT_EQ(frame.size(), cv::Size(240, 180));
      EXPECT_EQ(frame.type(), CV_8UC3);
    }
    ASSERT_TRUE(p.sidecar.location_mm.has_value());
    places.insert({(*p.sidecar.location_mm)[0], (*p.sidecar.location_mm)[1]});
  }
  EXPECT_EQ(places.size(), 5u);
}

TEST(GelSightPresses, SidecarPeakIsTheFrameMostUnlikeTheFirst) {
  for (const auto& [name, surface] : materials()) {
    test::TempDir dir;
    for (const WrittenPress& p : write_and_read(surface, name, 11, dir)) {
      SCOPED_TRACE(name + " press " + std::to_string(p.sidecar.press));
      ASSERT_EQ(int(p.frames.size()), p.sidecar.frames);
      EXPECT_EQ(test::frame_most_unlike_first(p.frames), p.sidecar.peak_frame);
    }
  }
}

TEST(GelSightPresses, QuietFramesDifferByNoiseAndDriftOnly) {
  for (const auto& [name, surface] : materials()) {
    test::TempDir dir;
    for (const WrittenPress& p : write_and_read(surface, name, 23, dir)) {
      SCOPED_TRACE(name + " press " + std::to_string(p.sidecar.press));
      double quiet = 0;
      for (int f = 0; f < p.sidecar.frames; ++f) {
        if (f >= p.sidecar.contact_first && f <= p.sidecar.contact_last) continue;
        const double difference = test::mean_abs_difference(p.frames[std::size_t(f)], p.frames[0]);
        EXPECT_LT(difference, 1.5) << "no-contact frame " << f;
        quiet = std::max(quiet, difference);
      }
      const double peak = test::mean_abs_difference(p.frames[std::size_t(p.sidecar.peak_frame)], p.frames[0]);
      // Even a polished surface shows where the gel touches it; a textured one shows much more.
      EXPECT_GT(peak, (name == "Polished" ? 1.7 : 3.0) * quiet);
    }
  }
}

TEST(GelSightPresses, DefaultSizeVideoReadsBack) {
  test::TempDir dir;
  const GelSightRenderer renderer(make_height_field(materials()[2].second, 4), RendererOptions{});
  MaterialPressOptions one;
  one.presses = 1;
  const PressSidecar sidecar = write_material_presses(renderer, dir.path().string(), "Woven", 8, "test", one)[0];
  const auto frames = test::read_press_frames(press_video_path(dir.path().string(), 0));
  ASSERT_EQ(int(frames.size()), sidecar.frames);
  EXPECT_EQ(frames[0].size(), cv::Size(960, 720));
  EXPECT_EQ(sidecar.width, 960);
  EXPECT_EQ(sidecar.height, 720);
  EXPECT_EQ(test::frame_most_unlike_first(frames), sidecar.peak_frame);
}

}  // namespace
}  // namespace haptex::synth
