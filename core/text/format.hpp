#pragma once
// printf's formatting into a std::string, for numbers and ids in messages and reports (the compiler
// checks each pattern against its arguments as it checks printf's), replacing text in one, and a list
// of names for a message.
#include <cstddef>
#include <string>
#include <vector>

namespace haptex::text {

std::string format(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

// `text` with every `from` (when not empty) written `to`, left to right.
std::string replace_all(std::string text, const std::string& from, const std::string& to);

// "a, b, c", the first `shown` names in full and then "and N more" (a model of all of HaTT has 100
// materials; a message lists what a user may choose without burying itself).
std::string listed(const std::vector<std::string>& names, std::size_t shown = 12);

}  // namespace haptex::text
