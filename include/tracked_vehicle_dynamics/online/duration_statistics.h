// Statistics of a stream of durations (step times of the real-time loop) without allocation:
// a histogram of 1 us bins up to kBins us (longer durations fall in the last bin, their exact
// maximum is kept), so a percentile costs O(kBins) and adding a sample O(1). ROS-free.
#pragma once

#include <array>
#include <cstdint>

namespace tracked_vehicle_dynamics {
namespace online {

class DurationStatistics {
 public:
  /// Histogram bins [1 us each]; durations of kBins us or more are counted in the last bin.
  static constexpr int kBins = 2000;

  /// Adds one duration [s] (negative values count as 0).
  void add(double seconds);
  /// Forgets everything.
  void clear();

  std::uint64_t count() const { return count_; }
  /// Mean [s]; 0 when empty.
  double mean() const;
  /// Largest duration [s]; 0 when empty.
  double max() const { return max_; }
  /// Smallest d [s] (resolution 1 us) with at least `fraction` (0..1) of the samples <= d;
  /// max() when it lies in the overflow bin; 0 when empty.
  double percentile(double fraction) const;

 private:
  std::array<std::uint64_t, kBins> bins_{};
  std::uint64_t count_ = 0;
  double sum_ = 0.0;
  double max_ = 0.0;
};

}  // namespace online
}  // namespace tracked_vehicle_dynamics
