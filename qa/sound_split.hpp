#pragma once
// The gate split, train and evaluate pass a manifest through: the same split.* checks `haptex qa
// --split` runs (qa/split_checks.cpp), so a leaky, empty or hand-damaged split never trains a model or
// yields a report. One validation, three callers (docs/split.md).
#include <string>

#include "split/manifest_reader.hpp"

namespace haptex::qa {

// Throws haptex::Error (bad input) naming the manifest, the place in it (material, sections) and
// the fix when any split.* check of severity error fails against dataset_path.
// A manifest `haptex split` has just made and not yet written is not the file at fault: the error
// then names the dataset and says nothing was written (review 13, C2).
enum class Manifest { written, about_to_be_written };
void require_sound_split(const split::SplitManifestDocument& manifest, const std::string& dataset_path,
                         Manifest state = Manifest::written);

}  // namespace haptex::qa
