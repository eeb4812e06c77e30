#include "predict/predictor.hpp"

#include <gtest/gtest.h>

#include <Eigen/QR>

#include <cmath>
#include <filesystem>
#include <limits>

#include "core/error.hpp"
#include "core/temporary_name.hpp"
#include "dataset/window.hpp"
#include "predict/model_file.hpp"
#include "predict/train.hpp"
#include "tests/predict/synthetic_problem.hpp"
#include "tests/support/allocation_counter.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::predict {
namespace {

const Model& trained(Variant variant) {
  static const Model models[2] = {[] {
                                    TrainOptions o;
                                    o.latent = 8, o.texture_hidden = 16, o.max_epochs = 5, o.texture_max_epochs = 5;
                                    return train_model(test::synthetic_problem(), o);
                                  }(),
                                  [] {
                                    TrainOptions o;
                                    o.variant = Variant::per_material, o.per_material_max_epochs = 5;
                                    return train_model(test::synthetic_problem(), o);
                                  }()};
  return models[variant == Variant::unified ? 0 : 1];
}

std::vector<float> action(float force, float speed) {
  std::vector<float> a(kActionValues, force);
  std::fill(a.begin() + 10, a.end(), speed);
  return a;
}

TEST(Predictor, SingleQueriesMatchTheBatchPathAndDoNotAllocate) {
  {
    const test::CountAllocations counter;
    Eigen::VectorXf counted(100);
    counted.setZero();
    ASSERT_GT(counter.count(), 0u) << "the allocation counter does not see Eigen's allocations";
  }
  for (Variant v : {Variant::unified, Variant::per_material}) {
    Predictor p(trained(v));
    const TextureCode code = p.material_code(1);
    Eigen::MatrixXf actions(kActionValues, 3);
    const float points[3][2] = {{0.5f, 50}, {1.5f, 150}, {2.5f, 280}};
    for (int c = 0; c < 3; ++c) actions.col(c) = Eigen::Map<const Eigen::VectorXf>(action(points[c][0], points[c][1]).data(), kActionValues);
    const Eigen::MatrixXf batch = p.predict_batch(code, actions);
    std::vector<float> out(kTargetBins);
    for (int c = 0; c < 3; ++c) {
      const std::vector<float> a = action(points[c][0], points[c][1]);
      const test::CountAllocations counter;
      EXPECT_FALSE(p.predict(code, a, out));
      EXPECT_EQ(counter.count(), 0u) << "predict() allocated";
      for (Eigen::Index k = 0; k < Eigen::Index(kTargetBins); ++k) EXPECT_NEAR(out[std::size_t(k)], batch(k, c), 1e-5f * (1 + std::abs(batch(k, c))));
    }
  }
}

// Several views of one press give the code of their mean latent; none is refused.
TEST(Predictor, ViewsOfAPressAreEncodedByTheirMeanLatent) {
  const Predictor p(trained(Variant::unified));
  const TrainingData data = test::synthetic_problem();
  const auto& views = data.materials[1].images[0];
  ASSERT_GE(views.size(), 3u);
  const std::vector<std::vector<float>> three(views.begin(), views.begin() + 3);
  Eigen::VectorXf mean = Eigen::VectorXf::Zero(p.model().latent_size());
  for (const auto& d : three) mean += p.encode_descriptor(d).image_latent / 3.0f;
  const TextureCode code = p.encode_descriptors(three);
  EXPECT_LT((code.image_latent - mean).norm(), 1e-5f * (1 + mean.norm()));
  EXPECT_LT((code.latent - p.recognised(mean)).norm(), 1e-5f * (1 + mean.norm()));
  EXPECT_LT((code.first_layer - p.encode_latent(p.recognised(mean)).first_layer).norm(), 1e-4f * (1 + code.first_layer.norm()));
  EXPECT_GT((code.image_latent - p.encode_descriptor(three[0]).image_latent).norm(), 0.0f);
  EXPECT_THROW(p.encode_descriptors({}), Error);
}

// A press is recognised: its latent is the materials' mean latents weighted by the classifier's
// probabilities (a distribution), most by the material the classifier ranks first.
TEST(Predictor, APressIsRecognisedAsTheMaterialsItResembles) {
  const Predictor p(trained(Variant::unified));
  const Model& m = p.model();
  const TrainingData data = test::synthetic_problem();
  for (std::size_t i = 0; i < data.materials.size(); ++i) {
    const TextureCode code = p.encode_descriptor(data.materials[i].images[2][0]);  // a test press
    // Recognised latents lie in the convex hull of the material latents: solve for the weights.
    const Eigen::VectorXf weights = m.material_latents.colPivHouseholderQr().solve(code.latent);
    EXPECT_NEAR(weights.sum(), 1.0f, 1e-3f) << i;
    EXPECT_GT(weights.minCoeff(), -1e-3f) << i;
    const DenseLayer& head = m.classifier.layers.at(0);
    Eigen::Index best, ranked_first;
    weights.maxCoeff(&best);
    (head.weight * code.image_latent + head.bias).maxCoeff(&ranked_first);
    EXPECT_EQ(best, ranked_first) << "the test press of material " << i;
  }
}

// Outside the training range (and for garbage in), outputs stay finite and non-negative, and say so.
TEST(Predictor, OutOfRangeInputsAreSaturatedAndFlagged) {
  Predictor p(trained(Variant::unified));
  const TextureCode code = p.material_code(0);
  std::vector<float> out(kTargetBins), in_range(kTargetBins);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const float cases[][2] = {{1e6f, 1e9f}, {0, 0}, {100, 1}, {nan, 100}, {1, inf}, {-5, -5}};
  for (const auto& c : cases) {
    EXPECT_TRUE(p.predict(code, action(c[0], c[1]), out)) << c[0] << " N, " << c[1] << " mm/s";
    for (float a : out) {
      EXPECT_TRUE(std::isfinite(a));
      EXPECT_GE(a, 0.0f);
    }
  }
  // Beyond the range the answer is the edge's answer.
  const Normalisation& n = p.model().normalisation;
  p.predict(code, action(n.force_max, n.speed_max), in_range);
  p.predict(code, action(1e6f, 1e9f), out);
  EXPECT_EQ(out, in_range);
}

TEST(ModelFile, RoundTripGivesIdenticalPredictions) {
  const test::TempDir dir;
  for (Variant v : {Variant::unified, Variant::per_material}) {
    const std::string path = dir.file(variant_name(v) + ".h5");
    write_model(trained(v), path, false, "test");
    const Model back = read_model(path);
    EXPECT_EQ(back.material_ids, trained(v).material_ids);
    EXPECT_EQ(back.metrics, trained(v).metrics);
    Predictor a(trained(v)), b(back);
    std::vector<float> x(kTargetBins), y(kTargetBins);
    for (int m = 0; m < 4; ++m) {
      a.predict(a.material_code(m), action(1.0f + 0.3f * float(m), 120), x);
      b.predict(b.material_code(m), action(1.0f + 0.3f * float(m), 120), y);
      EXPECT_EQ(x, y);
    }
    EXPECT_THROW(write_model(trained(v), path, false, "test"), Error);  // exists, no overwrite
  }
}

TEST(ModelFile, OtherFilesAreRefusedWithTheirName) {
  const test::TempDir dir;
  const std::string path = dir.file("not_a_model.h5");
  write_model(trained(Variant::unified), path, false, "test");
  {
    // A model whose predictor no longer fits its action encoder.
    Model broken = trained(Variant::unified);
    broken.nets[0].predictor.layers[0].weight.conservativeResize(Eigen::NoChange, 5);
    write_model(broken, dir.file("broken.h5"), false, "test");
  }
  try {
    read_model(dir.file("broken.h5"));
    FAIL() << "a broken model was read";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("broken.h5"), std::string::npos) << e.what();
  }
}

// Recognition needs a classifier from the latent to the model's materials: one that does not fit is
// refused on load, naming it, before any press could reach it.
TEST(ModelFile, AClassifierThatDoesNotFitIsRefused) {
  const test::TempDir dir;
  Model m = trained(Variant::unified);
  DenseLayer& head = m.classifier.layers.at(0);
  head.weight.conservativeResize(head.weight.rows() - 1, Eigen::NoChange);
  head.bias.conservativeResize(head.bias.size() - 1);
  write_model(m, dir.file("fewer.h5"), false, "test");
  try {
    read_model(dir.file("fewer.h5"));
    FAIL() << "a classifier for fewer materials was read";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input);
    EXPECT_NE(std::string(e.what()).find("/classifier"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("fewer.h5"), std::string::npos) << e.what();
  }
}

// Low-passed force rings slightly below zero after a stroke's turn (the 60 HaTT-driven materials' model
// has force_min = -0.0003 N): a range end below zero is fine, a reversed or infinite range is not.
TEST(ModelFile, ATrainingRangeMayDipBelowZeroButNotReverse) {
  const test::TempDir dir;
  Model m = trained(Variant::unified);
  m.normalisation.force_min = -0.0003f;
  write_model(m, dir.file("ringing.h5"), false, "test");
  EXPECT_FLOAT_EQ(read_model(dir.file("ringing.h5")).normalisation.force_min, -0.0003f);
  m.normalisation.speed_min = m.normalisation.speed_max + 1;
  write_model(m, dir.file("reversed.h5"), false, "test");
  EXPECT_THROW(read_model(dir.file("reversed.h5")), Error);
}

// Issue 11 point 3: a diverged training (NaN or infinite weights) writes no model at all.
TEST(ModelFile, ADivergedModelIsNotWritten) {
  const test::TempDir dir;
  for (const float bad : {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()}) {
    Model diverged = trained(Variant::unified);
    diverged.nets[0].predictor.layers[1].bias[7] = bad;
    try {
      write_model(diverged, dir.file("diverged.h5"), false, "test");
      ADD_FAILURE() << "a model holding " << bad << " was written";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("/nets/0/predictor/layers/1/bias"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("--learning-rate"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(dir.file("diverged.h5")));
    EXPECT_TRUE(temporaries_of(dir.file("diverged.h5")).empty());
  }
}

}  // namespace
}  // namespace haptex::predict
