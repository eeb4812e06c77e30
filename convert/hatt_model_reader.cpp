#include "convert/hatt_model_reader.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <pugixml.hpp>
#include <sstream>

#include "core/error.hpp"

namespace haptex::convert {
namespace {

std::size_t line_at(std::string_view xml, std::ptrdiff_t offset) {
  if (offset < 0) return 0;
  const auto end = xml.begin() + std::min<std::ptrdiff_t>(offset, std::ptrdiff_t(xml.size()));
  return std::size_t(std::count(xml.begin(), end, '\n')) + 1;
}

// Entity declarations can expand without bound ("billion laughs") or pull in other files; HaTT
// files never use them, so any DOCTYPE is refused before parsing.
void refuse_declarations(std::string_view xml, const std::string& source) {
  std::string upper(xml);
  std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return char(std::toupper(c)); });
  for (const char* keyword : {"<!DOCTYPE", "<!ENTITY"}) {
    const std::size_t at = upper.find(keyword);
    if (at != std::string::npos)
      throw input_error(source, "line " + std::to_string(line_at(xml, std::ptrdiff_t(at))),
                        std::string("the file declares ") + (keyword + 2) +
                            ", which haptex refuses (no DTDs, no entity expansion)",
                        "Remove the declaration; HaTT model files need none");
  }
}

// Element lookups and number parsing that name the element and its line when they fail.
class Reader {
 public:
  Reader(std::string_view xml, const std::string& source) : xml_(xml), source_(source) {}

  std::string where(pugi::xml_node node) const {
    std::string at = "<" + std::string(node.name()) + ">";
    const std::size_t line = line_at(xml_, node.offset_debug());
    return line ? "line " + std::to_string(line) + ", " + at : at;
  }

  Error error(pugi::xml_node node, const std::string& what, const std::string& fix) const {
    return input_error(source_, where(node), what, fix);
  }

  pugi::xml_node require(pugi::xml_node parent, const char* name) const {
    pugi::xml_node child = parent.child(name);
    if (!child)
      throw error(parent, std::string("missing <") + name + ">",
                  std::string("Add the <") + name + "> element (DESIGN.md section 4 lists the format)");
    return child;
  }

  double number(pugi::xml_node node) const {
    const std::string_view text = trimmed(node);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
      throw error(node, "\"" + std::string(text) + "\" is not a finite number", "Write a decimal number");
    return value;
  }

  long integer(pugi::xml_node node) const {
    const std::string_view text = trimmed(node);
    long value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size())
      throw error(node, "\"" + std::string(text) + "\" is not an integer", "Write a whole number");
    return value;
  }

  double number_child(pugi::xml_node parent, const char* name) const { return number(require(parent, name)); }

  std::size_t count_child(pugi::xml_node parent, const char* name) const {
    const pugi::xml_node node = require(parent, name);
    const long value = integer(node);
    if (value < 0) throw error(node, "must not be negative", "Write a count >= 0");
    return std::size_t(value);
  }

  std::vector<double> values(pugi::xml_node array) const {
    std::vector<double> out;
    for (pugi::xml_node v = array.child("value"); v; v = v.next_sibling("value")) out.push_back(number(v));
    return out;
  }

 private:
  static std::string_view trimmed(pugi::xml_node node) {
    std::string_view text = node.child_value();
    const auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
    while (!text.empty() && space(text.front())) text.remove_prefix(1);
    while (!text.empty() && space(text.back())) text.remove_suffix(1);
    return text;
  }

  std::string_view xml_;
  const std::string& source_;
};

void check_count(const Reader& r, pugi::xml_node count_node, std::size_t declared, std::size_t found,
                 const std::string& what_found) {
  if (declared != found)
    throw r.error(count_node, "says " + std::to_string(declared) + " but the file has " + std::to_string(found) + " " + what_found,
                  "Make <" + std::string(count_node.name()) + "> match the elements listed");
}

void read_header(const Reader& r, pugi::xml_node root, ar::ModelSet& set) {
  if (pugi::xml_attribute texture = root.attribute("texture")) {
    const std::string_view text = texture.value();
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), set.texture);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size())
      throw r.error(root, "texture=\"" + std::string(text) + "\" is not an integer", "Write texture=\"N\"");
  }
  set.material = root.child_value("material");
  if (root.child("AccelUnits")) set.accel_units = root.child_value("AccelUnits");
  if (root.child("SpeedUnits")) set.speed_units = root.child_value("SpeedUnits");
  if (root.child("ForceUnits")) set.force_units = root.child_value("ForceUnits");
  set.sample_rate_hz = r.number_child(root, "SampleRate");
  if (!(set.sample_rate_hz > 0.0))
    throw r.error(root.child("SampleRate"), "the sample rate must be positive", "Write the rate in Hz");
  set.mu = r.number_child(root, "mu");
  set.max_speed = r.number_child(root, "maxSpeed");
  set.max_force = r.number_child(root, "maxForce");
  set.num_ar_coeff = int(r.count_child(root, "numARCoeff"));
  if (root.child("numMACoeff")) set.num_ma_coeff = int(r.count_child(root, "numMACoeff"));
}

void read_vertices(const Reader& r, pugi::xml_node root, std::size_t num_mod, ar::ModelSet& set) {
  const pugi::xml_node speeds = r.require(root, "speedList");
  const pugi::xml_node forces = r.require(root, "forceList");
  set.speed_list = r.values(speeds);
  set.force_list = r.values(forces);
  const pugi::xml_node count_node = root.child("numMod");
  check_count(r, count_node, num_mod, set.speed_list.size(), "<value> elements in <speedList>");
  check_count(r, count_node, num_mod, set.force_list.size(), "<value> elements in <forceList>");
}

void read_triangles(const Reader& r, pugi::xml_node root, std::size_t num_mod, ar::ModelSet& set) {
  for (pugi::xml_node tri = root.child("tri"); tri; tri = tri.next_sibling("tri")) {
    std::array<std::size_t, 3> vertex{};
    std::size_t n = 0;
    for (pugi::xml_node v = tri.child("value"); v; v = v.next_sibling("value"), ++n) {
      if (n == 3) throw r.error(tri, "a triangle has more than 3 vertices", "List exactly 3 model indices");
      const long index = r.integer(v);
      if (index < 1 || std::size_t(index) > num_mod)
        throw r.error(v, "model index " + std::to_string(index) + " is outside 1.." + std::to_string(num_mod),
                      "Use 1-based indices of existing models");
      vertex[n] = std::size_t(index - 1);
    }
    if (n != 3) throw r.error(tri, "a triangle has " + std::to_string(n) + " vertices", "List exactly 3 model indices");
    set.triangles.push_back(vertex);
  }
  check_count(r, root.child("numTri"), r.count_child(root, "numTri"), set.triangles.size(), "<tri> elements");
}

ar::ArModel read_model(const Reader& r, pugi::xml_node node, std::size_t order) {
  ar::ArModel m;
  if (node.child("modNum")) m.number = int(r.integer(node.child("modNum")));
  const pugi::xml_node coeff = r.require(node, "ARcoeff");
  const pugi::xml_node lsf = r.require(node, "ARlsf");
  m.ar_coeff = r.values(coeff);
  m.ar_lsf = r.values(lsf);
  if (m.ar_lsf.size() != order)
    throw r.error(lsf, "has " + std::to_string(m.ar_lsf.size()) + " values but numARCoeff is " + std::to_string(order),
                  "Give numARCoeff LSFs per model");
  if (m.ar_coeff.size() != order + 1)
    throw r.error(coeff, "has " + std::to_string(m.ar_coeff.size()) + " values but numARCoeff + 1 is " + std::to_string(order + 1),
                  "Give the leading 1 and numARCoeff coefficients");
  if (node.child("MAcoeff")) m.ma_coeff = r.values(node.child("MAcoeff"));
  if (node.child("MAlsf")) m.ma_lsf = r.values(node.child("MAlsf"));
  m.variance = r.number_child(node, "var");
  if (node.child("gain")) m.gain = r.number(node.child("gain"));
  m.speed = r.number_child(node, "speedMod");
  m.force = r.number_child(node, "forceMod");
  return m;
}

}  // namespace

ar::ModelSet parse_hatt_model(std::string_view xml, const std::string& source) {
  refuse_declarations(xml, source);
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_buffer(xml.data(), xml.size(), pugi::parse_default);
  if (!parsed)
    throw input_error(source, "line " + std::to_string(line_at(xml, parsed.offset)),
                      std::string("malformed XML (") + parsed.description() + ")",
                      "The file looks truncated or corrupted; copy it again from the HaTT release");
  const pugi::xml_node root = doc.child("modelSet");
  if (!root) throw input_error(source, "", "no <modelSet> root element", "Give a HaTT model file (Models_<Material>.xml)");
  const Reader r(xml, source);
  ar::ModelSet set;
  set.source = source;
  read_header(r, root, set);
  const std::size_t num_mod = r.count_child(root, "numMod");
  read_vertices(r, root, num_mod, set);
  read_triangles(r, root, num_mod, set);
  for (pugi::xml_node m = root.child("model"); m; m = m.next_sibling("model"))
    set.models.push_back(read_model(r, m, std::size_t(set.num_ar_coeff)));
  check_count(r, root.child("numMod"), num_mod, set.models.size(), "<model> elements");
  return set;
}

ar::ModelSet read_hatt_model(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw input_error(file.string(), "", "cannot open the file", "Check the path and permissions");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw input_error(file.string(), "", "reading the file failed", "Check the disk and retry");
  return parse_hatt_model(text.str(), file.string());
}

ar::PiecewiseArModel load_hatt_model(const std::filesystem::path& file) {
  return ar::PiecewiseArModel(read_hatt_model(file));
}

}  // namespace haptex::convert
