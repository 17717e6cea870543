/* Defines TUNNELMAP_SANITIZED when a sanitizer owns the allocator (ASan, TSan, MSan), for the
 * C and C++ halves of the allocation counter: they must not replace it then. */
#ifndef TUNNELMAP_SANITIZER_DETECT_H
#define TUNNELMAP_SANITIZER_DETECT_H
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define TUNNELMAP_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || __has_feature(memory_sanitizer)
#define TUNNELMAP_SANITIZED 1
#endif
#endif
#endif
