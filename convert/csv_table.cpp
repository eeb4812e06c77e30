#include "convert/csv_table.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

#include "convert/input_limits.hpp"
#include "core/error.hpp"
#include "core/sha256.hpp"
#include "core/text/parse_number.hpp"
#include "core/text/utf8.hpp"

namespace haptex::convert {
namespace {

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

// A header cell without white space or surrounding quotes.
std::string column_name(std::string_view cell) {
  cell = text::trim(cell);
  if (cell.size() >= 2 && cell.front() == '"' && cell.back() == '"') cell = text::trim(cell.substr(1, cell.size() - 2));
  return std::string(cell);
}

// Walks the buffer line by line with 1-based line numbers.
class Lines {
 public:
  explicit Lines(const std::vector<char>& buffer) : text_(buffer.data(), buffer.size()) {
    text_ = text::without_byte_order_mark(text_);
  }
  bool next(std::string_view& line) {
    if (position_ >= text_.size()) return false;
    const std::size_t end = std::min(text_.find('\n', position_), text_.size());
    line = text_.substr(position_, end - position_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    position_ = end + 1;
    ++number_;
    return true;
  }
  std::size_t number() const { return number_; }

 private:
  std::string_view text_;
  std::size_t position_ = 0, number_ = 0;
};

}  // namespace

CsvTable read_csv_table(const std::string& path, std::uintmax_t max_bytes,
                        const std::function<bool(const std::string&)>& keep,
                        const std::function<bool(const std::string&)>& sparse) {
  const std::vector<char> buffer = read_whole_file(path, max_bytes);
  CsvTable table;
  table.sha256 = sha256_hex(buffer);
  Lines lines(buffer);
  std::string_view line;
  if (!lines.next(line))
    throw input_error(path, "line 1", "the file is empty", "Write a header row and one row per sample");
  std::vector<std::vector<double>*> kept;  // per column: where its values go, or null
  std::vector<std::vector<std::size_t>*> kept_lines;
  std::vector<bool> may_be_empty;
  for (auto field : split_fields(line)) {
    table.header.push_back(column_name(field));
    const std::string& name = table.header.back();
    // Which of two columns of one name holds the data is not knowable (CSV readers differ: Python's
    // csv.DictReader keeps the last, pandas both), so a column haptex reads may be named once only.
    if (keep(name) && table.columns.count(name))
      throw input_error(path, "line 1, column '" + name + "'", "the header names the column twice",
                        "Keep one: haptex cannot know which of the two holds the data");
    const bool wanted = keep(name);
    kept.push_back(wanted ? &table.columns[name] : nullptr);
    kept_lines.push_back(wanted ? &table.lines[name] : nullptr);
    may_be_empty.push_back(sparse && sparse(name));
  }
  std::size_t blank = 0;  // the first blank line since the last row: only the end of a file may hold them
  while (lines.next(line)) {
    if (line.find_first_not_of(" \t") == std::string_view::npos) {
      blank = blank ? blank : lines.number();
      continue;
    }
    if (blank)
      throw input_error(path, "line " + std::to_string(blank), "is blank, between rows of samples",
                        "Remove it, or fill in the row that is missing: every sample is a row");
    const std::string where = "line " + std::to_string(lines.number());
    // Counted before split: a line of 80 million empty fields took 2.3 GB as pieces (review 10, F3).
    if (const std::size_t count = std::size_t(std::count(line.begin(), line.end(), ',')) + 1; count != table.header.size())
      throw input_error(path, where, "has " + std::to_string(count) + " fields but the header has " + std::to_string(table.header.size()),
                        "Every row needs one value per header column");
    const auto fields = split_fields(line);
    for (std::size_t c = 0; c < fields.size(); ++c) {
      if (!kept[c] || (may_be_empty[c] && text::trim(fields[c]).empty())) continue;
      const std::optional<double> value = text::parse_stored_number(fields[c]);
      if (!value)
        throw input_error(path, where + ", column '" + table.header[c] + "'", text::describe_bad_number(fields[c]),
                          "Remove or interpolate bad samples in the source before converting");
      kept[c]->push_back(*value);
      kept_lines[c]->push_back(lines.number());
    }
  }
  return table;
}

}  // namespace haptex::convert
