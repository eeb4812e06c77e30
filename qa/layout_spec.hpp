#pragma once
// The tables of schemas/hdf5-layout.md, parsed from the copy compiled into the binary: the markdown
// is the single source of truth for what every haptex HDF5 file holds.
#include <string>
#include <string_view>
#include <vector>

namespace haptex::qa {

struct LayoutRow {
  std::string path;       // as written: /materials/{material}/recordings/{k}/accel, /windows/@stride
  std::string owner;      // the object: the path before '@', or the dataset's path
  std::string attribute;  // after '@'; empty for a dataset row
  std::string dtype;      // numpy's names (float32, int64, ...) or "string"
  std::vector<std::string> shape;  // extents: "N", "3", ...; empty for "()" (a scalar)
  std::string units;      // the `units` attribute the dataset must carry; empty: none
  bool always = false;    // "required when" is "always"; other conditions make the row optional
  int line = 0;           // line in the markdown, for messages
};

struct LayoutSection {
  std::string heading;  // "Recordings file (`haptex_format` = `recordings/1`, ...)"
  std::string format;   // the haptex_format the heading names; empty for "Every file"
  std::vector<LayoutRow> rows;
};

// Throws haptex::Error (failed) naming the line when a table row does not have the five columns.
std::vector<LayoutSection> parse_layout(std::string_view markdown);
// schemas/hdf5-layout.md as compiled in, parsed once.
const std::vector<LayoutSection>& embedded_layout();

// The rows a file of this haptex_format must satisfy: "Every file", its own section, the optional
// rows of "Merged file" (/shards, present only in files haptex merge wrote), and for a dataset file the
// recordings/1 and gelsight/2 rows below /materials/{material}/recordings/ and
// /materials/{material}/presses/ (the dataset file copies those groups unchanged).
std::vector<LayoutRow> rows_for_format(const std::vector<LayoutSection>& layout, std::string_view format);
// True when the layout has a section for this haptex_format.
bool layout_has_format(const std::vector<LayoutSection>& layout, std::string_view format);

}  // namespace haptex::qa
