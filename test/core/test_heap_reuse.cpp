// HeapReuse (heap_reuse.h): inside its scope a freed large matrix's pages are reused, not mapped
// and faulted in anew; after it glibc maps large blocks again and the free memory is returned.
#include <gtest/gtest.h>

#include <cstdlib>  // __GLIBC__

#include "sanitizer_build.h"
#include "tracked_vehicle_dynamics/heap_reuse.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tvd = tracked_vehicle_dynamics;

// glibc's heap only: a sanitizer's allocator neither maps nor reuses blocks as glibc does.
#if defined(__GLIBC__) && !defined(TVD_SANITIZER_BUILD)
#include <malloc.h>
#include <sys/resource.h>

namespace {

long minorFaults() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

// A 64 MB matrix (larger than the tracked T_CMS), every page written; returns the minor page
// faults it cost.
long faultsOfOneMatrix() {
  const long before = minorFaults();
  {
    tvd::Matrix a = tvd::Matrix::Constant(2048, 4096, 1.0);
    EXPECT_EQ(a(2047, 4095), 1.0);
  }
  return minorFaults() - before;
}

constexpr long kPages = 2048L * 4096L * 8L / 4096L;  // 16,384 pages of 4 KiB

}  // namespace

TEST(HeapReuse, FreedMatricesReuseTheirPagesInsideTheScope) {
  const tvd::HeapReuse reuse;
  faultsOfOneMatrix();  // the heap grows once
  // The second and third matrices take the pages the first left: (almost) no faults. Without
  // HeapReuse each of them is a fresh mapping: kPages faults (fewer with transparent huge pages,
  // which the heap gets too).
  EXPECT_LT(faultsOfOneMatrix(), kPages / 100);
  EXPECT_LT(faultsOfOneMatrix(), kPages / 100);
  // Deterministically: a 64 MB block comes from the heap, not from a mapping of its own (which
  // glibc would otherwise make for any block above 32 MiB).
  const std::size_t mapped = mallinfo2().hblkhd;
  void* block = std::malloc(64u << 20);
  ASSERT_NE(block, nullptr);
  EXPECT_EQ(mallinfo2().hblkhd, mapped);
  std::free(block);
}

TEST(HeapReuse, AfterwardsLargeBlocksAreMappedAndTheFreeMemoryIsReturned) {
  {
    const tvd::HeapReuse reuse;
    faultsOfOneMatrix();
  }
  // The heap kept no large free block (malloc_trim), and the thresholds sit at the ceiling of
  // glibc's dynamic rule: a block above 32 MiB is mapped on its own, one below comes from the heap.
  EXPECT_LT(mallinfo2().fordblks, 16u << 20);
  const std::size_t mapped = mallinfo2().hblkhd;
  void* large = std::malloc(64u << 20);
  ASSERT_NE(large, nullptr);
  EXPECT_GE(mallinfo2().hblkhd, mapped + (64u << 20));
  void* medium = std::malloc(16u << 20);
  ASSERT_NE(medium, nullptr);
  EXPECT_LT(mallinfo2().hblkhd, mapped + (80u << 20));
  std::free(medium);
  std::free(large);
}
#else
// Under a sanitizer the heap is the sanitizer's, which glibc's mallopt() settings do not reach:
// a HeapReuse must then leave it working (the node and tvd create one whatever the allocator).
TEST(HeapReuse, LeavesAnotherAllocatorWorking) {
  {
    const tvd::HeapReuse reuse;
    const tvd::Matrix a = tvd::Matrix::Constant(2048, 4096, 1.0);
    EXPECT_EQ(a.sum(), 2048.0 * 4096.0);
  }
  const tvd::Matrix b = tvd::Matrix::Constant(512, 512, 2.0);
  EXPECT_EQ(b.sum(), 2.0 * 512.0 * 512.0);
}
#endif
