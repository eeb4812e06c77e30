#include "apps/number_checks.hpp"

#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <string>

namespace haptex::apps {
namespace {

// An empty string when `input` is a finite number of at least `min` (above it when `strict`); what is
// wrong otherwise. Text that is no number is left to CLI11's conversion, which names the type. Many
// options are 32-bit floats, so every number is judged as one would hold it: 1e39 would be inf, and a
// positive 1e-320 would be 0.
std::string judge(const std::string& input, double min, bool strict) {
  char* end = nullptr;
  const double value = std::strtod(input.c_str(), &end);
  if (end == input.c_str()) return "";
  if (!std::isfinite(value) || std::abs(value) > FLT_MAX) return "must be a finite number (at most 3.4e38 in size), not " + input;
  if (value < min || (strict && value == min))
    return std::string("must be ") + (strict ? "above " : "at least ") + std::to_string(int(min)) + ", not " + input;
  // A subnormal would lose its digits in a 32-bit float (and a positive one becomes 0 in some kernels).
  if (value != 0 && std::abs(value) < FLT_MIN)
    return std::string("must be ") + (strict ? "at least 1.2e-38" : "0 or at least 1.2e-38 in size") +
           " (the least normal 32-bit float), not " + input;
  return "";
}

CLI::Validator checking(double min, bool strict, const std::string& description) {
  return CLI::Validator([=](std::string& input) { return judge(input, min, strict); }, description);
}

}  // namespace

CLI::Validator finite_number() { return checking(-INFINITY, false, ""); }
CLI::Validator positive_number() { return checking(0, true, "POSITIVE"); }
CLI::Validator non_negative_number() { return checking(0, false, "NONNEGATIVE"); }

CLI::Validator odd_number() {
  return CLI::Validator([](std::string& input) -> std::string {
    char* end = nullptr;
    const long value = std::strtol(input.c_str(), &end, 0);  // base 0: "0x4" is 4 to CLI11 too
    if (end == input.c_str() || *end) return "";                 // no whole number: left to CLI11's conversion
    return value % 2 ? "" : "must be odd, not " + input;
  }, "ODD");
}

CLI::Validator seed_number() {
  // Seeds are written into manifests, logs and reports; past 2^53 a JSON number is no longer exact,
  // and past 2^63 the schemas' integers end (review 4: split did all its work, then failed on its output).
  constexpr unsigned long long kMostSeed = 1ull << 53;
  return CLI::Validator([=](std::string& input) -> std::string {
    const bool digits = !input.empty() && input.size() <= 20 && input.find_first_not_of("0123456789") == std::string::npos;
    if (digits && std::strtoull(input.c_str(), nullptr, 10) <= kMostSeed) return "";  // an overflow gives ULLONG_MAX
    return "a seed is a whole number from 0 to " + std::to_string(kMostSeed) + " (2^53, which JSON keeps exact), not " + input;
  }, "SEED");
}

}  // namespace haptex::apps
