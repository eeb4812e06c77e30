#include "dataset/root_content.hpp"

#include <algorithm>
#include <array>

#include "core/h5/file.hpp"
#include "dataset/layout.hpp"

namespace haptex::dataset {
namespace {

using namespace layout;

constexpr std::array<const char*, 1> kRecordingsAttributes{kFieldMap};
constexpr std::array<const char*, 4> kDatasetAttributes{kRecordingsFile, kRecordingsSha256, kGelsightFile, kGelsightSha256};

bool has_rule(Kind kind) { return kind == Kind::recordings || kind == Kind::gelsight || kind == Kind::dataset; }

bool known_attribute(Kind kind, const std::string& name) {
  const auto is = [&](const char* known) { return name == known; };
  return std::any_of(h5::kStampAttributes.begin(), h5::kStampAttributes.end(), is) ||
         std::ranges::any_of(root_attribute_names(kind), is);
}

bool known_group(Kind kind, const std::string& name) {
  return name == kMaterials || name == kShards || (kind == Kind::dataset && name == kWindows);
}

}  // namespace

std::span<const char* const> root_attribute_names(Kind kind) {
  switch (kind) {
    case Kind::recordings: return kRecordingsAttributes;
    case Kind::dataset: return kDatasetAttributes;
    default: return {};  // gelsight files carry the stamp only
  }
}

std::vector<StrayRootContent> stray_root_content(const h5::Group& root, Kind kind) {
  std::vector<StrayRootContent> stray;
  if (!has_rule(kind)) return stray;
  const std::string format = format_name(kind);
  for (const std::string& name : root.attr_names())
    if (!known_attribute(kind, name))
      stray.push_back({"/@" + name, "is not an attribute haptex writes in a " + format + " file", "h5py: del f.attrs['" + name + "']"});
  for (const std::string& name : root.children())
    if (!known_group(kind, name) || !root.has_group(name))
      stray.push_back({"/" + name, "is not an object haptex writes at the root of a " + format + " file", "h5py: del f['" + name + "']"});
  return stray;
}

}  // namespace haptex::dataset
