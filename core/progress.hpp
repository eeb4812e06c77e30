#pragma once
// Libraries report progress through a callback; apps/ draws it on a terminal (or ignores it).
#include <cstddef>
#include <functional>
#include <string_view>

namespace haptex {

// done of total units of work finished; `what` names the current item.
using Progress = std::function<void(std::size_t done, std::size_t total, std::string_view what)>;

}  // namespace haptex
