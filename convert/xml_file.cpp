#include "convert/xml_file.hpp"

#include <charconv>
#include <cmath>

#include "convert/input_limits.hpp"
#include "convert/parse_number.hpp"
#include "convert/recording_checks.hpp"
#include "core/sha256.hpp"

namespace haptex::convert {

std::string_view trimmed_text(const pugi::xml_node& node) {
  std::string_view text = node.child_value();
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  while (!text.empty() && space(text.front())) text.remove_prefix(1);
  while (!text.empty() && space(text.back())) text.remove_suffix(1);
  return text;
}

XmlFile::XmlFile(std::string source, std::vector<char> bytes) : source_(std::move(source)), bytes_(std::move(bytes)) {
  Sha256 hash;
  hash.update(std::span(reinterpret_cast<const std::uint8_t*>(bytes_.data()), bytes_.size()));
  sha256_ = hash.hex_digest();
  // Minimal parsing keeps the <value> text in place; the doctype node is kept only so it can be refused.
  const unsigned flags = pugi::parse_minimal | pugi::parse_escapes | pugi::parse_doctype;
  const pugi::xml_parse_result result = doc_.load_buffer_inplace(bytes_.data(), bytes_.size(), flags);
  if (!result)
    throw input_error(source_, "line " + std::to_string(line_of_offset(bytes_, std::size_t(std::max<std::ptrdiff_t>(result.offset, 0)))),
                      std::string("malformed XML (") + result.description() + ")",
                      "The file looks truncated or damaged; export or copy it again");
  // Entity declarations can expand without bound ("billion laughs") or pull in other files; the
  // formats never need them, so any DOCTYPE is refused.
  for (const pugi::xml_node& node : doc_.children())
    if (node.type() == pugi::node_doctype)
      throw input_error(source_, "line " + std::to_string(line_of_offset(bytes_, std::size_t(node.offset_debug()))),
                        "the file has a DTD or entity declaration (<!DOCTYPE ...>)",
                        "haptex refuses DTDs and never expands entities; remove the <!DOCTYPE> block");
  if (!root()) throw input_error(source_, "", "the file has no document element", "Give an XML file with content");
}

std::string XmlFile::where(const pugi::xml_node& node) const {
  const std::string place = "<" + std::string(node.name()) + ">";
  const std::ptrdiff_t offset = node.offset_debug();
  return offset < 0 ? place : place + " at line " + std::to_string(line_of_offset(bytes_, std::size_t(offset)));
}

Error XmlFile::error(const pugi::xml_node& node, const std::string& what, const std::string& fix) const {
  return input_error(source_, where(node), what, fix);
}

pugi::xml_node XmlFile::require(const pugi::xml_node& parent, const std::string& name, const std::string& fix) const {
  pugi::xml_node child = parent.child(name.c_str());
  if (!child) throw error(parent, "element <" + name + "> is missing", fix);
  return child;
}

double XmlFile::number(const pugi::xml_node& node) const {
  const std::string_view text = trimmed_text(node);
  const std::optional<double> value = parse_number(text);
  if (!value || !std::isfinite(*value))
    throw error(node, describe_bad_value(text, value.has_value()), "Write a finite decimal number");
  return *value;
}

long XmlFile::integer(const pugi::xml_node& node) const {
  const std::string_view text = trimmed_text(node);
  long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size())
    throw error(node, "'" + std::string(text) + "' is not an integer", "Write a whole number");
  return value;
}

std::vector<double> XmlFile::values(const pugi::xml_node& array, const std::string& value_name) const {
  std::vector<double> samples;
  const char* name = value_name.c_str();
  for (pugi::xml_node value = array.child(name); value; value = value.next_sibling(name)) {
    const char* text = value.child_value();
    const std::optional<double> number = parse_number(text);
    if (!number || !std::isfinite(*number))
      throw input_error(source_, where(value) + " (value " + std::to_string(samples.size() + 1) + " of <" +
                                     array.name() + ">)",
                        describe_bad_value(text, number.has_value()),
                        "Remove or interpolate bad values in the source before converting");
    samples.push_back(*number);
  }
  return samples;
}

}  // namespace haptex::convert
