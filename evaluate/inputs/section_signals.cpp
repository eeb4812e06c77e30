#include "evaluate/inputs/section_signals.hpp"

#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/signal/spectrum.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"
#include "dataset/recordings_file.hpp"
#include "split/sections.hpp"

namespace haptex::evaluate {
namespace {

std::vector<double> widened(const std::vector<float>& v) { return {v.begin(), v.end()}; }

SectionSignals cut(const std::vector<double>& accel, const std::vector<double>& force, const std::vector<double>& speed, int recording,
                   const std::string& source_sha256, int section, std::size_t sections) {
  const auto n = std::int64_t(accel.size());
  const std::int64_t b = split::section_begin(std::size_t(section), n, sections), e = split::section_begin(std::size_t(section) + 1, n, sections);
  auto part = [&](const std::vector<double>& v) { return std::vector<double>(v.begin() + b, v.begin() + e); };
  return {recording, section, source_sha256, b, part(accel), part(force), part(speed)};
}

}  // namespace

std::vector<TrainingPiece> MaterialSignals::pieces() const {
  std::vector<TrainingPiece> out;
  for (const SectionSignals& s : training) out.push_back({s.accel, s.force, s.speed});
  return out;
}

std::vector<MaterialSignals> read_section_signals(const split::DatasetSplit& split) {
  const h5::File file = dataset::open_checked(split.dataset_path, dataset::Kind::dataset);
  std::vector<MaterialSignals> out;
  for (const split::MaterialSets& m : split.materials) {
    MaterialSignals signals{m.id, m.name, {}, {}};
    const h5::Group recordings = file.root().open_group(std::string(dataset::layout::kMaterials) + "/" + m.id + "/" + dataset::layout::kRecordings);
    for (const std::string& k : recordings.children()) {
      const dataset::RecordingSignals r = dataset::read_recording_signals(recordings.open_group(k));
      const auto accel = widened(r.accel), force = widened(r.force_lp), speed = widened(r.speed_lp);
      const std::string& sha = r.source_sha256;
      for (int s : m.sections[split::kTest]) signals.test.push_back(cut(accel, force, speed, std::stoi(k), sha, s, split.sections));
      for (std::size_t set : {split::kTrain, split::kVal})
        for (int s : m.sections[set]) signals.training.push_back(cut(accel, force, speed, std::stoi(k), sha, s, split.sections));
    }
    out.push_back(std::move(signals));
  }
  return out;
}

std::vector<std::size_t> section_grid(std::size_t samples) {
  const std::vector<std::int64_t> starts = dataset::window_starts(samples, dataset::kGridStride);
  return {starts.begin(), starts.end()};
}

Eigen::MatrixXf grid_actions(const SectionSignals& s, const std::vector<std::size_t>& grid) {
  Eigen::MatrixXf out(Eigen::Index(dataset::kActionValues), Eigen::Index(grid.size()));
  for (std::size_t j = 0; j < grid.size(); ++j)
    dataset::action_ending_at<double>(s.force, s.speed, grid[j] + dataset::kActionEnd,
                                      std::span(out.col(Eigen::Index(j)).data(), dataset::kActionValues));
  return out;
}

std::vector<std::vector<double>> grid_spectra(const std::vector<double>& signal, const std::vector<std::size_t>& grid, std::size_t origin) {
  std::vector<std::vector<double>> out;
  for (std::size_t t : grid) {
    if (t < origin || t - origin + dataset::kWindowSamples > signal.size()) throw failure("grid_spectra: window outside the signal");
    out.push_back(signal::amplitude_spectrum(std::span(signal).subspan(t - origin, dataset::kWindowSamples), dataset::kTargetBins));
  }
  return out;
}

}  // namespace haptex::evaluate
