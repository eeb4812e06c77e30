#include "tests/support/allocation_counter.hpp"

#include <cerrno>

namespace {
thread_local bool counting = false;
thread_local std::size_t allocations = 0;
void note() {
  if (counting) ++allocations;
}
}  // namespace

// glibc's own entry points, which the interposers below forward to.
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);

void* malloc(std::size_t size) {
  note();
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  note();
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) {
  note();
  return __libc_realloc(p, size);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t size) {
  note();
  if (alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0) return EINVAL;
  void* p = __libc_memalign(alignment, size);
  if (!p) return ENOMEM;
  *out = p;
  return 0;
}
void* aligned_alloc(std::size_t alignment, std::size_t size) {
  note();
  return __libc_memalign(alignment, size);
}
}

namespace haptex::test {

CountAllocations::CountAllocations() : start_(allocations), outer_(!counting) { counting = true; }
CountAllocations::~CountAllocations() {
  if (outer_) counting = false;
}
std::size_t CountAllocations::count() const { return allocations - start_; }

}  // namespace haptex::test
