#include "qa/sound_split.hpp"

#include "core/error.hpp"
#include "qa/checkers.hpp"

namespace haptex::qa {

void require_sound_split(const split::SplitManifestDocument& manifest, const std::string& dataset_path) {
  for (const CheckResult& check : check_split(manifest, dataset_path)) {
    if (check.severity != Severity::error || check.status != Status::fail) continue;
    throw input_error(manifest.path, "", check.message + " (" + check.id + ")",
                      check.hint + ". `haptex qa " + dataset_path + " --split " + manifest.path + "` lists every problem");
  }
}

}  // namespace haptex::qa
