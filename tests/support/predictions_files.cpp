#include "tests/support/predictions_files.hpp"

#include "core/h5/file.hpp"
#include "dataset/layout.hpp"

namespace haptex::test {

GridTable read_grid(const std::string& windows_file) {
  const h5::File f = h5::File::open(windows_file);
  const h5::Group w = f.root().open_group("windows");
  GridTable g{f.root().attr_string("dataset_sha256"), f.root().attr_string("split_sha256"), w.open_dataset("materials").read_strings(),
              w.open_dataset("material").read<std::int32_t>(), w.open_dataset("recording").read<std::int32_t>(),
              w.open_dataset("section").read<std::int32_t>(), w.open_dataset("start").read<std::int64_t>(),
              w.open_dataset("target").read<float>()};
  return g;
}

std::vector<GridSpan> grid_spans(const GridTable& g) {
  std::vector<GridSpan> out;
  for (std::size_t i = 0; i < g.rows(); ++i) {
    const bool same = i > 0 && g.material[i] == g.material[i - 1] && g.recording[i] == g.recording[i - 1] && g.section[i] == g.section[i - 1];
    if (!same) out.push_back({i, 0, g.start[i], 0});
    GridSpan& s = out.back();
    ++s.rows;
    s.covered = std::size_t(g.start[i] - s.first_start) + 1000;
  }
  return out;
}

Predictions perfect_predictions(const GridTable& grid, const std::string& dataset) {
  Predictions p{"predictions/1", grid.dataset_sha256, grid.split_sha256, "tests: the recorded spectra and signals", grid.target,
                {grid.rows(), 100}, 1e-4, {}};
  if (dataset.empty()) return p;
  const h5::File f = h5::File::open(dataset);
  for (const GridSpan& s : grid_spans(grid)) {
    const std::string recording = std::string(dataset::layout::kMaterials) + "/" + grid.materials[std::size_t(grid.material[s.first_row])] +
                                  "/" + dataset::layout::kRecordings + "/" + std::to_string(grid.recording[s.first_row]);
    const std::vector<float> accel = f.root().open_group(recording).open_dataset(dataset::layout::kAccel).read<float>();
    p.signals.emplace_back(accel.begin() + s.first_start, accel.begin() + s.first_start + std::ptrdiff_t(s.covered));
  }
  return p;
}

void write_predictions(const std::string& path, const Predictions& p) {
  h5::File f = h5::File::create(path);
  h5::Group root = f.root();
  root.set_attr("predictions_format", p.format);
  root.set_attr("dataset_sha256", p.dataset_sha256);
  root.set_attr("split_sha256", p.split_sha256);
  root.set_attr("source", p.source);
  if (p.query_seconds) root.set_attr("query_seconds", *p.query_seconds);
  if (!p.shape.empty()) root.write_array<float>("spectra", p.spectra, p.shape);
  if (!p.signals.empty()) {
    h5::Group signals = root.create_group("signals");
    signals.set_attr("seconds", 0.01);
    for (std::size_t k = 0; k < p.signals.size(); ++k) signals.write(std::to_string(k), p.signals[k]);
  }
  f.close();
}

}  // namespace haptex::test
