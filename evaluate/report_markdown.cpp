#include "evaluate/report_markdown.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/version.hpp"
#include "evaluate/paper_figures.hpp"
#include "evaluate/results_json.hpp"

namespace haptex::evaluate {
namespace {

// Text in a table cell or running text: markdown's active characters escaped.
std::string escaped(std::string_view text) {
  std::string s;
  for (char c : text) {
    if (c == '\n' || c == '\r') c = ' ';
    if (std::string_view("\\`*_[]<>|#").find(c) != std::string_view::npos) s += '\\';
    s += c;
  }
  return s;
}

// A path or hash as code in a table cell (a backtick cannot close it early; a pipe cannot end the cell).
std::string code(std::string_view text) {
  std::string s = "`";
  for (char c : text) s += c == '`' ? std::string("'") : c == '|' ? std::string("\\|") : std::string(1, c);
  return s + "`";
}

std::string percent(double share) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.0f %%", 100.0 * share);
  return buffer;
}
std::string percent(std::size_t count, std::size_t of) { return of == 0 ? "n/a" : percent(double(count) / double(of)); }

std::string materials_word(std::size_t n) { return n == 1 ? "material" : "materials"; }

std::string mean_text(const Experiment& x, double mean) { return x.materials.empty() ? "n/a" : format_number(mean); }

bool drawn(const ChartResult& charts, const std::string& stem) {
  return std::find(charts.images.begin(), charts.images.end(), stem + ".png") != charts.images.end();
}

// The chart as an image link, or where its data and script are when it was not drawn.
std::string chart(const ChartResult& charts, const std::string& stem, const std::string& alt, const std::string& csv) {
  if (drawn(charts, stem)) return "![" + escaped(alt) + "](" + stem + ".png)\n\n";
  return "*Chart not drawn (see Notes): its data is in " + code(csv) + ", its gnuplot script " + code(stem + ".gnuplot") + ".*\n\n";
}

// Starts a section; false (after saying so) when it has nothing to show.
bool section(std::ostringstream& s, std::string_view heading, bool empty, std::string_view when_empty) {
  s << "## " << heading << "\n\n";
  if (empty) s << when_empty << "\n\n";
  return !empty;
}

// What each experiment does, by the start of its id.
constexpr std::pair<std::string_view, std::string_view> kExplanations[] = {
    {"per-material",
     "Each material has its own model, trained on that material's training sections only. For every test window it "
     "predicts the vibration spectrum from the force and speed just before the window."},
    {"unified-new-actions",
     "One model for all materials, told which material it is by the texture latent of the material's training presses "
     "(GelSight images). The test sections hold strokes, force and speed over time, that the model never saw: does it "
     "generalise to new actions? This is the paper's main experiment."},
    {"unified-new-presses",
     "The same unified model, but the texture comes from the material's test press, a GelSight image the model never "
     "saw: does it generalise to a new image of a known surface?"},
    {"stitched-",
     "Above, predicted spectra are compared with the recording window by window. Here the model's spectra for a whole "
     "test section are first turned into one vibration signal by phase reconstruction, and that signal is scored "
     "exactly like the baseline's rendering: the vibration a haptic device would play."},
};

std::string_view experiment_explanation(std::string_view id) {
  for (const auto& [prefix, text] : kExplanations)
    if (id.starts_with(prefix)) return text;
  return "";
}

std::string baseline_explanation(const Evaluation& e) {
  std::string what = "the baseline `" + e.baseline + "`";
  if (e.baseline == "ar-refit")
    what = "`ar-refit`: per material a piecewise autoregressive model, fitted the way the Penn Haptic Texture Toolkit "
           "(HaTT) fits its models, from the material's training and validation sections (the paper's baseline)";
  else if (e.baseline == "hatt-published")
    what = "`hatt-published`: the Penn Haptic Texture Toolkit's own published model file of each material";
  return "The baseline is " + what + ". It renders each test section from the recorded force and speed " +
         std::to_string(e.repeats) + " times with different random seeds; its distances pool all renderings.";
}

void inputs_section(std::ostringstream& s, const Evaluation& e) {
  s << "## What was compared\n\n| input | file | SHA-256 |\n|---|---|---|\n"
    << "| dataset | " << code(e.dataset.path) << " | " << code(e.dataset.sha256) << " |\n"
    << "| split | " << code(e.split.path) << " | " << code(e.split.sha256) << " |\n";
  for (std::size_t i = 0; i < e.models.size(); ++i)
    s << "| model " << i + 1 << " | " << code(e.models[i].path) << " | " << code(e.models[i].sha256) << " |\n";
  s << "\nSettings: baseline " << code(e.baseline) << ", " << e.repeats << " baseline renderings per test section, "
    << "phase reconstruction " << code(e.reconstruct) << ". The evaluation took " << format_number(e.seconds) << " s.\n\n";
}

void explanations_section(std::ostringstream& s, const Evaluation& e) {
  s << "## How to read it\n\n"
    << "**Spectral distance** (m/s^2, lower is better). Every 10 ms, a 0.1 s window (1000 samples at 10 kHz) of the "
       "model's or the baseline's vibration and the same window of the recording are each turned into an amplitude "
       "spectrum from 10 to 1000 Hz (100 bins, 10 Hz apart). The distance is the Euclidean distance between the two "
       "spectra: 0 for identical spectra, larger the further apart. A material's figure is the mean over the windows "
       "of its test sections. Spectra rather than waveforms are compared because texture vibration is noise-like: two "
       "faithful renderings of the same stroke never agree sample by sample, but their spectra do.\n\n"
    << "**Baseline.** " << baseline_explanation(e) << "\n\n"
    << "**Difference** is baseline minus model, window by window: positive where the model is closer to the "
       "recording. The tables give its quartiles (Q1, median, Q3) over the test windows.\n\n"
    << "**Significance.** Welch's two-sided t-test (unequal variances) of the model's window distances against the "
       "baseline's; p < " << kSignificanceLevel << " counts as significant. t < 0 where the model's distances are lower. "
       "When neither sample varies and their means differ, t is infinite and p = 0: the two do not overlap at all.\n\n";
}

void totals_section(std::ostringstream& s, const Evaluation& e) {
  if (!section(s, "Totals", e.experiments.empty(), "No experiment was run (see Notes).")) return;
  s << "| experiment | materials | model better | significantly better | significantly worse | mean model | mean baseline "
       "| the paper (93 materials) |\n|---|---|---|---|---|---|---|---|\n";
  for (const Experiment& x : e.experiments) {
    const auto paper = paper_figure(x.id);
    s << "| " << escaped(x.title) << " (" << code(x.id) << ") | " << x.materials.size() << " | " << x.better() << " ("
      << percent(x.better(), x.materials.size()) << ") | " << x.significantly_better() << " ("
      << percent(x.significantly_better(), x.materials.size()) << ") | " << x.significantly_worse() << " ("
      << percent(x.significantly_worse(), x.materials.size()) << ") | " << mean_text(x, x.mean_model()) << " | "
      << mean_text(x, x.mean_baseline()) << " | " << (paper ? paper->text() : "not in the paper") << " |\n";
  }
  s << "\nMean model and mean baseline: spectral distance in m/s^2, averaged over the materials. The paper's column "
       "quotes Heravi et al. (ICRA 2020) for the same experiment against its AR baseline.\n\n";
}

void material_table(std::ostringstream& s, const Experiment& x, const std::string& csv) {
  s << "| material | windows | model | baseline | difference Q1 | median | Q3 | t | p | result |\n"
    << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const MaterialComparison& m : x.materials)
    s << "| " << escaped(m.name.empty() ? m.id : m.name) << " | " << m.windows << " | " << format_number(m.model) << " | "
      << format_number(m.baseline) << " | " << format_number(m.difference.q1) << " | " << format_number(m.difference.median)
      << " | " << format_number(m.difference.q3) << " | " << format_number(m.test.t) << " | " << format_p(m.test.p) << " | "
      << (m.better() ? "better" : "worse") << (m.significant() ? " \\*" : "") << " |\n";
  s << "\nModel and baseline: mean spectral distance (m/s^2) over the test windows. \\* significant: p < "
    << kSignificanceLevel << ". Data: " << code(csv) << ".\n\n";
}

void experiment_section(std::ostringstream& s, const Experiment& x, const std::string& stem, const ChartResult& charts) {
  s << "### " << escaped(x.title) << " (" << code(x.id) << ")\n\n";
  if (const std::string_view why = experiment_explanation(x.id); !why.empty()) s << why << "\n\n";
  s << "Model: " << escaped(x.model_label) << ". Baseline: " << escaped(x.baseline_label) << ".\n\n";
  if (x.materials.empty()) {
    s << "No material could be compared (see Notes).\n\n";
    return;
  }
  s << "**The model is " << totals_sentence(x) << "** (p < " << kSignificanceLevel << ", Welch's two-sided t-test).";
  if (const auto paper = paper_figure(x.id))
    s << " The paper (Heravi et al., ICRA 2020) reports its model " << paper->text() << "; here: better on " << x.better()
      << " of " << x.materials.size() << " (" << percent(x.better(), x.materials.size()) << "), significantly on "
      << x.significantly_better() << " (" << percent(x.significantly_better(), x.materials.size()) << ").";
  s << "\n\n"
    << chart(charts, stem, "Baseline minus model per material: " + x.title, stem + ".csv");
  material_table(s, x, stem + ".csv");
}

void examples_section(std::ostringstream& s, const Evaluation& e, const ReportLayout& layout, const ChartResult& charts) {
  if (!section(s, "Examples", e.examples.empty(), "No examples were recorded.")) return;
  s << "As the paper's Fig. 5: for each material below, the top plot shows the amplitude spectra of one test window "
       "(recorded, model, baseline), the bottom one the start of a test section as time signals (the model's signal "
       "stitched by phase reconstruction). Materials:";
  for (std::size_t i = 0; i < e.examples.size(); ++i)
    s << (i ? "; " : " ") << escaped(e.examples[i].name.empty() ? e.examples[i].id : e.examples[i].name);
  s << (e.examples.size() > 4 ? " (the chart shows the first four)" : "") << ".\n\n"
    << chart(charts, std::string(kExamplesStem), "Spectra and time signals of recorded, model and baseline vibration",
             layout.examples.front() + "-spectra.csv and the other example CSVs");
}

void latents_section(std::ostringstream& s, const Evaluation& e, const ChartResult& charts) {
  if (!section(s, "Texture map", e.latents.empty(), "No texture latents (no unified model).")) return;
  s << "The unified model describes each surface by a texture latent computed from GelSight images. The map projects "
       "the latents onto their first two principal components (PCA): one point per material for its mean training "
       "latent, one per test press. Surfaces the model finds alike lie close together; a test press near its own "
       "material means the model recognises the surface from an image it never saw. Coordinates: "
    << code(std::string(kLatentsStem) + ".csv") << ".\n\n"
    << chart(charts, std::string(kLatentsStem), "Texture latents, 2-D PCA", std::string(kLatentsStem) + ".csv");
}

void speed_section(std::ostringstream& s, const Evaluation& e, const ChartResult& charts) {
  if (!section(s, "Speed against accuracy", e.speed.empty(), "No timings were recorded.")) return;
  s << "Compute time per second of rendered vibration (one core; below 1 s it can run in real time) against the mean "
       "spectral distance over the test windows, one row per method and setting.\n\n"
    << "| method | setting | compute time per second of vibration | mean spectral distance (m/s^2) |\n|---|---|---|---|\n";
  for (const SpeedPoint& p : e.speed)
    s << "| " << escaped(p.method) << " | " << escaped(p.setting) << " | " << format_number(1000 * p.seconds_per_second)
      << " ms | " << format_number(p.distance) << " |\n";
  s << "\n" << chart(charts, std::string(kSpeedStem), "Speed against accuracy", std::string(kSpeedStem) + ".csv");
}

void notes_section(std::ostringstream& s, const Evaluation& e, const ChartResult& charts) {
  std::vector<std::string> notes = e.notes;
  if (!charts.note.empty()) notes.push_back(charts.note);
  s << "## Notes\n\n";
  if (notes.empty()) s << "None: every experiment ran on every material.\n";
  for (const std::string& n : notes) s << "- " << escaped(n) << "\n";
  s << "\n";
}

void files_section(std::ostringstream& s, const ReportLayout& layout, const ChartResult& charts) {
  s << "## Files\n\n"
    << "- `report.md`: this report.\n"
    << "- `results.json`: everything above, machine-readable (haptex's `schemas/results.schema.json`; infinite or "
       "undefined numbers are the strings \"inf\", \"-inf\", \"nan\").\n";
  if (!layout.experiments.empty()) {
    s << "- One CSV per experiment, a row per material:";
    for (std::size_t i = 0; i < layout.experiments.size(); ++i) s << (i ? ", " : " ") << code(layout.experiments[i] + ".csv");
    s << ". Columns: `material_id`, `name`, `windows` (test windows), `model_distance` and `baseline_distance` (mean "
         "spectral distance, m/s^2), `difference_q1`, `difference_median`, `difference_q3` (baseline - model), `t`, `df`, "
         "`p` (Welch's test), `n_model` and `n_baseline` (the window distances it compared), `better` and `significant` "
         "(1 or 0).\n";
  }
  s << "- `speed.csv`: the speed-vs-accuracy points (`method`, `setting`, `seconds_per_second`, `distance`).\n"
    << "- `latents.csv`: the texture map's coordinates (`material_id`, `name`, `kind`, `x`, `y`).\n";
  if (!layout.examples.empty()) {
    s << "- Two CSVs per example:";
    for (std::size_t i = 0; i < layout.examples.size(); ++i)
      s << (i ? ", " : " ") << code(layout.examples[i] + "-spectra.csv") << ", " << code(layout.examples[i] + "-signals.csv");
    s << ". Columns: `frequency_hz` or `time_s`, then `truth` (the recording), `model`, `baseline`.\n";
  }
  if (!charts.scripts.empty())
    s << "- `*.gnuplot`: the chart scripts; run `gnuplot NAME.gnuplot` in this folder to draw NAME.png again.\n";
  if (!charts.images.empty()) s << "- `*.png`: the charts.\n";
  s << "\nCSV numbers are written to full precision; `inf`, `-inf` and `nan` mark values that are not finite.\n";
}

}  // namespace

std::string totals_sentence(const Experiment& x) {
  return "better on " + std::to_string(x.better()) + " of " + std::to_string(x.materials.size()) + " " +
         materials_word(x.materials.size()) + ", significantly on " + std::to_string(x.significantly_better()) +
         ", significantly worse on " + std::to_string(x.significantly_worse());
}

std::string format_number(double x) {
  if (std::isnan(x)) return "n/a";
  if (std::isinf(x)) return x > 0 ? "+∞" : "-∞";
  if (x == 0) return "0";
  char buffer[32];
  const double magnitude = std::fabs(x);
  if (magnitude >= 1e-3 && magnitude < 99999.5) {
    const int decimals = std::max(0, 3 - int(std::floor(std::log10(magnitude))));
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, x);
  } else {
    std::snprintf(buffer, sizeof buffer, "%.3e", x);
  }
  return buffer;
}

std::string format_p(double p) {
  if (std::isnan(p)) return "n/a";
  if (p == 0) return "0";
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, p < 1e-3 ? "%.2e" : "%.3g", p);
  return buffer;
}

std::string report_markdown(const Evaluation& e, const ReportLayout& layout, const ChartResult& charts,
                            const std::string& created_utc) {
  std::ostringstream s;
  s << "# haptex evaluation report\n\n"
    << "Written by haptex " << kVersion << " on " << created_utc << ". It compares learned vibration models with an "
       "autoregressive baseline on every material's test sections, following Heravi, Yuan, Okamura and Bohg, "
       "\"Learning an Action-Conditional Model for Haptic Texture Generation\" (ICRA 2020). The same numbers, "
       "machine-readable, are in [results.json](results.json) and the CSV files listed at the end.\n\n";
  inputs_section(s, e);
  explanations_section(s, e);
  totals_section(s, e);
  if (!e.experiments.empty()) s << "## Experiments\n\n";
  for (std::size_t i = 0; i < e.experiments.size(); ++i) experiment_section(s, e.experiments[i], layout.experiments[i], charts);
  examples_section(s, e, layout, charts);
  latents_section(s, e, charts);
  speed_section(s, e, charts);
  notes_section(s, e, charts);
  files_section(s, layout, charts);
  return s.str();
}

}  // namespace haptex::evaluate
