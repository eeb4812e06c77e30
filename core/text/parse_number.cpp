#include "core/text/parse_number.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <limits>
#include <cmath>

namespace haptex::text {

std::string_view trim(std::string_view text) {
  auto is_space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  return text;
}

namespace {

// Plain decimals of at most 15 digits and no exponent ("-0.299263", a HaTT sample), without
// from_chars: the digits make an integer under 2^53 and the power of ten (at most 10^15) is exact, so
// one IEEE division rounds the exact quotient once, as from_chars does (Clinger's fast path). It
// cuts the parse of a 26 MB HaTT recording by a third (issue 37). nullopt: any other text.
std::optional<double> plain_short_decimal(std::string_view text) {
  static constexpr double kPowers[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
  const bool negative = !text.empty() && text.front() == '-';
  if (negative) text.remove_prefix(1);
  std::uint64_t digits = 0;
  int count = 0, after_point = -1;
  for (const char c : text) {
    if (c == '.' && after_point < 0) {
      after_point = 0;
      continue;
    }
    if (c < '0' || c > '9' || ++count > 15) return std::nullopt;
    digits = digits * 10 + std::uint64_t(c - '0');
    if (after_point >= 0) ++after_point;
  }
  if (count == 0) return std::nullopt;
  const double value = double(digits) / kPowers[std::max(after_point, 0)];
  return negative ? -value : value;
}

}  // namespace

std::optional<double> parse_number(std::string_view text) {
  text = trim(text);
  const bool plus = !text.empty() && text.front() == '+';
  if (plus) text.remove_prefix(1);
  // One sign: from_chars would read the '-' of "+-1" (review 16, F2).
  if (text.empty() || (plus && (text.front() == '-' || text.front() == '+'))) return std::nullopt;
  if (const std::optional<double> quick = plain_short_decimal(text)) return quick;
  double value = 0;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// Read left to right: std::regex matched these forms recursively, a frame a character, and a format
// attribute of 50 000 digits overflowed the stack (review 16, F4).
bool is_plain_decimal(std::string_view text, Decimal kind) {
  std::size_t i = 0;
  const auto digits = [&] {
    const std::size_t from = i;
    while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
    return i - from;
  };
  if (i < text.size() && (text[i] == '+' || (text[i] == '-' && kind != Decimal::natural))) ++i;
  const std::size_t first = i, integer = digits();
  if (integer > 1 && text[first] == '0') return false;  // a leading zero
  if (kind != Decimal::real) return integer > 0 && i == text.size();
  std::size_t fraction = 0;
  if (i < text.size() && text[i] == '.') {
    ++i;
    fraction = digits();
  }
  if (integer == 0 && fraction == 0) return false;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    ++i;
    if (i < text.size() && (text[i] == '+' || text[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == text.size();
}

std::optional<long long> parse_whole_number(std::string_view text) {
  if (!is_plain_decimal(text, Decimal::whole)) return std::nullopt;
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty() || text.front() == '+') return std::nullopt;
  long long value = 0;
  auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value, 10);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

bool within_float_range(double value) {
  // Half a unit in the last place above FLT_MAX: from there on, a value rounds to infinity.
  constexpr double kRoundsToInfinity = 3.4028235677973366e38;
  return std::isfinite(value) && std::abs(value) < kRoundsToInfinity;
}

bool fits_stored_float(double value) {
  return value == 0 || (within_float_range(value) && std::abs(float(value)) >= std::numeric_limits<float>::min());
}

std::optional<double> parse_stored_number(std::string_view text) {
  const std::optional<double> value = parse_number(text);
  if (!value || !fits_stored_float(*value)) return std::nullopt;
  return value;
}

std::string describe_bad_number(std::string_view text, bool) {
  const std::string quoted = "'" + std::string(text.substr(0, 40)) + (text.size() > 40 ? "...'" : "'");
  if (const std::optional<double> value = parse_number(text)) {
    if (!std::isfinite(*value)) return quoted + " is not a finite number (NaN or Inf)";
    if (!within_float_range(*value)) return quoted + " is beyond 3.4e38, the largest magnitude of the 32-bit floats haptex stores";
    return quoted + " is under 1.2e-38, the least magnitude the 32-bit floats haptex stores keep with all its digits (write 0 for none)";
  }
  std::string_view t = trim(text);
  if (!t.empty() && t.front() == '+') t.remove_prefix(1);
  double ignored = 0;
  const auto [end, error] = std::from_chars(t.data(), t.data() + t.size(), ignored);
  if (error == std::errc::result_out_of_range && end == t.data() + t.size())
    return quoted + " is out of range of the 32-bit floats haptex stores (magnitudes from 1.2e-38 to 3.4e38, or 0)";
  return quoted + " is not a number";
}

std::optional<FrameSize> parse_frame_size(std::string_view text) {
  const auto side = [](std::string_view digits) -> std::optional<long long> {
    if (digits.empty() || digits.size() > 9 || digits.front() == '0') return std::nullopt;
    long long value = 0;
    for (const char c : digits) {
      if (c < '0' || c > '9') return std::nullopt;
      value = value * 10 + (c - '0');
    }
    return value;
  };
  const std::size_t x = text.find('x');
  if (x == std::string_view::npos) return std::nullopt;
  const auto width = side(text.substr(0, x)), height = side(text.substr(x + 1));
  if (!width || !height) return std::nullopt;
  return FrameSize{*width, *height};
}

}  // namespace haptex::text
