#include "convert/xml_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "core/text/parse_number.hpp"
#include "convert/recording_checks.hpp"

namespace haptex::convert {

using text::describe_bad_number, text::parse_stored_number, text::trim;

namespace {

// Where a line starts after each line end XML knows (XML 1.0, 2.11): LF, CR LF, and a CR alone, which
// a file with classic Mac line ends has (review 16, F8: every message said "line 1").
std::vector<std::size_t> line_starts_any_end(const std::vector<char>& bytes) {
  std::vector<std::size_t> starts{0};
  for (std::size_t i = 0; i < bytes.size(); ++i)
    if (bytes[i] == '\n' || (bytes[i] == '\r' && (i + 1 == bytes.size() || bytes[i + 1] != '\n'))) starts.push_back(i + 1);
  return starts;
}

// The offset of every line's first byte, for messages. A HaTT recording has a line per sample, about
// 28 bytes apart: comparing 16 bytes at once (SSE2, on every x86-64) took 8 % off the parse, which
// memchr called once per line spent here. Other processors call memchr. A file with any CR counts
// line by line (line_starts_any_end).
std::vector<std::size_t> line_starts(const std::vector<char>& bytes) {
  if (std::memchr(bytes.data(), '\r', bytes.size()) != nullptr) return line_starts_any_end(bytes);
  std::vector<std::size_t> starts{0};
  std::size_t i = 0;
#if defined(__SSE2__)
  const __m128i newline = _mm_set1_epi8('\n');
  for (; i + 16 <= bytes.size(); i += 16) {
    const __m128i block = _mm_loadu_si128(reinterpret_cast<const __m128i*>(bytes.data() + i));
    for (unsigned mask = unsigned(_mm_movemask_epi8(_mm_cmpeq_epi8(block, newline))); mask != 0; mask &= mask - 1)
      starts.push_back(i + std::size_t(__builtin_ctz(mask)) + 1);
  }
#endif
  for (const char *at = bytes.data() + i, *end = bytes.data() + bytes.size();
       (at = static_cast<const char*>(std::memchr(at, '\n', std::size_t(end - at)))) != nullptr; ++at)
    starts.push_back(std::size_t(at - bytes.data()) + 1);
  return starts;
}

}  // namespace

// The offset of the first character reference to NUL (&#0;, &#x00;), which XML 1.0 does not allow and
// pugixml would decode into a string that ends there ("Wo&#0;ven" read as "Wo"); npos when none.
static std::size_t nul_reference(std::string_view text) {
  for (std::size_t at = text.find("&#"); at != std::string_view::npos; at = text.find("&#", at + 2)) {
    std::size_t i = at + 2;
    if (i < text.size() && (text[i] == 'x' || text[i] == 'X')) ++i;
    const std::size_t digits = i;
    while (i < text.size() && text[i] == '0') ++i;
    if (i > digits && i < text.size() && text[i] == ';') return at;
  }
  return std::string_view::npos;
}

XmlFile::XmlFile(std::string source, std::vector<char> bytes, std::string sha256)
    : source_(std::move(source)), bytes_(std::move(bytes)), sha256_(std::move(sha256)) {
  line_starts_ = line_starts(bytes_);
  if (const std::size_t at = nul_reference(std::string_view(bytes_.data(), bytes_.size())); at != std::string_view::npos)
    throw input_error(source_, "line " + std::to_string(line_of(std::ptrdiff_t(at))),
                      "a character reference to NUL (&#0;), which XML does not allow and no name may hold",
                      "Remove it from the file");
  // Minimal parsing keeps the <value> text in place; the doctype node is kept only so it can be refused.
  // An element's first piece of text is its value, not a node of its own: half the nodes (and the
  // memory they take) of a recording of a sample per element (issue 37).
  const unsigned flags =
      pugi::parse_minimal | pugi::parse_escapes | pugi::parse_doctype | pugi::parse_cdata | pugi::parse_embed_pcdata |
      pugi::parse_comments | pugi::parse_pi;  // so that text() sees where pieces of text were cut
  const pugi::xml_parse_result result = doc_.load_buffer_inplace(bytes_.data(), bytes_.size(), flags);
  if (!result)
    throw input_error(source_, "line " + std::to_string(line_of(result.offset)),
                      std::string("malformed XML (") + result.description() + ")",
                      "The file looks truncated or damaged; export or copy it again");
  // Entity declarations can expand without bound ("billion laughs") or pull in other files; the
  // formats never need them, so any DOCTYPE is refused.
  for (const pugi::xml_node& node : doc_.children())
    if (node.type() == pugi::node_doctype)
      throw input_error(source_, "line " + std::to_string(line_of(node.offset_debug())),
                        "the file has a DTD or entity declaration (<!DOCTYPE ...>)",
                        "haptex refuses DTDs and never expands entities; remove the <!DOCTYPE> block");
  if (!root()) throw input_error(source_, "", "the file has no document element", "Give an XML file with content");
  // XML has one document element; pugixml would read a second one and every lookup would skip it.
  for (pugi::xml_node node = root().next_sibling(); node; node = node.next_sibling())
    if (node.type() == pugi::node_element)
      throw error(node, "is a second document element after " + where(root()), "An XML file holds one document: give each its own file");
}

std::size_t XmlFile::line_of(std::ptrdiff_t offset) const {
  const auto after = std::upper_bound(line_starts_.begin(), line_starts_.end(), std::size_t(std::max<std::ptrdiff_t>(offset, 0)));
  return std::size_t(after - line_starts_.begin());
}

std::string XmlFile::where(const pugi::xml_node& node) const {
  const std::string place = "<" + std::string(node.name()) + ">";
  const std::ptrdiff_t offset = node.offset_debug();
  return offset < 0 ? place : place + " at line " + std::to_string(line_of(offset));
}

Error XmlFile::error(const pugi::xml_node& node, const std::string& what, const std::string& fix) const {
  return input_error(source_, where(node), what, fix);
}

pugi::xml_node XmlFile::child(const pugi::xml_node& parent, const std::string& name) const {
  const pugi::xml_node first = parent.child(name.c_str());
  if (const pugi::xml_node second = first.next_sibling(name.c_str()))
    throw error(second, "is the second <" + name + "> in <" + parent.name() + "> (the first is " + where(first) + ")",
                "Keep one: haptex cannot know which of the two holds the data");
  return first;
}

pugi::xml_node XmlFile::require(const pugi::xml_node& parent, const std::string& name, const std::string& fix) const {
  pugi::xml_node only = child(parent, name);
  if (!only) throw error(parent, "element <" + name + "> is missing", fix);
  return only;
}

std::string XmlFile::text(const pugi::xml_node& node) const {
  std::string text = node.value();  // the first piece of text, kept in the element (parse_embed_pcdata)
  // pugixml drops a piece of text that is only white space, which it is when it stands between two
  // comments, processing instructions or CDATA sections ("1<!-- --> <!-- -->5" is "1 5", not "15":
  // review 16, F1). Such a gap inside the text, with text before and after it, is refused.
  bool markup_before = false, gap = false;
  for (const pugi::xml_node& part : node.children()) {
    if (part.type() == pugi::node_element)
      throw error(node, "holds element <" + std::string(part.name()) + ">, where text is expected", "Write the text alone");
    const bool pcdata = part.type() == pugi::node_pcdata, cdata = part.type() == pugi::node_cdata;
    gap = gap || (markup_before && !pcdata && !trim(text).empty());
    if ((pcdata || cdata) && !trim(part.value()).empty() && gap)
      throw error(node, "holds text split by comments, processing instructions or CDATA sections with two of them side by side, "
                        "where white space between them cannot be told from none",
                  "Write the text as one piece");
    if (pcdata || cdata) text += part.value();
    markup_before = !pcdata;
  }
  return std::string(trim(text));
}

double XmlFile::number(const pugi::xml_node& node) const {
  const std::string text = this->text(node);
  const std::optional<double> value = parse_stored_number(text);
  if (!value) throw error(node, describe_bad_number(text), "Write a finite decimal number");
  return *value;
}

static std::optional<long> parse_integer(std::string_view text) {
  text = trim(text);
  long value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

long XmlFile::integer(const pugi::xml_node& node) const {
  const std::string text = this->text(node);
  const auto value = parse_integer(text);
  if (!value) throw error(node, "'" + text + "' is not an integer", "Write a whole number");
  return *value;
}

std::optional<long> XmlFile::integer_attribute(const pugi::xml_node& node, const std::string& name) const {
  const pugi::xml_attribute attribute = node.attribute(name.c_str());
  if (!attribute) return std::nullopt;
  const auto value = parse_integer(attribute.value());
  if (!value)
    throw error(node, name + "=\"" + attribute.value() + "\" is not an integer", "Write " + name + "=\"N\"");
  return value;
}

std::vector<double> XmlFile::values(const pugi::xml_node& array, const std::string& value_name) const {
  std::vector<double> samples;
  const char* name = value_name.c_str();
  std::string joined;
  for (pugi::xml_node value = array.child(name); value; value = value.next_sibling(name)) {
    const char* text = value.value();
    // Text in pieces (a comment or processing instruction between them, review 10 F2: "5<!-- -->00"
    // was read as 5) is joined, as XML means it; an element inside is refused (text()). One piece, kept
    // in the element (parse_embed_pcdata): as is.
    if (value.first_child()) {
      joined = this->text(value);
      text = joined.c_str();
    }
    const std::optional<double> number = parse_stored_number(text);
    if (!number)
      throw input_error(source_, where(value) + " (value " + std::to_string(samples.size() + 1) + " of <" +
                                     array.name() + ">)",
                        describe_bad_number(text),
                        "Remove or interpolate bad values in the source before converting");
    samples.push_back(*number);
  }
  return samples;
}

}  // namespace haptex::convert
