#include "tracked_vehicle_dynamics/heap_reuse.h"

#include <cstdlib>  // defines __GLIBC__ (through <features.h>) where the C library is glibc

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>

#include <cstdint>
#endif

namespace tracked_vehicle_dynamics {

namespace {
#if defined(__GLIBC__)
// Above the largest matrix of a reduction (the 50 MB T_CMS of the tracked vehicle) with a wide
// margin: every block of the process comes from the heap and stays there when freed.
constexpr int kKeepBytes = 1 << 30;
// After: glibc's dynamic rule cannot come back once mallopt() has set a threshold (it raises the
// mmap threshold to the size of each freed mapped block, up to 32 MiB on 64-bit systems, and the
// trim threshold to twice that). The ceiling it would reach is what the process keeps: blocks up
// to 32 MiB come from the heap and are reused, larger ones are mapped, and up to 64 MiB of free
// heap top is kept.
constexpr int kAfterMmapBytes = 32 << 20;
constexpr int kAfterTrimBytes = 64 << 20;
// The heap is grown by this much at once and the kernel asked for transparent huge pages on it
// (madvise MADV_HUGEPAGE; honoured when /sys/kernel/mm/transparent_hugepage/enabled is "always"
// or "madvise"): a 2 MiB page faults once where 512 small ones would, and the first reduction of
// a process touches some 150 MB. Address space only: pages become memory when touched.
constexpr std::size_t kReserveBytes = std::size_t{512} << 20;
constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;
#endif
}  // namespace

HeapReuse::HeapReuse() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, kKeepBytes);
  mallopt(M_TRIM_THRESHOLD, kKeepBytes);
  // Freed at once, the block stays in the heap (the trim threshold above) for the matrices to come.
  if (void* block = std::malloc(kReserveBytes)) {
    const auto start = reinterpret_cast<std::uintptr_t>(block);
    const std::uintptr_t begin = (start + kHugePage - 1) & ~(kHugePage - 1);
    const std::uintptr_t end = (start + kReserveBytes) & ~(kHugePage - 1);
    if (end > begin)
      madvise(reinterpret_cast<void*>(begin), end - begin,
              MADV_HUGEPAGE);  // a hint: errors ignored
    std::free(block);
  }
#endif
}

HeapReuse::~HeapReuse() {
#if defined(__GLIBC__)
  mallopt(M_MMAP_THRESHOLD, kAfterMmapBytes);
  mallopt(M_TRIM_THRESHOLD, kAfterTrimBytes);
  malloc_trim(0);
#endif
}

}  // namespace tracked_vehicle_dynamics
