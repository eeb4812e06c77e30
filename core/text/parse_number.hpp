#pragma once
#include <optional>
#include <string>
#include <string_view>

namespace haptex::text {

// text without leading and trailing spaces, tabs, CR and LF.
std::string_view trim(std::string_view text);

// The number in text (surrounding white space and a leading '+' allowed), nullopt when the
// text is not exactly one number. NaN and Inf parse; callers reject them with their own message.
std::optional<double> parse_number(std::string_view text);
// Why text is no finite number, for messages: "'abc' is not a number", "'1e-400' is out of range for
// a 64-bit float ...", "'nan' is not a finite number (NaN or Inf)". parsed: parse_number gave a value.
std::string describe_bad_number(std::string_view text, bool parsed);

}  // namespace haptex::text
