#include "core/error.hpp"

#include "core/text/format.hpp"
#include "core/text/utf8.hpp"

namespace haptex {

Error input_error(const std::string& file, const std::string& where, const std::string& what,
                  const std::string& fix) {
  // The file and the place are names: a newline or a terminal's escape inside one is shown escaped.
  std::string message = text::printable(file);
  if (!where.empty()) message += ": " + text::printable(where);
  message += ": " + what;
  if (!fix.empty()) message += ". " + fix;
  Error error(Error::Kind::bad_input, message);
  error.file_ = file, error.where_ = where, error.finding_ = what, error.fix_ = fix;
  return error;
}

Error failure(const std::string& what) { return Error(Error::Kind::failed, what); }

Error renamed_in(const Error& error, const std::string& from, const std::string& to) {
  const std::string message = text::replace_all(error.what(), text::printable(from), text::printable(to));  // as input_error wrote them
  Error renamed(error.kind(), text::replace_all(message, from, to));
  renamed.file_ = error.file_ == from ? to : error.file_, renamed.where_ = error.where_, renamed.finding_ = error.finding_, renamed.fix_ = error.fix_;
  return renamed;
}

}  // namespace haptex
