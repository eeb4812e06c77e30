#pragma once
// The windows file (schemas/hdf5-layout.md, "Windows file"; windows/2): the evaluation's grid of test
// windows for models trained outside haptex (docs/windows.md). `haptex windows` writes it from
// evaluate's grid; Python reads it (python/haptex_data.py).
#include <cstdint>
#include <string>
#include <vector>

#include "dataset/window_table.hpp"

namespace haptex::dataset {

struct WindowsFile {
  WindowTable windows;                // material, recording, start, action, target (stride 100)
  std::vector<std::int32_t> section;  // the test section of the recording each window lies in
  std::vector<std::int32_t> press;    // the material's test press (/materials/{material}/presses/{press})
  std::string dataset_file, dataset_sha256, split_file, split_sha256;
};

// Written atomically; throws haptex::Error (bad_input) when `path` exists and `overwrite` is false
// (or it is not a file haptex wrote).
void write_windows_file(const WindowsFile& file, const std::string& path, bool overwrite, const std::string& source);

}  // namespace haptex::dataset
