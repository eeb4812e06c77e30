#include "core/freed_memory.hpp"

#include <cstdlib>  // defines __GLIBC__ on glibc
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace haptex {

void keep_freed_memory() {
#if defined(__GLIBC__)
  // Blocks up to 32 MB (glibc's largest threshold on 64-bit) come from the heap, not from their own
  // mapping, and the heap's free top is never trimmed.
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
  mallopt(M_TRIM_THRESHOLD, 1 << 30);
#endif
}

}  // namespace haptex
