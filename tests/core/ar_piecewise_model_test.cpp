#include "core/ar/piecewise_model.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "convert/hatt_model_reader.hpp"
#include "core/ar/lsf.hpp"
#include "core/ar/poles.hpp"
#include "core/error.hpp"
#include "tests/support/ar_fixture.hpp"
#include "tests/support/npy.hpp"

namespace haptex::ar {
namespace {

PiecewiseArModel fixture() { return test::ar_fixture(); }

std::vector<std::filesystem::path> hatt_model_files() {
  std::vector<std::filesystem::path> files;
  const std::string shared = test::shared_data_dir();
  const std::filesystem::path dir = std::filesystem::path(shared) / "hatt" / "models";
  if (shared.empty() || !std::filesystem::is_directory(dir)) return files;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    if (entry.path().extension() == ".xml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  return files;
}

// Random points over the modelled rectangle and well beyond it (negative, past the maxima), the
// exact edges, the corners and every vertex.
std::vector<std::array<double, 2>> probe_points(const ModelSet& set, std::uint64_t seed, int random_count) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> s(-0.2 * set.max_speed, 1.5 * set.max_speed);
  std::uniform_real_distribution<double> f(-0.2 * set.max_force, 1.5 * set.max_force);
  std::vector<std::array<double, 2>> points;
  for (int i = 0; i < random_count; ++i) points.push_back({s(rng), f(rng)});
  for (double fs : {0.0, 0.02, 0.05, 0.5, 1.0, 1.0001, 3.0})
    for (double ff : {0.0, 0.02, 0.05, 0.5, 1.0, 1.0001, 3.0}) points.push_back({fs * set.max_speed, ff * set.max_force});
  for (std::size_t v = 0; v < set.speed_list.size(); ++v) points.push_back({set.speed_list[v], set.force_list[v]});
  return points;
}

// The property the LSF blend exists for: every pole of the blended filter strictly inside |z| = 1.
double worst_pole_radius(const PiecewiseArModel& model, std::uint64_t seed, int random_count) {
  double worst = 0.0;
  for (const auto& [speed, force] : probe_points(model.set(), seed, random_count)) {
    const BlendedAr blend = model.blend(speed, force);
    const double radius = max_pole_radius(blend.a);
    EXPECT_LT(radius, 1.0) << model.set().source << " at speed " << speed << ", force " << force;
    worst = std::max(worst, radius);
  }
  return worst;
}

TEST(ArPiecewiseModel, FixtureBlendIsStableEverywhere) {
  const double worst = worst_pole_radius(fixture(), 1, 2000);
  EXPECT_GT(worst, 0.99);  // the probe did reach the near-unit-circle models
}

// The fixture is hard enough to matter: halfway between models 3 and 4 the averaged coefficients
// have a pole outside the unit circle, the averaged LSFs do not.
TEST(ArPiecewiseModel, FixtureNeedsTheLsfBlend) {
  const PiecewiseArModel model = fixture();
  const auto& a3 = model.set().models[2].ar_coeff;
  const auto& a4 = model.set().models[3].ar_coeff;
  std::vector<double> averaged(a3.size());
  for (std::size_t i = 0; i < a3.size(); ++i) averaged[i] = 0.5 * (a3[i] + a4[i]);
  EXPECT_GT(max_pole_radius(averaged), 1.0);
  const BlendedAr blend = model.blend(50.0, 2.0);
  EXPECT_LT(max_pole_radius(blend.a), 1.0);
}

TEST(ArPiecewiseModel, HattBlendIsStableEverywhere) {
  const auto files = hatt_model_files();
  if (files.empty()) GTEST_SKIP() << "../shared/data/hatt/models is absent: HaTT stability property skipped";
  double worst = 0.0;
  std::uint64_t seed = 100;
  for (const auto& file : files) worst = std::max(worst, worst_pole_radius(convert::load_hatt_model(file), ++seed, 300));
  std::printf("HaTT blended filters: largest pole radius %.9f over %zu files\n", worst, files.size());
}

TEST(ArPiecewiseModel, ExactVertexGivesThatModel) {
  const PiecewiseArModel model = fixture();
  for (std::size_t v = 0; v < 4; ++v) {
    const Barycentric b = model.locate(model.set().speed_list[v], model.set().force_list[v]);
    double weight_of_v = 0.0;
    for (std::size_t k = 0; k < 3; ++k)
      if (b.vertex[k] == v) weight_of_v += b.weight[k];
    EXPECT_DOUBLE_EQ(weight_of_v, 1.0) << "vertex " << v;
  }
  // (100, 2) is a vertex the clamp leaves alone: the blend is model 4 itself.
  const BlendedAr at4 = model.blend(100.0, 2.0);
  EXPECT_EQ(at4.lsf, model.set().models[3].ar_lsf);
  EXPECT_EQ(at4.variance, 0.5);
  for (std::size_t i = 0; i < at4.a.size(); ++i) EXPECT_NEAR(at4.a[i], model.set().models[3].ar_coeff[i], 1e-11);
}

TEST(ArPiecewiseModel, BarycentricWeightsReproduceThePoint) {
  const PiecewiseArModel model = fixture();
  const auto& set = model.set();
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> s(0.0, 100.0), f(0.0, 2.0);
  for (int i = 0; i < 500; ++i) {
    const double speed = s(rng), force = f(rng);
    const Barycentric b = model.locate(speed, force);
    double sum = 0.0, x = 0.0, y = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_GE(b.weight[k], 0.0);
      sum += b.weight[k];
      x += b.weight[k] * set.speed_list[b.vertex[k]];
      y += b.weight[k] * set.force_list[b.vertex[k]];
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);
    EXPECT_NEAR(x, speed, 1e-10);
    EXPECT_NEAR(y, force, 1e-12);
    // Below the diagonal from (0, 0) to (100, 2) is triangle 1 (models 1, 2, 4), above it triangle 2.
    if (std::abs(force - speed / 50.0) > 1e-9) {
      EXPECT_EQ(b.triangle, force < speed / 50.0 ? 0u : 1u);
    }
  }
  const Barycentric centroid = model.locate(200.0 / 3.0, 2.0 / 3.0);  // of models 1, 2, 4
  EXPECT_EQ(centroid.triangle, 0u);
  for (double w : centroid.weight) EXPECT_NEAR(w, 1.0 / 3.0, 1e-14);
}

TEST(ArPiecewiseModel, OutsidePointsStayConvex) {
  const PiecewiseArModel model = fixture();
  for (const auto& [speed, force] : std::vector<std::array<double, 2>>{{-50, 1}, {150, 3}, {50, -1}, {1e6, 1e6}}) {
    const Barycentric b = model.locate(speed, force);
    double sum = 0.0;
    for (double w : b.weight) {
      EXPECT_GE(w, 0.0);
      sum += w;
    }
    EXPECT_NEAR(sum, 1.0, 1e-14);
  }
}

// The toolkit's saturation (AccSynthHashTable::HashAndInterp2).
TEST(ArPiecewiseModel, ClampsLikeTheToolkit) {
  const PiecewiseArModel model = fixture();
  EXPECT_EQ(model.clamp(150.0, 5.0), (std::array<double, 2>{99.99, 1.99}));
  EXPECT_EQ(model.clamp(100.0, 2.0), (std::array<double, 2>{100.0, 2.0}));
  EXPECT_EQ(model.clamp(0.04, 0.01), (std::array<double, 2>{0.0001, 0.0001}));
  EXPECT_EQ(model.clamp(-3.0, -1.0), (std::array<double, 2>{0.0001, 0.0001}));
  EXPECT_EQ(model.clamp(0.05, 0.05), (std::array<double, 2>{0.05, 0.05}));
  EXPECT_EQ(model.clamp(42.0, 1.25), (std::array<double, 2>{42.0, 1.25}));
  EXPECT_THROW(model.clamp(NAN, 1.0), Error);
  EXPECT_THROW(model.clamp(1.0, INFINITY), Error);
  // Beyond the maxima the blend is the one just inside them.
  const BlendedAr far = model.blend(1e4, 1e4), edge = model.blend(99.99, 1.99);
  EXPECT_EQ(far.a, edge.a);
  EXPECT_EQ(far.variance, edge.variance);
}

TEST(ArPiecewiseModel, VarianceVanishesOnTheZeroEdges) {
  const PiecewiseArModel model = fixture();
  // The clamp puts zero force at 0.0001 N: the variance is that sliver of model 4's 0.5.
  EXPECT_LT(model.blend(50.0, 0.0).variance, 1e-4);
  EXPECT_LT(model.blend(0.0, 1.0).variance, 1e-5);
  EXPECT_NEAR(model.blend(100.0, 1.0).variance, 0.25, 1e-12);  // halfway up the speed = max edge
}

TEST(ArPiecewiseModel, RefusesInconsistentSets) {
  const ModelSet good = convert::parse_hatt_model(test::kArFixtureXml, "fixture.xml");
  const auto expect_error = [](ModelSet set, const std::string& fragment) {
    try {
      PiecewiseArModel model(std::move(set));
      ADD_FAILURE() << "no error; expected one mentioning " << fragment;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("fixture.xml"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  ModelSet bad = good;
  std::swap(bad.models[2].ar_lsf[1], bad.models[2].ar_lsf[2]);
  expect_error(bad, "model 3");
  bad = good;
  bad.models[1].variance = -1.0;
  expect_error(bad, "var");
  bad = good;
  bad.models[0].speed = 5.0;
  expect_error(bad, "speedMod");
  bad = good;
  bad.triangles[1] = {0, 1, 1};
  expect_error(bad, "no area");
  bad = good;
  bad.triangles[0][2] = 7;
  expect_error(bad, "outside");
  bad = good;
  bad.models[3].ar_lsf.pop_back();
  expect_error(bad, "AR order");
  bad = good;
  bad.num_ma_coeff = 2;
  expect_error(bad, "ARMA");
}

}  // namespace
}  // namespace haptex::ar
