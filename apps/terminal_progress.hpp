#pragma once
// A progress bar on stderr, drawn only when stderr is a terminal and the user did not ask for quiet.
#include <string>

#include "apps/command.hpp"
#include "core/progress.hpp"

namespace haptex::apps {

Progress terminal_progress(const GlobalOptions& global, const std::string& label);

}  // namespace haptex::apps
