// Global operator new/delete replaced by counting versions over glibc's allocator; the malloc
// family is interposed in counting_malloc.c. Each allocation is counted once: operator new goes
// straight to __libc_malloc, not through the interposed malloc.
#include "tests/allocation/counting_allocator.h"

#include <atomic>
#include <cstddef>
#include <new>

#include "tests/allocation/sanitizer_detect.h"

#ifdef TUNNELMAP_SANITIZED
#define TUNNELMAP_ALLOC_COUNTING 0
#else
#define TUNNELMAP_ALLOC_COUNTING 1
#endif

namespace {
std::atomic<std::uint64_t> g_calls{0};
std::atomic<std::uint64_t> g_bytes{0};
}  // namespace

extern "C" void tunnelmap_alloc_count(std::size_t bytes) {
  g_calls.fetch_add(1, std::memory_order_relaxed);
  g_bytes.fetch_add(bytes, std::memory_order_relaxed);
}

namespace tunnelmap::alloc {
bool counting_enabled() { return TUNNELMAP_ALLOC_COUNTING != 0; }
Counts snapshot() { return {g_calls.load(), g_bytes.load()}; }
}  // namespace tunnelmap::alloc

#if TUNNELMAP_ALLOC_COUNTING
extern "C" {
void* __libc_malloc(std::size_t);
void* __libc_memalign(std::size_t, std::size_t);
void __libc_free(void*);
}

namespace {
void* counted_new(std::size_t n, std::size_t alignment, bool nothrow) {
  if (n == 0) n = 1;
  tunnelmap_alloc_count(n);
  void* p = alignment > alignof(std::max_align_t) ? __libc_memalign(alignment, n) : __libc_malloc(n);
  if (!p && !nothrow) throw std::bad_alloc();
  return p;
}
constexpr std::size_t kPlain = alignof(std::max_align_t);
}  // namespace

void* operator new(std::size_t n) { return counted_new(n, kPlain, false); }
void* operator new[](std::size_t n) { return counted_new(n, kPlain, false); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return counted_new(n, kPlain, true); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return counted_new(n, kPlain, true); }
void* operator new(std::size_t n, std::align_val_t a) { return counted_new(n, std::size_t(a), false); }
void* operator new[](std::size_t n, std::align_val_t a) { return counted_new(n, std::size_t(a), false); }
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return counted_new(n, std::size_t(a), true);
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return counted_new(n, std::size_t(a), true);
}
void operator delete(void* p) noexcept { __libc_free(p); }
void operator delete[](void* p) noexcept { __libc_free(p); }
void operator delete(void* p, std::size_t) noexcept { __libc_free(p); }
void operator delete[](void* p, std::size_t) noexcept { __libc_free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { __libc_free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { __libc_free(p); }
void operator delete(void* p, std::align_val_t) noexcept { __libc_free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { __libc_free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { __libc_free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { __libc_free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { __libc_free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { __libc_free(p); }
#endif
