#include "merge/root_attributes.hpp"

#include <algorithm>
#include <string_view>

#include "core/sha256.hpp"
#include "dataset/layout.hpp"
#include "dataset/root_content.hpp"

namespace haptex::merge {
namespace {

using namespace dataset::layout;

// The values without repeats, in their first order.
std::vector<std::string> distinct(const std::vector<std::string>& values) {
  std::vector<std::string> out;
  for (const std::string& v : values)
    if (std::find(out.begin(), out.end(), v) == out.end()) out.push_back(v);
  return out;
}

}  // namespace

std::vector<RootAttribute> root_attributes(dataset::Kind kind) {
  std::vector<RootAttribute> attributes;
  for (const char* name : dataset::root_attribute_names(kind)) {
    const std::string_view n = name;
    attributes.push_back({name, n == kRecordingsSha256 || n == kGelsightSha256 ? Join::digest : Join::lines});
  }
  return attributes;
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
