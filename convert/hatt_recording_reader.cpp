#include "convert/hatt_recording_reader.hpp"

#include "core/text/parse_number.hpp"
#include "convert/input_limits.hpp"
#include "convert/recording_checks.hpp"
#include "convert/resampling.hpp"
#include "convert/xml_file.hpp"
#include "core/text/utf8.hpp"

namespace haptex::convert {

using text::trim;
namespace {

void read_identity(const XmlFile& xml, const pugi::xml_node& root, const FieldMap& map, Recording& recording) {
  const pugi::xml_node material =
      xml.require(root, map.material, "Add <" + map.material + ">surface name</" + map.material + ">");
  recording.material = xml.text(material);
  text::require_utf8(recording.material, xml.source(), xml.where(material));
  if (recording.material.empty())
    throw xml.error(material, "the material name is empty",
                    "Name the surface, e.g. <" + map.material + ">Book</" + map.material + ">");
  if (!map.texture_attribute.empty())
    if (auto texture = xml.integer_attribute(root, map.texture_attribute)) recording.texture = int(*texture);
  const pugi::xml_node rate = xml.require(
      root, map.sample_rate, "Add <" + map.sample_rate + ">10000</" + map.sample_rate + "> (the rate in Hz; 10 kHz in HaTT)");
  recording.sample_rate_hz = whole_source_rate(xml.source(), xml.where(rate), xml.number(rate), kLowestAccelRateHz, false);
}

}  // namespace

Recording read_hatt_recording_xml(const std::string& path, const FieldMap& map, std::uintmax_t max_bytes) {
  InputFile file = read_input_file(path, max_bytes);
  const XmlFile xml(path, std::move(file.contents), std::move(file.sha256));
  const pugi::xml_node root = xml.root();
  if (map.root != root.name())
    throw xml.error(root, "the document element is <" + std::string(root.name()) + ">, not <" + map.root + ">",
                    "Is this a HaTT recorded-data file? If your files name it differently, set \"root\" in a "
                    "field map and pass it with --map");
  Recording recording;
  recording.source_path = path;
  recording.source_sha256 = xml.sha256();
  read_identity(xml, root, map, recording);

  std::map<std::string, pugi::xml_node> channel_nodes;
  for (const auto& [channel, element] : map.channels) {
    const pugi::xml_node array = xml.child(root, element);
    if (!array && !is_required_channel(channel)) continue;
    if (!array)
      throw xml.error(root, "channel <" + element + "> (" + channel + ") is missing",
                      "Add it, or point \"" + channel + "\" at your element's name in a field map (--map)");
    recording.channels[channel] = xml.values(array, map.value);
    channel_nodes[channel] = array;
  }
  for (const auto& [quantity, element] : map.units) {
    const pugi::xml_node node = xml.child(root, element);
    if (node) apply_units(recording, quantity, xml.text(node), xml.where(node));
    else recording.units[quantity] = kExpectedUnits.at(quantity);  // the format's documented default
  }
  const auto where = [&](const std::string& channel) {
    auto it = channel_nodes.find(channel);
    return it == channel_nodes.end() ? "<" + map.channels.at(channel) + ">" : xml.where(it->second);
  };
  check_channels(recording, where);  // lengths as the file holds them, where they can be named
  resample_uniform(recording, int(recording.sample_rate_hz));
  check_channels(recording, where);  // and at least one model window at 10 kHz
  return recording;
}

}  // namespace haptex::convert
