#include "split/split_manifest.hpp"

#include <algorithm>

#include "core/h5/file.hpp"
#include "core/sha256.hpp"
#include "core/version.hpp"
#include "dataset/layout.hpp"

namespace haptex::split {
namespace {

nlohmann::json sets_json(const Sets& s) { return {{"train", s.train}, {"val", s.val}, {"test", s.test}}; }

}  // namespace

nlohmann::json manifest_json(const std::string& dataset_path, const SplitOptions& o,
                             const std::vector<MaterialSplit>& materials, const std::string& source) {
  const h5::Group root = h5::File::open(dataset_path).root();
  nlohmann::json list = nlohmann::json::array();
  double worst = 1.0;
  for (const MaterialSplit& m : materials) {
    worst = std::min(worst, m.worst());
    list.push_back({{"id", m.id},
                    {"name", m.name},
                    {"recordings", m.recordings},
                    {"sections", sets_json(m.sections)},
                    {"windows", {{"train", m.train_windows}, {"val", m.val_windows}, {"test", m.test_windows},
                                 {"crossing", m.crossing_windows}}},
                    {"coverage", {{"val", m.val_coverage}, {"test", m.test_coverage}}},
                    {"presses", sets_json(m.presses)}});
  }
  return {{"format", kManifestFormat},
          {"haptex_version", kVersion},
          {"created_utc", h5::utc_now_iso8601()},
          {"source", source},
          {"dataset", {{"path", dataset_path}, {"sha256", sha256_file(dataset_path)},
                       {"recordings_sha256", root.attr_string(dataset::layout::kRecordingsSha256)},
                       {"gelsight_sha256", root.attr_string(dataset::layout::kGelsightSha256)}}},
          {"parameters", {{"sections", o.sections}, {"val", o.val}, {"test", o.test}, {"seed", o.seed},
                          {"min_coverage", o.min_coverage}, {"tries", o.tries}}},
          {"materials", list},
          {"worst_coverage", worst}};
}

}  // namespace haptex::split
