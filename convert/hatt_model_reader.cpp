#include "convert/hatt_model_reader.hpp"

#include <charconv>

#include "convert/input_limits.hpp"
#include "convert/xml_file.hpp"
#include "core/sha256.hpp"

namespace haptex::convert {
namespace {

pugi::xml_node require(const XmlFile& xml, const pugi::xml_node& parent, const char* name) {
  return xml.require(parent, name, std::string("Add the <") + name + "> element (docs/convert.md describes the format)");
}

double number_child(const XmlFile& xml, const pugi::xml_node& parent, const char* name) {
  return xml.number(require(xml, parent, name));
}

std::size_t count_child(const XmlFile& xml, const pugi::xml_node& parent, const char* name) {
  const pugi::xml_node node = require(xml, parent, name);
  const long value = xml.integer(node);
  if (value < 0) throw xml.error(node, "must not be negative", "Write a count >= 0");
  return std::size_t(value);
}

void check_count(const XmlFile& r, pugi::xml_node count_node, std::size_t declared, std::size_t found,
                 const std::string& what_found) {
  if (declared != found)
    throw r.error(count_node, "says " + std::to_string(declared) + " but the file has " + std::to_string(found) + " " + what_found,
                  "Make <" + std::string(count_node.name()) + "> match the elements listed");
}

void read_header(const XmlFile& r, pugi::xml_node root, ar::ModelSet& set) {
  if (auto texture = r.integer_attribute(root, "texture")) set.texture = int(*texture);
  set.material = r.text(r.child(root, "material"));
  if (auto units = r.child(root, "AccelUnits")) set.accel_units = r.text(units);
  if (auto units = r.child(root, "SpeedUnits")) set.speed_units = r.text(units);
  if (auto units = r.child(root, "ForceUnits")) set.force_units = r.text(units);
  set.sample_rate_hz = number_child(r, root, "SampleRate");
  if (!(set.sample_rate_hz > 0.0))
    throw r.error(r.child(root, "SampleRate"), "the sample rate must be positive", "Write the rate in Hz");
  set.mu = number_child(r, root, "mu");
  set.max_speed = number_child(r, root, "maxSpeed");
  set.max_force = number_child(r, root, "maxForce");
  set.num_ar_coeff = int(count_child(r, root, "numARCoeff"));
  if (r.child(root, "numMACoeff")) set.num_ma_coeff = int(count_child(r, root, "numMACoeff"));
}

void read_vertices(const XmlFile& r, pugi::xml_node root, std::size_t num_mod, ar::ModelSet& set) {
  const pugi::xml_node speeds = require(r, root, "speedList");
  const pugi::xml_node forces = require(r, root, "forceList");
  set.speed_list = r.values(speeds, "value");
  set.force_list = r.values(forces, "value");
  const pugi::xml_node count_node = r.child(root, "numMod");
  check_count(r, count_node, num_mod, set.speed_list.size(), "<value> elements in <speedList>");
  check_count(r, count_node, num_mod, set.force_list.size(), "<value> elements in <forceList>");
}

void read_triangles(const XmlFile& r, pugi::xml_node root, std::size_t num_mod, ar::ModelSet& set) {
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
  check_count(r, r.child(root, "numTri"), count_child(r, root, "numTri"), set.triangles.size(), "<tri> elements");
}

ar::ArModel read_model(const XmlFile& r, pugi::xml_node node, std::size_t order) {
  ar::ArModel m;
  if (auto number = r.child(node, "modNum")) m.number = int(r.integer(number));
  const pugi::xml_node coeff = require(r, node, "ARcoeff");
  const pugi::xml_node lsf = require(r, node, "ARlsf");
  m.ar_coeff = r.values(coeff, "value");
  m.ar_lsf = r.values(lsf, "value");
  if (m.ar_lsf.size() != order)
    throw r.error(lsf, "has " + std::to_string(m.ar_lsf.size()) + " values but numARCoeff is " + std::to_string(order),
                  "Give numARCoeff LSFs per model");
  if (m.ar_coeff.size() != order + 1)
    throw r.error(coeff, "has " + std::to_string(m.ar_coeff.size()) + " values but numARCoeff + 1 is " + std::to_string(order + 1),
                  "Give the leading 1 and numARCoeff coefficients");
  if (auto ma = r.child(node, "MAcoeff")) m.ma_coeff = r.values(ma, "value");
  if (auto ma = r.child(node, "MAlsf")) m.ma_lsf = r.values(ma, "value");
  m.variance = number_child(r, node, "var");
  if (auto gain = r.child(node, "gain")) m.gain = r.number(gain);
  m.speed = number_child(r, node, "speedMod");
  m.force = number_child(r, node, "forceMod");
  return m;
}

ar::ModelSet read_model_set(const XmlFile& r) {
  const pugi::xml_node root = r.root();
  if (std::string_view(root.name()) != "modelSet")
    throw r.error(root, "the document element is not <modelSet>", "Give a HaTT model file (Models_<Material>.xml)");
  ar::ModelSet set;
  set.source = r.source();
  read_header(r, root, set);
  const std::size_t num_mod = count_child(r, root, "numMod");
  read_vertices(r, root, num_mod, set);
  read_triangles(r, root, num_mod, set);
  for (pugi::xml_node m = root.child("model"); m; m = m.next_sibling("model"))
    set.models.push_back(read_model(r, m, std::size_t(set.num_ar_coeff)));
  check_count(r, r.child(root, "numMod"), num_mod, set.models.size(), "<model> elements");
  return set;
}

}  // namespace

ar::ModelSet parse_hatt_model(std::string_view xml, const std::string& source) {
  return read_model_set(XmlFile(source, std::vector<char>(xml.begin(), xml.end()), sha256_hex(xml)));
}

ar::ModelSet read_hatt_model(const std::filesystem::path& file) {
  InputFile in = read_input_file(file.string(), kDefaultMaxBytes);
  return read_model_set(XmlFile(file.string(), std::move(in.contents), std::move(in.sha256)));
}

ar::PiecewiseArModel load_hatt_model(const std::filesystem::path& file) {
  return ar::PiecewiseArModel(read_hatt_model(file));
}

}  // namespace haptex::convert
