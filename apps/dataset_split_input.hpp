#pragma once
// The input train, windows and evaluate share (issue 33): a dataset file and the split manifest made
// from it, declared once and read once, through the split gate that refuses a leaky or empty split
// (qa/sound_split.hpp) before any work.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "split/split_windows.hpp"

namespace haptex::apps {

struct DatasetSplitInput {
  std::string dataset, split;

  // The positional dataset and --split, both required; `split_help` says which split it is.
  void declare(CLI::App& app, const std::string& split_help = "Split manifest (haptex split) made from this dataset");
  // The dataset's windows by set. Throws haptex::Error (bad_input) as split::read_dataset_split
  // does, and when the split fails the gate.
  split::DatasetSplit read() const;
  std::vector<std::string> files() const { return {dataset, split}; }
};

}  // namespace haptex::apps
