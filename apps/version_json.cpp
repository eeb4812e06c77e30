#include "apps/version_json.hpp"

#include <string>
#include <vector>

#include "capture/recording/session_manifest.hpp"
#include "core/version.hpp"
#include "dataset/format.hpp"
#include "dataset/layout.hpp"
#include "evaluate/report/results_json.hpp"
#include "predict/train.hpp"
#include "split/split_manifest.hpp"

namespace haptex::apps {

nlohmann::json version_json() {
  std::vector<std::string> hdf5;
  for (const dataset::Format& f : dataset::formats()) hdf5.push_back(dataset::format_name(f.kind));
  return {{"haptex_version", kVersion},
          {"formats",
           {{"hdf5_written", hdf5},
            {"json_written", {split::kManifestFormat, predict::kTrainingLogFormat, capture::kSessionManifestFormat, evaluate::kResultsFormat}},
            {"hdf5_read", {std::string(dataset::layout::kPredictionsFormat)}}}}};
}

}  // namespace haptex::apps
