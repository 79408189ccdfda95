// TVD_SANITIZER_BUILD is defined when a sanitizer's runtime owns the allocator (AddressSanitizer,
// ThreadSanitizer, MemorySanitizer; GCC and Clang spell the check differently). Tests that
// interpose malloc or read glibc's heap statistics do not apply there: the sanitizer's heap is
// not glibc's.
#pragma once

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define TVD_SANITIZER_BUILD 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define TVD_SANITIZER_BUILD 1
#endif
#endif
