#pragma once
// Where an output lives while it is written (docs/architecture.md, "Outputs are atomic"): beside its
// final name NAME, at NAME.<8 random letters and digits>.partial, created exclusively (a name that
// exists, file, folder or link, is never opened, followed, emptied or reused: another one is drawn)
// and locked with flock while the run writes it. So a user's own NAME.partial, a link planted there or
// an input of that name is never touched, and a killed run's leftover is never mistaken for the
// current one; haptex does not delete leftovers either (it cannot tell them from files of the user's).
// Two runs writing the same NAME find each other through these locks: the later one refuses.
#include <mutex>
#include <string>
#include <vector>

namespace haptex {

// Throws haptex::Error (bad_input) naming final_path when its name is longer than its folder's file
// system allows (255 bytes on Linux): checked before any work, since nothing could be renamed to it.
void require_name_fits(const std::string& final_path);

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

// True while `path` names the file or folder `fd` was opened on, not a link or another file put in
// its place by someone else writing the same folder (review 14, F1).
bool still_names(const std::string& path, int fd);
// Throws haptex::Error (failed) naming final_path unless still_names(path, fd): the temporary of
// final_path was replaced meanwhile, so it is neither renamed nor left as the output (review 14, F1).
void require_still_named(const std::string& path, int fd, const std::string& final_path);
// A name for fd's own file that no change to the folder can redirect (/proc/self/fd/N), for a library
// that opens its files by name (HDF5, libsndfile); `path` itself where /proc is not mounted.
std::string name_of_descriptor(int fd, const std::string& path);

// The temporary names of final_path that exist now: any run's, finished, killed or running.
std::vector<std::string> temporaries_of(const std::string& final_path);

// Every temporary this process creates is listed until forget_temporary (called once it has been
// renamed or removed), so that an interrupted run can take its temporaries away.
void forget_temporary(const std::string& path);

// From now on SIGINT, SIGTERM and SIGHUP (Ctrl-C, kill, a closed terminal or ssh session) remove
// every listed temporary, say so on stderr, then end the process by the same signal, as it would
// have ended without haptex's help. Call it at the start of main, before any thread is made: the
// signals are blocked in every thread and taken by one that waits for them (sigwait), so the removal
// runs outside a signal handler, and no temporary is created while it runs. A signal ignored when
// the process started (nohup's HUP, a background job's INT) stays ignored. Child processes start
// with them unblocked (core/process/run_program.hpp). A command that ends on these signals itself
// (capture record keeps the press in progress) does not call it.
void remove_temporaries_on_signals();

// For a process about to end without unwinding (a signal, a stuck call: core/bounded_call.hpp):
// removes every listed temporary and returns how many went. No temporary is made or forgotten after
// it (they wait for good), so call it only on the way out.
std::size_t remove_every_temporary();

// Held while outputs that belong together are renamed one after another: a signal taken meanwhile
// waits until every one is in place (the run then ends by it, its outputs whole). Nothing that makes
// or forgets a temporary (creating a PartialFile, destroying one) may run while it is held.
[[nodiscard]] std::unique_lock<std::mutex> hold_temporaries();

// Returns at once, unless a signal is taking the temporaries away: then it never returns, and the
// signal ends the run. Called before an error is reported, since the error may be the signal's own
// doing (a file made in a temporary folder the signal has just removed).
void let_a_taken_signal_finish();

}  // namespace haptex
