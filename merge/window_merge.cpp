#include "merge/window_merge.hpp"

#include <algorithm>
#include <set>
#include <utility>

#include "core/error.hpp"
#include "dataset/layout.hpp"

namespace haptex::merge {
namespace {

using namespace dataset::layout;

constexpr const char* kRealign = "Run haptex align again to rebuild the shard";

std::string windows_path(const char* column) { return "/" + std::string(kWindows) + "/" + column; }

void check_materials_listed(const Shard& shard, const dataset::WindowTable& t) {
  std::vector<std::string> listed = t.materials;
  std::sort(listed.begin(), listed.end());
  if (listed != shard.materials)
    throw input_error(shard.path, windows_path(kWindowMaterials),
                      "lists '" + id_list(t.materials) + "', but /" + kMaterials + " holds '" + id_list(shard.materials) + "'", kRealign);
}

// Every (material, recording) a window names must be a recording group of the shard.
void check_rows_point_at_data(const Shard& shard, const dataset::WindowTable& t) {
  const h5::Group materials = shard.file.root().open_group(kMaterials);
  std::set<std::pair<std::int32_t, std::int32_t>> seen;
  for (std::size_t w = 0; w < t.size(); ++w) {
    const std::int32_t m = t.material[w], r = t.recording[w];
    if (m < 0 || std::size_t(m) >= t.materials.size())
      throw input_error(shard.path, windows_path(kWindowMaterial) + "[" + std::to_string(w) + "]",
                        "is " + std::to_string(m) + ", but " + windows_path(kWindowMaterials) + " has " + std::to_string(t.materials.size()) + " entries",
                        kRealign);
    if (!seen.insert({m, r}).second) continue;
    const h5::Group material = materials.open_group(t.materials[std::size_t(m)]);
    if (r < 0 || !material.has_group(kRecordings) || !material.open_group(kRecordings).has_group(std::to_string(r)))
      throw input_error(shard.path, windows_path(kWindowRecording) + "[" + std::to_string(w) + "]",
                        "is " + std::to_string(r) + ", but material " + t.materials[std::size_t(m)] + " has no such recording", kRealign);
  }
}

void append_row(dataset::WindowTable& out, const dataset::WindowTable& in, std::size_t w, std::int32_t material) {
  out.material.push_back(material);
  out.recording.push_back(in.recording[w]);
  out.start.push_back(in.start[w]);
  const auto action = in.action_of(w), target = in.target_of(w);
  out.action.insert(out.action.end(), action.begin(), action.end());
  out.target.insert(out.target.end(), target.begin(), target.end());
}

void require_one_stride(const std::vector<ShardWindows>& shards) {
  for (const ShardWindows& s : shards)
    if (s.table.stride != shards.front().table.stride)
      throw input_error(s.path, "/" + std::string(kWindows) + "/@" + kStride,
                        "is " + std::to_string(s.table.stride) + ", but " + shards.front().path + "'s is " + std::to_string(shards.front().table.stride),
                        "Align every shard with the same --stride");
}

}  // namespace

ShardWindows read_shard_windows(const Shard& shard) {
  ShardWindows s{shard.path, dataset::read_window_table(shard.file)};
  check_materials_listed(shard, s.table);
  check_rows_point_at_data(shard, s.table);
  return s;
}

dataset::WindowTable merge_windows(const std::vector<ShardWindows>& shards, const MaterialPlan& plan) {
  dataset::WindowTable out;
  if (shards.empty()) return out;
  require_one_stride(shards);
  out.stride = shards.front().table.stride;
  // Each shard's rows by its material index, found in one pass over its table.
  std::vector<std::vector<std::vector<std::size_t>>> rows(shards.size());
  for (std::size_t s = 0; s < shards.size(); ++s) {
    const dataset::WindowTable& t = shards[s].table;
    rows[s].resize(t.materials.size());
    for (std::size_t w = 0; w < t.size(); ++w) rows[s][std::size_t(t.material[w])].push_back(w);
  }
  for (const MaterialSource& m : plan.materials) {
    const dataset::WindowTable& t = shards[m.shard].table;
    const auto index = std::size_t(std::find(t.materials.begin(), t.materials.end(), m.id) - t.materials.begin());
    for (std::size_t w : rows[m.shard][index]) append_row(out, t, w, std::int32_t(out.materials.size()));
    out.materials.push_back(m.id);
  }
  return out;
}

}  // namespace haptex::merge
