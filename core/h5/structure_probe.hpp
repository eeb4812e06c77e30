#pragma once
// libhdf5 1.10 (Debian 12's) is not safe against a damaged file: one wrong byte in an attribute's
// message header makes it free the half-decoded attribute twice (SIGSEGV in H5Aiterate2 or H5Fclose;
// review 27, F1), and a damaged global heap makes it copy past the heap (SIGSEGV in H5HG_read) or loop
// in it; no error comes back to catch. So each file haptex opens for reading is first read by a small
// separate program, haptex-h5-probe (tools/h5-probe), in a process of its own: its structure (every
// object's header, every attribute, every variable-length string) when the file is opened, and its
// variable-length byte values (encoded images and frames) before the first of them is read. The probe
// runs under AddressSanitizer's runtime when it can (LD_PRELOAD), so a read past a heap block stops it
// every time rather than by chance. When it dies of a signal, or HDF5 refuses one of its reads, the
// file is refused as damaged, naming the place, before this process's HDF5 has read it
// (docs/architecture.md, "Damaged files").
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>

#include <H5Ipublic.h>

namespace haptex::h5 {

// Probes the structure of `path` (File::open, reading, before HDF5 opens it), once per file (device,
// inode, size, modification time) in this process. Throws haptex::Error (bad_input) naming the file and
// the place when the probe crashed, did not end within its processor time, or HDF5 refused one of its
// reads; (failed) when it could not be started (out of descriptors: the limit, core/open_files.hpp) or
// ended another way, which says nothing of the file. Returns at once when the probe is not installed
// beside this program (a program that links haptex: docs/library.md).
void probe_structure(const std::string& path);

// The same for the file HDF5 opened as `file` (File::open, right after H5Fopen, through the descriptor
// HDF5 reads): a file put at the path after probe_structure(path) read the one there (a rename, an
// in-place write) is probed before HDF5 reads more than its first headers (review 30, F1); the same
// file is not probed again.
void probe_structure(hid_t file, const std::string& path);

// Probes the variable-length byte values of the file holding `object` (named `path`) the same way,
// through the descriptor HDF5 reads, before the first is read (dataset::read_vlen_bytes,
// Group::copy_from); does nothing for a file probe_structure has not seen (a file this process writes).
void probe_values(hid_t object, const std::string& path);

// What haptex-h5-probe reads (tools/h5-probe/main.cpp: `haptex-h5-probe [--values] FILE`).
enum class ProbeDepth { structure, values };

// haptex-h5-probe's exit codes.
inline constexpr int kProbeRead = 0;       // read it all, without a fault
inline constexpr int kProbeRefused = 1;    // HDF5 refused a read: its place, finding and fix are the last records
inline constexpr int kProbeNotOpened = 3;  // HDF5 could not open it at all: File::open says why

// The probe's own work: writes an empty record (it started), opens `path` read-only and walks it as
// check_links does, reading every attribute and, by `depth`, every variable-length string or byte value;
// before each read it writes the place ("PATH", "PATH@NAME", "PATH, element N"), NUL-ended, to `out`.
// Returns kProbeRead once all was read and the file closed, as a reader closes it; at the first read
// HDF5 refuses, writes the error's place, finding and fix (each NUL-ended) and returns kProbeRefused,
// leaving the file open (HDF5 1.10 may crash closing it). Once HDF5 has opened the file, `opened` gets
// its end of address (the superblock's: HDF5 reads no byte past it), before anything else is read.
int read_structure(const std::string& path, ProbeDepth depth, std::ostream& out,
                   const std::function<void(std::uint64_t end_of_address)>& opened = {});

}  // namespace haptex::h5
