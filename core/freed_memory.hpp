#pragma once
// Process-wide: keep freed heap memory for reuse instead of handing it back to the kernel.
//
// haptex works file by file (convert a folder of HaTT recordings, align, evaluate materials): each
// file allocates buffers of tens of MB and frees them. glibc hands blocks over 128 KB back to the
// kernel when they are freed, and the next file's buffers then come as fresh zeroed pages, one page
// fault per 4 KB: half of a HaTT XML parse was the kernel doing that (docs/convert.md, "Speed").
// Kept, they are reused warm; the process's peak memory is unchanged, it just is not given back
// before exit. Called first thing by the haptex binary and by the bench programs, which time the
// library as haptex runs it. A no-op on C libraries other than glibc.
namespace haptex {

void keep_freed_memory();

}  // namespace haptex
