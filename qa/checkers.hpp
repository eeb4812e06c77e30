#pragma once
// The groups of checks run_qa() (qa/run_qa.hpp) puts together per kind of file. Each returns one
// CheckResult per check id it owns, in catalog order; none throws for a defect of the file it is
// checking (that is a failed check), only for files it cannot read at all. Within a group every
// check is one function named after its id (check_signal_nan for signal.nan, ...), and the group
// function reads like its part of the catalog (qa/catalog.cpp, docs/qa.md).
#include <optional>
#include <string>
#include <vector>

#include "core/h5/node.hpp"
#include "dataset/format.hpp"
#include "qa/check.hpp"
#include "split/manifest_reader.hpp"

namespace haptex::qa {

// The split manifest reader lives in split/ (train and evaluate read manifests too).
using split::kSetNames;
using split::SplitManifest;
using split::SplitManifestDocument;
using split::SplitMaterial;
using split::SplitSet;

// layout.*: the file against the tables of schemas/hdf5-layout.md for its haptex_format.
std::vector<CheckResult> check_layout(const h5::Group& root, dataset::Kind kind);

// signal.*, filter.* and recordings.duplicate over every recording of a recordings or dataset file
// (qa/recording_checks.hpp).
std::vector<CheckResult> check_recordings(const h5::Group& root);

// gelsight.*: every press of a gelsight or dataset file (qa/gelsight_checks.hpp).
std::vector<CheckResult> check_gelsight(const h5::Group& root);

// dataset.*: the window table of a dataset file against its recordings.
std::vector<CheckResult> check_dataset(const h5::Group& root);

// split.*: a manifest, with the dataset file it was made from when that is at hand (qa/split_checks.hpp).
std::vector<CheckResult> check_split(const SplitManifestDocument& manifest, const std::optional<std::string>& dataset_path);

}  // namespace haptex::qa
