#include "evaluate/inputs/evaluation_grid.hpp"


namespace haptex::evaluate {
namespace {

// One test section's windows appended to the grid: the same offsets, actions and spectra the
// evaluation scores (section_grid, grid_actions, grid_spectra).
void append_section(EvaluationGrid& g, std::int32_t material, std::int32_t press, const SectionSignals& s) {
  const std::vector<std::size_t> offsets = section_grid(s.accel.size());
  if (offsets.empty()) return;
  const Eigen::MatrixXf actions = grid_actions(s, offsets);
  const std::vector<std::vector<double>> spectra = grid_spectra(s.accel, offsets);
  dataset::WindowTable& w = g.windows;
  for (std::size_t j = 0; j < offsets.size(); ++j) {
    w.material.push_back(material);
    w.recording.push_back(s.recording);
    w.start.push_back(s.begin + std::int64_t(offsets[j]));
    w.action.insert(w.action.end(), actions.col(Eigen::Index(j)).data(), actions.col(Eigen::Index(j)).data() + dataset::kActionValues);
    w.target.insert(w.target.end(), spectra[j].begin(), spectra[j].end());
    g.section.push_back(s.section);
    g.press.push_back(press);
  }
}

}  // namespace

EvaluationGrid evaluation_grid(const split::DatasetSplit& split, const std::vector<MaterialSignals>& signals) {
  EvaluationGrid g;
  g.dataset_sha256 = split.dataset_sha256, g.split_sha256 = split.manifest_sha256;
  g.windows.stride = dataset::kGridStride;
  for (std::size_t m = 0; m < signals.size(); ++m) {
    // A sound split (qa/sound_split.hpp, which the command passes it through) gives every material
    // exactly one test press; the new-press experiment encodes it.
    const int press = split.materials[m].presses[split::kTest].front();
    g.windows.materials.push_back(signals[m].id);
    for (const SectionSignals& s : signals[m].test) append_section(g, std::int32_t(m), press, s);
  }
  return g;
}

}  // namespace haptex::evaluate
