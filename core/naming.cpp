#include "core/naming.hpp"

#include "core/error.hpp"
#include "core/text/format.hpp"
#include "core/text/utf8.hpp"

namespace haptex {
namespace {

// Spaces and punctuation beyond ASCII, which separate words as ' ' and '-' do: Latin-1's (no-break
// space to inverted question mark, multiplication and division signs), General Punctuation
// (dashes, quotes, spaces), CJK symbols and punctuation (ideographic space, brackets), the
// fullwidth ASCII punctuation; and every character that acts on text rather than shows
// (core/text/utf8.hpp), invisible in a name.
bool separates(char32_t u) {
  return (u >= 0xA0 && u <= 0xBF) || u == 0xD7 || u == 0xF7 || (u >= 0x2000 && u <= 0x206F) || (u >= 0x3000 && u <= 0x303F) ||
         (u >= 0xFF01 && u <= 0xFF0F) || (u >= 0xFF1A && u <= 0xFF20) || (u >= 0xFF3B && u <= 0xFF40) ||
         (u >= 0xFF5B && u <= 0xFF65) || text::acts_on_text(u);
}

// Lower case where a script has one and the pair is a fixed offset: Latin-1, Latin Extended-A (in
// pairs, but for the dotted I and the long s), Greek and Cyrillic capitals.
char32_t lower(char32_t u) {
  if ((u >= 0xC0 && u <= 0xDE && u != 0xD7)) return u + 0x20;
  if (u >= 0x100 && u <= 0x137 && u % 2 == 0 && u != 0x130) return u + 1;
  if (u >= 0x139 && u <= 0x148 && u % 2 == 1) return u + 1;
  if (u >= 0x14A && u <= 0x177 && u % 2 == 0) return u + 1;
  if (u == 0x179 || u == 0x17B || u == 0x17D) return u + 1;
  if ((u >= 0x391 && u <= 0x3A9 && u != 0x3A2)) return u + 0x20;
  if (u >= 0x410 && u <= 0x42F) return u + 0x20;
  if (u >= 0x400 && u <= 0x40F) return u + 0x50;
  return u;
}

bool ascii_alnum(char32_t u) { return (u >= '0' && u <= '9') || (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z'); }

}  // namespace

std::string material_id(std::string_view name) {
  std::string id;
  bool pending_separator = false;
  for (const text::Utf8Character& c : text::utf8_characters(name)) {
    const char32_t u = c.valid ? c.code_point : char32_t(static_cast<unsigned char>(c.bytes.front()));
    if (ascii_alnum(u)) {
      if (pending_separator && !id.empty()) id += '_';
      id += char(u >= 'A' && u <= 'Z' ? u + ('a' - 'A') : u);
      pending_separator = false;
    } else if (u < 0x80 || separates(u)) {
      pending_separator = true;
    } else {  // a letter beyond ASCII: a word of its own
      if (!id.empty()) id += '_';
      id += text::format("u%04x", unsigned(lower(u)));
      pending_separator = true;
    }
  }
  return id;
}

namespace {

// A name's letters and digits in order, case folded: what tells two materials apart.
std::u32string letters_of(std::string_view name) {
  std::u32string letters;
  for (const text::Utf8Character& c : text::utf8_characters(name)) {
    const char32_t u = c.valid ? c.code_point : char32_t(static_cast<unsigned char>(c.bytes.front()));
    if (ascii_alnum(u)) letters += (u >= 'A' && u <= 'Z') ? u + ('a' - 'A') : u;
    else if (u >= 0x80 && !separates(u)) letters += lower(u);
  }
  return letters;
}

}  // namespace

bool same_material_name(std::string_view a, std::string_view b) { return letters_of(a) == letters_of(b); }

std::string checked_material_id(std::string_view name, const std::string& file, const std::string& where) {
  const std::string id = material_id(name);
  const std::string shown = text::printable(name.size() > 60 ? std::string(name.substr(0, 60)) + "..." : std::string(name));
  if (id.empty())
    throw input_error(file, where, "'" + shown + "' has no letter or digit to make a material id from",
                      "Give the material a name with at least one letter or digit, e.g. \"Brick 2\"");
  if (id.size() > kLongestMaterialId)
    throw input_error(file, where,
                      text::format("'%s' makes a material id of %zu bytes, longer than the %zu haptex takes (file names are made of it)",
                                   shown.c_str(), id.size(), kLongestMaterialId),
                      "Give the material a shorter name");
  return id;
}

}  // namespace haptex
