#pragma once
// Progress on stderr, unless the user asked for quiet (docs/architecture.md, "Command line"): on a
// terminal a bar redrawn in place; where stderr is a file or a pipe (a Slurm log, CI) a line every 10 s
// while a stage runs and one when it ends, so a log shows a long run moving without filling up (and a
// run refused at once prints its error alone).
#include <string>

#include "apps/command.hpp"
#include "core/progress.hpp"

namespace haptex::apps {

Progress terminal_progress(const GlobalOptions& global, const std::string& label);

}  // namespace haptex::apps
