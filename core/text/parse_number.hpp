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
// Numbers on the command line and in device specs are plain decimals, as a user means them: no
// leading zero (CLI11 reads 025 as octal 21), no 0x, no spaces (issue 32, reviews 2 and 6).
enum class Decimal { whole, natural, real };  // [+-]123, [+]123, [+-]1.5e3
bool is_plain_decimal(std::string_view text, Decimal kind);
// The plain decimal integer that is all of text (a leading '-' or '+' allowed; no spaces, no 0x, no
// leading zero, no exponent, no fraction), nullopt otherwise or when it does not fit in 64 bits.
std::optional<long long> parse_whole_number(std::string_view text);
// "WIDTHxHEIGHT" as a user writes a frame size: two numbers of digits only, from 1, without a sign, a
// leading zero or a space (synth --size, capture record --size, fake:size=; review 14, F11); nullopt
// otherwise or when a side does not fit in 9 digits. The range each command takes is its own.
struct FrameSize {
  long long width = 0, height = 0;
};
std::optional<FrameSize> parse_frame_size(std::string_view text);
// The least magnitude but 0 a 32-bit float holds with all its digits (FLT_MIN): smaller ones are
// subnormal, stored with their digits lost or as 0, so readers refuse them as they refuse one too large.
inline constexpr double kSmallestStored = 1.1754943508222875e-38;
// True when value rounds to a finite 32-bit float: up to FLT_MAX and half a unit in the last place
// beyond it, so 3.4028235e38, FLT_MAX as float printers write it, does (review 16, F3).
bool within_float_range(double value);
// True when value is 0, or rounds to a finite 32-bit float of FLT_MIN or more in magnitude (not to a
// subnormal one, whose digits are lost): 1.17549435e-38, FLT_MIN as printed, does.
bool fits_stored_float(double value);
// parse_number, for a value fits_stored_float takes only.
std::optional<double> parse_stored_number(std::string_view text);
// Why text is no number parse_stored_number takes, for messages: "'abc' is not a number", "'1e-400' is
// out of range for a 64-bit float ...", "'nan' is not a finite number (NaN or Inf)", "'1e39' is beyond
// ...". parsed: unused (the text is parsed again).
std::string describe_bad_number(std::string_view text, bool parsed = false);

}  // namespace haptex::text
