#include "apps/dataset_split_input.hpp"

#include "qa/integrity.hpp"
#include "qa/sound_split.hpp"
#include "split/manifest_reader.hpp"

namespace haptex::apps {

void DatasetSplitInput::declare(CLI::App& app, const std::string& split_help) {
  app.add_option("dataset", dataset, "Dataset file (haptex align)")->required();
  app.add_option("--split", split, split_help)->required();
}

split::DatasetSplit DatasetSplitInput::read() const {
  const split::SplitManifestDocument manifest = split::read_split_manifest(split);  // read once, for both
  split::DatasetSplit windows = split::read_dataset_split(dataset, manifest);
  qa::require_sound_dataset(dataset);
  qa::require_sound_split(manifest, dataset);
  return windows;
}

}  // namespace haptex::apps
