#pragma once
// `haptex convert hatt`: HaTT recorded-data XML and CSV files -> one recordings file.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "convert/input_limits.hpp"
#include "core/progress.hpp"

namespace haptex::convert {

struct ConvertOptions {
  std::optional<std::string> map_path;  // field map; the built-in default when absent
  std::uintmax_t max_bytes = kDefaultMaxBytes;
  bool overwrite = false;
  std::string provenance;  // the command line, stored as the file's `source`
};

struct ConvertedRecording {
  std::string source, material, material_id;
  int index = 0;
  std::size_t samples = 0;
  double sample_rate_hz = 0;
};

struct ConvertResult {
  std::vector<ConvertedRecording> recordings;
  std::uintmax_t input_bytes = 0;
  std::vector<std::string> notes;  // what the command should tell the user (a named texture no take has)
};

// Files as given; directories searched recursively for *.xml, *.xml.gz and *.csv; sorted by path so the
// recording numbers are stable. Refuses missing paths and an input list with no recordings.
std::vector<std::string> expand_inputs(const std::vector<std::string>& inputs);

// Validates the output path before reading anything; writes atomically, so any error leaves no output.
ConvertResult convert_recordings(const std::vector<std::string>& inputs, const std::string& output,
                                 const ConvertOptions& options, const Progress& progress = {});

// `haptex convert cluster`: the Cluster Haptic Texture Database under `root` (convert/cluster_database.hpp),
// one recording per take; textures named from `names_path` (convert/texture_names.hpp) when given.
ConvertResult convert_cluster(const std::string& root, const std::string& output, const ConvertOptions& options,
                              const std::optional<std::string>& names_path, const Progress& progress = {});

}  // namespace haptex::convert
