#pragma once
// The checks that say whether a file holds what its haptex_format promises, as opposed to whether
// its data is good enough to train on: the layout (layout.*), finite signals at the format's rate
// (signal.nan, signal.sample_rate) made with the format's filter (filter.stated), no recording or press
// twice (recordings.duplicate, gelsight.duplicate: a leak between train and test, however good the data),
// press images in a known channel order (gelsight.channel_order)
// and whole (gelsight.images), frame numbers that agree (gelsight.frame_numbers), and a window table that matches its recordings (dataset.windows,
// dataset.cache). `haptex merge` refuses a shard that fails any of them (docs/merge.md): it reads
// what it copies as strictly as qa does. The quality checks stay qa's, run on the merged file.
#include <string>
#include <vector>

#include "core/h5/node.hpp"
#include "dataset/format.hpp"
#include "qa/check.hpp"

namespace haptex::qa {

// The integrity checks of a recordings, gelsight or dataset file, in catalog order.
std::vector<CheckResult> check_integrity(const h5::Group& root, dataset::Kind kind);

// Throws haptex::Error (bad_input) naming the file, the first failed place, the check and the fix
// when check_integrity finds anything.
void require_integrity(const h5::Group& root, dataset::Kind kind);

// The layout checks (layout.*) and the window table's (dataset.windows, dataset.cache) on the dataset
// at path, which split, windows, train and evaluate read their windows, actions and targets from: a
// table qa fails (rows twice, out of order, targets that are not the recordings' spectra) never
// splits, trains or scores (review 12, F4), and neither does a file whose objects qa calls malformed,
// even ones these commands do not read (review 18, F9: a press @fps of two values or NaN). The image
// and signal checks stay qa's and align's: they decode every image. Throws as require_integrity.
void require_sound_dataset(const std::string& dataset_path);

// The layout checks (layout.*) alone, for a reader of recordings that reads no window (trajectory):
// its messages count on what the layout holds, e.g. recordings numbered 0..n-1. Throws as require_integrity.
void require_sound_layout(const h5::Group& root, dataset::Kind kind);

}  // namespace haptex::qa
