#pragma once
// Small, real inputs for the steps after convert and capture: a recordings file (haptex convert of
// sample recordings) and a gelsight file (capture's writer with tiny frames), and the dataset align makes.
#include <string>

#include "tests/support/temp_dir.hpp"

namespace haptex::test {

struct PipelineFiles {
  TempDir dir;
  std::string recordings = dir.file("recordings.h5"), gelsight = dir.file("gelsight.h5"), dataset = dir.file("dataset.h5");
};

struct PipelineSpec {
  double seconds = 0.5;        // per recording
  int odd_press_size = 0;      // non-zero: Book's press 4 gets this image size
};

// Recordings of Book (2), "Sandpaper_100" (1) and Felt (1); 5 presses each of Book, "sandpaper 100"
// and Glass.
void make_pipeline_inputs(PipelineFiles& files, const PipelineSpec& spec = {});

// make_pipeline_inputs, then haptex align's library call into files.dataset.
void make_pipeline_dataset(PipelineFiles& files, const PipelineSpec& spec = {});

}  // namespace haptex::test
