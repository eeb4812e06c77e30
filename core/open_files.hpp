#pragma once
// File descriptors: how many a run may hold, and what it says when there are none left.
//
// A run that holds a file per input (merge of a shard per material, evaluate of many predictions files)
// meets the soft limit `ulimit -n`, 1024 on most systems, long before the hard one (524 288 under
// systemd). The limit is the machine's, not an input's fault: an open that fails for it is exit 1
// naming the limit, never "cannot open FILE, check that it exists" (reviews 23 F4, 24 F2).
#include <string>

namespace haptex {

// Raises this process's soft limit on open files to its hard limit (setrlimit RLIMIT_NOFILE), so
// that merging a thousand shards works under the default `ulimit -n`. haptex waits on no descriptor
// with select(), whose sets end at 1024. Called first thing by the haptex binary. Returns the limit.
unsigned long use_every_open_file_allowed();

// Throws haptex::Error (failed) naming path and the limit when `error` (an errno) is EMFILE or ENFILE;
// returns otherwise, for the caller to say what else went wrong.
void refuse_if_out_of_descriptors(int error, const std::string& path);

// Why path does not open, for a library that failed without saying (HDF5's H5Fis_hdf5, FFmpeg through
// OpenCV): opens and closes it; 0 when it opens, else the errno. Throws as above when there is no
// descriptor to open it with.
int error_opening(const std::string& path);

}  // namespace haptex
