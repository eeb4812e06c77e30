#include "qa/layout_spec.hpp"

#include <regex>
#include <sstream>

#include "dataset/format.hpp"
#include "core/embedded.hpp"
#include "core/error.hpp"

namespace haptex::qa {
namespace {

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return std::string(s.substr(first, last - first + 1));
}

std::string strip_backticks(const std::string& s) {
  if (s.size() >= 2 && s.front() == '`' && s.back() == '`') return s.substr(1, s.size() - 2);
  return s;
}

std::vector<std::string> split_cells(const std::string& line) {
  std::string body = trim(line);
  if (!body.empty() && body.front() == '|') body.erase(0, 1);
  if (!body.empty() && body.back() == '|') body.pop_back();
  std::vector<std::string> cells;
  std::stringstream in(body);
  for (std::string cell; std::getline(in, cell, '|');) cells.push_back(trim(cell));
  return cells;
}

// "(N, 3)" -> {"N", "3"}; "()" -> {}
std::vector<std::string> parse_shape(const std::string& text, int line) {
  if (text.size() < 2 || text.front() != '(' || text.back() != ')')
    throw failure("schemas/hdf5-layout.md line " + std::to_string(line) + ": shape '" + text +
                  "' is not of the form (A, B, ...)");
  std::vector<std::string> extents;
  std::stringstream in(text.substr(1, text.size() - 2));
  for (std::string extent; std::getline(in, extent, ',');)
    if (!trim(extent).empty()) extents.push_back(trim(extent));
  return extents;
}

bool under_materials_collection(const std::string& path) {
  static const std::regex collection("^/materials/\\{[a-z_]+\\}/(recordings|presses)/.*");
  return std::regex_match(path, collection);
}

}  // namespace

std::vector<LayoutSection> parse_layout(std::string_view markdown) {
  static const std::regex format_in_heading("`haptex_format`\\s*=\\s*`([^`]+)`");
  std::vector<LayoutSection> sections;
  std::stringstream in{std::string(markdown)};
  int line_number = 0;
  for (std::string line; std::getline(in, line);) {
    ++line_number;
    if (line.rfind("## ", 0) == 0) {
      LayoutSection section{trim(line.substr(3)), {}, {}};
      std::smatch m;
      if (std::regex_search(section.heading, m, format_in_heading)) section.format = m[1];
      sections.push_back(std::move(section));
      continue;
    }
    // Table rows whose first cell is a `path` (the header and the |---| rule are skipped).
    if (sections.empty() || line.rfind("| `", 0) != 0) continue;
    const auto cells = split_cells(line);
    if (cells.size() != 5)
      throw failure("schemas/hdf5-layout.md line " + std::to_string(line_number) + ": a layout row has " +
                    std::to_string(cells.size()) + " columns, expected 5 (path, dtype, shape, units, required when)");
    LayoutRow row;
    row.path = strip_backticks(cells[0]);
    const auto at = row.path.find('@');
    row.owner = at == std::string::npos ? row.path : row.path.substr(0, at);
    if (row.owner.size() > 1 && row.owner.back() == '/') row.owner.pop_back();
    if (at != std::string::npos) row.attribute = row.path.substr(at + 1);
    row.dtype = strip_backticks(cells[1]);
    row.shape = parse_shape(cells[2], line_number);
    row.units = strip_backticks(cells[3]);
    row.always = cells[4] == "always";
    row.line = line_number;
    sections.back().rows.push_back(std::move(row));
  }
  return sections;
}

const std::vector<LayoutSection>& embedded_layout() {
  static const std::vector<LayoutSection> layout = parse_layout(embedded::schema("hdf5-layout.md"));
  return layout;
}

bool layout_has_format(const std::vector<LayoutSection>& layout, std::string_view format) {
  for (const auto& section : layout)
    if (section.format == format) return true;
  return false;
}

std::vector<LayoutRow> rows_for_format(const std::vector<LayoutSection>& layout, std::string_view format) {
  std::vector<LayoutRow> rows;
  for (const auto& section : layout) {
    const bool every_file = section.format.empty() && section.heading.rfind("Every file", 0) == 0;
    // /shards of `haptex merge`: optional rows, present only in merged files of any format.
    const bool merged = section.format.empty() && section.heading.rfind("Merged file", 0) == 0;
    const bool own = !section.format.empty() && section.format == format;
    const bool copied_into_dataset =
        format == dataset::format_name(dataset::Kind::dataset) &&
        (section.format == dataset::format_name(dataset::Kind::recordings) || section.format == dataset::format_name(dataset::Kind::gelsight));
    for (const auto& row : section.rows)
      if (every_file || merged || own || (copied_into_dataset && under_materials_collection(row.path))) rows.push_back(row);
  }
  return rows;
}

}  // namespace haptex::qa
