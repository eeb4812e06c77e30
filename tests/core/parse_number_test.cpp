// parse_number's short-decimal path must give what from_chars gives, bit for bit, and the same refusals.
#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cstdint>
#include <optional>
#include <random>
#include <string>

#include "core/text/parse_number.hpp"

namespace haptex::text {
namespace {

// What parse_number meant before the short path: the whole trimmed text, less one leading '+', through from_chars.
std::optional<double> by_from_chars(std::string_view text) {
  text = trim(text);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return std::nullopt;
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

void expect_same(const std::string& text) {
  const std::optional<double> ours = parse_number(text), theirs = by_from_chars(text);
  ASSERT_EQ(ours.has_value(), theirs.has_value()) << "'" << text << "'";
  if (ours) {
    ASSERT_EQ(std::bit_cast<std::uint64_t>(*ours), std::bit_cast<std::uint64_t>(*theirs)) << "'" << text << "'";
  }
}

TEST(ParseNumber, EdgeCasesMatchFromChars) {
  for (const char* text : {"1.", ".5", "-.5", "+.5", "-0", "0.", "-0.0", ".", "-", "+", "+-1", "--1", "1.2.3", "1e5", "-1E-3", "0x1p3",
                           " 7 ", "\t-3.25\r\n", "000000000000001", "0000000000000001", "123456789012345", "1234567890123456",
                           "0.000000000000001", "9999999999999.99", "99999999999999.99", "1,5", "1 5", "", "  ", "nan", "inf",
                           "-inf", "1e400", "4.9e-324", "0.1", "0.3", "2.675", "-0.299263", "3.628481"})
    expect_same(text);
}

TEST(ParseNumber, RandomShortDecimalsMatchFromCharsBitForBit) {
  std::mt19937_64 random(37);
  std::uniform_int_distribution<int> length(1, 17), digit(0, 9), coin(0, 3);
  for (int n = 0; n < 300000; ++n) {
    const int digits = length(random);
    std::string text = coin(random) == 0 ? "-" : coin(random) == 0 ? "+" : "";
    const int point = std::uniform_int_distribution<int>(-1, digits)(random);
    for (int i = 0; i < digits; ++i) {
      if (i == point) text += '.';
      text += char('0' + digit(random));
    }
    if (point == digits) text += '.';
    expect_same(text);
  }
}

}  // namespace
}  // namespace haptex::text
