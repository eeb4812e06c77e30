#pragma once
// Per material, the paper's Fig. 6: (left) the (speed, force) points of the train, validation and
// test windows; (right) recording 0's acceleration with its sections shaded by set. The data go
// to CSV files; gnuplot, when installed, draws them as PNG.
#include <string>
#include <vector>

#include "split/dataset_view.hpp"
#include "split/split_search.hpp"

namespace haptex::split {

struct PlotResult {
  std::vector<std::string> images;  // PNGs drawn
  std::string note;                 // why none were drawn, when so
};

PlotResult write_split_plots(const std::string& dataset_path, const std::vector<MaterialWindows>& windows,
                             const std::vector<MaterialSplit>& splits, const std::size_t sections,
                             const std::string& directory);

}  // namespace haptex::split
