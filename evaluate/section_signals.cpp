#include "evaluate/section_signals.hpp"

#include "align/window_table.hpp"
#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/signal/spectrum.hpp"
#include "split/sections.hpp"

namespace haptex::evaluate {
namespace {

using align::kActionSamples;

std::vector<double> read_signal(const h5::Group& recording, const char* name, const std::string& file) {
  if (!recording.has_dataset(name))
    throw input_error(file, recording.object_path() + "/" + name, "missing", "Run haptex convert and haptex align again");
  const std::vector<float> v = recording.open_dataset(name).read<float>();
  return {v.begin(), v.end()};
}

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
  const h5::File file = h5::File::open(split.dataset_path);
  std::vector<MaterialSignals> out;
  for (const split::MaterialSets& m : split.materials) {
    MaterialSignals signals{m.id, m.name, {}, {}};
    const h5::Group recordings = file.root().open_group("materials/" + m.id + "/recordings");
    for (const std::string& k : recordings.children()) {
      const h5::Group r = recordings.open_group(k);
      const auto accel = read_signal(r, "accel", split.dataset_path), force = read_signal(r, "force_normal_lp", split.dataset_path),
                 speed = read_signal(r, "speed_lp", split.dataset_path);
      if (force.size() != accel.size() || speed.size() != accel.size())
        throw input_error(split.dataset_path, r.object_path(), "signals of different lengths", "Run haptex convert again");
      const std::string sha = r.has_attr("source_sha256") ? r.attr_string("source_sha256") : std::string();
      for (int s : m.sections[split::kTest]) signals.test.push_back(cut(accel, force, speed, std::stoi(k), sha, s, split.sections));
      for (std::size_t set : {split::kTrain, split::kVal})
        for (int s : m.sections[set]) signals.training.push_back(cut(accel, force, speed, std::stoi(k), sha, s, split.sections));
    }
    out.push_back(std::move(signals));
  }
  return out;
}

std::vector<std::size_t> section_grid(std::size_t samples) {
  const std::vector<std::int64_t> starts = align::window_starts(samples, kSectionGridStride);
  return {starts.begin(), starts.end()};
}

Eigen::MatrixXf grid_actions(const SectionSignals& s, const std::vector<std::size_t>& grid) {
  Eigen::MatrixXf out(2 * Eigen::Index(kActionSamples), Eigen::Index(grid.size()));
  for (std::size_t j = 0; j < grid.size(); ++j)
    for (std::size_t k = 0; k < kActionSamples; ++k) {
      const std::size_t i = std::size_t(align::window_action_first(std::int64_t(grid[j]))) + k;
      out(Eigen::Index(k), Eigen::Index(j)) = float(s.force[i]);
      out(Eigen::Index(kActionSamples + k), Eigen::Index(j)) = float(s.speed[i]);
    }
  return out;
}

std::vector<std::vector<double>> grid_spectra(const std::vector<double>& signal, const std::vector<std::size_t>& grid, std::size_t origin) {
  std::vector<std::vector<double>> out;
  for (std::size_t t : grid) {
    if (t < origin || t - origin + signal::kWindowSamples > signal.size()) throw failure("grid_spectra: window outside the signal");
    out.push_back(signal::amplitude_spectrum(std::span(signal).subspan(t - origin, signal::kWindowSamples)));
  }
  return out;
}

}  // namespace haptex::evaluate
