// HeapReuse (heap_reuse.h): inside its scope a freed large matrix's pages are reused, not mapped
// and faulted in anew; after it glibc maps large blocks again and the free memory is returned.
#include <gtest/gtest.h>

#include <cstdlib>  // __GLIBC__

#include "tracked_vehicle_dynamics/heap_reuse.h"
#include "tracked_vehicle_dynamics/types.h"

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/resource.h>

namespace tvd = tracked_vehicle_dynamics;

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
}

TEST(HeapReuse, RestoresTheMappingOfLargeBlocksAndReturnsFreeMemory) {
  { const tvd::HeapReuse reuse; faultsOfOneMatrix(); }
  // Outside the scope a large block is mapped on its own again (glibc's fixed default threshold)
  // and the heap kept no large free block.
  EXPECT_LT(mallinfo2().fordblks, 16u << 20);
  void* block = std::malloc(64u << 20);
  ASSERT_NE(block, nullptr);
  EXPECT_GE(mallinfo2().hblkhd, 64u << 20);
  std::free(block);
}
#endif
