// Keeping freed memory in the process while the large dense matrices of a reduction come and go.
//
// glibc serves an allocation above its mmap threshold (128 KiB, raised on its own up to 32 MiB)
// with a fresh anonymous mapping and unmaps it when it is freed. The dense matrices of the tracked
// vehicle's Craig-Bampton reduction are larger than that (T_m: 14,372 x 389 doubles = 45 MB;
// T_CMS, when a caller forms it, 50 MB), so each is mapped anew and every one of its 4 KiB pages
// faults on first touch: some 12,000 faults per matrix. On a virtual machine a fault costs
// microseconds; on this project's 2-core VM `tvd reduce --variant tracked` spent 0.87 s of its
// 2.9 s in the kernel. HeapReuse raises the mmap and trim thresholds for its lifetime, so a freed
// matrix stays in the heap and the next one reuses pages already mapped; and it grows the heap by
// 512 MB of address space at once with transparent huge pages asked for (madvise), so the pages
// the reduction does touch fault 2 MiB at a time: 1,000 faults instead of 92,000, 0.73 s instead of
// 2.8 s wall, peak memory 166 MB instead of 247 MB (with the blocked solves of craig_bampton.cpp;
// 119 MB since the constraint modes are solved into T_m).
// Its destructor returns the free memory to the system (malloc_trim) and leaves the thresholds at
// the ceiling of glibc's dynamic rule (32 MiB mmap, 64 MiB trim), which no mallopt() can switch
// back on: for a long-running process (the ROS node) that needs the large blocks only while it
// builds or loads its model.
//
// The allocator is process-wide: programs create one in main() (tvd, the benchmarks) or around
// their model set-up (the node, before its stepping starts); the core itself never changes it.
// Not nested: at most one at a time. It helps the main thread's heap (arena) only: glibc gives
// other threads arenas of their own, which the 512 MB reserve does not reach, so a reduction on a
// worker thread faults its pages as without it (review 160: 1.0-1.3 s for the tracked one,
// 0.84-0.97 s on the main thread; the results are the same). Without glibc it does nothing. The 512
// MB reserve is address space; on a system with strict overcommit (vm.overcommit_memory = 2) it
// counts against the commit limit while the HeapReuse lives.
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
