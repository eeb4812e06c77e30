#include "evaluate/report/results_json.hpp"

#include <algorithm>
#include <cmath>

#include "core/version.hpp"
#include "evaluate/report/paper_figures.hpp"

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
          {"significant", m.significant()},
          {"model_lsd_db", json_measured(m.model_lsd_db)},
          {"baseline_lsd_db", json_measured(m.baseline_lsd_db)},
          {"floor", json_measured(m.floor)},
          {"floor_ratio", json_measured(m.floor_ratio())},
          {"mean_spectrum", json_measured(m.mean_spectrum)},
          {"mean_spectrum_ratio", json_measured(m.mean_spectrum_ratio())},
          {"below_floor", m.below_floor}};
}

nlohmann::json totals_json(const Experiment& x) {
  return {{"materials", x.materials.size()},
          {"better", x.better()},
          {"significantly_better", x.significantly_better()},
          {"significantly_worse", x.significantly_worse()},
          {"with_floor", materials_with_floor(x)},
          {"within_floor_10_percent", x.within_floor(0.10)},
          {"within_floor_15_percent", x.within_floor(0.15)},
          {"below_floor", x.below_floor()}};
}

nlohmann::json paper_json(const PaperFigure& paper) {
  nlohmann::json p = {{"materials", paper.materials},
                      {"share_better", paper.better_share()},
                      {"significantly_better", paper.significantly_better},
                      {"share_significantly_better", paper.significantly_better_share()},
                      {"text", paper.text()}};
  if (paper.better) p["better"] = *paper.better;
  if (paper.better_percent) p["better_percent"] = *paper.better_percent;
  if (paper.significantly_worse) p["significantly_worse"] = *paper.significantly_worse;
  return p;
}

nlohmann::json experiment_json(const Experiment& x, const std::string& csv) {
  nlohmann::json materials = nlohmann::json::array();
  for (const MaterialComparison& m : x.materials) materials.push_back(material_json(m));
  nlohmann::json doc = {{"id", x.id},
                        {"title", x.title},
                        {"comparison", comparison_name(comparison_of(x.id))},
                        {"model_label", x.model_label},
                        {"baseline_label", x.baseline_label},
                        {"csv", csv},
                        {"totals", totals_json(x)},
                        {"mean_model", json_number(x.mean_model())},
                        {"mean_baseline", json_number(x.mean_baseline())},
                        {"median_floor_ratio", json_measured(x.median_floor_ratio())},
                        {"worst_floor_ratio", json_measured(x.worst_floor_ratio())},
                        {"materials", materials}};
  if (const auto paper = paper_figure(x.id)) doc["paper"] = paper_json(*paper);
  return doc;
}

nlohmann::json speed_json(const SpeedPoint& s) {
  return {{"method", s.method},
          {"setting", s.setting},
          {"kind", s.kind},
          {"seconds_per_second", json_number(s.seconds_per_second)},
          {"distance", json_number(s.distance)},
          {"section_lsd_db", json_measured(s.section_lsd_db)},
          {"spread_ratio", json_measured(s.spread_ratio)}};
}

nlohmann::json floor_json(const MaterialFloor& f) {
  return {{"id", f.id},
          {"name", f.name},
          {"kind", f.kind},
          {"method", f.method},
          {"windows", f.windows},
          {"distance", json_measured(f.distance)},
          {"lsd_db", json_measured(f.lsd_db)},
          {"closed_form", json_measured(f.closed_form)},
          {"monte_carlo", json_measured(f.monte_carlo)},
          {"closed_form_gap_percent", json_measured(closed_form_gap_percent(f))},
          {"rendered", json_measured(f.rendered)},
          {"rendered_ratio", json_measured(rendered_ratio(f))},
          {"estimate", json_measured(f.estimate)},
          {"baseline_expected", json_measured(f.baseline_expected)},
          {"input_floor", json_measured(f.input_floor)}};
}

nlohmann::json realism_json(const Realism& r) {
  nlohmann::json materials = nlohmann::json::array();
  for (const MaterialRealism& m : r.materials)
    materials.push_back({{"id", m.id},
                         {"name", m.name},
                         {"section_lsd_db", json_measured(m.section_lsd_db)},
                         {"spread_ratio", json_measured(m.spread_ratio)},
                         {"distance", json_measured(m.distance)},
                         {"floor_ratio", json_measured(m.floor_ratio)},
                         {"rendered_floor_ratio", json_measured(m.rendered_floor_ratio)}});
  const RealismMedians medians = realism_medians(r);
  return {{"method", r.method},
          {"setting", r.setting},
          {"median_section_lsd_db", json_measured(medians.section_lsd_db)},
          {"median_spread_ratio", json_measured(medians.spread_ratio)},
          {"median_floor_ratio", json_measured(medians.floor_ratio)},
          {"median_rendered_floor_ratio", json_measured(medians.rendered_floor_ratio)},
          {"spread_in_range", medians.spread_in_range},
          {"near_rendered_floor", medians.near_rendered_floor},
          {"materials", materials}};
}

// Each item of v as item_json gives it.
template <typename T, typename ToJson>
nlohmann::json json_array(const std::vector<T>& v, ToJson item_json) {
  nlohmann::json out = nlohmann::json::array();
  for (const T& item : v) out.push_back(item_json(item));
  return out;
}


}  // namespace

nlohmann::json json_number(double x) {
  if (std::isnan(x)) return "nan";
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return x;
}

nlohmann::json json_measured(double x) { return std::isnan(x) ? nlohmann::json(nullptr) : json_number(x); }

nlohmann::json results_json(const Evaluation& e, const ReportLayout& layout, const std::string& created_utc) {
  nlohmann::json experiments = nlohmann::json::array();
  for (std::size_t i = 0; i < e.experiments.size(); ++i)
    experiments.push_back(experiment_json(e.experiments[i], layout.experiments[i] + ".csv"));
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
  const auto latent_json = [](const LatentPoint& p) {
    return nlohmann::json{{"id", p.id}, {"name", p.name}, {"kind", p.kind}, {"x", json_number(p.x)}, {"y", json_number(p.y)}};
  };
  const auto predictions_json = [](const PredictionsFile& p) {
    return nlohmann::json{{"name", p.name}, {"path", p.path}, {"sha256", p.sha256}, {"source", p.source}};
  };
  return {{"format", kResultsFormat},
          {"haptex_version", kVersion},
          {"created_utc", created_utc},
          {"inputs", {{"dataset", input_json(e.dataset)}, {"split", input_json(e.split)}, {"models", json_array(e.models, input_json)},
                      {"predictions", json_array(e.predictions, predictions_json)}}},
          {"settings", {{"baseline", e.baseline}, {"reconstruct", e.reconstruct}, {"repeats", e.repeats}}},
          {"significance", {{"test", "Welch's t-test, two-sided"}, {"level", kSignificanceLevel}}},
          {"seconds", json_number(e.seconds)},
          {"experiments", experiments},
          {"speed", json_array(e.speed, speed_json)},
          {"floor_kind", e.floor_kind.empty() ? nlohmann::json(nullptr) : nlohmann::json(e.floor_kind)},
          {"floors", json_array(e.floors, floor_json)},
          {"realism", json_array(e.realism, realism_json)},
          {"examples", examples},
          {"latents", json_array(e.latents, latent_json)},
          {"notes", e.notes}};
}

}  // namespace haptex::evaluate
