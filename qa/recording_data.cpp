#include "qa/recording_data.hpp"

#include "core/error.hpp"
#include "dataset/layout.hpp"
#include "dataset/object_paths.hpp"
#include "qa/thresholds.hpp"

namespace haptex::qa {

namespace layout = dataset::layout;
namespace {

Signal read_signal(const h5::Group& group, const std::string& name, std::size_t columns,
                   std::optional<std::size_t> rows) {
  Signal s;
  s.columns = columns;
  if (!group.has_dataset(name)) {
    s.problem = "missing";
    return s;
  }
  const h5::Dataset d = group.open_dataset(name);
  const h5::Shape shape = d.shape();
  const bool shape_ok = columns == 1 ? shape.size() == 1 : shape.size() == 2 && shape[1] == columns;
  if (!shape_ok || (rows && shape[0] != *rows)) {
    s.problem = "unexpected shape";
    return s;
  }
  const std::string dtype = d.dtype();
  if (dtype.rfind("float", 0) != 0 && dtype.rfind("int", 0) != 0 && dtype.rfind("uint", 0) != 0) {
    s.problem = "not numeric (" + dtype + ")";
    return s;
  }
  if (const std::string chunks = d.chunk_problem(); !chunks.empty()) {
    s.problem = chunks;  // layout.links reports it; reading would inflate the whole chunk
    return s;
  }
  s.rows = shape[0];
  s.values = d.read<double>();
  return s;
}

}  // namespace

const std::vector<SignalSpec> kSignalSpecs = {
    {layout::kAccel, 1, false},       {layout::kAccelXyz, 3, false},        {layout::kForceNormal, 1, false},
    {layout::kForceNormalLp, 1, false}, {layout::kSpeed, 1, false},        {layout::kSpeedLp, 1, false},
    {layout::kForceTangential, 1, true}, {layout::kPosition, 3, true},
};

std::vector<double> Signal::column(std::size_t c) const {
  std::vector<double> out(rows);
  for (std::size_t i = 0; i < rows; ++i) out[i] = values[i * columns + c];
  return out;
}

double LoadedRecording::analysis_rate() const {
  return sample_rate_hz && *sample_rate_hz > 0 ? *sample_rate_hz : kSampleRateHz;
}

std::vector<std::string> recording_paths(const h5::Group& root) {
  std::vector<std::string> paths;
  if (!root.has_group(layout::kMaterials)) return paths;
  const h5::Group materials = root.open_group(layout::kMaterials);
  for (const auto& id : materials.children()) {
    if (!materials.has_group(id)) continue;
    const h5::Group material = materials.open_group(id);
    if (!material.has_group(layout::kRecordings)) continue;
    const h5::Group recordings = material.open_group(layout::kRecordings);
    for (const auto& k : recordings.children())
      if (recordings.has_group(k)) paths.push_back(dataset::recording_path(id, k));
  }
  return paths;
}

LoadedRecording load_recording(const h5::Group& root, const std::string& path) {
  const h5::Group group = root.open_group(path.substr(1));
  LoadedRecording r;
  r.path = path;
  r.material = dataset::material_of(path);
  r.sample_rate_hz = group.try_attr<double>(layout::kSampleRate);
  r.duration_s = group.try_attr<double>(layout::kDuration);
  r.samples = group.try_attr<std::int64_t>(layout::kSamples);
  r.source_sha256 = group.try_attr<std::string>(layout::kSourceSha256);
  r.lowpass_order = group.try_attr<std::int64_t>(layout::kLowpassOrderAttr);
  r.lowpass_cutoff_hz = group.try_attr<double>(layout::kLowpassCutoffAttr);
  r.reduction_window = group.try_attr<std::int64_t>(layout::kAccelReductionWindow);
  r.reduction_hop = group.try_attr<std::int64_t>(layout::kAccelReductionHop);
  // Rows: the recording's `samples`; without it, whatever `accel` has (layout.required reports it).
  std::optional<std::size_t> rows;
  if (r.samples && *r.samples >= 0) rows = std::size_t(*r.samples);
  for (const auto& spec : kSignalSpecs) {
    Signal s = read_signal(group, spec.name, spec.columns, rows);
    if (!rows && s.ok()) rows = s.rows;
    r.signals.emplace(spec.name, std::move(s));
  }
  return r;
}

}  // namespace haptex::qa
