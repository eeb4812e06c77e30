#include "core/error.hpp"

namespace haptex {

Error input_error(const std::string& file, const std::string& where, const std::string& what,
                  const std::string& fix) {
  std::string message = file;
  if (!where.empty()) message += ": " + where;
  message += ": " + what;
  if (!fix.empty()) message += ". " + fix;
  return Error(Error::Kind::bad_input, message);
}

Error failure(const std::string& what) { return Error(Error::Kind::failed, what); }

Error renamed_in(const Error& error, const std::string& from, const std::string& to) {
  std::string message = error.what();
  if (!from.empty())
    for (std::size_t at = message.find(from); at != std::string::npos; at = message.find(from, at + to.size()))
      message.replace(at, from.size(), to);
  return Error(error.kind(), message);
}

}  // namespace haptex
