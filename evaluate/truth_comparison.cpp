#include "evaluate/truth_comparison.hpp"

#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "predict/predictor.hpp"

namespace haptex::evaluate {
namespace {

TruthComparison compare_material(predict::Predictor& p, int material, const h5::Group& g) {
  const auto speeds = g.open_dataset("speeds").read<double>(), forces = g.open_dataset("forces").read<double>();
  const auto spectrum = g.open_dataset("spectrum").read<double>();
  const predict::Normalisation& n = p.model().normalisation;
  const predict::TextureCode code = p.material_code(material);
  std::vector<Eigen::VectorXf> truths, predictions;
  std::vector<float> action(predict::kActionValues), out(predict::kSpectrumBins);
  for (std::size_t s = 0; s < speeds.size(); ++s)
    for (std::size_t f = 0; f < forces.size(); ++f) {
      if (speeds[s] < n.speed_min || speeds[s] > n.speed_max || forces[f] < n.force_min || forces[f] > n.force_max) continue;
      std::fill(action.begin(), action.begin() + 10, float(forces[f]));
      std::fill(action.begin() + 10, action.end(), float(speeds[s]));
      p.predict(code, action, out);
      predictions.push_back(Eigen::Map<const Eigen::VectorXf>(out.data(), predict::kSpectrumBins));
      Eigen::VectorXf t(predict::kSpectrumBins);
      for (int k = 0; k < predict::kSpectrumBins; ++k) t[k] = float(spectrum[(s * forces.size() + f) * predict::kSpectrumBins + std::size_t(k)]);
      truths.push_back(t);
    }
  TruthComparison c;
  c.points = truths.size();
  if (truths.empty()) return c;
  Eigen::VectorXf mean = Eigen::VectorXf::Zero(predict::kSpectrumBins);
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
  const h5::File file = h5::File::open(truth_path);
  const h5::Group root = file.root();
  if (!root.has_attr("haptex_format") || root.attr_string("haptex_format") != "truth/1")
    throw input_error(truth_path, "/", "not a truth file (truth/1)", "Give OUT/truth.h5 of haptex synth materials");
  predict::Predictor p(model);
  std::vector<TruthComparison> out;
  const h5::Group materials = root.open_group("materials");
  for (const std::string& id : materials.children()) {
    const int m = model.material_index(id);
    if (m < 0) continue;
    TruthComparison c = compare_material(p, m, materials.open_group(id));
    c.id = id;
    out.push_back(c);
  }
  if (out.empty()) throw input_error(truth_path, "/materials", "no material of the model is in this file", "Give the truth.h5 of the synthetic data the model was trained on");
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
