#include "core/embedded.hpp"

#include "core/error.hpp"

namespace haptex::embedded {

std::string_view schema(std::string_view name) {
  const auto& table = files();
  auto it = table.find(name);
  if (it == table.end()) throw failure("internal: schemas/" + std::string(name) + " was not compiled in");
  return it->second;
}

}  // namespace haptex::embedded
