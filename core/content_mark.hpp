#pragma once
// How --force knows a CSV, JSON or WAV output is haptex's and unchanged (review 15, R10). Their own
// marks (a header line, a "format" field, a software string) are the documented formats, which a
// user's own file written to the docs carries too, and which an edit keeps. So haptex keeps the
// SHA-256 of the bytes it wrote in the file's extended attribute user.haptex.sha256, and --force
// replaces such a file only while its bytes still hash to it. A copy (cp drops extended attributes),
// an edit, or a file system without extended attributes loses the mark: the file is then kept, as
// any file of the user's is.
#include <string>

namespace haptex {

inline constexpr const char* kContentMarkAttribute = "user.haptex.sha256";

// Sets the mark on the open file fd (its bytes as they are now). A file system that keeps no extended
// attributes leaves the file unmarked: it is written all the same.
void mark_content(int fd);
// Throws haptex::Error (bad_input) naming path unless it carries the mark and its bytes still hash
// to it: for --force.
void require_content_mark(const std::string& path);

}  // namespace haptex
