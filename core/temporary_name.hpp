#pragma once
// Where an output lives while it is written (docs/architecture.md, "Outputs are atomic"): beside its
// final name NAME, at NAME.<8 random letters and digits>.partial, created exclusively (a name that
// exists, file, folder or link, is never opened, followed, emptied or reused: another one is drawn)
// and locked with flock while the run writes it. So a user's own NAME.partial, a link planted there or
// an input of that name is never touched, and a killed run's leftover is never mistaken for the
// current one; haptex does not delete leftovers either (it cannot tell them from files of the user's).
// Two runs writing the same NAME find each other through these locks: the later one refuses.
#include <string>
#include <vector>

namespace haptex {

// A temporary file or folder, open and locked. The caller closes `fd` (which releases the lock).
struct Temporary {
  std::string path;
  int fd = -1;
};

// A new empty file (mode 0666 less the umask) at a fresh temporary name for final_path, locked.
// Throws haptex::Error (bad_input) naming final_path when its folder refuses the file, or when
// another run is writing final_path now (nothing is left behind then).
Temporary create_temporary_file(const std::string& final_path);

// The same for a folder (mode 0777 less the umask).
Temporary create_temporary_folder(const std::string& final_path);

// The temporary names of final_path that exist now: any run's, finished, killed or running.
std::vector<std::string> temporaries_of(const std::string& final_path);

}  // namespace haptex
