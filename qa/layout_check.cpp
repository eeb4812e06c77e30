// layout.*: a file against the tables of schemas/hdf5-layout.md (the same rules as
// tests/e2e/check_layout.py, plus: a missing group on a required path is reported, not skipped).
#include <map>
#include <set>

#include "core/error.hpp"
#include "qa/checkers.hpp"
#include "qa/h5_inspect.hpp"
#include "qa/layout_spec.hpp"

namespace haptex::qa {
namespace {

std::string parent_of(const std::string& path) {
  const auto slash = path.rfind('/');
  return slash == 0 ? "/" : path.substr(0, slash);
}

std::string shape_text(const std::vector<std::string>& extents) {
  std::string text = "(";
  for (std::size_t i = 0; i < extents.size(); ++i) text += (i ? ", " : "") + extents[i];
  return text + ")";
}

std::string shape_text(const h5::Shape& shape) { return h5::shape_text(shape); }

bool is_number(const std::string& s) {
  return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos;
}

struct FoundDataset {
  const LayoutRow* row;
  std::string path;
  h5::Shape shape;
};

class LayoutChecker {
 public:
  explicit LayoutChecker(const h5::Group& root)
      : root_(root),
        required_("layout.required", "objects and attributes"),
        dtype_("layout.dtype", "objects and attributes"),
        shape_("layout.shape", "datasets"),
        units_("layout.units", "datasets") {}

  void check(const LayoutRow& row) {
    const PatternMatch match = match_pattern(root_, row.owner);
    for (const auto& missing : match.missing)
      if (row.always && reported_missing_.insert(missing).second)
        required_.fail(missing, "missing (schemas/hdf5-layout.md line " + std::to_string(row.line) + ": " + row.path +
                                    ")");
    for (const auto& path : match.paths) {
      if (row.attribute.empty()) check_dataset(row, path);
      else check_attribute(row, path);
    }
  }

  std::vector<CheckResult> results() {
    check_shapes();
    return {required_.result(), dtype_.result(), shape_.result(), units_.result()};
  }

 private:
  void check_attribute(const LayoutRow& row, const std::string& owner) {
    const h5::Node node = open_node(root_, owner);
    const std::string where = (owner == "/" ? "/" : owner + "/") + "@" + row.attribute;
    if (!node.has_attr(row.attribute)) {
      if (row.always) required_.fail(where, "attribute missing");
      return;
    }
    required_.pass();
    const AttributeInfo info = attribute_info(node, row.attribute);
    if (info.dtype != row.dtype) dtype_.fail(where, "dtype " + info.dtype + ", expected " + row.dtype);
    else if (row.shape.empty() && !info.scalar) dtype_.fail(where, "holds several values, expected one " + row.dtype);
    else dtype_.pass();
  }

  void check_dataset(const LayoutRow& row, const std::string& path) {
    const ObjectType type = object_type(root_, path);
    if (type != ObjectType::dataset) {
      required_.fail(path, "is a group, expected a " + row.dtype + " dataset");
      return;
    }
    required_.pass();
    const h5::Dataset d = open_dataset_at(root_, path);
    const std::string dtype = d.dtype();
    if (dtype != row.dtype) dtype_.fail(path, "dtype " + dtype + ", expected " + row.dtype);
    else dtype_.pass();
    if (!row.units.empty()) {
      if (!d.has_attr("units")) units_.fail(path, "no units attribute, expected '" + row.units + "'");
      else {
        std::string units;
        try {
          units = d.attr_string("units");
        } catch (const Error&) {
          units = "(not a string)";
        }
        if (units != row.units) units_.fail(path, "units '" + units + "', expected '" + row.units + "'");
        else units_.pass();
      }
    }
    datasets_.push_back({&row, path, d.shape()});
  }

  // Symbolic extents: N, H and W are attributes of the parent group (when it has them as integers);
  // any other letter must take one value over the datasets of a group (the most common one wins,
  // so the odd dataset out is the one reported).
  void check_shapes() {
    std::map<std::string, std::map<std::string, std::map<hsize_t, int>>> votes;  // group -> symbol -> extent -> count
    for (const auto& d : datasets_)
      if (d.shape.size() == d.row->shape.size())
        for (std::size_t i = 0; i < d.shape.size(); ++i)
          if (!is_number(d.row->shape[i])) ++votes[parent_of(d.path)][d.row->shape[i]][d.shape[i]];
    for (const auto& d : datasets_) {
      const std::string group = parent_of(d.path);
      if (d.shape.size() != d.row->shape.size()) {
        shape_.fail(d.path, "shape " + shape_text(d.shape) + ", expected " + shape_text(d.row->shape));
        continue;
      }
      bool ok = true, known = true;
      std::vector<std::string> expected;
      for (std::size_t i = 0; i < d.shape.size(); ++i) {
        const std::string& symbol = d.row->shape[i];
        std::optional<hsize_t> want;
        if (is_number(symbol)) want = std::stoull(symbol);
        else if (const char* attr = attribute_for(symbol)) want = int_attribute(group, attr);
        if (!want) {
          const auto& candidates = votes[group][symbol];
          int best = -1;
          for (const auto& [extent, count] : candidates)
            if (count > best) best = count, want = extent;
        }
        if (!want) known = false;
        expected.push_back(want ? std::to_string(*want) : symbol);
        if (want && d.shape[i] != *want) ok = false;
      }
      if (!known) shape_.skip(d.path + ": extent of " + shape_text(d.row->shape) + " unknown");
      else if (!ok)
        shape_.fail(d.path, "shape " + shape_text(d.shape) + ", expected " + shape_text(expected) + " = " +
                                shape_text(d.row->shape));
      else shape_.pass();
    }
  }

  // The extents schemas/hdf5-layout.md defines by an attribute of the dataset's group: N its
  // `samples`, H and W its `height` and `width` (where the group has them: in /windows, W is the
  // window count, bound by vote).
  static const char* attribute_for(const std::string& symbol) {
    if (symbol == "N") return "samples";
    if (symbol == "H") return "height";
    if (symbol == "W") return "width";
    return nullptr;
  }

  std::optional<hsize_t> int_attribute(const std::string& group, const char* name) {
    const h5::Node node = open_node(root_, group);
    if (!node.has_attr(name)) return std::nullopt;
    try {
      const std::int64_t n = node.attr_int(name);
      if (n >= 0) return hsize_t(n);
    } catch (const Error&) {
    }
    return std::nullopt;
  }

  const h5::Group& root_;
  CheckTally required_, dtype_, shape_, units_;
  std::set<std::string> reported_missing_;
  std::vector<FoundDataset> datasets_;
};

}  // namespace

std::vector<CheckResult> check_layout(const h5::Group& root, const std::string& format) {
  const auto rows = rows_for_format(embedded_layout(), format);
  LayoutChecker checker(root);
  for (const auto& row : rows) checker.check(row);
  return checker.results();
}

}  // namespace haptex::qa
