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

// Writes the plots into `directory` (an existing folder: split writes them into a PartialDirectory's,
// core/partial_directory.hpp); `named` is the folder as messages name it (where they will be).
PlotResult write_split_plots(const std::string& dataset_path, const std::vector<MaterialWindows>& windows,
                             const std::vector<MaterialSplit>& splits, const std::size_t sections,
                             const std::string& directory, const std::string& named);

}  // namespace haptex::split
