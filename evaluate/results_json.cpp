#include "evaluate/results_json.hpp"

#include <cmath>

#include "core/version.hpp"
#include "evaluate/paper_figures.hpp"

namespace haptex::evaluate {
namespace {

nlohmann::json input_json(const InputFile& f) { return {{"path", f.path}, {"sha256", f.sha256}}; }

nlohmann::json material_json(const MaterialComparison& m) {
  return {{"id", m.id},
          {"name", m.name},
          {"windows", m.windows},
          {"model", json_number(m.model)},
          {"baseline", json_number(m.baseline)},
          {"difference", {{"q1", json_number(m.difference.q1)},
                          {"median", json_number(m.difference.median)},
                          {"q3", json_number(m.difference.q3)}}},
          {"test", {{"t", json_number(m.test.t)},
                    {"df", json_number(m.test.df)},
                    {"p", json_number(m.test.p)},
                    {"n_model", m.test.n_a},
                    {"n_baseline", m.test.n_b}}},
          {"better", m.better()},
          {"significant", m.significant()}};
}

nlohmann::json experiment_json(const Experiment& x, const std::string& csv) {
  nlohmann::json materials = nlohmann::json::array();
  for (const MaterialComparison& m : x.materials) materials.push_back(material_json(m));
  nlohmann::json doc = {{"id", x.id},
                        {"title", x.title},
                        {"model_label", x.model_label},
                        {"baseline_label", x.baseline_label},
                        {"csv", csv},
                        {"totals", {{"materials", x.materials.size()},
                                    {"better", x.better()},
                                    {"significantly_better", x.significantly_better()},
                                    {"significantly_worse", x.significantly_worse()}}},
                        {"mean_model", json_number(x.mean_model())},
                        {"mean_baseline", json_number(x.mean_baseline())},
                        {"materials", materials}};
  if (const auto paper = paper_figure(x.id)) {
    nlohmann::json& p = doc["paper"];
    p = {{"materials", paper->materials},
         {"share_better", paper->better_share()},
         {"significantly_better", paper->significantly_better},
         {"share_significantly_better", paper->significantly_better_share()},
         {"text", paper->text()}};
    if (paper->better) p["better"] = *paper->better;
    if (paper->better_percent) p["better_percent"] = *paper->better_percent;
    if (paper->significantly_worse) p["significantly_worse"] = *paper->significantly_worse;
  }
  return doc;
}

}  // namespace

nlohmann::json json_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return x;
}

nlohmann::json results_json(const Evaluation& e, const ReportLayout& layout, const std::string& created_utc) {
  nlohmann::json models = nlohmann::json::array();
  for (const InputFile& m : e.models) models.push_back(input_json(m));
  nlohmann::json experiments = nlohmann::json::array();
  for (std::size_t i = 0; i < e.experiments.size(); ++i)
    experiments.push_back(experiment_json(e.experiments[i], layout.experiments[i] + ".csv"));
  nlohmann::json speed = nlohmann::json::array();
  for (const SpeedPoint& s : e.speed)
    speed.push_back({{"method", s.method}, {"setting", s.setting}, {"seconds_per_second", json_number(s.seconds_per_second)},
                     {"distance", json_number(s.distance)}});
  nlohmann::json examples = nlohmann::json::array();
  for (std::size_t i = 0; i < e.examples.size(); ++i) {
    const Example& x = e.examples[i];
    examples.push_back({{"id", x.id},
                        {"name", x.name},
                        {"spectrum_bins", x.truth_spectrum.size()},
                        {"signal_samples", x.truth_signal.size()},
                        {"spectra_csv", layout.examples[i] + "-spectra.csv"},
                        {"signals_csv", layout.examples[i] + "-signals.csv"}});
  }
  nlohmann::json latents = nlohmann::json::array();
  for (const LatentPoint& p : e.latents)
    latents.push_back({{"id", p.id}, {"name", p.name}, {"kind", p.kind}, {"x", json_number(p.x)}, {"y", json_number(p.y)}});
  return {{"format", "results/1"},
          {"haptex_version", kVersion},
          {"created_utc", created_utc},
          {"inputs", {{"dataset", input_json(e.dataset)}, {"split", input_json(e.split)}, {"models", models}}},
          {"settings", {{"baseline", e.baseline}, {"reconstruct", e.reconstruct}, {"repeats", e.repeats}}},
          {"significance", {{"test", "Welch's t-test, two-sided"}, {"level", kSignificanceLevel}}},
          {"seconds", json_number(e.seconds)},
          {"experiments", experiments},
          {"speed", speed},
          {"examples", examples},
          {"latents", latents},
          {"notes", e.notes}};
}

}  // namespace haptex::evaluate
