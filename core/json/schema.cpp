#include "core/json/schema.hpp"

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <vector>
#include <nlohmann/json.hpp>
#include <valijson/adapters/nlohmann_json_adapter.hpp>
#include <valijson/schema.hpp>
#include <valijson/schema_parser.hpp>
#include <valijson/validation_results.hpp>
#include <valijson/validator.hpp>

#include "core/content_mark.hpp"
#include "core/durable_file.hpp"
#include "core/embedded.hpp"
#include "core/error.hpp"
#include "core/format_version.hpp"
#include "core/input_file.hpp"
#include "core/open_files.hpp"

namespace haptex::json {
namespace {

// valijson compares every pair of an array's items for uniqueItems, and keeps an error per repeated
// pair: a 7 MB list never finishes, 10 000 repeats take gigabytes (review 15, R6). So the keyword is
// the readers' to check, in linear time (split/manifest_reader.hpp, validate_split_manifest, for
// split.schema.json, the one schema that has it); the schema files keep it for other validators.
void drop_unique_items(nlohmann::json& schema) {
  if (schema.is_object()) schema.erase("uniqueItems");
  if (schema.is_structured())
    for (nlohmann::json& part : schema) drop_unique_items(part);
}

// The schema file `name` as JSON, parsed once: validate reads it for the format, the patterns, the
// description and valijson's compiled form.
const nlohmann::json& schema_document(std::string_view name) {
  static std::mutex mutex;
  static std::map<std::string, nlohmann::json, std::less<>> cache;
  std::lock_guard lock(mutex);
  auto it = cache.find(name);
  if (it == cache.end()) it = cache.emplace(std::string(name), nlohmann::json::parse(embedded::schema(name))).first;
  return it->second;  // std::map never moves its elements
}

const valijson::Schema& compiled_schema(std::string_view name) {
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<valijson::Schema>, std::less<>> cache;
  std::lock_guard lock(mutex);
  auto it = cache.find(name);
  if (it != cache.end()) return *it->second;
  nlohmann::json schema_doc = schema_document(name);
  drop_unique_items(schema_doc);
  auto schema = std::make_unique<valijson::Schema>();
  valijson::SchemaParser parser;
  valijson::adapters::NlohmannJsonAdapter adapter(schema_doc);
  parser.populateSchema(adapter, *schema);
  return *cache.emplace(std::string(name), std::move(schema)).first->second;
}

// A document of a later version of the schema's format ("split/2" where split.schema.json says
// "split/1") came from a newer haptex: said so, not as a schema failure.
void refuse_newer_format(const nlohmann::json& doc, std::string_view schema_name, const std::string& file) {
  if (!doc.is_object() || !doc.contains("format") || !doc["format"].is_string()) return;
  const nlohmann::json& schema_doc = schema_document(schema_name);
  const nlohmann::json::json_pointer wanted_at("/properties/format/const");
  if (!schema_doc.contains(wanted_at) || !schema_doc[wanted_at].is_string()) return;
  const std::string found = doc["format"].get<std::string>(), wanted = schema_doc[wanted_at].get<std::string>();
  if (is_newer_version(found, wanted)) throw newer_version_error(file, "/format", found, wanted);
}

// valijson matches a "pattern" with std::regex, whose matcher recurses once per character: a split
// manifest's 30 000-letter id overflowed an 8 MB stack (review 23, F7; 20 000 passed). Every pattern in
// schemas/ checks an id, a hash, a file name or a number, so what a pattern would check is bounded first.
constexpr std::size_t kLongestPatternText = 4096;

// `schema` itself, or what its "$ref" ("#/definitions/..." or any pointer into the schema file) names.
const nlohmann::json& resolved(const nlohmann::json& schema, const nlohmann::json& root) {
  const nlohmann::json* at = &schema;
  for (int hops = 0; hops < 16 && at->is_object() && at->contains("$ref") && (*at)["$ref"].is_string(); ++hops) {
    const std::string ref = (*at)["$ref"].get<std::string>();
    if (!ref.starts_with("#")) break;
    const nlohmann::json::json_pointer pointer(ref.substr(1));
    if (!root.contains(pointer)) break;
    at = &root.at(pointer);
  }
  return *at;
}

// Walks doc with the schema that applies to each part (properties, additionalProperties, items,
// oneOf/anyOf/allOf, $ref: what schemas/ uses) and throws naming the first string that a "pattern"
// checks and that is longer than kLongestPatternText. Only those: a material's name is as long as
// a user makes it (review 24, F1: a 5010-byte name under results.json's `name` was refused, where the
// pattern is an external model's name).
void refuse_long_pattern_texts(const nlohmann::json& doc, const nlohmann::json& schema, const nlohmann::json& root,
                               const std::string& pointer, const std::string& file) {
  const nlohmann::json& s = resolved(schema, root);
  if (!s.is_object()) return;
  if (doc.is_string() && s.contains("pattern") && doc.get_ref<const std::string&>().size() > kLongestPatternText)
    throw input_error(file, pointer.empty() ? "/" : pointer,
                      "is a text of " + std::to_string(doc.get_ref<const std::string&>().size()) +
                          " bytes where an id, a hash or a file name goes (at most " + std::to_string(kLongestPatternText) + ")",
                      "Give the right value");
  for (const char* alternatives : {"oneOf", "anyOf", "allOf"})
    if (s.contains(alternatives) && s[alternatives].is_array())
      for (const nlohmann::json& alternative : s[alternatives]) refuse_long_pattern_texts(doc, alternative, root, pointer, file);
  if (doc.is_object())
    for (const auto& [key, value] : doc.items()) {
      if (s.contains("properties") && s["properties"].is_object() && s["properties"].contains(key))
        refuse_long_pattern_texts(value, s["properties"][key], root, pointer + "/" + key, file);
      else if (s.contains("additionalProperties"))
        refuse_long_pattern_texts(value, s["additionalProperties"], root, pointer + "/" + key, file);
    }
  if (doc.is_array() && s.contains("items"))
    for (std::size_t i = 0; i < doc.size(); ++i) refuse_long_pattern_texts(doc[i], s["items"], root, pointer + "/" + std::to_string(i), file);
}

// The JSON pointer of the first key or string value holding a NUL (\u0000), "" when none does.
std::string nul_at(const nlohmann::json& doc, const std::string& pointer) {
  if (doc.is_string()) return doc.get_ref<const std::string&>().find('\0') == std::string::npos ? "" : pointer.empty() ? "/" : pointer;
  if (doc.is_array())
    for (std::size_t i = 0; i < doc.size(); ++i)
      if (std::string at = nul_at(doc[i], pointer + "/" + std::to_string(i)); !at.empty()) return at;
  if (doc.is_object())
    for (const auto& [key, value] : doc.items()) {
      if (key.find('\0') != std::string::npos) return pointer + "/" + key;
      if (std::string at = nul_at(value, pointer + "/" + key); !at.empty()) return at;
    }
  return "";
}

// Where the parser is: one level per open object or array, so that a key given twice is named by
// its JSON pointer (nlohmann keeps the last of two equal keys without a word).
class OpenLevels {
 public:
  void open(bool array) { levels_.push_back({array, {}, {}, 0}); }
  void close() {
    levels_.pop_back();
    finished_value();
  }
  void finished_value() {
    if (!levels_.empty() && levels_.back().array) ++levels_.back().index;
  }
  // Throws when the innermost object already has `key`.
  void key(const std::string& key, const std::string& file) {
    Level& level = levels_.back();
    if (!level.keys.insert(key).second)
      throw input_error(file, pointer() + "/" + key, "the key is given twice",
                        "Give each key once: a JSON reader keeps only one of the two, and which one differs between readers");
    level.key = key;
  }

 private:
  struct Level {
    bool array;
    std::set<std::string> keys;
    std::string key;
    std::size_t index;
  };
  std::string pointer() const {
    std::string at;
    for (std::size_t i = 0; i + 1 < levels_.size(); ++i)
      at += "/" + (levels_[i].array ? std::to_string(levels_[i].index) : levels_[i].key);
    return at;
  }
  std::vector<Level> levels_;
};

}  // namespace

nlohmann::json parse_text(std::string_view text, const std::string& file) {
  using Event = nlohmann::json::parse_event_t;
  OpenLevels levels;
  const auto check = [&](int depth, Event event, nlohmann::json& parsed) {
    if (depth > kDeepestJson)
      throw input_error(file, "", "nests deeper than " + std::to_string(kDeepestJson) + " levels", "No haptex document nests so deep: give the right file");
    if (event == Event::object_start || event == Event::array_start) levels.open(event == Event::array_start);
    if (event == Event::object_end || event == Event::array_end) levels.close();
    if (event == Event::key) levels.key(parsed.get<std::string>(), file);
    if (event == Event::value) levels.finished_value();
    return true;
  };
  try {
    nlohmann::json doc = nlohmann::json::parse(text, check);
    if (const std::string at = nul_at(doc, ""); !at.empty())  // at most kDeepestJson deep: the walk's stack is safe
      throw input_error(file, at, "holds a NUL character (\\u0000)", "Remove it: no name, path or hash has one");
    return doc;
  } catch (const nlohmann::json::parse_error& e) {
    throw input_error(file, "byte " + std::to_string(e.byte), "not valid JSON (" + std::string(e.what()) + ")",
                      "Fix the syntax; a JSON linter shows the exact spot");
  } catch (const nlohmann::json::exception& e) {  // 1e400: out_of_range 406
    throw input_error(file, "", "not JSON haptex can read (" + std::string(e.what()) + ")", "Write numbers within 64-bit floats (at most about 1.8e308)");
  }
}

nlohmann::json read_file(const std::string& path) {
  require_regular_file(path);
  std::error_code ec;
  if (std::filesystem::file_size(path, ec) > kLargestJsonBytes)
    throw input_error(path, "", "is over 64 MiB, more than any JSON document haptex reads", "Give the right file");
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    refuse_if_out_of_descriptors(errno, path);
    throw input_error(path, "", "cannot open the JSON file", "Check the path and permissions");
  }
  const std::string text{std::istreambuf_iterator<char>(in), {}};
  return parse_text(text, path);
}

namespace {

// A JSON file's top-level "format" and "haptex_version" strings (empty where it has none, is no JSON,
// or is over 64 MiB).
std::pair<std::string, std::string> format_of_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec) || std::filesystem::file_size(path, ec) > kLargestJsonBytes || ec) return {};
  std::ifstream in(path, std::ios::binary);
  try {
    const nlohmann::json doc = parse_text(std::string(std::istreambuf_iterator<char>(in), {}), path);
    const auto text = [&](const char* key) {
      return doc.is_object() && doc.contains(key) && doc[key].is_string() ? doc[key].get<std::string>() : std::string();
    };
    return {text("format"), text("haptex_version")};
  } catch (const Error&) {
  }
  return {};
}

}  // namespace

void check_replaceable_json(const std::string& path, bool overwrite, const std::string& format) {
  check_output_path(path, overwrite);
  std::error_code ec;
  if (overwrite && std::filesystem::exists(path, ec)) {
    const auto [found, written_by] = format_of_file(path);
    require_replaceable_format(path, found, format, written_by);
    require_content_mark(path);
  }
}

void validate(const nlohmann::json& doc, std::string_view schema_name, const std::string& file) {
  refuse_newer_format(doc, schema_name, file);
  const nlohmann::json& schema = schema_document(schema_name);
  refuse_long_pattern_texts(doc, schema, schema, "", file);
  valijson::Validator validator;
  valijson::ValidationResults results;
  valijson::adapters::NlohmannJsonAdapter adapter(doc);
  if (validator.validate(compiled_schema(schema_name), adapter, &results)) return;
  // valijson reports the innermost failure first: the element that actually broke the rule.
  valijson::ValidationResults::Error error;
  results.popError(error);
  std::string where;
  for (std::string part : error.context) {
    if (part == "<root>") continue;
    if (part.size() >= 2 && part.front() == '[' && part.back() == ']') part = part.substr(1, part.size() - 2);
    if (part.size() >= 2 && part.front() == '"' && part.back() == '"') part = part.substr(1, part.size() - 2);
    where += "/" + part;
  }
  if (where.empty()) where = "(top level)";
  std::string reason = error.description;
  while (!reason.empty() && reason.back() == '.') reason.pop_back();  // valijson ends its sentences; input_error adds one
  // The schema says what the file is (review 10, C4: a pointer to the schema alone was no fix).
  const nlohmann::json& schema_doc = schema_document(schema_name);
  const auto description = schema_doc.find("description");
  throw input_error(file, where, reason,
                    "See schemas/" + std::string(schema_name) +
                        (description != schema_doc.end() && description->is_string() ? ": " + description->get<std::string>()
                                                                                      : std::string(" for the expected form")));
}

void write_file(const nlohmann::json& doc, std::string_view schema_name, const std::string& path) {
  PartialFile out(path, false);  // a new file: JSON outputs that may replace one go through the PartialFile overload
  write_file(doc, schema_name, out);
  out.commit();
}

void write_file(const nlohmann::json& doc, std::string_view schema_name, PartialFile& out) {
  try {
    validate(doc, schema_name, out.final_path());
  } catch (const Error& e) {
    throw failure(std::string("internal: the document to write does not follow its schema: ") + e.what());
  }
  write_text(out, doc.dump(2) + "\n");
}

}  // namespace haptex::json
