#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string_view>

#include <nlohmann/json.hpp>

#include "apps/command.hpp"
#include "apps/input_file_option.hpp"
#include "apps/number_checks.hpp"
#include "apps/printable_stream.hpp"
#include "apps/provenance.hpp"
#include "core/bounded_call.hpp"
#include "core/durable_file.hpp"
#include "core/text/parse_number.hpp"
#include "core/error.hpp"
#include "core/freed_memory.hpp"
#include "core/input_file.hpp"
#include "core/open_files.hpp"
#include "core/temporary_name.hpp"
#include "core/text/format.hpp"
#include "core/text/utf8.hpp"
#include "apps/version_json.hpp"
#include "core/version.hpp"

namespace haptex::apps {
namespace {

// Every floating-point option of every command takes finite numbers only (apps/number_checks.hpp).
void require_finite_numbers(CLI::App& app) {
  for (CLI::Option* option : app.get_options())
    if (option->get_type_name().find("FLOAT") != std::string::npos) option->check(finite_number());
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) require_finite_numbers(*sub);
}

// What every command's options must hold, checked before any work: one rule for every name and path
// given on the command line (issue 32), valid UTF-8 without NUL as names inside files must be
// (core/text/utf8.hpp), naming the option and the first bad byte (a file name that is not UTF-8 would
// reach JSON and HDF5 attributes that must be); and an output option given as "" names no file
// (apps/provenance.hpp lists them).
// CLI11 reads 025 as octal 21, 0x10 as 16 and " 30" as 30, and wraps -1 into an unsigned 2^64-1:
// a number on the command line is plain decimal, as a user means it (issue 32, review 2).
// The option's own default where it has one, so the example lies in its range (review 12, C2).
std::string decimal_example(const CLI::Option& option, const std::string& type, text::Decimal form) {
  const std::string fallback = type == "FLOAT" ? "0.5" : "25";
  const std::string default_value = option.get_default_str();
  return !default_value.empty() && text::is_plain_decimal(default_value, form) ? default_value : fallback;
}

void check_decimal(const CLI::Option& option, const std::string& value) {
  const std::string described = option.get_type_name();  // "UINT:INT in [3 - 10000]" with a range check
  const std::string type = described.substr(0, described.find(':'));
  using text::Decimal;
  const std::optional<Decimal> form = type == "INT"     ? std::optional(Decimal::whole)
                                      : type == "UINT"  ? std::optional(Decimal::natural)
                                      : type == "FLOAT" ? std::optional(Decimal::real)
                                                        : std::nullopt;
  if (form && !text::is_plain_decimal(value, *form))
    throw input_error(option.get_name(), "", "'" + value + "' is not a plain decimal " + (type == "FLOAT" ? "number" : type == "UINT" ? "whole number of 0 or more" : "whole number") +
                                                 " (no leading zeros, 0x, spaces)",
                      "Write it in decimal, e.g. " + option.get_name() + " " + decimal_example(option, type, *form));
}

// Whether `word` (-x, --name, --name=value) names an option of `command` or of haptex itself.
bool names_an_option(const CLI::App* command, const std::string& word) {
  const std::string name = word.substr(0, word.find('='));
  for (const CLI::App* scope = command; scope; scope = scope->get_parent())
    if (scope->get_option_no_throw(name) != nullptr) return true;
  return false;
}

void check_option_values(const CLI::App& app) {
  for (const CLI::Option* option : app.get_options()) {
    if (option->count() == 0) continue;
    for (const std::string& value : option->results()) {
      text::require_utf8(value, "command line", option->get_name());
      check_decimal(*option, value);
      if (value.empty() && is_output_option(*option))
        throw input_error(option->get_name(), "", "is empty, which names no file", "Name the output with " + option->get_name());
      if (value.empty())  // `--names ""` named no file and was taken as no option at all
        throw input_error(option->get_name(), "", "is empty", "Give it a value, or leave the option out");
      // `-o --force` took the flag as the output's name and wrote a file called --force (review 15, R14).
      if (value.size() > 1 && value[0] == '-' && !text::parse_number(value) && names_an_option(&app, value))
        throw input_error(option->get_name(), "", "is followed by '" + value + "', which is an option, not its value",
                          "Give " + option->get_name() + " its value right after it");
      if (is_input_file_option(*option)) require_regular_file(value);
    }
  }
  for (const CLI::App* sub : app.get_subcommands()) check_option_values(*sub);
}

// printable() keeps a message's own newlines; a newline or tab inside a name given on the command line
// is the name's, so wherever the message quotes that name it is escaped first.
std::string shown_message(const std::string& message, int argc, char** argv) {
  std::string shown = message;
  for (int i = 1; i < argc; ++i)
    if (const std::string name = argv[i]; name.find_first_of("\n\t") != std::string::npos)
      shown = text::replace_all(shown, name, text::printable(name));
  return text::printable(shown, true);
}

// What a command printed on stdout (predict's CSV, --json, info) is an output too: a full disk or a
// closed file under a redirection is exit 1 saying so, not a cut-off file and exit 0.
int with_stdout_written(const std::string& command, int code) {
  errno = 0;
  std::cout.flush();
  if (!std::cout.fail() && std::fflush(stdout) == 0 && !std::ferror(stdout)) return code;
  std::cerr << "haptex " << command << ": error: standard output: cannot write it: " << why_not_written(errno != 0 ? errno : EIO)
            << ". What was printed is incomplete: free space, or send the output elsewhere\n";
  return 1;
}

// An error as a command reports it: on stderr, and with --json also on stdout as
// {"error": {"command", "message", "file", "where", "fix", "exit_code"}} (docs/architecture.md,
// "Command line") unless the command printed its own result there, so a script reading stdout always
// parses one JSON document.
struct Reported {
  std::string message;
  int exit_code = 1;
  std::string file, where, fix;  // what the message names, where it names them
};

int report(const std::string& command, const Reported& r, bool json) {
  std::cerr << "haptex" << (command.empty() ? "" : " " + command) << ": " << r.message << "\n";
  if (json) {
    const auto text_or_null = [](const std::string& s) { return s.empty() ? nlohmann::json() : nlohmann::json(text::printable(s)); };
    const nlohmann::json error = {{"command", command}, {"message", r.message}, {"file", text_or_null(r.file)},
                                  {"where", text_or_null(r.where)}, {"fix", text_or_null(r.fix)}, {"exit_code", r.exit_code}};
    std::cout << nlohmann::json{{"error", error}}.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) << "\n";
  }
  return r.exit_code;
}

// Reports the exception being handled as an error of `command` and returns the exit code it means.
int reported_error(const std::string& command, int argc, char** argv, bool json) {
  try {
    throw;
  } catch (const Error& e) {
    return report(command, {"error: " + shown_message(e.what(), argc, argv), e.kind() == Error::Kind::bad_input ? 2 : 1, e.file(), e.where(), e.fix()},
                  json);
  } catch (const std::filesystem::filesystem_error& e) {
    try {
      refuse_if_out_of_descriptors(e.code().value(), e.path1().string());  // the machine's limit, not the path's
    } catch (const Error& limit) {
      return report(command, {"error: " + std::string(limit.what()), 1, "", "", ""}, json);
    }
    return report(command, {"error: " + text::printable(e.path1().string()) + ": " + e.code().message() + ". Check the path and its permissions", 2,
                            e.path1().string(), "", "Check the path and its permissions"},
                  json);
  } catch (const std::bad_alloc&) {
    return report(command, {"error: out of memory. Give smaller inputs, or run it on a machine with more memory", 1, "", "",
                            "Give smaller inputs, or run it on a machine with more memory"},
                  json);
  } catch (const std::exception& e) {
    return report(command, {"unexpected error: " + shown_message(e.what(), argc, argv), 1, "", "", ""}, json);
  }
}

// The subcommand (with its part, "capture extract") that a parse error belongs to; "" before one.
std::string parsed_command(const CLI::App& app) {
  std::string name;
  for (const CLI::App* sub = &app; !sub->get_subcommands().empty();) {
    sub = sub->get_subcommands().front();
    name += (name.empty() ? "" : " ") + sub->get_name();
  }
  return name;
}

// A word of argv that looks like an option (-x, --name, --name=value) but that neither the command
// parsed nor haptex itself knows; "" when there is none. CLI11 reports a missing required argument
// before an unknown flag, which then hides the real mistake (`haptex --bogus train`). Numbers such as
// a negative value are no options, nor is anything after "--".
std::string unknown_flag(const CLI::App& app, int argc, char** argv) {
  const CLI::App* command = &app;
  while (!command->get_subcommands().empty()) command = command->get_subcommands().front();
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word == "--") break;
    if (word.size() < 2 || word[0] != '-' || text::parse_number(word)) continue;
    if (!names_an_option(command, word)) return word;
  }
  return "";
}

// Every subcommand's help ends with the flags all of them take, which CLI11 lists only in haptex --help.
constexpr const char* kGlobalFlagsHelp =
    "Flags of every command (before or after its name):\n"
    "  --json        Machine-readable result on stdout; an error is {\"error\": {\"message\", \"file\", \"exit_code\", ...}}\n"
    "  -q,--quiet    Print only errors\n"
    "  -v,--verbose  Print more detail on stderr (repeatable)";

void with_global_flags_help(CLI::App& app) {
  app.footer(kGlobalFlagsHelp);
  for (CLI::App* part : app.get_subcommands([](CLI::App*) { return true; })) with_global_flags_help(*part);
}

// `haptex --json CMD --help`: the help text as one JSON document, {"command", "help"}, so stdout is
// JSON whenever --json is given (review 13).
int help_json(const CLI::App& app) {
  const CLI::App* shown = &app;
  while (!shown->get_subcommands().empty()) shown = shown->get_subcommands().front();
  std::cout << nlohmann::json{{"command", parsed_command(app)}, {"help", shown->help()}}.dump(2, ' ', false, nlohmann::json::error_handler_t::replace)
            << "\n";
  return 0;
}

}  // namespace

int run_main(int argc, char** argv) {
  keep_freed_memory();
  use_every_open_file_allowed();
  const PrintableStream out(std::cout), err(std::cerr);
  CLI::App app{"haptex: build, check and model haptic texture data (GelSight images + vibrations)", "haptex"};
  app.set_version_flag("--version", std::string("haptex ") + kVersion);
  app.require_subcommand(1);
  app.fallthrough();  // shared flags may follow the subcommand's own

  GlobalOptions global;
  app.add_flag("--json", global.json, "Machine-readable result on stdout (errors too: {\"error\": {...}})");
  app.add_flag("-q,--quiet", global.quiet, "Print only errors");
  app.add_flag("-v,--verbose", global.verbose, "Print more detail on stderr (repeatable)");

  auto commands = all_commands();
  std::vector<std::pair<CLI::App*, Command*>> parsed;
  for (auto& command : commands) {
    CLI::App* sub = app.add_subcommand(command->name(), command->summary());
    command->declare(*sub);
    with_global_flags_help(*sub);
    parsed.emplace_back(sub, command.get());
  }
  require_finite_numbers(app);

  // --json was asked for whether or not CLI11 got as far as setting global.json.
  const bool json = std::any_of(argv + 1, argv + argc, [](const char* a) { return std::string_view(a) == "--json"; });
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    if (json) return help_json(app);
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    if (json) return help_json(app);
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    // With --json, one JSON document as every other answer (review 13, C4).
    if (json) {
      std::cout << version_json().dump(2) << "\n";
      return 0;
    }
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // A value CLI11's range check refused may break haptex's own rules first (0x10 is not a plain
    // decimal, whatever its value): that is the message that names the mistake (review 12, C2).
    if (std::string_view(e.what()).find("not in range") != std::string_view::npos) try {
        check_option_values(app);
      } catch (const Error&) {
        return reported_error(parsed_command(app), argc, argv, json);
      }
    // A number too large for its option (review 6: --presses 2147483648) says what fits.
    const bool too_large = dynamic_cast<const CLI::ConversionError*>(&e) != nullptr;
    const std::string command = parsed_command(app);
    const std::string help = command.empty() ? "haptex --help" : "haptex " + command + " --help";
    // `haptex nosuch` is a name CLI11 does not know, which it reports as no subcommand at all (review 13, C3).
    const char* const* word = std::find_if(argv + 1, argv + argc, [](const char* a) { return a[0] != '-'; });
    if (command.empty() && word != argv + argc)
      return report("", {"error: '" + text::printable(*word) + "' is no haptex command. Run 'haptex --help' for the list", 2, "", "",
                         "Run 'haptex --help' for the list"},
                    json);
    if (dynamic_cast<const CLI::RequiredError*>(&e) != nullptr)
      if (const std::string flag = unknown_flag(app, argc, argv); !flag.empty() && !command.empty())
        return report(command, {"error: '" + text::printable(flag) + "' is no option of 'haptex " + command + "'. Run '" + help + "' for its options",
                                2, "", "", "Run '" + help + "' for its options"},
                      json);
    return report(command,
                  {"error: " + text::printable(e.what()) +
                       (too_large ? ": not a number this option holds (a whole number up to 2147483647, or as its help says)" : "") +
                       ". Run '" + help + "' for usage",
                   2, "", "", "Run '" + help + "' for usage"},
                  json);
  }

  for (auto& [sub, command] : parsed) {
    if (!sub->parsed()) continue;
    global.command_line = command_line(*sub);
    if (!command->ends_on_signals_itself()) remove_temporaries_on_signals();  // before any thread is made
    std::string name = command->name();  // "capture extract": the part of a command with parts too
    for (const CLI::App* part : sub->get_subcommands()) name += " " + part->get_name();
    // A read that never ends (core/bounded_call.hpp) is reported as any error, its outputs removed.
    on_stuck_call([&, name](const Error& stuck) {
      remove_every_temporary();
      int code = 2;
      try {
        throw stuck;
      } catch (...) {
        code = reported_error(name, argc, argv, global.json && !out.written());
      }
      std::cout.flush();
      std::cerr.flush();
      std::_Exit(code);
    });
    try {
      check_option_values(*sub);
      return with_stdout_written(name, command->run(global));
    } catch (...) {
      let_a_taken_signal_finish();  // an error the signal caused is not reported: the signal ends the run
      // A command that printed its result already (extract's JSON of what it found, then exit 1) has
      // answered on stdout: the error goes to stderr only, so stdout stays one JSON document.
      return reported_error(name, argc, argv, global.json && !out.written());
    }
  }
  return 2;
}

}  // namespace haptex::apps
