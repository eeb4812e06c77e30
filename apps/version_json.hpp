#pragma once
// `haptex --json --version`: the version and every file format this haptex writes or reads, so a
// script (or tests/e2e/docs_numbers.py against docs/architecture.md) can check what it talks to.
#include <nlohmann/json.hpp>

namespace haptex::apps {

nlohmann::json version_json();

}  // namespace haptex::apps
