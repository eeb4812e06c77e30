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

// Review 23, F7: std::regex recurses once per character, so a 200 000-letter string a schema "pattern"
// checks overflowed the stack; such strings are refused first. Review 24, F1: only those: results.json's
// `name` is pattern-checked for an external model's name, not a material's, which is as long as a user
// makes it.
TEST(JsonValidate, OnlyStringsAPatternChecksAreBoundedBeforeTheRegex) {
  const std::string long_text(200000, 'a');
  nlohmann::json external;
  external["inputs"]["predictions"] = nlohmann::json::array({{{"name", long_text}}});
  const std::string message = bad_input_message([&] { json::validate(external, "results.schema.json", "results.json"); });
  EXPECT_NE(message.find("results.json: /inputs/predictions/0/name: is a text of 200000 bytes where an id"), std::string::npos) << message;
  nlohmann::json material;
  material["examples"] = nlohmann::json::array({{{"name", long_text}}});
  const std::string other = bad_input_message([&] { json::validate(material, "results.schema.json", "results.json"); });
  EXPECT_EQ(other.find("where an id"), std::string::npos) << other;  // the schema's own complaint (fields missing)
  nlohmann::json hashed;
  hashed["inputs"]["dataset"]["sha256"] = long_text;  // through "$ref": "#/definitions/input"
  const std::string hash = bad_input_message([&] { json::validate(hashed, "results.schema.json", "results.json"); });
  EXPECT_NE(hash.find("/inputs/dataset/sha256: is a text of 200000 bytes"), std::string::npos) << hash;
}

}  // namespace
}  // namespace haptex
