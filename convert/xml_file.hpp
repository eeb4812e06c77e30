#pragma once
// An XML input (HaTT recorded data or models) parsed in place with pugixml. DTDs and entity
// declarations are refused, never expanded; every lookup that fails names the element and its line.
#include <pugixml.hpp>

#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"

namespace haptex::convert {

class XmlFile {
 public:
  // `bytes` is the whole document; `source` names it in messages; `sha256` is the file's (for
  // provenance: read_input_file gives both). Parses the bytes in place.
  XmlFile(std::string source, std::vector<char> bytes, std::string sha256);
  XmlFile(const XmlFile&) = delete;
  XmlFile& operator=(const XmlFile&) = delete;

  const std::string& source() const { return source_; }
  const std::string& sha256() const { return sha256_; }
  pugi::xml_node root() const { return doc_.document_element(); }

  // "<name> at line N"
  std::string where(const pugi::xml_node& node) const;
  Error error(const pugi::xml_node& node, const std::string& what, const std::string& fix) const;
  // The one child called `name` (null when there is none), or an error when there are two: which of
  // them holds the data is not knowable, so neither is taken.
  pugi::xml_node child(const pugi::xml_node& parent, const std::string& name) const;
  // The one child, or an error at the parent saying it is missing, with the fix.
  pugi::xml_node require(const pugi::xml_node& parent, const std::string& name, const std::string& fix) const;
  // The node's text, CDATA sections included and pieces split by a comment or processing instruction
  // joined (as XML means it), trimmed; an error when it holds an element.
  std::string text(const pugi::xml_node& node) const;
  // The node's text as a finite number / an integer, or an error at the node.
  double number(const pugi::xml_node& node) const;
  long integer(const pugi::xml_node& node) const;
  // An integer attribute of node: nullopt when absent, an error at the node when not an integer.
  std::optional<long> integer_attribute(const pugi::xml_node& node, const std::string& name) const;
  // Every <value_name> child of an array element, streamed straight into doubles.
  std::vector<double> values(const pugi::xml_node& array, const std::string& value_name) const;

 private:
  std::string source_;
  std::vector<char> bytes_;
  std::string sha256_;
  std::vector<std::size_t> line_starts_;  // taken before in-place parsing overwrites some newlines
  pugi::xml_document doc_;

  std::size_t line_of(std::ptrdiff_t offset) const;
};

}  // namespace haptex::convert
