#pragma once
// Process-wide allocation counters, fed by counting_allocator.cpp, which replaces the global
// operator new/delete and interposes malloc/calloc/realloc/posix_memalign/aligned_alloc/
// memalign (OpenCV's and Eigen's buffers bypass operator new). Link that file into an
// executable of its own: it changes allocation for everything in the process.
#include <cstdint>

namespace tunnelmap::alloc {

struct Counts {
  std::uint64_t calls = 0;  // allocations (new + malloc family; realloc counts as one)
  std::uint64_t bytes = 0;  // bytes requested by them
};

// False when built with a sanitizer (its own allocator must stay in charge): nothing counted.
bool counting_enabled();
Counts snapshot();

}  // namespace tunnelmap::alloc
