// What the benchmarks share: wall time, the median of repeated runs, and the --repeat option.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace bench {

using Clock = std::chrono::steady_clock;

/// Seconds since `start`.
inline double seconds(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

/// The median of `v` (the upper one of an even count); v not empty.
inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// Reads `[--repeat N]` (N >= 1) and --help/-h into *repeat, saying `usage`: -1 to go on, else
/// the exit status (0 after --help, 2 for a bad or unknown argument, named on stderr).
inline int parseRepeat(int argc, char** argv, const char* name, const char* usage, int* repeat) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--help") == 0 || std::strcmp(argv[i], "-h") == 0) {
      std::fputs(usage, stdout);
      return 0;
    }
    if (std::strcmp(argv[i], "--repeat") == 0) {
      *repeat = i + 1 < argc ? std::atoi(argv[++i]) : 0;
      if (*repeat >= 1)
        continue;
      std::fprintf(stderr, "%s: --repeat needs a whole number >= 1\n%s", name, usage);
      return 2;
    }
    std::fprintf(stderr, "%s: unexpected argument '%s'\n%s", name, argv[i], usage);
    return 2;
  }
  return -1;
}

}  // namespace bench
