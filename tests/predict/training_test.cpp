#include "predict/train.hpp"

#include <gtest/gtest.h>

#include "dataset/window.hpp"
#include "predict/predictor.hpp"
#include "predict/spectrum_training.hpp"
#include "tests/predict/synthetic_problem.hpp"

namespace haptex::predict {
namespace {

TrainOptions small_options(Variant variant, unsigned threads = 0) {
  TrainOptions o;
  o.variant = variant;
  o.latent = 8;
  o.texture_hidden = 16;
  o.predictor_hidden = 32;
  o.batch = 64;
  o.max_epochs = 150;
  o.patience = 15;
  o.texture_max_epochs = 30;
  o.per_material_max_epochs = 60;
  o.learning_rate = 3e-3f;
  o.seed = 3;
  o.threads = threads;
  return o;
}

double val_distance(const Model& m) {
  if (m.variant == Variant::unified) return m.metrics["spectrum"]["val_distance"];
  double sum = 0;
  for (const auto& [id, r] : m.metrics["spectrum"].items()) sum += r["val_distance"].get<double>();
  return sum / double(m.metrics["spectrum"].size());
}

// Distance of the model's prediction for the test windows' true (noise-free) spectra: the model
// should recover the law behind the noisy targets.
double test_error_against_truth(const Model& m, const TrainingData& data) {
  Predictor p(m);
  double sum = 0, count = 0;
  for (std::size_t i = 0; i < data.materials.size(); ++i) {
    const TextureCode code = m.variant == Variant::unified ? p.encode_descriptor(data.materials[i].images[2][0]) : p.material_code(int(i));
    for (std::size_t c : data.materials[i].rows[2]) {
      std::vector<float> predicted(kTargetBins);
      p.predict(code, std::span<const float>(data.action.col(Eigen::Index(c)).data(), kActionValues), predicted);
      const std::vector<float> truth = test::synthetic_truth(int(i), data.action(9, Eigen::Index(c)), data.action(19, Eigen::Index(c)));
      double d = 0;
      for (std::size_t k = 0; k < kTargetBins; ++k) d += std::pow(predicted[std::size_t(k)] - truth[std::size_t(k)], 2);
      sum += std::sqrt(d), ++count;
    }
  }
  return sum / count;
}

TEST(Training, UnifiedModelLearnsTheMaterialsAndTheActions) {
  const TrainingData data = test::synthetic_problem();
  const Model m = train_model(data, small_options(Variant::unified));
  EXPECT_DOUBLE_EQ(m.metrics["texture"]["val_accuracy"].get<double>(), 1.0);
  const double baseline = m.metrics["mean_spectrum_baseline"]["val_distance"];
  EXPECT_LT(val_distance(m), 0.6 * baseline) << "model " << val_distance(m) << " vs mean spectrum " << baseline;
  // On the test presses and windows, against the noise-free law behind the noisy targets.
  const double error = test_error_against_truth(m, data);
  EXPECT_LT(error, 0.25 * baseline) << error;
}

// Targets scattered by half their value, as single windows' spectra are: the model trained on them as
// they are and averaged over 3 bins, each scored against the noise-free law.
struct SmoothingComparison {
  double raw = 0, smoothed = 0;
  Model model;  // the one trained on smoothed targets
};
SmoothingComparison compare_smoothing(Variant variant) {
  const TrainingData data = test::synthetic_problem({.windows = 300, .noise = 0.5});
  TrainOptions o = small_options(variant);
  o.target_smoothing = 1;
  SmoothingComparison c;
  c.raw = test_error_against_truth(train_model(data, o), data);
  o.target_smoothing = 3;
  c.model = train_model(data, o);
  c.smoothed = test_error_against_truth(c.model, data);
  return c;
}

TEST(Training, SmoothedTargetsBringTheModelNearerTheTruth) {
  const SmoothingComparison c = compare_smoothing(Variant::unified);
  EXPECT_EQ(c.model.config["target_smoothing"], 3);
  // Its training distance is to the windows' own spectra, as the validation distance is, not to what it fitted.
  const double train = c.model.metrics["spectrum"]["train_distance"], val = c.model.metrics["spectrum"]["val_distance"];
  EXPECT_GT(train, 0.85 * val) << train << " against " << val;
  EXPECT_LT(c.smoothed, 0.95 * c.raw) << "smoothed " << c.smoothed << " against " << c.raw;
}

// The per-material models fit the smoothed targets too.
TEST(Training, PerMaterialModelsFitSmoothedTargetsToo) {
  const SmoothingComparison c = compare_smoothing(Variant::per_material);
  EXPECT_LT(c.smoothed, 0.95 * c.raw) << "smoothed " << c.smoothed << " against " << c.raw;
}

TEST(Training, PerMaterialModelsLearnTheActions) {
  const TrainingData data = test::synthetic_problem();
  const Model m = train_model(data, small_options(Variant::per_material));
  ASSERT_EQ(m.nets.size(), data.materials.size());
  EXPECT_LT(val_distance(m), 0.6 * m.metrics["mean_spectrum_baseline"]["val_distance"].get<double>());
  EXPECT_FALSE(m.metrics.contains("texture"));
}

bool same_weights(const Mlp& a, const Mlp& b) {
  if (a.layers.size() != b.layers.size()) return false;
  for (std::size_t i = 0; i < a.layers.size(); ++i)
    if (a.layers[i].weight != b.layers[i].weight || a.layers[i].bias != b.layers[i].bias) return false;
  return true;
}

// Same seed, same weights, bit for bit, whatever the number of threads; another seed, other weights.
TEST(Training, SameSeedGivesIdenticalWeightsOnAnyThreadCount) {
  test::SyntheticSpec spec;
  spec.windows = 200;
  const TrainingData data = test::synthetic_problem(spec);
  TrainOptions o = small_options(Variant::unified, 1);
  o.max_epochs = o.texture_max_epochs = 5;
  const Model one = train_model(data, o);
  o.threads = 3;
  const Model three = train_model(data, o);
  EXPECT_TRUE(same_weights(one.texture, three.texture));
  EXPECT_TRUE(same_weights(one.nets[0].action, three.nets[0].action));
  EXPECT_TRUE(same_weights(one.nets[0].predictor, three.nets[0].predictor));
  o.seed = 4;
  const Model other = train_model(data, o);
  EXPECT_FALSE(same_weights(one.nets[0].predictor, other.nets[0].predictor));
}

// Balancing: a window's weight is inverse to its material's mean squared target norm over the
// training windows, and the training windows' weights average 1. A material 10 times louder weighs
// 100 times less; validation windows take their material's weight; a column of no material weighs 1.
TEST(Training, BalanceWeightsMakeEveryMaterialCountAlike) {
  Eigen::MatrixXf targets(2, 6);
  targets << 1, 1, 10, 10, 1, 7,
             0, 0, 0, 0, 0, 7;
  const std::vector<int> material{0, 0, 1, 1, 0, -1};
  const std::vector<std::size_t> train{0, 1, 2, 3};
  const std::vector<float> w = material_balance_weights(targets, material, train, 2);
  ASSERT_EQ(w.size(), 6u);
  EXPECT_NEAR(w[0] / w[2], 100.0, 1e-3);
  EXPECT_FLOAT_EQ(w[0], w[1]);
  EXPECT_FLOAT_EQ(w[4], w[0]);  // a validation window of material 0
  EXPECT_FLOAT_EQ(w[5], 1.0f);
  EXPECT_NEAR((w[0] + w[1] + w[2] + w[3]) / 4, 1.0, 1e-6);
  // Each material's weighted squared targets are then alike.
  EXPECT_NEAR(w[0] * 1.0, w[2] * 100.0, 1e-4);
}

// Stage 2 keeps the epoch with the best validation distance weighted as the loss is (every
// material alike), and reports the plain distance beside it; the two differ when materials differ
// in level, as the synthetic ones do.
TEST(Training, StageTwoStopsOnTheWeightedValidationDistance) {
  test::SyntheticSpec spec;
  spec.windows = 200;
  const TrainingData data = test::synthetic_problem(spec);
  TrainOptions o = small_options(Variant::unified);
  o.max_epochs = 12, o.texture_max_epochs = 5;
  std::vector<EpochReport> reports;
  const Model m = train_model(data, o, [&](const EpochReport& r) {
    if (r.stage == "spectrum") reports.push_back(r);
  });
  ASSERT_FALSE(reports.empty());
  double best = 1e300, best_plain = 0;
  bool differ = false;
  for (const EpochReport& r : reports) {
    ASSERT_GE(r.val_weighted, 0.0);
    EXPECT_EQ(r.best, r.val_weighted < best) << "epoch " << r.epoch;
    if (r.best) best = r.val_weighted, best_plain = r.val_loss;
    differ |= std::abs(r.val_weighted - r.val_loss) > 1e-6 * r.val_loss;
  }
  EXPECT_TRUE(differ);
  EXPECT_DOUBLE_EQ(m.metrics["spectrum"]["val_distance"].get<double>(), best_plain);
}

TEST(Training, EarlyStoppingKeepsTheBestEpoch) {
  EarlyStopping s(2);
  EXPECT_TRUE(s.improved(3.0));
  EXPECT_TRUE(s.improved(2.0));
  EXPECT_FALSE(s.improved(2.5));
  EXPECT_FALSE(s.stop());
  EXPECT_FALSE(s.improved(2.0));
  EXPECT_TRUE(s.stop());
  EXPECT_EQ(s.best_epoch(), 2);
  EXPECT_DOUBLE_EQ(s.best(), 2.0);
}

}  // namespace
}  // namespace haptex::predict
