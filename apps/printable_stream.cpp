#include "apps/printable_stream.hpp"

#include <string>

#include "core/text/utf8.hpp"

namespace haptex::apps {
namespace {

// The length of the UTF-8 character `lead` starts; 0 for a byte that starts none.
std::size_t sequence_length(unsigned char lead) {
  return lead >= 0xC2 && lead <= 0xDF ? 2 : lead >= 0xE0 && lead <= 0xEF ? 3 : lead >= 0xF0 && lead <= 0xF4 ? 4 : 0;
}

// text::printable's escapes, but in JSON's notation where its own is not JSON (review 16, F5: DEL as
// \x7f made `--json` output invalid): \u007f, and a character beyond U+FFFF as a UTF-16 surrogate
// pair (U+E0041 as \udb40\udc41, not \U000e0041). JSON strings may hold the others as they are.
std::string escaped(std::string_view text) {
  static constexpr char kHex[] = "0123456789abcdef";
  const auto unit = [](char32_t u) { return std::string{'\\', 'u', kHex[(u >> 12) & 15], kHex[(u >> 8) & 15], kHex[(u >> 4) & 15], kHex[u & 15]}; };
  std::string out;
  for (const text::Utf8Character& c : text::utf8_characters(text)) {
    const char32_t u = c.code_point;
    if (c.valid && u == 0x7f) {
      out += unit(u);
    } else if (c.valid && u > 0xffff && text::acts_on_text(u, true)) {
      out += unit(0xd800 + ((u - 0x10000) >> 10)) + unit(0xdc00 + ((u - 0x10000) & 0x3ff));
    } else {
      out += text::printable(c.bytes, true);
    }
  }
  return out;
}

}  // namespace

bool PrintableBuffer::put(std::string_view text) {
  return target_->sputn(text.data(), std::streamsize(text.size())) == std::streamsize(text.size());
}

// The pending bytes as they came: not a whole character after all.
bool PrintableBuffer::flush_pending() {
  const bool ok = put(pending_);
  pending_.clear();
  return ok;
}

PrintableBuffer::int_type PrintableBuffer::overflow(int_type c) {
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  written_ = true;
  const char ch = traits_type::to_char_type(c);
  const auto byte = static_cast<unsigned char>(ch);
  if (!pending_.empty() && (byte & 0xC0) != 0x80 && !flush_pending()) return traits_type::eof();
  if (!pending_.empty()) {
    pending_ += ch;
    if (pending_.size() < expected_) return c;
    const std::string character = std::move(pending_);
    pending_.clear();
    return put(escaped(character)) ? c : traits_type::eof();
  }
  if (byte >= 0x80 && sequence_length(byte) > 0) {
    pending_ = std::string(1, ch);
    expected_ = sequence_length(byte);
    return c;
  }
  // ASCII (controls escaped), or a stray byte, which passes as it came.
  if (byte < 0x80 && text::acts_on_text(byte, true)) return put(escaped(std::string(1, ch))) ? c : traits_type::eof();
  return traits_type::eq_int_type(target_->sputc(ch), traits_type::eof()) ? traits_type::eof() : c;
}

int PrintableBuffer::sync() {
  if (!pending_.empty()) flush_pending();
  return target_->pubsync();
}

}  // namespace haptex::apps
