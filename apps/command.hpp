#pragma once
// A subcommand in the PDAL-kernel style: declare options, validate, call a library, print.
// Libraries never print and never exit; only apps/ does.
#include <CLI/CLI.hpp>

#include <memory>
#include <string>
#include <vector>

namespace haptex::apps {

// Flags every subcommand shares (docs/architecture.md, "Command line").
struct GlobalOptions {
  bool json = false;   // machine-readable result on stdout
  bool quiet = false;  // only errors on stderr
  int verbose = 0;     // more detail on stderr
  std::string command_line;  // the subcommand as given, for outputs' `source` (apps/provenance.hpp)
};

class Command {
 public:
  virtual ~Command() = default;
  virtual std::string name() const = 0;
  virtual std::string summary() const = 0;
  // Adds this command's options (and sub-subcommands) to its CLI11 subcommand.
  virtual void declare(CLI::App& app) = 0;
  // Runs after parsing; returns the exit code. Throws haptex::Error for bad input or failed work.
  virtual int run(const GlobalOptions& global) = 0;
  // Whether the parsed command ends by itself on SIGINT, SIGTERM and SIGHUP (capture record keeps the
  // press in progress). Otherwise run_main has those signals remove its unfinished outputs
  // (core/temporary_name.hpp, remove_temporaries_on_signals).
  virtual bool ends_on_signals_itself() const { return false; }
};

std::vector<std::unique_ptr<Command>> all_commands();  // apps/commands.cpp
int run_main(int argc, char** argv);                   // apps/run_main.cpp

}  // namespace haptex::apps
