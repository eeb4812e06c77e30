#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

#include "core/json/schema.hpp"
#include "tests/support/bad_input.hpp"

namespace haptex {
namespace {

using test::bad_input_message;

// A key given twice is named by its JSON pointer, through arrays and nested objects alike.
TEST(JsonParse, AKeyGivenTwiceIsNamedByItsPointer) {
  const auto refusal = [](const std::string& text) { return bad_input_message([&] { json::parse_text(text, "f.json"); }); };
  EXPECT_NE(refusal(R"({"a": 1, "a": 1})").find("f.json: /a: the key is given twice"), std::string::npos);
  EXPECT_NE(refusal(R"({"a": [1, {"b": 1}, {"c": [], "d": {"e": 0}, "c": 2}]})").find("/a/2/c: the key"), std::string::npos);
  EXPECT_NE(refusal(R"([[], [{"x": 1}], {"y": {"z": 1, "z": 2}}])").find("/2/y/z: the key"), std::string::npos);
}

TEST(JsonParse, EqualKeysInDifferentObjectsAreFine) {
  const nlohmann::json doc = json::parse_text(R"({"a": {"k": 1}, "b": [{"k": 2}, {"k": 3}], "k": 4})", "f.json");
  EXPECT_EQ(doc["b"][1]["k"], 3);
  EXPECT_EQ(doc["k"], 4);
}

// Review 10, C4: a schema's refusal ended "..", and its fix only pointed at the schema. It says what
// the file is where the schema does.
TEST(JsonValidate, ARefusalEndsOnceAndSaysWhatTheFileIs) {
  const std::string message = bad_input_message([] { json::validate(nlohmann::json::array(), "name-map.schema.json", "names.json"); });
  EXPECT_EQ(message.find(".."), std::string::npos) << message;
  EXPECT_NE(message.find("names.json: (top level): "), std::string::npos) << message;
  EXPECT_NE(message.find("See schemas/name-map.schema.json: Each key is a material's name in the gelsight file"), std::string::npos) << message;
}

}  // namespace
}  // namespace haptex
