#pragma once
// The folder a take records into (docs/capture.md, "Recording"): press_<j>.h5 files and session.json.
// A folder that already holds a session is refused unless --force, and --force replaces only what the
// old session wrote, as its session.json lists it: session.json itself and the press files it names
// (each one a file haptex wrote). A folder holding anything else, a session.json that is not haptex's,
// a press file it does not list, a link, or one of the take's inputs (a replayed press file), is refused
// naming the file, and nothing is deleted.
#include <string>
#include <vector>

namespace haptex::capture {

// Refuses (haptex::Error, bad_input) a folder that cannot be made or already holds a session (unless
// overwrite, within the rule above), touching nothing. `inputs`: files the take reads.
void check_session_dir(const std::string& dir, bool overwrite, const std::vector<std::string>& inputs = {});
// The same checks, then creates the folder and, with overwrite, removes the old session's files.
void prepare_session_dir(const std::string& dir, bool overwrite, const std::vector<std::string>& inputs = {});

}  // namespace haptex::capture
