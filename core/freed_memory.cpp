#include "core/freed_memory.hpp"

#include <cstdlib>  // defines __GLIBC__ on glibc
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace haptex {

bool keep_freed_memory() {
#if defined(__GLIBC__)
  // Blocks up to 32 MB (glibc's largest threshold on 64-bit; 32-bit refuses it) come from the heap,
  // not from their own mapping; only then is trimming switched off, since that also stops glibc from
  // raising its threshold on its own.
  return mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024) == 1 && mallopt(M_TRIM_THRESHOLD, 1 << 30) == 1;
#else
  return false;
#endif
}

}  // namespace haptex
