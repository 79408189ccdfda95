// A vehicle speed that varies in time (paper §4.2.1 drives at constant speed; engineers also brake
// and accelerate over a track): v(t) piecewise linear between samples (t_k, v_k), and the
// travelled station its exact integral,
//   s(t) = S_k + v_k tau + (v_{k+1} - v_k) tau^2 / (2 h_k),   tau = t - t_k,  h_k = t_{k+1} - t_k,
//   S_k  = sum_{i<k} (v_i + v_{i+1}) h_i / 2            (trapezoids: exact for linear v).
// After the last sample the speed is held.
#pragma once

#include <string>
#include <vector>

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// The fastest travel the tools accept [km/h]: a high-speed tracked vehicle tops out near 70 km/h,
/// and beyond 200 km/h the linear, bonded-ground model describes nothing a vehicle does. One limit
/// for tvd simulate, frf and ride and tvd_make_bag.
constexpr double kMaxSpeedKmh = 200.0;

class SpeedProfile {
 public:
  /// time [s]: at least two samples, the first 0, strictly increasing, finite; speed [m/s]: one
  /// per time, finite and >= 0 (the road inputs assume forward travel). `name` prefixes errors
  /// (e.g. the file). Throws InputError naming the offending sample.
  SpeedProfile(std::vector<double> time, std::vector<double> speed,
               const std::string& name = "speed profile");

  /// v(t) [m/s]; t >= 0 (t < 0 is read as 0).
  double speed(double t) const;
  /// a(t) = dv/dt [m/s^2]: (v_{k+1} - v_k) / h_k on the segment [t_k, t_{k+1}) (piecewise
  /// constant, right-continuous: at a sample the next segment's), 0 after the last sample.
  double acceleration(double t) const;
  /// s(t) = integral of v from 0 to t [m].
  double station(double t) const;
  /// Time of the last sample [s].
  double endTime() const { return time_.back(); }
  /// Largest sampled speed [m/s].
  double maxSpeed() const;
  /// Largest |a| over the segments [m/s^2], and (when `at` is given) the start t_k [s] of the
  /// first segment that reaches it. 0 for a constant speed.
  double maxAbsAcceleration(double* at = nullptr) const;

  const std::vector<double>& times() const { return time_; }
  const std::vector<double>& speeds() const { return speed_; }
  /// What the profile was made from (its file, for one loaded): the start of later messages.
  const std::string& name() const { return name_; }

 private:
  /// Index k of the segment [t_k, t_{k+1}) that holds t (the last sample for t >= endTime()).
  std::size_t segment(double t) const;

  std::vector<double> time_;
  std::vector<double> speed_;
  std::vector<double> station_;  // S_k at each sample
  std::string name_;
};

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
