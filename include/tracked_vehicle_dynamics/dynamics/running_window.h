// ISO 2631-1's running r.m.s. by linear integration (6.3.1, the first of its two forms):
//   a_w(t0) = sqrt(1/τ ∫_{t0-τ}^{t0} a_w^2(t) dt),
// sampled: the mean of the last N = round(fs τ) squares, the samples before the first taken as
// zero (the record starts at rest, as the exponential form's filter does). The standard allows
// either form; on a transient this one reads higher (the exponential weights the last second
// by e^-1 at its far end): 5-28 % on the runs of `tvd simulate` checked, enough to move the
// MTVV / a_w,rms ratio across its 1.5 limit. A ring of N squares with their running sum,
// re-added exactly once per N samples so the subtraction's round-off cannot accumulate.
#ifndef TRACKED_VEHICLE_DYNAMICS_DYNAMICS_RUNNING_WINDOW_H
#define TRACKED_VEHICLE_DYNAMICS_DYNAMICS_RUNNING_WINDOW_H

#include <cstddef>
#include <vector>

namespace tracked_vehicle_dynamics {
namespace dynamics {

class LinearRunningMeanSquare {
 public:
  /// Largest window held [samples] (80 MB of doubles): ten seconds at 1 MHz, 10^4 s at 1 kHz.
  static constexpr std::size_t kMaxWindow = 10'000'000;

  /// window = round(sample_rate * time) samples, at least 1. Throws InputError when it exceeds
  /// kMaxWindow (naming both figures).
  LinearRunningMeanSquare(double sample_rate, double time);
  /// The window the constructor would hold, checked as it checks it, without holding it.
  static std::size_t windowSamples(double sample_rate, double time);

  /// Adds one squared sample; returns the mean square of the window ending with it.
  double add(double square);
  /// The mean square of the window ending with the last sample (0 before the first).
  double value() const;
  /// Forgets every sample.
  void reset();
  std::size_t window() const { return squares_.size(); }

 private:
  std::vector<double> squares_;  // the last N squares, oldest at next_
  std::size_t next_ = 0;
  double sum_ = 0.0;
};

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics

#endif  // TRACKED_VEHICLE_DYNAMICS_DYNAMICS_RUNNING_WINDOW_H
