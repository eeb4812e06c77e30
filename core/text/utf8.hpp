#pragma once
// UTF-8, strictly (RFC 3629): no overlong forms, no surrogates, nothing past U+10FFFF. Names enter
// haptex from files, folders and the command line; they must be UTF-8 before anything stores them
// (JSON and HDF5 strings are UTF-8), so readers refuse the rest at the door with require_utf8().
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace haptex::text {

struct Utf8Character {
  char32_t code_point = 0;  // U+FFFD when not valid
  std::string_view bytes;   // the encoded character, or the one byte that starts no valid character
  bool valid = true;
};

std::vector<Utf8Character> utf8_characters(std::string_view text);

// Byte offset of the first byte that starts no valid UTF-8 character; npos when text is all UTF-8.
std::size_t invalid_utf8_offset(std::string_view text);

// Whether a terminal or a text viewer would act on code point u rather than show it: a control
// character (C0, DEL, C1: a terminal's escape sequences start with one; newline and tab unless
// keep_newlines) or an invisible format character that reorders or breaks the text around it (the
// bidirectional marks, embeddings, overrides and isolates such as U+202E RIGHT-TO-LEFT OVERRIDE, the
// line and paragraph separators U+2028 and U+2029, zero-width characters, the soft hyphen, U+FEFF,
// and the tag characters U+E0000..U+E007F, which carry invisible text).
bool acts_on_text(char32_t u, bool keep_newlines = false);

// text as a terminal may show it: each byte that is not UTF-8 as \xHH, each character acts_on_text
// names as \xHH (below U+0080), \uHHHH or \UHHHHHHHH. Names and paths pass through it before they are printed,
// and before they are written into a report.
std::string printable(std::string_view text, bool keep_newlines = false);

// At most `most` bytes of text, cut before a character's continuation bytes, and "... (N bytes)" after
// it when cut: what a file holds, quoted in one line whatever its length (a 2 MB attribute).
std::string shortened(std::string_view text, std::size_t most = 80);

// text without a leading UTF-8 byte order mark, which spreadsheets and some editors write before
// CSV and JSON (nlohmann's parser skips it too).
std::string_view without_byte_order_mark(std::string_view text);

// What is wrong with text as a name, said as a finding about it ("is not valid UTF-8 (byte 3 of
// \"Caf\\xe9\")", "holds a NUL character (byte 2), ..."); nullopt when it is UTF-8 without a NUL.
std::optional<std::string> utf8_problem(std::string_view text);

// Throws haptex::Error (bad input) naming file, what (e.g. "the material name") and the byte
// offset when text is not UTF-8, or holds a NUL (which HDF5 and C strings would cut the name at).
void require_utf8(std::string_view text, const std::string& file, const std::string& what);

}  // namespace haptex::text
