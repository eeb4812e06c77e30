#pragma once
// Command lines haptex records for a user to read and paste (provenance, session.json's `command`):
// a word a POSIX shell would read differently is single-quoted, with a ' inside written '\'' , so
// pasting the line runs the same command and never a name's contents. haptex itself never runs such a
// line (docs/architecture.md: no data reaches a shell).
#include <string>
#include <string_view>

namespace haptex::text {

// `word` as it is when it holds only letters, digits and @%+=:,./_- (and is not empty); otherwise quoted.
std::string shell_quoted(std::string_view word);

}  // namespace haptex::text
