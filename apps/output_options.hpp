#pragma once
// -o and --force, declared one way by every command that writes (issue 33): -o says what it names,
// --force has one meaning and one help text everywhere (docs/architecture.md, "Outputs are atomic").
#include <CLI/CLI.hpp>
#include <string>

namespace haptex::apps {

// Declares -o/--output (required) bound to `output`, helped by `what` ("Dataset file to write
// (HDF5)"), and --force bound to `force`.
void add_output_options(CLI::App& app, std::string& output, bool& force, const std::string& what);

// --force alone, for a command whose output is optional (play --record).
void add_force_option(CLI::App& app, bool& force);

}  // namespace haptex::apps
