#include "merge/shard.hpp"

#include <algorithm>
#include <array>
#include <filesystem>

#include "core/error.hpp"
#include "core/naming.hpp"
#include "core/text/utf8.hpp"
#include "dataset/layout.hpp"
#include "dataset/root_content.hpp"
#include "merge/root_attributes.hpp"

namespace haptex::merge {
namespace {

using namespace dataset::layout;

constexpr std::array kMergeable{dataset::Kind::recordings, dataset::Kind::gelsight, dataset::Kind::dataset};
constexpr const char* kWriteAgain = "Write the file again with the haptex command that made it";

// Anything else at the root has no rule to join it by, and leaving it out would lose it unsaid.
void refuse_unknown_root_content(const std::string& path, const h5::Group& root, dataset::Kind kind) {
  const std::vector<dataset::StrayRootContent> stray = dataset::stray_root_content(root, kind);
  if (!stray.empty())
    throw input_error(path, stray.front().where, stray.front().what + ", so merge cannot tell how to join it",
                      "Remove it from a copy of the shard (" + stray.front().remove + ") and merge the copy");
}

std::vector<std::string> material_ids(const std::string& path, const h5::Group& root) {
  const std::string where = "/" + std::string(kMaterials);
  if (!root.has_group(kMaterials) || root.open_group(kMaterials).children().empty())
    throw input_error(path, where, "holds no material, so there is nothing to merge from this shard", "Leave the file out of the merge");
  const h5::Group materials = root.open_group(kMaterials);
  std::vector<std::string> ids = materials.children();
  for (const std::string& id : ids)
    if (material_id(id) != id || !materials.has_group(id))
      throw input_error(path, where + "/" + id, "is not a material group named by a material id (lower case letters, digits and '_')",
                        kWriteAgain);
  return ids;
}

}  // namespace

std::string Shard::attribute(const std::string& name) const {
  for (const auto& [key, value] : root_attributes)
    if (key == name) return value;
  return "";
}

bool mergeable(dataset::Kind kind) { return std::find(kMergeable.begin(), kMergeable.end(), kind) != kMergeable.end(); }

Shard open_shard(const std::string& path) {
  text::require_utf8(path, "(command line)", "a shard's file name");
  auto [file, kind] = dataset::open_any(path, kMergeable, "haptex merge joins", "Give shards of one of those formats");
  const h5::Group root = file.root();
  refuse_unknown_root_content(path, root, kind);
  Shard shard{path, std::move(file), kind, material_ids(path, root), {}};
  for (const char* name : h5::kStampAttributes) shard.root_attributes.emplace_back(name, root.attr_string(name));
  for (const RootAttribute& a : root_attributes(kind)) shard.root_attributes.emplace_back(a.name, root.attr_string(a.name));
  return shard;
}

void require_joinable(const std::vector<Shard>& shards) {
  for (std::size_t i = 1; i < shards.size(); ++i) {
    const Shard &first = shards.front(), &shard = shards[i];
    if (shard.kind != first.kind)
      throw input_error(shard.path, "/@" + std::string(h5::kFormatAttribute),
                        "is " + dataset::format_name(shard.kind) + ", but " + first.path + " is " + dataset::format_name(first.kind),
                        "Merge files of one format: recordings with recordings, gelsight with gelsight, datasets with datasets");
  }
  for (std::size_t i = 0; i < shards.size(); ++i)
    for (std::size_t j = i + 1; j < shards.size(); ++j) {
      std::error_code ec;
      if (std::filesystem::equivalent(shards[i].path, shards[j].path, ec))
        throw input_error(shards[j].path, "", "is the same file as " + shards[i].path + ", given twice", "Name each shard once");
    }
}

}  // namespace haptex::merge
