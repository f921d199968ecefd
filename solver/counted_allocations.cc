// The global operator new replaced by one that counts, for the test binaries that measure
// heap allocations on a hot path (allocation_test: an impact; sweep_allocation_test: a sweep's
// rows). Linked into those binaries only; each declares
//   long heap_allocations_so_far();
// and compares the count before and after the work it measures.
//
// The replacements pair std::malloc with std::free. With -fsanitize=address (make asan) GCC
// inlines them into callers and then warns -Wmismatched-new-delete that a pointer from
// operator new reaches std::free: a false positive for a replaced operator new built on malloc
// (three of them broke the warning-free `make asan` build), silenced for these definitions only.
#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<long> g_allocations{0};
}

long heap_allocations_so_far() {
  return g_allocations.load();
}

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
#pragma GCC diagnostic pop
