#include "core/text/utf8.hpp"

#include "core/error.hpp"

namespace haptex::text {

namespace {

// Decodes the character at text[i]; length 0 when no valid character starts there.
Utf8Character decode(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  Utf8Character c{0xFFFD, text.substr(i, 1), false};
  if (lead < 0x80) return {lead, text.substr(i, 1), true};
  const int length = lead >= 0xC2 && lead <= 0xDF ? 2 : lead >= 0xE0 && lead <= 0xEF ? 3 : lead >= 0xF0 && lead <= 0xF4 ? 4 : 0;
  if (length == 0 || i + std::size_t(length) > text.size()) return c;
  char32_t code = lead & (0x7F >> length);
  for (int k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return c;
    code = (code << 6) | (byte(i + k) & 0x3F);
  }
  const char32_t smallest[] = {0, 0, 0x80, 0x800, 0x10000};
  if (code < smallest[length] || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return c;
  return {code, text.substr(i, std::size_t(length)), true};
}

}  // namespace

std::vector<Utf8Character> utf8_characters(std::string_view text) {
  std::vector<Utf8Character> characters;
  for (std::size_t i = 0; i < text.size();) {
    characters.push_back(decode(text, i));
    i += characters.back().bytes.size();
  }
  return characters;
}

std::size_t invalid_utf8_offset(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const Utf8Character c = decode(text, i);
    if (!c.valid) return i;
    i += c.bytes.size();
  }
  return std::string_view::npos;
}

bool acts_on_text(char32_t u, bool keep_newlines) {
  if (keep_newlines && (u == '\n' || u == '\t')) return false;
  return u < 0x20 || u == 0x7f || (u >= 0x80 && u <= 0x9f) || u == 0xad || u == 0x061c || u == 0x180e || (u >= 0x200b && u <= 0x200f) ||
         (u >= 0x2028 && u <= 0x202e) || (u >= 0x2060 && u <= 0x206f) || u == 0xfeff || (u >= 0xfff9 && u <= 0xfffb) ||
         (u >= 0xe0000 && u <= 0xe007f);
}

std::string_view without_byte_order_mark(std::string_view text) {
  return text.starts_with("\xEF\xBB\xBF") ? text.substr(3) : text;
}

std::string shortened(std::string_view text, std::size_t most) {
  if (text.size() <= most) return std::string(text);
  std::size_t cut = most;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return std::string(text.substr(0, cut)) + "... (" + std::to_string(text.size()) + " bytes)";
}

std::string printable(std::string_view text, bool keep_newlines) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (const Utf8Character& c : utf8_characters(text)) {
    const char32_t u = c.code_point;
    if (c.valid && !acts_on_text(u, keep_newlines)) {
      out += c.bytes;
    } else if (c.valid && u < 0x80) {
      out += {'\\', 'x', kHex[u >> 4], kHex[u & 15]};
    } else if (c.valid && u <= 0xffff) {
      out += {'\\', 'u', kHex[(u >> 12) & 15], kHex[(u >> 8) & 15], kHex[(u >> 4) & 15], kHex[u & 15]};
    } else if (c.valid) {
      out += {'\\', 'U', '0', '0', kHex[(u >> 20) & 15], kHex[(u >> 16) & 15], kHex[(u >> 12) & 15], kHex[(u >> 8) & 15],
              kHex[(u >> 4) & 15], kHex[u & 15]};
    } else {
      const auto b = static_cast<unsigned char>(c.bytes[0]);
      out += {'\\', 'x', kHex[b >> 4], kHex[b & 15]};
    }
  }
  return out;
}

std::optional<std::string> utf8_problem(std::string_view text) {
  if (const std::size_t nul = text.find('\0'); nul != std::string_view::npos)
    return "holds a NUL character (byte " + std::to_string(nul) + "), which no name may hold";
  const std::size_t offset = invalid_utf8_offset(text);
  if (offset == std::string_view::npos) return std::nullopt;
  return "is not valid UTF-8 (byte " + std::to_string(offset) + " of \"" + printable(text) + "\")";
}

void require_utf8(std::string_view text, const std::string& file, const std::string& what) {
  const std::optional<std::string> problem = utf8_problem(text);
  if (!problem) return;
  throw input_error(file, what, *problem,
                    text.find('\0') != std::string_view::npos
                        ? "Remove it: HDF5 and C strings end at a NUL, so the name would be cut there"
                        : "Write it in UTF-8 (iconv -f latin1 -t utf-8 converts a file, convmv a folder name)");
}

}  // namespace haptex::text
