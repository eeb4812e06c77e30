// parse_number's short-decimal path must give what from_chars gives, bit for bit, and the same refusals.
#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cfloat>
#include <cstdint>
#include <optional>
#include <random>
#include <regex>
#include <string>
#include <vector>

#include "core/text/parse_number.hpp"

namespace haptex::text {
namespace {

// What parse_number means, through from_chars alone: the whole trimmed text, less one leading '+'
// that no other sign follows.
std::optional<double> by_from_chars(std::string_view text) {
  text = trim(text);
  const bool plus = !text.empty() && text.front() == '+';
  if (plus) text.remove_prefix(1);
  if (text.empty() || (plus && (text.front() == '-' || text.front() == '+'))) return std::nullopt;
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

// Review 16, F2: one sign only.
TEST(ParseNumber, OneSignOnly) {
  for (const char* text : {"+-1", "+--1", "++1", "-+1", "--1", "+ 1"}) EXPECT_FALSE(parse_number(text).has_value()) << text;
  EXPECT_EQ(parse_number("+1"), 1.0);
  EXPECT_EQ(parse_number("-1"), -1.0);
}

// Review 16, F3: the extremes of float32 as float printers write them round to finite normal floats.
TEST(ParseNumber, StoredFloatsTakeTheExtremesAsPrinted) {
  for (const char* text : {"3.4028235e38", "-3.4028235e38", "3.40282356e38", "1.17549435e-38", "-1.1754944e-38", "0", "-0"})
    EXPECT_TRUE(parse_stored_number(text).has_value()) << text;
  // 2^128 - 2^103 rounds (to even) to infinity; 1.1754942e-38 to the largest subnormal.
  for (const char* text : {"3.4028235677973366e38", "3.5e38", "1e39", "1.1754942e-38", "1e-40", "nan", "inf"})
    EXPECT_FALSE(parse_stored_number(text).has_value()) << text;
  EXPECT_TRUE(within_float_range(std::nextafter(3.4028235677973366e38, 0.0)));
  EXPECT_EQ(float(*parse_stored_number("3.4028235e38")), FLT_MAX);
  EXPECT_EQ(float(*parse_stored_number("1.17549435e-38")), FLT_MIN);
  EXPECT_NE(describe_bad_number("3.5e38").find("beyond 3.4e38"), std::string::npos);
  EXPECT_NE(describe_bad_number("1e-40").find("under 1.2e-38"), std::string::npos);
}

// Review 16, F4: the plain-decimal forms are read without recursion; they are the forms these
// expressions describe, checked on every string of up to 5 characters from the characters that matter.
TEST(PlainDecimal, SameFormsAsTheRegularExpressionsWithoutItsRecursion) {
  const std::regex whole("[+-]?(0|[1-9][0-9]*)"), natural("\\+?(0|[1-9][0-9]*)"),
      real("[+-]?((0|[1-9][0-9]*)(\\.[0-9]*)?|\\.[0-9]+)([eE][+-]?[0-9]+)?");
  const std::string alphabet = "015.+-e ";
  std::vector<std::string> texts{""};
  for (std::size_t begin = 0, length = 1; length <= 5; ++length) {
    const std::size_t end = texts.size();
    for (std::size_t i = begin; i < end; ++i)
      for (const char c : alphabet) texts.push_back(texts[i] + c);
    begin = end;
  }
  for (const std::string& t : texts) {
    ASSERT_EQ(is_plain_decimal(t, Decimal::whole), std::regex_match(t, whole)) << "'" << t << "'";
    ASSERT_EQ(is_plain_decimal(t, Decimal::natural), std::regex_match(t, natural)) << "'" << t << "'";
    ASSERT_EQ(is_plain_decimal(t, Decimal::real), std::regex_match(t, real)) << "'" << t << "'";
  }
  const std::string long_number(200000, '7');
  EXPECT_TRUE(is_plain_decimal(long_number, Decimal::natural));
  EXPECT_FALSE(is_plain_decimal(long_number + "x", Decimal::real));
}

}  // namespace
}  // namespace haptex::text
