#pragma once
// What `haptex info` shows of any haptex HDF5 file: format, version, provenance, and per material
// its items (recordings, presses, ...) with their datasets, shapes, units and durations.
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace haptex::info {

struct DatasetSummary {
  std::string name, dtype, units;
  std::vector<std::uint64_t> shape;
};

struct ItemSummary {  // one recording, press, ...
  std::string key;
  std::optional<double> sample_rate_hz, duration_s;
  std::string source;
  std::vector<DatasetSummary> datasets;
};

struct CollectionSummary {  // "recordings", "presses", ...
  std::string name;
  std::vector<ItemSummary> items;
};

struct MaterialSummary {
  std::string id, name;
  std::vector<CollectionSummary> collections;
};

struct FileSummary {
  std::string path, format, version, created_utc, source;
  std::string format_remark;  // why this haptex cannot read the file ("" when it can: dataset::format_remark)
  std::uintmax_t bytes = 0;
  std::vector<MaterialSummary> materials;
  std::vector<DatasetSummary> other_datasets;  // datasets outside /materials, by full path
};

FileSummary summarize_file(const std::string& path);
nlohmann::json to_json(const FileSummary& summary);  // schemas/info.schema.json

}  // namespace haptex::info
