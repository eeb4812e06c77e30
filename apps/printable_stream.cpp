#include "apps/printable_stream.hpp"

#include <cstdio>

namespace haptex::apps {

bool PrintableBuffer::put(const char* text) {
  for (; *text; ++text)
    if (target_->sputc(*text) == traits_type::eof()) return false;
  return true;
}

PrintableBuffer::int_type PrintableBuffer::overflow(int_type c) {
  if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
  const auto byte = static_cast<unsigned char>(traits_type::to_char_type(c));
  char escaped[8];
  if (lead_c2_) {
    lead_c2_ = false;
    if (byte >= 0x80 && byte <= 0x9f) {
      std::snprintf(escaped, sizeof escaped, "\\u%04x", byte);
      return put(escaped) ? c : traits_type::eof();
    }
    if (target_->sputc(char(0xc2)) == traits_type::eof()) return traits_type::eof();
  }
  if (byte == 0xc2) {
    lead_c2_ = true;
    return c;
  }
  if ((byte < 0x20 && byte != '\n' && byte != '\t') || byte == 0x7f) {
    std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
    return put(escaped) ? c : traits_type::eof();
  }
  return target_->sputc(char(byte)) == traits_type::eof() ? traits_type::eof() : c;
}

int PrintableBuffer::sync() {
  if (lead_c2_ && target_->sputc(char(0xc2)) != traits_type::eof()) lead_c2_ = false;
  return target_->pubsync();
}

}  // namespace haptex::apps
