#pragma once
// What every output records as its `source` (docs/architecture.md, "The data path"): the command
// line that made it, rebuilt from the parsed options so that none is dropped.
#include <CLI/CLI.hpp>

#include <string>

namespace haptex::apps {

// "haptex <subcommand> [<sub-subcommand>] <every option given, positionals by value>" (values quoted
// as a shell reads them: core/text/shell_quote.hpp), without
// where the output goes (-o, --output, --sheets, --log, --csv), --force and the shared output flags:
// enough to make the same output again, and the same run written elsewhere records the same line.
std::string command_line(const CLI::App& subcommand);

// Whether the option names where an output goes: -o/--output, --sheets, --log, --csv.
bool is_output_option(const CLI::Option& option);

}  // namespace haptex::apps
