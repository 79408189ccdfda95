// Statistics of a stream of durations (step times of the real-time loop) without allocation:
// a histogram of 1 us bins up to kBins us, then bins growing by 1 % (edges kBins us * 1.01^i) up
// to about 2 s (longer durations fall in the last bin, their exact maximum is kept), so a
// percentile costs O(bins) and adding a sample O(1), and a p99 of ticks that often take a few ms
// (catch-up steps under load) is a p99, not the maximum. ROS-free.
#pragma once

#include <array>
#include <cstdint>

namespace tracked_vehicle_dynamics {
namespace online {

class DurationStatistics {
 public:
  /// Linear bins [1 us each] below kBins us.
  static constexpr int kBins = 2000;
  /// Geometric bins above: [kBins us * 1.01^i, kBins us * 1.01^(i+1)), i < kWideBins (up to
  /// 2 ms * 1.01^695 = 2.0 s); durations beyond fall in the last one.
  static constexpr int kWideBins = 695;
  static constexpr double kWideRatio = 1.01;

  /// Adds one duration [s] (negative values count as 0).
  void add(double seconds);
  /// Forgets everything.
  void clear();

  std::uint64_t count() const { return count_; }
  /// Mean [s]; 0 when empty.
  double mean() const;
  /// Largest duration [s]; 0 when empty.
  double max() const { return max_; }
  /// Smallest d [s] (resolution 1 us below 2 ms, 1 % above) with at least `fraction` (0..1) of
  /// the samples <= d (a bin's upper edge, never above max()); max() when it lies in the last
  /// bin; 0 when empty.
  double percentile(double fraction) const;

 private:
  std::array<std::uint64_t, kBins + kWideBins> bins_{};
  std::uint64_t count_ = 0;
  double sum_ = 0.0;
  double max_ = 0.0;
};

}  // namespace online
}  // namespace tracked_vehicle_dynamics
