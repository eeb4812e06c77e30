#pragma once
// What the layout check needs beyond core/h5: any object by path, an attribute's dtype and rank, and
// the concrete paths a layout pattern (/materials/{material}/recordings/{k}) stands for.
#include <string>
#include <vector>

#include "core/h5/node.hpp"

namespace haptex::qa {

struct AttributeInfo {
  std::string dtype;  // as h5::Dataset::dtype() names types
  long long values = 1;  // a scalar or an array of one holds one, as haptex's readers take it
};
AttributeInfo attribute_info(const h5::Node& node, const std::string& name);

enum class ObjectType { missing, group, dataset, other };
ObjectType object_type(const h5::Group& root, const std::string& path);
// A group or dataset as a Node (attributes only). Throws haptex::Error (bad_input) when missing.
h5::Node open_node(const h5::Group& root, const std::string& path);
h5::Dataset open_dataset_at(const h5::Group& root, const std::string& path);

struct PatternMatch {
  std::vector<std::string> paths;    // existing objects the pattern stands for
  std::vector<std::string> missing;  // literal segments missing where their parent exists
  std::vector<std::string> not_groups;  // objects on the way that are datasets (or other) where the pattern needs a group
};
// Segments written {name} stand for every child group; other segments are literal.
PatternMatch match_pattern(const h5::Group& root, const std::string& pattern);

}  // namespace haptex::qa
