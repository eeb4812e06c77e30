#pragma once
// haptex::Error is the one exception type the libraries throw. Its message names the file,
// the place in it and what the user can do; apps/ turns its kind into the exit code.
#include <stdexcept>
#include <string>

namespace haptex {

class Error : public std::runtime_error {
 public:
  enum class Kind {
    bad_input,  // unreadable or invalid input, bad usage: exit code 2
    failed,     // the work itself failed (or a check found errors): exit code 1
  };

  // A NUL quoted from an input would cut what() short: it is written \x00.
  Error(Kind kind, const std::string& message) : std::runtime_error(without_nul(message)), kind_(kind) {}
  Kind kind() const { return kind_; }
  // What input_error was given, for `--json` errors (apps/run_main.cpp); empty for other errors.
  const std::string& file() const { return file_; }
  const std::string& where() const { return where_; }
  const std::string& finding() const { return finding_; }  // WHAT: what is wrong there
  const std::string& fix() const { return fix_; }

 private:
  friend Error input_error(const std::string&, const std::string&, const std::string&, const std::string&);
  friend Error renamed_in(const Error&, const std::string&, const std::string&);
  static std::string without_nul(std::string text) {
    for (std::size_t at = text.find('\0'); at != std::string::npos; at = text.find('\0', at)) text.replace(at, 1, "\\x00");
    return text;
  }
  Kind kind_;
  std::string file_, where_, finding_, fix_;
};

// "FILE: WHERE: WHAT. FIX" — the shape every bad-input message takes; FILE and WHERE are shown
// through text::printable (control characters escaped, a newline too).
[[nodiscard]] Error input_error(const std::string& file, const std::string& where, const std::string& what,
                                const std::string& fix);
[[nodiscard]] Error failure(const std::string& what);
// The same error with every `from` in its message written `to`: a temporary name replaced by the
// output's final name, which is the one the user knows.
[[nodiscard]] Error renamed_in(const Error& error, const std::string& from, const std::string& to);

}  // namespace haptex
