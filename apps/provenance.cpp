#include "apps/provenance.hpp"

#include <array>
#include <span>
#include <string_view>

#include "core/text/shell_quote.hpp"

namespace haptex::apps {
namespace {

constexpr std::array<std::string_view, 4> kOutputs{"--output", "--sheets", "--log", "--csv"};
constexpr std::array<std::string_view, 5> kShared{"--help", "--force", "--json", "--quiet", "--verbose"};

bool named(const CLI::Option& option, std::span<const std::string_view> names) {
  for (std::string_view name : names)
    if (option.check_lname(std::string(name.substr(2)))) return true;
  return false;
}

bool left_out(const CLI::Option& option) { return named(option, kOutputs) || named(option, kShared); }

void append_options(const CLI::App& app, std::string& line) {
  for (const CLI::Option* option : app.get_options()) {
    if (option->count() == 0 || left_out(*option)) continue;
    for (const std::string& value : option->results()) {
      if (option->nonpositional()) line += " " + option->get_name();
      if (!option->nonpositional() || option->get_expected_max() != 0) line += " " + text::shell_quoted(value);
    }
  }
  for (const CLI::App* sub : app.get_subcommands()) {
    line += " " + sub->get_name();
    append_options(*sub, line);
  }
}

}  // namespace

bool is_output_option(const CLI::Option& option) { return named(option, kOutputs); }

std::string command_line(const CLI::App& subcommand) {
  std::string line = "haptex " + subcommand.get_name();
  append_options(subcommand, line);
  return line;
}

}  // namespace haptex::apps
