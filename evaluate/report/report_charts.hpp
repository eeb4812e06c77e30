#pragma once
// The report's charts: gnuplot scripts written beside the CSVs they read and, when gnuplot is
// installed, run to PNG (pngcairo when gnuplot has it, else png). The scripts name their files
// relative to the report folder, so `gnuplot NAME.gnuplot` run there draws NAME.png again.
//
// - experiment-<id>.png (the paper's Fig. 4), per experiment: per material a bar at the median of
//   baseline - model over the test windows with the quartiles as error bars, coloured by the Welch
//   test (significantly better, not significant, significantly worse; the key lists the colours drawn),
//   titled with the experiment and, on a second line, how to read bars and whiskers;
// - examples.png (Fig. 5): the first four examples in a 2 x 4 grid, spectra of one test window
//   above, the start of the stitched signals below; recorded, model and baseline;
// - latents.png: the texture latents' 2-D PCA, mean training latents and test presses, labelled;
// - speed.png: two panels against compute time per second of rendered vibration (log axis), one
//   point per method and setting, labelled with the setting (a label that would cover another moves
//   down a line): left, "spectrum accuracy", the speed
//   points of kind spectrum at their mean spectral distance, with a line at the mean floor distance
//   (read from floors.csv; "oracle" or "floor (estimate)"); right, "signal realism", the points of
//   kind signal at their spread ratio, with a line at 1 (the recording). A panel without a point
//   is left out.
// A chart without data (no materials, examples, latents or speed points) is left out.
#include <string>
#include <vector>

#include "evaluate/evaluation_results.hpp"
#include "evaluate/report/report_csv.hpp"

namespace haptex::evaluate {

struct ChartResult {
  std::vector<std::string> scripts;  // file names in the folder, one per chart with data
  std::vector<std::string> images;   // file names of the PNGs drawn (valid PNG files)
  std::string note;                  // empty, or why some or all charts were not drawn
};

// Writes the scripts into directory, where write_report_csvs wrote the CSVs (same layout), and
// draws them. A chart gnuplot fails on leaves no PNG and is named in the note. Throws
// haptex::Error (failed) when a script cannot be written.
ChartResult write_report_charts(const Evaluation& e, const ReportLayout& layout, const std::string& directory);

}  // namespace haptex::evaluate
