// The predictor's speed on one core (issue 6): a single query of predict::Predictor::predict (the
// haptic loop's per-millisecond call; goal under 5 us), predict_batch on 1000 actions, encoding a
// 960 x 720 press (texture descriptor and texture encoder), and the per-material variant's single
// query. The models have train_options.hpp's default sizes and random weights: the time does not
// depend on the weights' values. `bench_predict --export-model FILE` writes the unified model, so
// bench/torch_forward.py times the same network in PyTorch.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstring>
#include <opencv2/imgproc.hpp>
#include <random>
#include <vector>

#include "bench/run_benchmarks.hpp"
#include "predict/model_file.hpp"
#include "dataset/window.hpp"
#include "predict/predictor.hpp"
#include "predict/train_options.hpp"

namespace {

using namespace haptex::predict;

constexpr int kMaterials = 60;

std::vector<int> sizes(std::initializer_list<int> list) { return list; }

SpectrumNet spectrum_net(const TrainOptions& o, int latent, std::uint64_t seed) {
  std::vector<int> action{kActionValues}, predictor;
  for (int i = 0; i < o.action_layers; ++i) action.push_back(o.action_hidden);
  predictor.push_back(latent + action.back());
  for (int i = 0; i < o.predictor_layers; ++i) predictor.push_back(o.predictor_hidden);
  predictor.push_back(kTargetBins);
  return {make_mlp(action, Activation::relu, Activation::relu, seed),
          make_mlp(predictor, Activation::relu, Activation::softplus, seed + 1)};
}

// A model as train_model builds it (texture_training.cpp, spectrum_training.cpp), with plausible
// normalisation statistics.
Model make_model(Variant variant, const TrainOptions& o) {
  Model m;
  m.variant = variant;
  const auto d = Eigen::Index(descriptor_length(m.descriptor));
  Normalisation& n = m.normalisation;
  n.action_mean = Eigen::VectorXf::Constant(kActionValues, 1.0f);
  n.action_mean.tail(10).setConstant(120.0f);
  n.action_scale = Eigen::VectorXf::Constant(kActionValues, 0.6f);
  n.action_scale.tail(10).setConstant(70.0f);
  n.force_min = 0.05f, n.force_max = 4.0f, n.speed_min = 1.0f, n.speed_max = 400.0f;
  n.target_scale = Eigen::VectorXf::LinSpaced(kTargetBins, 0.05f, 0.01f);
  for (int k = 0; k < kMaterials; ++k) {
    m.material_ids.push_back("material_" + std::to_string(k));
    m.material_names.push_back("Material " + std::to_string(k));
  }
  m.dataset_sha256 = std::string(64, '0'), m.split_sha256 = std::string(64, '0');
  if (variant == Variant::unified) {
    n.descriptor_mean = Eigen::VectorXf::Zero(d);
    n.descriptor_scale = Eigen::VectorXf::Ones(d);
    m.texture = make_mlp(sizes({int(d), o.texture_hidden, o.latent}), Activation::relu, Activation::linear, 1);
    m.classifier = make_mlp(sizes({o.latent, kMaterials}), Activation::linear, Activation::linear, 2);
    m.material_latents = Eigen::MatrixXf::Random(o.latent, kMaterials);
    m.nets = {spectrum_net(o, o.latent, 3)};
  } else {
    for (int k = 0; k < kMaterials; ++k) m.nets.push_back(spectrum_net(o, 0, 10 + 2 * std::uint64_t(k)));
  }
  m.config = o.to_json();
  return m;
}

const Model& model(Variant variant) {
  static const Model unified = make_model(Variant::unified, {}), per_material = make_model(Variant::per_material, {});
  return variant == Variant::unified ? unified : per_material;
}

// 45 ms of a stroke at about 1.2 N and 150 mm/s, inside the training range (no saturation).
std::vector<float> stroke_action() {
  std::vector<float> a(kActionValues);
  for (int i = 0; i < 10; ++i) a[std::size_t(i)] = 1.2f + 0.005f * float(i), a[std::size_t(10 + i)] = 150.0f + 0.5f * float(i);
  return a;
}

void single_query(benchmark::State& state, const Model& model) {
  Predictor predictor(model);
  const TextureCode code = predictor.material_code(7);
  std::vector<float> action = stroke_action(), spectrum(kTargetBins);
  for (auto _ : state) {
    predictor.predict(code, action, spectrum);
    benchmark::DoNotOptimize(spectrum.data());
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()));
}

void BM_PredictSingle(benchmark::State& state) { single_query(state, model(Variant::unified)); }
BENCHMARK(BM_PredictSingle)->Unit(benchmark::kNanosecond);

void BM_PredictSinglePerMaterial(benchmark::State& state) { single_query(state, model(Variant::per_material)); }
BENCHMARK(BM_PredictSinglePerMaterial)->Unit(benchmark::kNanosecond);

// The unified model's query at other predictor widths (bench/predict_sweep.sh's sizes).
void BM_PredictSingleHidden(benchmark::State& state) {
  TrainOptions o;
  o.predictor_hidden = int(state.range(0));
  single_query(state, make_model(Variant::unified, o));
}
BENCHMARK(BM_PredictSingleHidden)->ArgName("hidden")->Arg(64)->Arg(256)->Unit(benchmark::kNanosecond);

void BM_PredictBatch(benchmark::State& state) {
  Predictor predictor(model(Variant::unified));
  const TextureCode code = predictor.material_code(7);
  const auto batch = Eigen::Index(state.range(0));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<float> force(0.1f, 3.5f), speed(5.0f, 350.0f);
  Eigen::MatrixXf actions(kActionValues, batch);
  for (Eigen::Index c = 0; c < batch; ++c) actions.col(c) << Eigen::VectorXf::Constant(10, force(rng)), Eigen::VectorXf::Constant(10, speed(rng));
  for (auto _ : state) {
    Eigen::MatrixXf spectra = predictor.predict_batch(code, actions);
    benchmark::DoNotOptimize(spectra.data());
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * batch);
}
BENCHMARK(BM_PredictBatch)->Arg(1000)->Unit(benchmark::kMicrosecond);

// A 960 x 720 press as a GelSight Mini shows it: vignetted, coloured lighting in the reference, and
// the peak frame adds the imprint of a random rough surface (RGB, as the dataset stores frames).
void press_images(cv::Mat& peak, cv::Mat& reference) {
  const cv::Size size(960, 720);
  reference.create(size, CV_8UC3);
  for (int y = 0; y < size.height; ++y)
    for (int x = 0; x < size.width; ++x) {
      const double r2 = (std::pow(x - 480.0, 2) + std::pow(y - 360.0, 2)) / (600.0 * 600.0);
      const double light = 170.0 * (1.0 - 0.4 * r2);
      reference.at<cv::Vec3b>(y, x) = cv::Vec3b(cv::saturate_cast<uchar>(light * 0.8), cv::saturate_cast<uchar>(light),
                                                 cv::saturate_cast<uchar>(light * 0.9 + 0.02 * x));
    }
  cv::Mat relief(size, CV_32F);
  cv::randn(relief, 0.0, 1.0);
  cv::GaussianBlur(relief, relief, cv::Size(0, 0), 3.0);
  cv::normalize(relief, relief, -25.0, 25.0, cv::NORM_MINMAX);
  cv::Mat relief3;
  cv::merge(std::vector<cv::Mat>{relief, relief * 0.8, relief * 1.2}, relief3);
  cv::Mat sum;
  reference.convertTo(sum, CV_32FC3);
  sum += relief3;
  sum.convertTo(peak, CV_8UC3);
}

void BM_Encode960x720(benchmark::State& state) {
  const Predictor predictor(model(Variant::unified));
  cv::Mat peak, reference;
  press_images(peak, reference);
  for (auto _ : state) {
    TextureCode code = predictor.encode(peak, reference);
    benchmark::DoNotOptimize(code.first_layer.data());
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()));
}
BENCHMARK(BM_Encode960x720)->Unit(benchmark::kMicrosecond);

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::strcmp(argv[1], "--export-model") == 0) {
    write_model(model(Variant::unified), argv[2], true, "bench_predict --export-model: default sizes, random weights");
    return 0;
  }
  return haptex::bench::run_benchmarks(argc, argv);
}
