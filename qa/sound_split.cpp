#include "qa/sound_split.hpp"

#include "core/error.hpp"
#include "qa/checkers.hpp"

namespace haptex::qa {

void require_sound_split(const split::SplitManifestDocument& manifest, const std::string& dataset_path, Manifest state) {
  for (const CheckResult& check : check_split(manifest, dataset_path)) {
    if (check.severity != Severity::error || check.status != Status::fail) continue;
    if (state == Manifest::about_to_be_written)
      throw input_error(dataset_path, "", "the split made from it fails " + check.id + ": " + check.message,
                        check.hint + ". Nothing was written");
    throw input_error(manifest.path, "", check.message + " (" + check.id + ")",
                      check.hint + ". `haptex qa " + dataset_path + " --split " + manifest.path + "` lists every problem");
  }
}

}  // namespace haptex::qa
