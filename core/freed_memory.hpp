#pragma once
// Process-wide: keep freed heap memory for reuse instead of handing it back to the kernel.
//
// haptex works file by file (convert a folder of HaTT recordings, align, evaluate materials): each
// file allocates buffers of up to tens of MB and frees them. By default glibc maps a block that large
// on its own and unmaps it when freed (the threshold rises only to the largest block freed so far, and
// the heap's free top is trimmed), so the next file's buffers come as fresh zeroed pages, one page
// fault per 4 KB: half of a HaTT XML parse was the kernel doing that (docs/convert.md, "Speed"). Kept,
// they are reused warm. Memory is not given back before exit: each thread's heap stays at the most it
// held at once, so a process holds the sum of its threads' peaks. Blocks over 32 MB are still mapped
// on their own. Called first thing by the haptex binary and by the bench programs, which time the
// library as haptex runs it.
namespace haptex {

// Whether the setting took (64-bit glibc); elsewhere nothing changes.
bool keep_freed_memory();

}  // namespace haptex
