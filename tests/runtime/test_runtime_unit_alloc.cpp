// Replaces the global allocation functions of the runtime unit-test binary with
// counting ones, so a test can assert that Runtime::step() allocates nothing.
// A separate translation unit, so the compiler does not pair our malloc/free
// with new/delete expressions it can see.
#include <atomic>
#include <cstdlib>
#include <new>

namespace cemv_test {
std::atomic<long> allocations{0};
long allocation_count() { return allocations.load(); }
}  // namespace cemv_test

void* operator new(std::size_t n) {
  ++cemv_test::allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) { return operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
