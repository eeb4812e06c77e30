#pragma once
// The groups of checks run_qa() (qa/run_qa.hpp) puts together per kind of file. Each returns one
// CheckResult per check id it owns, in catalog order; none throws for a defect of the file it is
// checking (that is a failed check), only for files it cannot read at all.
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "core/h5/node.hpp"
#include "qa/check.hpp"
#include "qa/recording_data.hpp"
#include "split/manifest_reader.hpp"

namespace haptex::qa {

// The split manifest reader lives in split/ (train and evaluate read manifests too).
using split::kSetNames;
using split::SplitManifest;
using split::SplitManifestDocument;
using split::SplitMaterial;
using split::SplitSet;

// layout.*: the file against the tables of schemas/hdf5-layout.md for its haptex_format.
std::vector<CheckResult> check_layout(const h5::Group& root, const std::string& format);

// signal.*: per recording.
class SignalChecks {
 public:
  SignalChecks();
  void add(const LoadedRecording& recording);
  std::vector<CheckResult> results() const;

 private:
  CheckTally nan_, rate_, duration_, short_, clipping_, force_, speed_, spectrum_, reduction_;
  // The worst values seen, for the pass messages.
  double worst_clip_share_ = 0, force_lo_ = INFINITY, force_hi_ = -INFINITY, speed_lo_ = INFINITY,
         speed_hi_ = -INFINITY, lowest_band_share_ = INFINITY, reduction_lo_ = INFINITY, reduction_hi_ = 0;
};

// filter.*: the low-passed and raw force and speed of each recording.
class FilterChecks {
 public:
  FilterChecks();
  void add(const LoadedRecording& recording);
  std::vector<CheckResult> results() const;

 private:
  CheckTally lowpass_, raw_;
  double highest_lowpass_share_ = 0, lowest_raw_share_ = INFINITY;
};

// recordings.duplicate: over all recordings of the file.
class DuplicateCheck {
 public:
  DuplicateCheck();
  void add(const LoadedRecording& recording);
  std::vector<CheckResult> results() const;

 private:
  CheckTally tally_;
  std::vector<std::pair<std::string, std::string>> source_hashes_, data_hashes_;  // hash, path
};

// All recording checks over every recording of a recordings or dataset file.
std::vector<CheckResult> check_recordings(const h5::Group& root);

// gelsight.*: every press of a gelsight or dataset file.
std::vector<CheckResult> check_gelsight(const h5::Group& root);

// dataset.*: the window table of a dataset file against its recordings.
std::vector<CheckResult> check_dataset(const h5::Group& root);

// split.*: a manifest, with the dataset file it was made from when that is at hand.
std::vector<CheckResult> check_split(const SplitManifestDocument& manifest, const std::optional<std::string>& dataset_path);

}  // namespace haptex::qa
