#include "apps/input_file_option.hpp"

namespace haptex::apps {
namespace {
constexpr const char* kMark = "FILE";  // the description CLI11 appends to the option's type name
}

CLI::Validator input_file() {
  return CLI::Validator([](const std::string&) { return std::string(); }, kMark);
}

bool is_input_file_option(const CLI::Option& option) {
  const std::string type = option.get_type_name();  // "TEXT:FILE"
  return type.size() > 5 && type.ends_with(std::string(":") + kMark);
}

}  // namespace haptex::apps
