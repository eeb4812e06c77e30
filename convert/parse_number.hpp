#pragma once
#include <optional>
#include <string_view>

namespace haptex::convert {

// text without leading and trailing spaces, tabs, CR and LF.
std::string_view trim(std::string_view text);

// The number in text (surrounding white space and a leading '+' allowed), nullopt when the
// text is not exactly one number. NaN and Inf parse; callers reject them with their own message.
std::optional<double> parse_number(std::string_view text);

}  // namespace haptex::convert
