#pragma once
// printf's formatting into a std::string, for numbers and ids in messages and reports. The compiler
// checks each pattern against its arguments as it checks printf's.
#include <string>

namespace haptex::text {

std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

}  // namespace haptex::text
