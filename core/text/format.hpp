#pragma once
// printf's formatting into a std::string, for numbers and ids in messages and reports (the compiler
// checks each pattern against its arguments as it checks printf's), and replacing text in one.
#include <string>

namespace haptex::text {

std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

// `text` with every `from` (when not empty) written `to`, left to right.
std::string replace_all(std::string text, const std::string& from, const std::string& to);

}  // namespace haptex::text
