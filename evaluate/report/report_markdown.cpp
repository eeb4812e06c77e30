#include "evaluate/report/report_markdown.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/text/format.hpp"
#include "core/text/utf8.hpp"
#include "core/version.hpp"
#include "evaluate/report/paper_figures.hpp"
#include "evaluate/report/results_json.hpp"
#include "evaluate/inputs/window_sets.hpp"

namespace haptex::evaluate {
namespace {

// Text in a table cell or running text: markdown's active characters escaped, and characters a
// terminal or viewer would act on (an ESC sequence, U+202E) written as \xHH or \uHHHH
// (text::printable; review 4: `cat report.md` retitled and cleared the terminal).
std::string escaped(std::string_view raw) {
  const std::string text = text::printable(raw);
  std::string s;
  for (char c : text) {
    if (c == '\n' || c == '\r') c = ' ';
    if (std::string_view("\\`*_[]<>|#").find(c) != std::string_view::npos) s += '\\';
    s += c;
  }
  return s;
}

// A path or hash as code in a table cell: fenced by one backtick more than its longest run of them, so
// a backtick in a name is shown as it is (CommonMark code spans); a pipe cannot end the cell.
std::string code(std::string_view raw) {
  const std::string text = text::printable(raw);
  std::size_t longest = 0;
  for (std::size_t i = 0, run = 0; i < text.size(); ++i) longest = std::max(longest, run = text[i] == '`' ? run + 1 : 0);
  const std::string fence(longest + 1, '`'), pad = longest > 0 ? " " : "";
  std::string s;
  for (char c : text) s += c == '|' ? std::string("\\|") : std::string(1, c);
  return fence + pad + s + pad + fence;
}

std::string percent(double share) {
  return text::format("%.0f %%", 100.0 * share);
}
std::string percent(std::size_t count, std::size_t of) { return of == 0 ? "n/a" : percent(double(count) / double(of)); }

std::string materials_word(std::size_t n) { return n == 1 ? "material" : "materials"; }

std::string mean_text(const Experiment& x, double mean) { return x.materials.empty() ? "n/a" : format_number(mean); }

// A figure that may not have been measured: "–" when it was not.
std::string measured(double x) { return std::isnan(x) ? "–" : format_number(x); }
std::string measured_percent(double x) { return std::isnan(x) ? "–" : format_number(x) + " %"; }

std::string shown_name(const std::string& name, const std::string& id) { return escaped(name.empty() ? id : name); }

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
     "saw: does it generalise to a new image of a known surface? A press is recognised (docs/predict.md, \"A new press\"): "
     "its latent is the training materials' latents weighted by how surely the classifier takes it for each. A press "
     "taken for its own material outright gets that material's training latent, and its figures then equal "
     "unified-new-actions': for such a material this experiment measures recognition, not how a new image carries over."},
    {"external-",
     "A model trained outside haptex (docs/benchmark.md): its predictions file holds one spectrum per test window of the "
     "grid `haptex windows` writes, scored here exactly as the built-in models are. What it was told (the material, the "
     "test press's image, the action) is its own; the file's source says how it was made."},
    {"stitched-external-",
     "The external model's own vibration signal of each test section (its predictions file's signals), scored exactly "
     "like the baseline's rendering."},
    {"stitched-",
     "Above, predicted spectra are compared with the recording window by window. Here the model's spectra for a whole "
     "test section are first turned into one vibration signal (by phase reconstruction, or by shaping noise), and that signal is scored "
     "exactly like the baseline's rendering: the vibration a haptic device would play."},
};

// What each comparison is and which question it answers (docs/evaluate.md, "Which comparison answers which
// question"); explanation: the experiment's own, where its id's start does not give one (kExplanations).
struct ComparisonText {
  Comparison kind;
  std::string_view what, question, explanation;
};
constexpr ComparisonText kComparisons[] = {
    {Comparison::rendered_ar, "Predicted spectra against the AR baseline **rendered**",
     "The paper's protocol: is the learned model closer to the recording than the vibration the AR baseline plays? Not "
     "like for like: a stochastic renderer pays the texture's randomness twice (the recording is one random draw, its "
     "rendering another), while a spectrum predictor can aim at the expected spectrum, so even the true generating "
     "model, rendered, loses to a good predictor.",
     ""},
    {Comparison::expected_ar, "Predicted spectra against the AR baseline's **expected spectrum** at each window's action",
     "Which model knows the texture better? Like for like: both predict a spectrum from the same action, neither plays "
     "a random draw.",
     "The same predictions against the AR baseline used as a spectrum predictor: its expected amplitude spectrum at each "
     "test window's action (in closed form, or averaged over many renderings where the two disagree), not one random "
     "rendering. Like for like: which model knows the texture better?"},
    {Comparison::mean_spectrum, "Predicted spectra against each material's **mean training spectrum**",
     "Does the model use the actions? The mean spectrum is the best predictor that ignores force and speed; a model "
     "significantly worse than it has learnt less than the texture's average colour.",
     "The same predictions against a predictor that ignores the actions: each material's mean training spectrum, the "
     "same for every window (the baseline columns below). A model that uses force and speed should beat it; every "
     "material where it is significantly worse is named."},
    {Comparison::stitched, "The model's spectra **stitched** into a signal against the AR baseline rendered",
     "Signal against signal: which renders vibration closer to the recording? Both play one random draw (the stitched "
     "signal through its reconstructed phase).",
     ""},
};

const ComparisonText& comparison_text(Comparison kind) {
  for (const ComparisonText& c : kComparisons)
    if (c.kind == kind) return c;
  return kComparisons[0];
}

std::string_view experiment_explanation(std::string_view id) {
  if (const std::string_view own = comparison_text(comparison_of(id)).explanation; !own.empty()) return own;
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
  for (const PredictionsFile& p : e.predictions)
    s << "| predictions " << code(p.name) << (p.source.empty() ? "" : " (" + escaped(p.source) + ")") << " | " << code(p.path) << " | "
      << code(p.sha256) << " |\n";
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
       "When neither sample varies and their means differ, t is infinite and p = 0: the two do not overlap at all.\n\n"
    << "**Log-spectral distance** (LSD, dB, lower is better): the same windows compared on a log scale, the root mean "
       "square over the bins of 20 log10 of the two amplitudes' ratio, each amplitude raised to the material's noise "
       "level (the 5th percentile of the bin over its training windows) so that silent bins count as equal. The "
       "Euclidean distance is ruled by the loudest bins and the loudest materials; the LSD weighs them all alike.\n\n"
    << "**Noise floor** (m/s^2): the best any predictor can score on a material's test windows (section *Noise "
       "floor*). **Model/floor** is the model's distance over it: 1 is as good as possible. **Model/mean spectrum** is "
       "the model's distance over that of the material's mean training spectrum: below 1 where the model gains from "
       "the actions. A dash (–) marks a figure that was not measured.\n\n";
}

// Which experiments of this report compare kind, as code; "none".
std::string experiments_of(const Evaluation& e, Comparison kind) {
  std::string ids;
  for (const Experiment& x : e.experiments)
    if (comparison_of(x.id) == kind) ids += (ids.empty() ? "" : ", ") + code(x.id);
  return ids.empty() ? "none" : ids;
}

void questions_section(std::ostringstream& s, const Evaluation& e) {
  s << "## Which comparison answers which question\n\n| comparison | experiments here | question |\n|---|---|---|\n";
  for (const ComparisonText& c : kComparisons) s << "| " << c.what << " | " << experiments_of(e, c.kind) << " | " << c.question << " |\n";
  s << "| Model / noise floor | every experiment with a floor | How far from the best possible? 1 is as good as any "
       "predictor can be on these windows; clearly below 1 means the oracle is wrong or the model saw the test data. |\n"
    << "| Realism of rendered signals | every rendering scored | Does a rendered signal vary like the surface? The "
       "distances above reward the smooth expected spectrum, which no surface plays. |\n\n";
}

void totals_section(std::ostringstream& s, const Evaluation& e) {
  if (!section(s, "Totals", e.experiments.empty(), "No experiment was run (see Notes).")) return;
  s << "| experiment | materials | model better | significantly better | significantly worse | mean model | mean baseline "
       "| median model/floor | the paper (93 materials) |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const Experiment& x : e.experiments) {
    const auto paper = paper_figure(x.id);
    s << "| " << escaped(x.title) << " (" << code(x.id) << ") | " << x.materials.size() << " | " << x.better() << " ("
      << percent(x.better(), x.materials.size()) << ") | " << x.significantly_better() << " ("
      << percent(x.significantly_better(), x.materials.size()) << ") | " << x.significantly_worse() << " ("
      << percent(x.significantly_worse(), x.materials.size()) << ") | " << mean_text(x, x.mean_model()) << " | "
      << mean_text(x, x.mean_baseline()) << " | " << measured(x.median_floor_ratio()) << " | "
      << (paper ? paper->text() : "not in the paper") << " |\n";
  }
  s << "\nMean model and mean baseline: spectral distance in m/s^2, averaged over the materials. Median model/floor: "
       "over the materials with a noise floor (1: as good as possible). The paper's column "
       "quotes Heravi et al. (ICRA 2020) for the same experiment against its AR baseline.\n\n";
}

void material_table(std::ostringstream& s, const Experiment& x, const std::string& csv) {
  s << "| material | windows | model | baseline | difference Q1 | median | Q3 | t | p | result | LSD model (dB) "
       "| LSD baseline (dB) | floor (m/s^2) | model/floor | model/mean spectrum |\n"
    << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const MaterialComparison& m : x.materials)
    s << "| " << shown_name(m.name, m.id) << " | " << m.windows << " | " << format_number(m.model) << " | "
      << format_number(m.baseline) << " | " << format_number(m.difference.q1) << " | " << format_number(m.difference.median)
      << " | " << format_number(m.difference.q3) << " | " << format_number(m.test.t) << " | " << format_p(m.test.p) << " | "
      << (m.better() ? "better" : "worse") << (m.significant() ? " \\*" : "") << " | " << measured(m.model_lsd_db) << " | "
      << measured(m.baseline_lsd_db) << " | " << measured(m.floor) << " | " << measured(m.floor_ratio())
      << (m.below_floor ? " †" : "") << " | " << measured(m.mean_spectrum_ratio()) << " |\n";
  s << "\nModel and baseline: mean spectral distance (m/s^2) over the test windows. \\* significant: p < "
    << kSignificanceLevel << ". LSD: mean log-spectral distance over the same windows. Floor: the material's noise "
       "floor; model/floor and model/mean spectrum: the model's distance over the floor's and over the mean training "
       "spectrum's. † below the floor beyond sampling error. – not measured. Data: " << code(csv) << ".\n\n";
}

// "Against the noise floor (oracle): within 10 % of the floor on X of N materials ..." and a warning for any
// material below it; nothing without a floor.
void floor_totals(std::ostringstream& s, const Experiment& x, const std::string& floor_kind) {
  const std::size_t n = materials_with_floor(x);
  if (n == 0) return;
  s << "**Against the noise floor" << (floor_kind.empty() ? "" : " (" + escaped(floor_kind) + ")") << ":** within 10 % "
    << "of the floor on " << x.within_floor(0.10) << " of " << n << " " << materials_word(n) << ", within 15 % on "
    << x.within_floor(0.15) << "; model/floor median " << format_number(x.median_floor_ratio()) << ", worst "
    << format_number(x.worst_floor_ratio()) << "; below the floor on " << x.below_floor() << ".";
  if (n < x.materials.size()) s << " " << x.materials.size() - n << " " << materials_word(x.materials.size() - n) << " without a floor.";
  s << "\n\n";
  if (x.below_floor() > 0)
    s << "> **Warning:** the model scores below the floor on " << x.below_floor() << " " << materials_word(x.below_floor())
      << " (marked † below): the oracle is wrong or the model saw the test data.\n\n";
}

// Against the mean training spectrum: every material where the model is significantly worse, by name.
void worse_than_mean_spectrum(std::ostringstream& s, const Experiment& x) {
  if (comparison_of(x.id) != Comparison::mean_spectrum) return;
  std::string names;
  for (const MaterialComparison& m : x.materials)
    if (m.significant() && !m.better()) names += (names.empty() ? "" : "; ") + shown_name(m.name, m.id);
  s << "**Significantly worse than the material's mean training spectrum** (the model does not gain from the actions) "
       "on: " << (names.empty() ? "none" : names) << ".\n\n";
}

// unified-new-presses beside unified-new-actions of the same model: on how many materials the
// figures are the same, the press recognised as its material outright ("" for other experiments).
std::string recognition_note(const Evaluation& e, const Experiment& x) {
  constexpr std::string_view presses = "unified-new-presses", actions = "unified-new-actions";
  if (x.id.rfind(presses, 0) != 0) return "";
  const std::string twin = std::string(actions) + x.id.substr(presses.size());
  const auto other = std::find_if(e.experiments.begin(), e.experiments.end(), [&](const Experiment& y) { return y.id == twin; });
  if (other == e.experiments.end()) return "";
  std::size_t same = 0;
  for (const MaterialComparison& m : x.materials)
    for (const MaterialComparison& n : other->materials)
      same += m.id == n.id && std::abs(m.model - n.model) <= 1e-9 * std::max(std::abs(n.model), 1e-12);
  if (same == 0) return "";
  if (same == x.materials.size())
    return "**Here every test press was recognised as its own material outright:** these figures equal " + code(twin) +
           "'s and measure recognition, not how a new image carries over.\n\n";
  return text::format("On %zu of %zu materials the test press was recognised as its own material outright: there the figures "
                      "equal ", same, x.materials.size()) + code(twin) + "'s and measure recognition.\n\n";
}

void experiment_section(std::ostringstream& s, const Evaluation& e, const Experiment& x, const std::string& stem, const ChartResult& charts) {
  const std::string& floor_kind = e.floor_kind;
  s << "### " << escaped(x.title) << " (" << code(x.id) << ")\n\n";
  if (const std::string_view why = experiment_explanation(x.id); !why.empty()) s << why << "\n\n";
  s << recognition_note(e, x);
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
  s << "\n\n";
  floor_totals(s, x, floor_kind);
  worse_than_mean_spectrum(s, x);
  s << chart(charts, stem, "Baseline minus model per material: " + x.title, stem + ".csv");
  material_table(s, x, stem + ".csv");
}

std::string floor_kind_text(const std::string& kind) {
  if (kind == "oracle")
    return "**Oracle.** The process that generated every material's vibration is known (`--truth`: synthetic data), so "
           "the floor is its expected spectrum at each test window's action: the best any predictor can score, since "
           "what remains is the texture's own randomness and the sensor noise. A model clearly below it means the "
           "oracle is wrong or the model saw the test data.";
  if (kind == "estimate")
    return "**Estimate.** The generating process is unknown, so the floor is estimated: for each test window, the mean "
           "spectrum of the " + std::to_string(kNearestWindows) + " training windows nearest in action space (speed and "
           "force, each scaled by its spread). It is an estimate, not a bound: its own sampling error and the spread of "
           "actions among those windows put it above the true floor, so a good model may score below it.";
  return "The floor's kind was not recorded.";
}

void floor_section(std::ostringstream& s, const Evaluation& e) {
  if (!section(s, "Noise floor", e.floors.empty(), "No noise floor was computed.")) return;
  s << floor_kind_text(e.floor_kind) << "\n\n"
    << "| material | kind | method | windows | floor (m/s^2) | floor LSD (dB) | closed form | Monte Carlo "
       "| closed form vs Monte Carlo | rendered | rendered/floor | estimate | AR baseline expected | input floor |\n"
       "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const MaterialFloor& f : e.floors)
    s << "| " << shown_name(f.name, f.id) << " | " << escaped(f.kind) << " | " << escaped(f.method) << " | " << f.windows
      << " | " << measured(f.distance) << " | " << measured(f.lsd_db) << " | " << measured(f.closed_form) << " | "
      << measured(f.monte_carlo) << " | " << measured_percent(closed_form_gap_percent(f)) << " | " << measured(f.rendered)
      << " | " << measured(rendered_ratio(f)) << " | " << measured(f.estimate) << " | " << measured(f.baseline_expected) << " | " << measured(f.input_floor)
      << " |\n";
  s << "\nFloor: the floor's mean spectral distance to the recording over the material's test windows, and as "
       "log-spectral distance (for scale, not a bound: the LSD is lowest for a predictor about 0.85 times the oracle). Closed form and Monte Carlo (AR oracles): the expected spectra computed both ways, "
       "their distances, and how far apart their spectra are (the mean over windows of the closed form's summed "
       "amplitude against Monte Carlo's; the closed form is used while within 2 %). "
       "Rendered: the generating model rendered, one random rendering scored like the AR baseline; rendered/floor is "
       "well above 1 because the generating model rendered pays the randomness twice, once in the recording and once "
       "in its own rendering. Estimate: the empirical estimate (nearest training windows) beside the oracle, to "
       "check it. AR baseline expected: the baseline's expected spectrum at the recorded action, on the same windows, "
       "for scale. Input floor (oracles): the generating process knowing only what the model is given, the recorded "
       "action at each window's middle held over the window; a model above it has learning left to do, the floor below "
       "it is what the model's input cannot tell. – not measured. Data: " << code(std::string(kFloorsStem) + ".csv") << ".\n\n";
}

void realism_section(std::ostringstream& s, const Evaluation& e) {
  if (!section(s, "Realism of rendered signals", e.realism.empty(), "No rendered signal was scored for realism.")) return;
  s << "Window-by-window distances reward the smooth expected spectrum, which no real surface plays. These figures ask "
       "instead whether a rendered signal varies like the recording, per material over its test sections, here as the "
       "median over materials.\n\n"
    << "| method | setting | materials | median section LSD (dB) | median spread ratio | spread 0.8 to 1.2 | median distance / "
       "oracle | median distance / oracle rendered | within 25 % of the oracle rendered |\n|---|---|---|---|---|---|---|---|---|\n";
  for (const Realism& r : e.realism) {
    const RealismMedians m = realism_medians(r);
    const bool rendered_floor = std::isfinite(m.rendered_floor_ratio);
    s << "| " << escaped(r.method) << " | " << escaped(r.setting) << " | " << m.materials << " | " << measured(m.section_lsd_db)
      << " | " << measured(m.spread_ratio) << " | " << m.spread_in_range << " | " << measured(m.floor_ratio) << " | "
      << measured(m.rendered_floor_ratio) << " | " << (rendered_floor ? std::to_string(m.near_rendered_floor) : "–") << " |\n";
  }
  s << "\n**Section LSD**: the log-spectral distance (dB) of the section-average power spectra, rendered against "
       "recorded: is the overall colour right? **Spread ratio**: per frequency bin, the coefficient of variation "
       "(standard deviation / mean) of the window amplitudes, rendered over recorded, the median over the bins. 1 = as "
       "steady as the recording; < 1 too steady (Griffin-Lim from smooth predicted spectra); > 1 too wild. Noise-like "
       "texture at a steady action has a per-bin coefficient of variation of about 0.52 (Rayleigh amplitudes). "
       "**Distance / oracle rendered**: the rendering's mean window distance over that of the generating model's own "
       "renderings (AR oracles): a rendering that varies like the surface pays the randomness twice, so even a perfect "
       "one scores about sqrt(2) times the oracle; the generating model rendered is the floor a rendering is measured "
       "against, and a rendering that is both real and close stays within 25 % of it. "
       "Materials: those with a spread ratio. Per material: " << code(std::string(kRealismStem) + ".csv") << ".\n\n";
}

void examples_section(std::ostringstream& s, const Evaluation& e, const ReportLayout& layout, const ChartResult& charts) {
  if (!section(s, "Examples", e.examples.empty(), "No examples were recorded.")) return;
  s << "As the paper's Fig. 5: for each material below, the top plot shows the amplitude spectra of one test window "
       "(recorded, model, baseline), the bottom one the start of a test section as time signals (the model's signal "
       "stitched by phase reconstruction). Materials:";
  for (std::size_t i = 0; i < e.examples.size(); ++i)
    s << (i ? "; " : " ") << shown_name(e.examples[i].name, e.examples[i].id);
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
       "spectral distance over the test windows, one row per method and setting. Kind: `spectrum` for a method that "
       "predicts spectra, `signal` for one that renders vibration; for signals the medians over materials of the "
       "realism figures (section *Realism of rendered signals*).\n\n"
    << "| method | setting | compute time per second of vibration | mean spectral distance (m/s^2) | kind "
       "| section LSD (dB) | spread ratio |\n|---|---|---|---|---|---|---|\n";
  for (const SpeedPoint& p : e.speed)
    s << "| " << escaped(p.method) << " | " << escaped(p.setting) << " | " << format_number(1000 * p.seconds_per_second)
      << " ms | " << format_number(p.distance) << " | " << escaped(p.kind) << " | " << measured(p.section_lsd_db) << " | "
      << measured(p.spread_ratio) << " |\n";
  s << "\n"
    << chart(charts, std::string(kSpeedStem),
             "Speed against accuracy: spectrum accuracy (left) and signal realism (right)", std::string(kSpeedStem) + ".csv");
}

void notes_section(std::ostringstream& s, const Evaluation& e, const ChartResult& charts) {
  std::vector<std::string> notes = e.notes;
  if (!charts.note.empty()) notes.push_back(charts.note);
  s << "## Notes\n\n";
  if (notes.empty()) s << "None: every experiment ran on every material.\n";
  for (const std::string& n : notes) s << "- " << escaped(n) << "\n";
  s << "\n";
}

// A CSV header as code: "`a`, `b`, `c`".
std::string column_list(std::string_view header) {
  std::string s = "`";
  for (char c : header) s += c == ',' ? std::string("`, `") : std::string(1, c);
  return s + "`";
}

void files_section(std::ostringstream& s, const ReportLayout& layout, const ChartResult& charts) {
  s << "## Files\n\n"
    << "- `report.md`: this report.\n"
    << "- `results.json`: everything above, machine-readable (haptex's `schemas/results.schema.json`; infinite or "
       "undefined numbers are the strings \"inf\", \"-inf\", \"nan\"; a figure that was not measured is null).\n";
  if (!layout.experiments.empty()) {
    s << "- One CSV per experiment, a row per material:";
    for (std::size_t i = 0; i < layout.experiments.size(); ++i) s << (i ? ", " : " ") << code(layout.experiments[i] + ".csv");
    s << ". Columns: `material_id`, `name`, `windows` (test windows), `model_distance` and `baseline_distance` (mean "
         "spectral distance, m/s^2), `difference_q1`, `difference_median`, `difference_q3` (baseline - model), `t`, `df`, "
         "`p` (Welch's test), `n_model` and `n_baseline` (the window distances it compared), `better` and `significant` "
         "(1 or 0), `model_lsd_db` and `baseline_lsd_db` (mean log-spectral distance, dB), `floor` (the noise floor, "
         "m/s^2), `floor_ratio` (model / floor), `mean_spectrum` (the mean training spectrum's distance), "
         "`mean_spectrum_ratio` (model / mean spectrum), `below_floor` (1 or 0).\n";
  }
  s << "- `speed.csv`: the speed-vs-accuracy points (" << column_list(kSpeedColumns) << ").\n"
    << "- `latents.csv`: the texture map's coordinates (" << column_list(kLatentColumns) << ").\n"
    << "- `floors.csv`: the noise floor per material (" << column_list(kFloorColumns) << ").\n"
    << "- `realism.csv`: realism per rendering method and material (" << column_list(kRealismColumns) << ").\n";
  if (!layout.examples.empty()) {
    s << "- Two CSVs per example:";
    for (std::size_t i = 0; i < layout.examples.size(); ++i)
      s << (i ? ", " : " ") << code(layout.examples[i] + "-spectra.csv") << ", " << code(layout.examples[i] + "-signals.csv");
    s << ". Columns: `frequency_hz` or `time_s`, then `truth` (the recording), `model`, `baseline`.\n";
  }
  if (!charts.scripts.empty())
    s << "- `*.gnuplot`: the chart scripts; run `gnuplot NAME.gnuplot` in this folder to draw NAME.png again.\n";
  if (!charts.images.empty()) s << "- `*.png`: the charts.\n";
  s << "\nCSV numbers are written to full precision; `inf`, `-inf` and `nan` mark values that are not finite, an empty "
       "cell a figure that was not measured.\n";
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
  return p < 1e-3 ? text::format("%.2e", p) : text::format("%.3g", p);
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
  questions_section(s, e);
  totals_section(s, e);
  if (!e.experiments.empty()) s << "## Experiments\n\n";
  for (std::size_t i = 0; i < e.experiments.size(); ++i)
    experiment_section(s, e, e.experiments[i], layout.experiments[i], charts);
  floor_section(s, e);
  realism_section(s, e);
  examples_section(s, e, layout, charts);
  latents_section(s, e, charts);
  speed_section(s, e, charts);
  notes_section(s, e, charts);
  files_section(s, layout, charts);
  return s.str();
}

}  // namespace haptex::evaluate
