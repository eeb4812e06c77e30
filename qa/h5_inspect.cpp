#include "qa/h5_inspect.hpp"

#include <sstream>

#include "core/error.hpp"

namespace haptex::qa {
namespace {

std::string dtype_name(hid_t type) {
  const std::size_t bytes = H5Tget_size(type);
  switch (H5Tget_class(type)) {
    case H5T_FLOAT: return "float" + std::to_string(8 * bytes);
    case H5T_INTEGER: return std::string(H5Tget_sign(type) == H5T_SGN_NONE ? "uint" : "int") + std::to_string(8 * bytes);
    case H5T_STRING: return "string";
    case H5T_VLEN: return "vlen";
    default: return "other";
  }
}

std::vector<std::string> segments(const std::string& path) {
  std::vector<std::string> parts;
  std::stringstream in(path);
  for (std::string part; std::getline(in, part, '/');)
    if (!part.empty()) parts.push_back(part);
  return parts;
}

std::string join(const std::string& base, const std::string& name) { return (base == "/" ? "/" : base + "/") + name; }

}  // namespace

AttributeInfo attribute_info(const h5::Node& node, const std::string& name) {
  h5::Handle attr(h5::check(H5Aopen(node.id(), name.c_str(), H5P_DEFAULT), "open attribute " + name, node.where()));
  h5::Handle type(H5Aget_type(attr.get()));
  h5::Handle space(H5Aget_space(attr.get()));
  return {dtype_name(type.get()), static_cast<long long>(H5Sget_simple_extent_npoints(space.get()))};
}

ObjectType object_type(const h5::Group& root, const std::string& path) {
  if (path == "/") return ObjectType::group;
  // Every link on the way must exist before H5Oget_info_by_name may look at the last one.
  std::string so_far;
  for (const auto& part : segments(path)) {
    so_far += "/" + part;
    if (H5Lexists(root.id(), so_far.c_str(), H5P_DEFAULT) <= 0) return ObjectType::missing;
  }
  H5O_info_t info;
  if (H5Oget_info_by_name(root.id(), path.c_str(), &info, H5P_DEFAULT) < 0) return ObjectType::missing;
  if (info.type == H5O_TYPE_GROUP) return ObjectType::group;
  if (info.type == H5O_TYPE_DATASET) return ObjectType::dataset;
  return ObjectType::other;
}

h5::Node open_node(const h5::Group& root, const std::string& path) {
  if (object_type(root, path) == ObjectType::missing)
    throw input_error(root.file(), path, "object is missing", "Check the file's layout with 'haptex qa'");
  return h5::Node(h5::Handle(h5::check(H5Oopen(root.id(), path.c_str(), H5P_DEFAULT), "open object", root.file() + ":" + path)),
                  root.file(), path);
}

h5::Dataset open_dataset_at(const h5::Group& root, const std::string& path) {
  if (object_type(root, path) != ObjectType::dataset)
    throw input_error(root.file(), path, "dataset is missing", "Check the file's layout with 'haptex qa'");
  return h5::Dataset(
      h5::Handle(h5::check(H5Dopen2(root.id(), path.c_str(), H5P_DEFAULT), "open dataset", root.file() + ":" + path)),
      root.file(), path);
}

PatternMatch match_pattern(const h5::Group& root, const std::string& pattern) {
  PatternMatch match;
  std::vector<std::string> found = {"/"};
  const auto parts = segments(pattern);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const std::string& part = parts[i];
    const bool last = i + 1 == parts.size();
    std::vector<std::string> next;
    for (const auto& base : found) {
      if (object_type(root, base) != ObjectType::group) continue;
      if (part.front() == '{') {
        const h5::Group group = base == "/" ? root : root.open_group(base.substr(1));
        for (const auto& child : group.children()) {
          if (last || group.has_group(child)) next.push_back(join(base, child));
          else match.not_groups.push_back(join(base, child));
        }
      } else {
        const std::string path = join(base, part);
        const ObjectType type = object_type(root, path);
        if (type == ObjectType::missing) match.missing.push_back(path);
        else if (last || type == ObjectType::group) next.push_back(path);
        else match.not_groups.push_back(path);
      }
    }
    found = std::move(next);
  }
  match.paths = found;
  return match;
}

}  // namespace haptex::qa
