/* Interposes the malloc family for the allocation counter (counting_allocator.h): the
 * executable's definitions win over libc's for every library in the process, and forward to
 * glibc's exported __libc_* entry points. Written in C: the C++ headers declare malloc with
 * exception specifications that a C++ redefinition would have to repeat exactly. */
#include <errno.h>
#include <stddef.h>

#include "tests/allocation/sanitizer_detect.h"

#ifndef TUNNELMAP_SANITIZED  /* the sanitizer's allocator must stay in charge */

void* __libc_malloc(size_t);
void __libc_free(void*);
void* __libc_calloc(size_t, size_t);
void* __libc_realloc(void*, size_t);
void* __libc_memalign(size_t, size_t);
void* __libc_valloc(size_t);
void* __libc_pvalloc(size_t);

void tunnelmap_alloc_count(size_t bytes); /* counting_allocator.cpp */

void* malloc(size_t n) {
  tunnelmap_alloc_count(n);
  return __libc_malloc(n);
}
void free(void* p) { __libc_free(p); }
void* calloc(size_t count, size_t size) {
  tunnelmap_alloc_count(count * size);
  return __libc_calloc(count, size);
}
void* realloc(void* p, size_t n) {
  tunnelmap_alloc_count(n);
  return __libc_realloc(p, n);
}
void* memalign(size_t alignment, size_t n) {
  tunnelmap_alloc_count(n);
  return __libc_memalign(alignment, n);
}
void* aligned_alloc(size_t alignment, size_t n) {
  tunnelmap_alloc_count(n);
  return __libc_memalign(alignment, n);
}
void* valloc(size_t n) {
  tunnelmap_alloc_count(n);
  return __libc_valloc(n);
}
void* pvalloc(size_t n) {
  tunnelmap_alloc_count(n);
  return __libc_pvalloc(n);
}
int posix_memalign(void** out, size_t alignment, size_t n) {
  if (alignment < sizeof(void*) || (alignment & (alignment - 1)) != 0) return EINVAL;
  void* p = __libc_memalign(alignment, n);
  if (!p) return ENOMEM;
  tunnelmap_alloc_count(n);
  *out = p;
  return 0;
}

#endif
