// Keeping freed memory in the process while the large dense matrices of a reduction come and go.
//
// glibc serves an allocation above its mmap threshold (128 KiB, raised on its own up to 32 MiB)
// with a fresh anonymous mapping and unmaps it when it is freed. The dense matrices of the tracked
// vehicle's Craig-Bampton reduction are larger than that (T_CMS: 14,372 x 431 doubles = 50 MB; the
// constraint modes and K_sm 43 MB each), so each is mapped anew and every one of its 4 KiB pages
// faults on first touch: some 12,000 faults per matrix. On a virtual machine a fault costs
// microseconds; on this project's 2-core VM `tvd reduce --variant tracked` spent 0.87 s of its
// 2.9 s in the kernel. HeapReuse raises the mmap and trim thresholds for its lifetime, so a freed
// matrix stays in the heap and the next one reuses pages already mapped; and it grows the heap by
// 512 MB of address space at once with transparent huge pages asked for (madvise), so the pages
// the reduction does touch fault 2 MiB at a time: 1,000 faults instead of 92,000, 1.4-1.9 s
// instead of 2.8 s, peak memory 168 MB instead of 247 MB. Its destructor restores glibc's default thresholds and returns the free
// memory to the system (malloc_trim), for a long-running process (the ROS node) that needs the
// memory only while it builds or loads its model.
//
// The allocator is process-wide: programs create one in main() (tvd, the node's start-up, the
// benchmarks); the core itself never changes it. Not nested: at most one at a time. Without glibc
// it does nothing.
#pragma once

namespace tracked_vehicle_dynamics {

class HeapReuse {
 public:
  HeapReuse();
  ~HeapReuse();
  HeapReuse(const HeapReuse&) = delete;
  HeapReuse& operator=(const HeapReuse&) = delete;
};

}  // namespace tracked_vehicle_dynamics
