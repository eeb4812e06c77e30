#include "merge/root_attributes.hpp"

#include <algorithm>
#include <array>

#include "core/sha256.hpp"
#include "dataset/layout.hpp"

namespace haptex::merge {
namespace {

using namespace dataset::layout;

constexpr std::array<RootAttribute, 1> kRecordings{{{kFieldMap, Join::lines}}};
constexpr std::array<RootAttribute, 4> kDataset{{{kRecordingsFile, Join::lines},
                                                {kRecordingsSha256, Join::digest},
                                                {kGelsightFile, Join::lines},
                                                {kGelsightSha256, Join::digest}}};

// The values without repeats, in their first order.
std::vector<std::string> distinct(const std::vector<std::string>& values) {
  std::vector<std::string> out;
  for (const std::string& v : values)
    if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
  return out;
}

}  // namespace

std::span<const RootAttribute> root_attributes(dataset::Kind kind) {
  switch (kind) {
    case dataset::Kind::recordings: return kRecordings;
    case dataset::Kind::dataset: return kDataset;
    default: return {};  // gelsight files carry the stamp only
  }
}

std::string join_values(Join join, const std::vector<std::string>& values) {
  std::vector<std::string> unique = distinct(values);
  if (unique.size() == 1) return unique.front();
  std::string text;
  if (join == Join::lines) {
    for (std::size_t i = 0; i < unique.size(); ++i) text += (i ? "\n" : "") + unique[i];
    return text;
  }
  std::sort(unique.begin(), unique.end());  // the same inputs give the same hash in any order
  for (const std::string& v : unique) text += v + "\n";
  return sha256_hex(text);
}

}  // namespace haptex::merge
