#pragma once
// What library tests assert about a refusal: a haptex::Error of kind bad_input, whose message the
// test then searches for the file, the place and the fix.
#include <functional>
#include <string>

namespace haptex::test {

// The message of the bad-input error `action` throws; a gtest failure (and "") when it throws none
// or an error of another kind.
std::string bad_input_message(const std::function<void()>& action);

}  // namespace haptex::test
