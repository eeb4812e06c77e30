#include "convert/hatt_recording_reader.hpp"

#include <cmath>
#include <cstring>
#include <pugixml.hpp>

#include "convert/parse_number.hpp"
#include "convert/recording_checks.hpp"
#include "core/error.hpp"
#include "core/sha256.hpp"

namespace haptex::convert {
namespace {

// The parsed document and the buffer it points into, for line numbers in messages.
struct XmlFile {
  std::string path;
  std::vector<char> buffer;
  pugi::xml_document doc;

  std::string line(const pugi::xml_node& node) const {
    const std::ptrdiff_t offset = node.offset_debug();
    return offset < 0 ? std::string() : "line " + std::to_string(line_of_offset(buffer, std::size_t(offset)));
  }
  std::string where(const pugi::xml_node& node) const {
    std::string place = "<" + std::string(node.name()) + ">";
    const std::string at = line(node);
    return at.empty() ? place : place + " at " + at;
  }
};

std::string trimmed(const char* text) {
  std::string s = text;
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
}

void parse(XmlFile& xml) {
  // Minimal parsing keeps the <value> text in place; the doctype node is kept only so we can refuse it.
  const unsigned flags = pugi::parse_minimal | pugi::parse_escapes | pugi::parse_doctype;
  const pugi::xml_parse_result result = xml.doc.load_buffer_inplace(xml.buffer.data(), xml.buffer.size(), flags);
  if (!result) {
    const std::size_t line = line_of_offset(xml.buffer, std::size_t(std::max<std::ptrdiff_t>(result.offset, 0)));
    throw input_error(xml.path, "line " + std::to_string(line),
                      std::string("malformed XML (") + result.description() + ")",
                      "The file looks truncated or damaged; export or copy it again");
  }
  for (const pugi::xml_node& node : xml.doc.children())
    if (node.type() == pugi::node_doctype)
      throw input_error(xml.path, xml.line(node), "the file has a DTD or entity declaration (<!DOCTYPE ...>)",
                        "haptex refuses DTDs and never expands entities; remove the <!DOCTYPE> block");
}

pugi::xml_node required_child(const XmlFile& xml, const pugi::xml_node& parent, const std::string& name,
                              const std::string& fix) {
  pugi::xml_node node = parent.child(name.c_str());
  if (!node) throw input_error(xml.path, xml.where(parent), "element <" + name + "> is missing", fix);
  return node;
}

// Streams every <value> child straight into one vector of doubles.
std::vector<double> read_values(const XmlFile& xml, const pugi::xml_node& array, const std::string& value_name) {
  std::vector<double> samples;
  const char* name = value_name.c_str();
  for (pugi::xml_node value = array.child(name); value; value = value.next_sibling(name)) {
    const char* text = value.child_value();
    std::optional<double> number = parse_number(text);
    if (!number || !std::isfinite(*number))
      throw input_error(xml.path, xml.where(value) + " (value " + std::to_string(samples.size() + 1) + " of <" +
                                      array.name() + ">)",
                        describe_bad_value(text, number.has_value()),
                        "Remove or interpolate bad samples in the source before converting");
    samples.push_back(*number);
  }
  return samples;
}

double read_sample_rate(const XmlFile& xml, const pugi::xml_node& root, const FieldMap& map) {
  pugi::xml_node node = required_child(xml, root, map.sample_rate,
                                       "Add <" + map.sample_rate + ">10000</" + map.sample_rate +
                                           ">; haptex needs recordings at 10 kHz");
  std::optional<double> rate = parse_number(node.child_value());
  if (!rate || !std::isfinite(*rate))
    throw input_error(xml.path, xml.where(node), describe_bad_value(node.child_value(), rate.has_value()),
                      "Write the sample rate in Hz, e.g. 10000");
  check_sample_rate(xml.path, xml.where(node), *rate);
  return *rate;
}

}  // namespace

Recording read_hatt_recording_xml(const std::string& path, const FieldMap& map, std::uintmax_t max_bytes) {
  XmlFile xml{path, read_whole_file(path, max_bytes), {}};
  Recording recording;
  recording.source_path = path;
  {
    Sha256 hash;  // hash before in-place parsing changes the buffer
    hash.update(std::span(reinterpret_cast<const std::uint8_t*>(xml.buffer.data()), xml.buffer.size()));
    recording.source_sha256 = hash.hex_digest();
  }
  parse(xml);

  pugi::xml_node root = xml.doc.document_element();
  if (map.root != root.name())
    throw input_error(path, xml.where(root), "the document element is <" + std::string(root.name()) + ">, not <" +
                                                 map.root + ">",
                      "Is this a HaTT recorded-data file? If your files name it differently, set \"root\" in a "
                      "field map and pass it with --map");
  recording.material = trimmed(required_child(xml, root, map.material, "Add <" + map.material +
                                                                           ">surface name</" + map.material + ">")
                                   .child_value());
  if (recording.material.empty())
    throw input_error(path, xml.where(root.child(map.material.c_str())), "the material name is empty",
                      "Name the surface, e.g. <" + map.material + ">Book</" + map.material + ">");
  if (!map.texture_attribute.empty())
    if (pugi::xml_attribute texture = root.attribute(map.texture_attribute.c_str()))
      recording.texture = texture.as_int();
  recording.sample_rate_hz = read_sample_rate(xml, root, map);

  std::map<std::string, pugi::xml_node> channel_nodes;
  for (const auto& [channel, element] : map.channels) {
    pugi::xml_node array = root.child(element.c_str());
    const bool required = std::find(kRequiredChannels.begin(), kRequiredChannels.end(), channel) !=
                          kRequiredChannels.end();
    if (!array) {
      if (!required) continue;
      throw input_error(path, xml.where(root), "channel <" + element + "> (" + channel + ") is missing",
                        "Add it, or point \"" + channel + "\" at your element's name in a field map (--map)");
    }
    recording.channels[channel] = read_values(xml, array, map.value);
    channel_nodes[channel] = array;
  }
  for (const auto& [quantity, element] : map.units) {
    pugi::xml_node node = root.child(element.c_str());
    if (node) apply_units(recording, quantity, trimmed(node.child_value()), xml.where(node));
    else recording.units[quantity] = kExpectedUnits.at(quantity);  // the format's documented default
  }
  check_channels(recording, [&](const std::string& channel) {
    auto it = channel_nodes.find(channel);
    return it == channel_nodes.end() ? "<" + map.channels.at(channel) + ">" : xml.where(it->second);
  });
  return recording;
}

}  // namespace haptex::convert
