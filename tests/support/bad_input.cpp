#include "tests/support/bad_input.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"

namespace haptex::test {

std::string bad_input_message(const std::function<void()>& action) {
  try {
    action();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), Error::Kind::bad_input) << e.what();
    return e.what();
  }
  ADD_FAILURE() << "no error was thrown";
  return "";
}

}  // namespace haptex::test
