// Counts every heap allocation of the process while g_count_allocations is set, for the tests
// that a real-time step allocates nothing. Eigen allocates with malloc (not operator new), so
// malloc itself is interposed and forwarded to glibc. Include it in one translation unit of a
// test executable (it defines malloc, calloc and realloc).
//
// TVD_COUNTS_ALLOCATIONS is 1 where that works: glibc (for __libc_malloc), and not under a
// sanitizer, whose runtime interposes malloc itself (ASan then reports the hooks' memory as
// foreign and the test binary dies before any test runs).
#pragma once

#include <cstddef>
#include <cstdlib>  // __GLIBC__

#include "sanitizer_build.h"

#if defined(__GLIBC__) && !defined(TVD_SANITIZER_BUILD)
#define TVD_COUNTS_ALLOCATIONS 1

namespace {
bool g_count_allocations = false;
long g_allocations = 0;
}  // namespace

extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* pointer, std::size_t size);
void* malloc(std::size_t size) noexcept {
  if (g_count_allocations)
    ++g_allocations;
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) noexcept {
  if (g_count_allocations)
    ++g_allocations;
  return __libc_calloc(count, size);
}
void* realloc(void* pointer, std::size_t size) noexcept {
  if (g_count_allocations)
    ++g_allocations;
  return __libc_realloc(pointer, size);
}
}
#else
#define TVD_COUNTS_ALLOCATIONS 0
#endif
