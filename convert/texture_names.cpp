#include "convert/texture_names.hpp"

#include <charconv>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "convert/input_limits.hpp"
#include "core/error.hpp"
#include "core/json/schema.hpp"
#include "core/naming.hpp"
#include "core/text/parse_number.hpp"
#include "core/text/utf8.hpp"

namespace haptex::convert {
namespace {

constexpr const char* kFix = "Give a JSON object {\"0\": \"Aluminium plate\", ...} or a CSV with the header id,name";

int texture_id(std::string_view text, const std::string& path, const std::string& where) {
  text = text::trim(text);
  int id = -1;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), id);
  if (error != std::errc() || end != text.data() + text.size() || id < 0)
    throw input_error(path, where, "'" + std::string(text) + "' is not a texture id (a whole number of 0 or more)", kFix);
  if (text != std::to_string(id))  // "03" and "3" would both name texture 3
    throw input_error(path, where, "'" + std::string(text) + "' is written with a leading zero", "Write the texture id as " + std::to_string(id));
  return id;
}

void add(std::map<int, std::string>& names, int id, std::string name, const std::string& path, const std::string& where) {
  text::require_utf8(name, path, where + ": the texture's name");
  if (name.empty()) throw input_error(path, where, "the name of texture " + std::to_string(id) + " is empty", kFix);
  if (!names.emplace(id, std::move(name)).second)
    throw input_error(path, where, "texture " + std::to_string(id) + " is named twice", "Name each texture once");
}

// Names files are small; a bigger one (or /dev/zero) is no names file.
constexpr std::uintmax_t kMaxNamesBytes = 1 << 20;

std::string names_text(const std::string& path) {
  const std::vector<char> bytes = read_whole_file(path, kMaxNamesBytes);
  return std::string(bytes.begin(), bytes.end());
}

std::map<int, std::string> from_json(const std::string& path) {
  const nlohmann::json doc = json::parse_text(names_text(path), path);  // refuses a key given twice
  if (!doc.is_object()) throw input_error(path, "/", "the file is not a JSON object", kFix);
  std::map<int, std::string> names;
  for (const auto& [key, value] : doc.items()) {
    const std::string where = "/" + key;
    if (!value.is_string()) throw input_error(path, where, "the name is not a string", kFix);
    add(names, texture_id(key, path, where), value.get<std::string>(), path, where);
  }
  return names;
}

// id,name per line; the name is the rest of the line (it may hold commas), quotes around it dropped.
std::map<int, std::string> from_csv(const std::string& path) {
  std::istringstream in(names_text(path));
  std::map<int, std::string> names;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string where = "line " + std::to_string(number);
    const std::size_t comma = line.find(',');
    if (number == 1) {
      if (comma == std::string::npos || text::trim(std::string_view(line).substr(0, comma)) != "id")
        throw input_error(path, where, "the header is not id,name", kFix);
      continue;
    }
    if (text::trim(line).empty()) continue;
    if (comma == std::string::npos) throw input_error(path, where, "has no comma between the id and the name", kFix);
    std::string_view name = text::trim(std::string_view(line).substr(comma + 1));
    const bool opens = !name.empty() && name.front() == '"', closes = name.size() >= 2 && name.back() == '"';
    if (opens != closes) throw input_error(path, where, "the name's quotes are not closed", "Put the name in two quotes or none");
    if (opens) name = name.substr(1, name.size() - 2);
    add(names, texture_id(std::string_view(line).substr(0, comma), path, where), std::string(name), path, where);
  }
  return names;
}

}  // namespace

std::map<int, std::string> read_texture_names(const std::string& path) {
  const std::string extension = std::filesystem::path(path).extension().string();
  std::map<int, std::string> names;
  if (extension == ".json" || extension == ".JSON") names = from_json(path);
  else if (extension == ".csv" || extension == ".CSV") names = from_csv(path);
  else throw input_error(path, "", "the names file is neither .json nor .csv", kFix);
  if (names.empty()) throw input_error(path, "", "names no texture", kFix);
  // Two names that make one material id would join two textures' takes into one material.
  std::map<std::string, int> by_id;
  for (const auto& [texture, name] : names) {
    checked_material_id(name, path, "texture " + std::to_string(texture));
    const auto [at, added] = by_id.emplace(material_id(name), texture);
    if (!added)
      throw input_error(path, "texture " + std::to_string(texture),
                        "'" + name + "' and texture " + std::to_string(at->second) + "'s '" + names.at(at->second) +
                            "' make one material id, '" + at->first + "'",
                        "Give each texture a name of its own (ids ignore case, spaces and punctuation)");
  }
  return names;
}

}  // namespace haptex::convert
