#include "core/ar/texture_renderer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "convert/hatt_model_reader.hpp"
#include "core/ar/burg.hpp"
#include "core/error.hpp"
#include "tests/support/npy.hpp"

namespace haptex::ar {
namespace {

// Two AR(4) models plus two zero-variance ones on [0, 100] x [0, 2]; see ar_piecewise_model_test
// for the larger fixture.
constexpr const char* kFixture = R"(<?xml version="1.0"?>
<modelSet texture="902"><material>Renderer fixture</material><SampleRate>10000</SampleRate><mu>0.2</mu>
  <numMod>4</numMod><numTri>2</numTri><maxSpeed>100</maxSpeed><maxForce>2</maxForce>
  <speedList type="array"><value>0</value><value>100</value><value>0</value><value>100</value></speedList>
  <forceList type="array"><value>0</value><value>0</value><value>2</value><value>2</value></forceList>
  <tri type="array"><value>1</value><value>2</value><value>4</value></tri>
  <tri type="array"><value>1</value><value>4</value><value>3</value></tri>
  <numARCoeff>4</numARCoeff><numMACoeff>0</numMACoeff>
  <model><modNum>1</modNum><ARcoeff><value>1</value><value>0</value><value>0</value><value>0</value><value>0</value></ARcoeff>
    <ARlsf><value>0.4</value><value>1.0</value><value>1.6</value><value>2.4</value></ARlsf><var>0</var><speedMod>0</speedMod><forceMod>0</forceMod></model>
  <model><modNum>2</modNum><ARcoeff><value>1</value><value>0</value><value>0</value><value>0</value><value>0</value></ARcoeff>
    <ARlsf><value>0.3</value><value>0.5</value><value>1.9</value><value>2.1</value></ARlsf><var>0</var><speedMod>100</speedMod><forceMod>0</forceMod></model>
  <model><modNum>3</modNum><ARcoeff><value>1</value><value>0</value><value>0</value><value>0</value><value>0</value></ARcoeff>
    <ARlsf><value>0.2</value><value>0.7</value><value>1.3</value><value>2.8</value></ARlsf><var>0</var><speedMod>0</speedMod><forceMod>2</forceMod></model>
  <model><modNum>4</modNum><ARcoeff><value>1</value><value>0</value><value>0</value><value>0</value><value>0</value></ARcoeff>
    <ARlsf><value>0.25</value><value>0.35</value><value>1.2</value><value>1.4</value></ARlsf><var>0.8</var><speedMod>100</speedMod><forceMod>2</forceMod></model>
</modelSet>
)";

PiecewiseArModel fixture() { return PiecewiseArModel(convert::parse_hatt_model(kFixture, "renderer_fixture.xml")); }

// A stroke that sweeps speed and force through the whole region and past its edges.
void stroke(std::size_t n, std::vector<double>& speed, std::vector<double>& force) {
  speed.resize(n);
  force.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = double(i) / 10000.0;
    speed[i] = 60.0 + 70.0 * std::sin(2.0 * std::numbers::pi * 0.7 * t);
    force[i] = 1.1 + 1.3 * std::sin(2.0 * std::numbers::pi * 0.3 * t + 1.0);
  }
}

TEST(ArTextureRenderer, SameSeedSameSamples) {
  std::vector<double> speed, force;
  stroke(20000, speed, force);
  const auto first = render_texture(fixture(), speed, force, 5);
  EXPECT_EQ(first, render_texture(fixture(), speed, force, 5));
  EXPECT_NE(first, render_texture(fixture(), speed, force, 6));
  for (double v : first) ASSERT_TRUE(std::isfinite(v));
}

TEST(ArTextureRenderer, OneSampleAtATimeEqualsWholeTrajectory) {
  std::vector<double> speed, force;
  stroke(5000, speed, force);
  TextureRenderer renderer(fixture(), 8);
  std::vector<double> one_by_one;
  for (std::size_t i = 0; i < speed.size(); ++i) one_by_one.push_back(renderer.next(speed[i], force[i]));
  EXPECT_EQ(one_by_one, render_texture(fixture(), speed, force, 8));
  // reset() restarts from rest with the new seed.
  renderer.reset(8);
  EXPECT_EQ(renderer.render(speed, force), one_by_one);
}

// At a fixed operating point the renderer is plain AR synthesis with the blended model.
TEST(ArTextureRenderer, FixedPointIsArSynthesis) {
  const PiecewiseArModel model = fixture();
  const std::size_t n = 100000;
  const std::vector<double> speed(n, 80.0), force(n, 1.5);
  const auto y = render_texture(model, speed, force, 21);
  const BlendedAr blend = model.blend(80.0, 1.5);
  EXPECT_EQ(y, synthesize_ar(blend.a, blend.variance, n, 21));
  const ArFit fit = burg(y, model.order());
  for (std::size_t i = 1; i < blend.a.size(); ++i) EXPECT_NEAR(fit.a[i], blend.a[i], 0.03) << "a" << i;
  EXPECT_NEAR(fit.variance, blend.variance, 0.03 * blend.variance);
}

TEST(ArTextureRenderer, SilentWithoutForce) {
  const std::size_t n = 20000;
  const auto quiet = render_texture(fixture(), std::vector<double>(n, 80.0), std::vector<double>(n, 0.0), 2);
  const auto loud = render_texture(fixture(), std::vector<double>(n, 80.0), std::vector<double>(n, 2.0), 2);
  const auto rms = [](const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x * x;
    return std::sqrt(s / double(v.size()));
  };
  EXPECT_LT(rms(quiet), 0.02 * rms(loud));
}

TEST(ArTextureRenderer, RefusesMismatchedTrajectories) {
  TextureRenderer renderer(fixture(), 1);
  EXPECT_THROW(renderer.render(std::vector<double>(10, 1.0), std::vector<double>(9, 1.0)), Error);
  EXPECT_THROW(renderer.next(NAN, 1.0), Error);
}

TEST(ArTextureRenderer, RendersEveryHattModel) {
  const std::string shared = test::shared_data_dir();
  const std::filesystem::path dir = std::filesystem::path(shared) / "hatt" / "models";
  if (shared.empty() || !std::filesystem::is_directory(dir))
    GTEST_SKIP() << "../shared/data/hatt/models is absent: HaTT rendering skipped";
  std::vector<double> speed, force;
  stroke(10000, speed, force);
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const PiecewiseArModel model = convert::load_hatt_model(entry.path());
    std::vector<double> s = speed, f = force;
    for (double& v : s) v *= model.set().max_speed / 100.0;
    for (double& v : f) v *= model.set().max_force / 2.0;
    const auto y = render_texture(model, s, f, 3);
    double peak = 0.0;
    for (double v : y) peak = std::max(peak, std::abs(v));
    EXPECT_TRUE(std::isfinite(peak) && peak > 0.0 && peak < 1e3) << entry.path().filename() << " peak " << peak;
  }
}

}  // namespace
}  // namespace haptex::ar
