// layout.*: a file against the tables of schemas/hdf5-layout.md (the same rules as
// tests/e2e/check_layout.py, plus: a missing group on a required path is reported, not skipped).
// The objects every row describes are looked up once (find_rows); each check then judges them.
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "core/error.hpp"
#include "core/h5/link_rule.hpp"
#include "core/naming.hpp"
#include "core/text/utf8.hpp"
#include "dataset/object_paths.hpp"
#include "dataset/layout.hpp"
#include "dataset/root_content.hpp"
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

// One object a row describes, as the file holds it.
struct FoundObject {
  std::string where;  // the dataset's path, or OWNER/@attribute
  bool present = false;  // the attribute exists; the path is a dataset (not a group)
  std::string dtype;
  long long values = 1;  // how many an attribute holds (datasets: 1)
  h5::Shape shape;     // datasets
  std::optional<std::string> units;  // datasets whose row names units: their `units` attribute, when they have one
  std::string text_problem;  // string attributes: why haptex cannot read it as a name (not UTF-8, a NUL inside); empty when it can
  bool finite = true;         // scalar float attributes: not NaN or infinite (rates, durations, thresholds)
};

struct RowFindings {
  const LayoutRow* row;
  std::vector<std::string> missing;  // missing groups on the row's path (rows required `always`; each path once)
  std::vector<std::string> not_groups;  // objects on the row's path that are not groups (each path once)
  std::vector<FoundObject> found;
};

bool is_attribute_row(const LayoutRow& row) { return !row.attribute.empty(); }

// The first bad byte is named, as the readers of names name it (README, "Names and paths").
std::string text_problem(const h5::Node& node, const std::string& name) {
  try {
    return text::utf8_problem(node.attr_bytes(name)).value_or("");
  } catch (const Error& e) {  // a NUL inside a fixed-length string, a damaged or absurd type
    return "is not readable as text (" + e.finding() + ")";
  }
}

FoundObject find_attribute(const h5::Group& root, const LayoutRow& row, const std::string& owner) {
  FoundObject f;
  f.where = (owner == "/" ? "/" : owner + "/") + "@" + row.attribute;
  const h5::Node node = open_node(root, owner);
  if (!node.has_attr(row.attribute)) return f;
  const AttributeInfo info = attribute_info(node, row.attribute);
  f.present = true;
  f.dtype = info.dtype;
  f.values = info.values;
  if (f.dtype == "string" && f.values == 1) f.text_problem = text_problem(node, row.attribute);
  if (f.dtype.rfind("float", 0) == 0 && f.values == 1) {
    const std::optional<double> value = node.try_attr<double>(row.attribute);
    f.finite = value && std::isfinite(*value);
  }
  return f;
}

FoundObject find_dataset(const h5::Group& root, const LayoutRow& row, const std::string& path) {
  FoundObject f;
  f.where = path;
  if (object_type(root, path) != ObjectType::dataset) return f;
  const h5::Dataset d = open_dataset_at(root, path);
  f.present = true;
  f.dtype = d.dtype();
  if (!row.units.empty() && d.has_attr(dataset::layout::kUnits)) {
    try {
      f.units = d.attr_string(dataset::layout::kUnits);
    } catch (const Error&) {
      f.units = "(not a string)";
    }
  }
  f.shape = d.shape();
  return f;
}

std::vector<RowFindings> find_rows(const h5::Group& root, const std::vector<LayoutRow>& rows) {
  std::vector<RowFindings> out;
  std::set<std::string> reported_missing;
  for (const auto& row : rows) {
    RowFindings& r = out.emplace_back(RowFindings{&row, {}, {}, {}});
    const PatternMatch match = match_pattern(root, row.owner);
    for (const auto& missing : match.missing)
      if (row.always && reported_missing.insert(missing).second) r.missing.push_back(missing);
    for (const auto& wrong : match.not_groups)
      if (reported_missing.insert(wrong).second) r.not_groups.push_back(wrong);
    for (const auto& path : match.paths)
      r.found.push_back(is_attribute_row(row) ? find_attribute(root, row, path) : find_dataset(root, row, path));
  }
  return out;
}

// The extents schemas/hdf5-layout.md defines by an attribute of the dataset's group: N its
// `samples`, H and W its `height` and `width` (where the group has them: in /windows, W is the
// window count, bound by vote).
const char* attribute_for(const std::string& symbol) {
  if (symbol == "N") return "samples";
  if (symbol == "H") return "height";
  if (symbol == "W") return "width";
  return nullptr;
}

// A negative count stays what it is: no dataset has that extent, so the shape is reported wrong.
std::optional<std::int64_t> int_attribute(const h5::Group& root, const std::string& group, const char* name) {
  return open_node(root, group).try_attr<std::int64_t>(name);
}

// Per group and shape symbol, how many of the group's datasets have each extent there.
using ExtentVotes = std::map<std::string, std::map<std::string, std::map<hsize_t, int>>>;

ExtentVotes count_extents(const std::vector<RowFindings>& rows) {
  ExtentVotes votes;
  for (const auto& r : rows)
    for (const auto& d : r.found)
      if (!is_attribute_row(*r.row) && d.present && d.shape.size() == r.row->shape.size())
        for (std::size_t i = 0; i < d.shape.size(); ++i)
          if (!is_number(r.row->shape[i])) ++votes[parent_of(d.where)][r.row->shape[i]][d.shape[i]];
  return votes;
}

// What a shape symbol stands for in a group: a number as written; N, H and W the group's attribute
// (when it has it as an integer); any other letter the extent most of the group's datasets have
// there (so the odd dataset out is the one reported).
std::optional<std::int64_t> extent_of(const h5::Group& root, const std::string& group, const std::string& symbol,
                                      const ExtentVotes& votes) {
  if (is_number(symbol)) return std::stoll(symbol);
  if (const char* attr = attribute_for(symbol))
    if (const auto n = int_attribute(root, group, attr)) return n;
  std::optional<std::int64_t> want;
  const auto in_group = votes.find(group);
  if (in_group == votes.end()) return want;
  const auto candidates = in_group->second.find(symbol);
  if (candidates == in_group->second.end()) return want;
  int best = -1;
  for (const auto& [extent, count] : candidates->second)
    if (count > best) best = count, want = std::int64_t(extent);
  return want;
}

// layout.shape for one dataset.
void judge_shape(const h5::Group& root, const LayoutRow& row, const FoundObject& d, const ExtentVotes& votes,
                 CheckTally& tally) {
  if (d.shape.size() != row.shape.size())
    return tally.fail(d.where, "shape " + shape_text(d.shape) + ", expected " + shape_text(row.shape));
  const std::string group = parent_of(d.where);
  bool ok = true, known = true;
  std::vector<std::string> expected;
  for (std::size_t i = 0; i < d.shape.size(); ++i) {
    const std::optional<std::int64_t> want = extent_of(root, group, row.shape[i], votes);
    if (!want) known = false;
    expected.push_back(want ? std::to_string(*want) : row.shape[i]);
    if (want && (*want < 0 || d.shape[i] != hsize_t(*want))) ok = false;
  }
  if (!known) tally.skip(d.where + ": extent of " + shape_text(row.shape) + " unknown");
  else if (!ok)
    tally.fail(d.where, "shape " + shape_text(d.shape) + ", expected " + shape_text(expected) + " = " + shape_text(row.shape));
  else tally.pass();
}

// Review 20, F2 and F4: a material's name gives its id (so no two materials share a name, and align,
// which joins by name, joins what the ids say), and its recordings and presses are numbered 0, 1, ...
// as every reader indexes them (a recording named "best" or "00" passed qa, then align ended in an
// uncaught exception or wrote windows of a recording that does not exist).
void check_material_group(const h5::Group& materials, const std::string& id, CheckTally& tally) {
  if (!materials.has_group(id)) return;
  const h5::Group material = materials.open_group(id);
  const std::string path = dataset::material_path(id);
  if (const std::optional<std::string> name = material.try_attr<std::string>(dataset::layout::kName); name && material_id(*name) != id)
    tally.fail(path + "/@" + dataset::layout::kName, "'" + text::printable(text::shortened(*name)) + "' is the name of the material '" + text::shortened(material_id(*name)) +
                                                         "', not of '" + id + "' (a material's id is its name's, core/naming.hpp)");
  for (const char* numbered : {dataset::layout::kRecordings, dataset::layout::kPresses}) {
    if (!material.has_group(numbered)) continue;
    const std::vector<std::string> children = material.open_group(numbered).children();
    if (children.empty())  // review 21, F4: split then failed its own manifest check
      tally.fail(path + "/" + numbered, std::string("holds no ") + numbered + " (remove the material, or give it some)");
    std::set<std::string> expected;
    for (std::size_t k = 0; k < children.size(); ++k) expected.insert(std::to_string(k));
    for (const std::string& child : children)
      if (!expected.count(child))
        tally.fail(path + "/" + numbered + "/" + text::printable(child),
                   "is not numbered as the " + std::to_string(children.size()) + " " + numbered + " of a material are: 0 to " +
                       std::to_string(children.size() - 1) + ", without gaps or leading zeros");
  }
}

CheckResult check_layout_required(const h5::Group& root, dataset::Kind kind, const std::vector<RowFindings>& rows) {
  CheckTally tally("layout.required", "objects and attributes");
  for (const dataset::StrayRootContent& stray : dataset::stray_root_content(root, kind))
    tally.fail(stray.where, stray.what + "; merge and align refuse it (remove it: " + stray.remove + ")");
  // {material} is a material id (core/naming.hpp): merge and align join materials by it (review 5:
  // "Woven_1" and "wovén_1" passed qa, which merge refused and align joined to the wrong presses).
  if (root.has_group(dataset::layout::kMaterials)) {
    for (const std::string& id : root.open_group(dataset::layout::kMaterials).children()) {
      if (material_id(id) != id)
        tally.fail(dataset::material_path(id), "is not named by a material id (lower case letters, digits and '_'; '" + material_id(id) +
                                                   "' for this name)");
      else if (id.size() > kLongestMaterialId)  // review 10, F5: split and extract then failed at their end
        tally.fail(dataset::material_path(id).substr(0, 80) + "...", "is a material id of " + std::to_string(id.size()) + " bytes, longer than the " +
                                                                          std::to_string(kLongestMaterialId) + " haptex takes");
      else check_material_group(root.open_group(dataset::layout::kMaterials), id, tally);
    }
  }
  for (const auto& [row, missing, not_groups, found] : rows) {
    const std::string line = "schemas/hdf5-layout.md line " + std::to_string(row->line) + ": " + row->path;
    for (const auto& path : missing) tally.fail(path, "missing (" + line + ")");
    for (const auto& path : not_groups) tally.fail(path, "is not a group, the layout needs one here (" + line + ")");
    for (const auto& f : found)
      if (f.present) tally.pass();
      else if (!is_attribute_row(*row)) tally.fail(f.where, "is a group, expected a " + row->dtype + " dataset");
      else if (row->always) tally.fail(f.where, "attribute missing");
  }
  return tally.result();
}

CheckResult check_layout_dtype(const std::vector<RowFindings>& rows) {
  CheckTally tally("layout.dtype", "objects and attributes");
  for (const auto& r : rows)
    for (const auto& f : r.found) {
      if (!f.present) continue;
      if (f.dtype != r.row->dtype) tally.fail(f.where, "dtype " + f.dtype + ", expected " + r.row->dtype);
      else if (r.row->shape.empty() && f.values != 1)
        tally.fail(f.where, "holds " + std::to_string(f.values) + " values, expected one " + r.row->dtype);
      else if (!f.text_problem.empty()) tally.fail(f.where, f.text_problem);
      else if (!f.finite) tally.fail(f.where, "is not a finite number (NaN or infinite)");
      else tally.pass();
    }
  return tally.result();
}

CheckResult check_layout_shape(const h5::Group& root, const std::vector<RowFindings>& rows) {
  CheckTally tally("layout.shape", "datasets");
  const ExtentVotes votes = count_extents(rows);
  for (const auto& r : rows)
    for (const auto& d : r.found)
      if (!is_attribute_row(*r.row) && d.present) judge_shape(root, *r.row, d, votes, tally);
  return tally.result();
}

CheckResult check_layout_units(const std::vector<RowFindings>& rows) {
  CheckTally tally("layout.units", "datasets");
  for (const auto& r : rows) {
    const std::string& wanted = r.row->units;
    if (is_attribute_row(*r.row) || wanted.empty()) continue;
    for (const auto& d : r.found) {
      if (!d.present) continue;
      if (!d.units) tally.fail(d.where, "no units attribute, expected '" + wanted + "'");
      else if (*d.units != wanted) tally.fail(d.where, "units '" + *d.units + "', expected '" + wanted + "'");
      else tally.pass();
    }
  }
  return tally.result();
}

CheckResult check_layout_links(const h5::Group& root) {
  CheckTally tally("layout.links", "links");
  const h5::LinkReport report = h5::check_links(root);
  // Each fault has its own fix (a second link is removed, a dataset too large to read too: review 15, R4).
  for (const auto& [path, fault] : report.faults) tally.fail(path, fault.what + ". " + fault.fix);
  for (std::size_t i = report.faults.size(); i < report.links; ++i) tally.pass();
  return tally.result();
}

}  // namespace

std::vector<CheckResult> check_layout(const h5::Group& root, dataset::Kind kind) {
  // The links first: looking objects up by name follows links, and an external one opens the file it
  // names, a FIFO among them (review 5). When they break the rule, nothing is looked up.
  CheckResult links = check_layout_links(root);
  if (links.status == Status::fail) {
    const std::string why = "not run: the file's links break the rule (layout.links)";
    return {make_result("layout.required", Status::skip, why), make_result("layout.dtype", Status::skip, why),
            make_result("layout.shape", Status::skip, why), make_result("layout.units", Status::skip, why), std::move(links)};
  }
  const std::vector<LayoutRow> rows = rows_for_format(embedded_layout(), dataset::format_name(kind));
  const std::vector<RowFindings> found = find_rows(root, rows);
  return {check_layout_required(root, kind, found), check_layout_dtype(found), check_layout_shape(root, found),
          check_layout_units(found), std::move(links)};
}

}  // namespace haptex::qa
