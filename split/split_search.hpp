#pragma once
// The split (docs/split.md): per material, the recordings' sections regrouped into train,
// validation and test sets from a seed; among `tries` assignments the one whose worse of validation
// and test coverage is best is kept; presses 3/1/1.
#include <cstdint>
#include <string>
#include <vector>

#include "split/dataset_view.hpp"

namespace haptex::split {

struct SplitOptions {
  std::size_t sections = 25, val = 3, test = 3;
  std::uint64_t seed = 0;
  double min_coverage = 0.9;
  int tries = 200;
};

struct Sets {
  std::vector<int> train, val, test;
};

struct MaterialSplit {
  std::string id, name;
  std::size_t recordings = 0;
  Sets sections, presses;
  std::size_t train_windows = 0, val_windows = 0, test_windows = 0, crossing_windows = 0;
  double val_coverage = 0, test_coverage = 0;
  double worst() const { return std::min(val_coverage, test_coverage); }
};

// Each window's section, or -1 when it crosses a section boundary.
std::vector<int> window_sections(const MaterialWindows& m, std::size_t sections);

// Which set (0 train, 1 val, 2 test) each section is in, and -1 for windows crossing sections.
int set_of_section(const Sets& sections, int section);

// Throws haptex::Error: bad_input for impossible options or a material with fewer than 5 presses;
// failed (naming every material below min_coverage, their coverage, and what to try) when the
// search cannot reach the threshold.
// dataset_path names the file in messages.
std::vector<MaterialSplit> search_split(const std::vector<MaterialWindows>& materials, const SplitOptions& options,
                                        const std::string& dataset_path);

}  // namespace haptex::split
