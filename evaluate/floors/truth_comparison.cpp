#include "evaluate/floors/truth_comparison.hpp"

#include "core/error.hpp"
#include "core/naming.hpp"
#include "dataset/window.hpp"
#include "predict/predictor.hpp"
#include "dataset/truth_file.hpp"

namespace haptex::evaluate {
namespace {

TruthComparison compare_material(predict::Predictor& p, int material, const dataset::TruthGrid& grid) {
  const std::vector<double>& speeds = grid.speeds_mm_s;
  const std::vector<double>& forces = grid.forces_n;
  const predict::Normalisation& n = p.model().normalisation;
  const predict::TextureCode code = p.material_code(material);
  std::vector<Eigen::VectorXf> truths, predictions;
  using dataset::kActionSamples, dataset::kTargetBins;
  std::vector<float> action(dataset::kActionValues), out(kTargetBins);
  for (std::size_t s = 0; s < speeds.size(); ++s)
    for (std::size_t f = 0; f < forces.size(); ++f) {
      if (speeds[s] < n.speed_min || speeds[s] > n.speed_max || forces[f] < n.force_min || forces[f] > n.force_max) continue;
      std::fill(action.begin(), action.begin() + kActionSamples, float(forces[f]));
      std::fill(action.begin() + kActionSamples, action.end(), float(speeds[s]));
      p.predict(code, action, out);
      predictions.push_back(Eigen::Map<const Eigen::VectorXf>(out.data(), Eigen::Index(kTargetBins)));
      Eigen::VectorXf t(kTargetBins);
      const double* truth = grid.spectrum(s, f);
      for (std::size_t k = 0; k < kTargetBins; ++k) t[Eigen::Index(k)] = float(truth[k]);
      truths.push_back(t);
    }
  TruthComparison c;
  c.points = truths.size();
  if (truths.empty()) return c;
  Eigen::VectorXf mean = Eigen::VectorXf::Zero(Eigen::Index(kTargetBins));
  for (const auto& t : truths) mean += t / float(truths.size());
  for (std::size_t i = 0; i < truths.size(); ++i) {
    c.model += (predictions[i] - truths[i]).norm() / double(truths.size());
    c.constant += (mean - truths[i]).norm() / double(truths.size());
    c.truth_norm += truths[i].norm() / double(truths.size());
  }
  return c;
}

}  // namespace

std::vector<TruthComparison> compare_with_truth(const predict::Model& model, const std::string& truth_path) {
  const dataset::Truth truth = dataset::read_truth_file(truth_path);
  predict::Predictor p(model);
  std::vector<TruthComparison> out;
  bool known = false;
  for (const dataset::MaterialTruth& m : truth.materials) {
    const std::string id = material_id(m.name);
    const int index = model.material_index(id);
    known = known || index >= 0;
    if (index < 0 || !m.grid) continue;  // a HaTT model's truth is the model itself (evaluate/floors/oracle.hpp), not a grid
    TruthComparison c = compare_material(p, index, *m.grid);
    c.id = id;
    out.push_back(c);
  }
  if (!known) throw input_error(truth_path, "/materials", "no material of the model is in this file", "Give the truth.h5 of the synthetic data the model was trained on");
  return out;
}

TruthComparison overall(const std::vector<TruthComparison>& materials) {
  TruthComparison all;
  for (const TruthComparison& c : materials) {
    all.points += c.points;
    all.model += c.model * double(c.points);
    all.constant += c.constant * double(c.points);
    all.truth_norm += c.truth_norm * double(c.points);
  }
  if (all.points == 0) return all;
  for (double* v : {&all.model, &all.constant, &all.truth_norm}) *v /= double(all.points);
  return all;
}

}  // namespace haptex::evaluate
