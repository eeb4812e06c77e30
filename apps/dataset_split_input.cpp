#include "apps/dataset_split_input.hpp"

#include "qa/sound_split.hpp"
#include "split/manifest_reader.hpp"

namespace haptex::apps {

void DatasetSplitInput::declare(CLI::App& app, const std::string& split_help) {
  app.add_option("dataset", dataset, "Dataset file (haptex align)")->required();
  app.add_option("--split", split, split_help)->required();
}

split::DatasetSplit DatasetSplitInput::read() const {
  split::DatasetSplit windows = split::read_dataset_split(dataset, split);
  qa::require_sound_split(split::read_split_manifest(split), dataset);
  return windows;
}

}  // namespace haptex::apps
