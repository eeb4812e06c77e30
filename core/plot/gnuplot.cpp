#include "core/plot/gnuplot.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "core/process/run_program.hpp"
#include "core/text/utf8.hpp"

namespace haptex::gnuplot {
namespace fs = std::filesystem;

namespace {

// What replaces a character that gnuplot could read as syntax; "" keeps the character.
std::string_view replacement(char32_t c) {
  switch (c) {
    case U'\'': return "\u2019";
    case U'"': return "\u201d";
    case U'`': return "\u2018";
    case U'\\': return "/";
    default: return text::acts_on_text(c) ? " " : "";  // controls and text-reordering format characters
  }
}

bool is_png(const fs::path& path) {
  static constexpr char kSignature[8] = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};
  std::ifstream in(path, std::ios::binary);
  char head[8] = {};
  return in.read(head, 8) && std::equal(head, head + 8, kSignature);
}

}  // namespace

std::string text(std::string_view label, std::size_t max_characters) {
  std::string out = "'";
  std::size_t count = 0;
  for (const text::Utf8Character& c : text::utf8_characters(label)) {
    if (count++ == max_characters) {
      out += "\u2026";
      break;
    }
    const std::string_view r = c.valid ? replacement(c.code_point) : "\ufffd";
    out += r.empty() ? c.bytes : r;
  }
  return out + "'";
}

std::string file(std::string_view name) { return text(name, name.size()); }

std::string png_terminal() {
  if (!process::program_on_path("gnuplot")) return "";
  return process::run_program({{"gnuplot", "-e", "set terminal pngcairo"}, "", "", "", "", {}}) == 0 ? "pngcairo" : "png";
}

bool draw(const std::string& directory, const std::string& script, const std::string& png) {
  const fs::path image = fs::path(directory) / png;
  if (process::run_program({{"gnuplot", script}, directory, "", "", "", {}}) == 0 && is_png(image)) return true;
  std::error_code ignored;
  fs::remove(image, ignored);
  return false;
}

}  // namespace haptex::gnuplot
