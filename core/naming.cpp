#include "core/naming.hpp"

#include <cctype>

namespace haptex {

std::string material_id(std::string_view name) {
  std::string id;
  bool pending_separator = false;
  for (unsigned char c : name) {
    if (std::isalnum(c)) {
      if (pending_separator && !id.empty()) id += '_';
      pending_separator = false;
      id += static_cast<char>(std::tolower(c));
    } else {
      pending_separator = true;
    }
  }
  return id;
}

}  // namespace haptex
