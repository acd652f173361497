#include "checker/context_pool.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace cemv::checker {

namespace {

// A fresh Z3 context (Z3 4.8.12) allocates two tables of 8.5 MB and fills
// them, and destroying it frees them. glibc gives blocks that large their own
// mapping, or trims them off the top of the heap when freed, so every context
// came on fresh pages from the kernel: page faults and zeroing by the
// kernel, then Z3's fill. On `cemv defeats` of burner-management that was
// 64 % of the CPU (perf: Z3_mk_context_rc's two fill loops and the page
// faults under them; 12.7 of 36.4 s in the kernel). Blocks up to 32 MB now
// come from the heap, and up to 512 MB of freed heap stays mapped for the
// next context: the same bytes out, a third of the CPU. The peak resident
// memory is the same (what is freed is reused, not added to). Set once, by
// any process that makes contexts through the checker, before main runs.
struct KeepFreedContextsMapped {
  KeepFreedContextsMapped() {
#if defined(__GLIBC__)
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 512 << 20);
#endif
  }
};
const KeepFreedContextsMapped keep_freed_contexts_mapped;

}  // namespace

void discard_when_released(const z3::context&) {}

PooledContext::PooledContext() : ctx_(std::make_unique<z3::context>()) {}

PooledContext::~PooledContext() = default;

}  // namespace cemv::checker
