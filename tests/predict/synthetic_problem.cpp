#include "tests/predict/synthetic_problem.hpp"

#include <cmath>
#include <random>

namespace haptex::test {

std::vector<float> synthetic_truth(int material, double force, double speed) {
  const double f0 = (120.0 + 140.0 * material) * (0.5 + speed / 200.0), gain = 0.02 * (1 + material) * std::sqrt(force) * speed / 100.0;
  std::vector<float> s(100);
  for (int k = 0; k < 100; ++k) {
    const double f = 10.0 * (k + 1), d = (f - f0) / 60.0;
    s[std::size_t(k)] = float(gain * (0.1 + std::exp(-0.5 * d * d)));
  }
  return s;
}

predict::TrainingData synthetic_problem(const SyntheticSpec& spec) {
  std::mt19937_64 rng(spec.seed);
  std::normal_distribution<float> normal;
  std::uniform_real_distribution<double> uniform;
  const auto length = predict::descriptor_length();
  predict::TrainingData data;
  const int total = spec.materials * spec.windows;
  data.action.resize(20, total);
  data.target.resize(100, total);
  data.dataset_sha256 = std::string(64, 'a');
  data.split_sha256 = std::string(64, 'b');
  for (int m = 0; m < spec.materials; ++m) {
    predict::MaterialData md;
    md.id = "material_" + std::to_string(m);
    md.name = "Material " + std::to_string(m);
    std::vector<float> centre(length);
    for (float& c : centre) c = normal(rng);
    for (std::size_t set = 0; set < 3; ++set) {
      const int images = set == 0 ? spec.train_images : 2;
      for (int i = 0; i < images; ++i) {
        std::vector<float> d = centre;
        for (float& v : d) v += 0.3f * normal(rng);
        md.images[set].push_back(d);
      }
    }
    for (int w = 0; w < spec.windows; ++w) {
      const int column = m * spec.windows + w;
      const double force = 0.2 + 2.8 * uniform(rng), speed = 20 + 280 * uniform(rng);
      for (int k = 0; k < 10; ++k) {
        data.action(k, column) = float(force * (1 + 0.01 * normal(rng)));
        data.action(10 + k, column) = float(speed * (1 + 0.01 * normal(rng)));
      }
      const std::vector<float> truth = synthetic_truth(m, force, speed);
      for (int k = 0; k < 100; ++k)
        data.target(k, column) = std::max(0.0f, truth[std::size_t(k)] * float(1 + spec.noise * normal(rng)));
      const double u = uniform(rng);
      md.rows[u < 0.7 ? 0 : u < 0.85 ? 1 : 2].push_back(std::size_t(column));
    }
    data.materials.push_back(std::move(md));
  }
  return data;
}

}  // namespace haptex::test
