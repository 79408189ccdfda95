// Peak vertical acceleration at a point of the hull for obstacle crossing: the NATO Reference
// Mobility Model's shock criterion rates a vehicle by the speed at which the driver's seat first
// sees 2.5 g going over a half-round obstacle, reading the peak of the vertical acceleration
// after a 30 Hz low-pass (Project Chrono's ChISO2631_Shock_SeatCushionLogger::GetLegacyAz, its
// "traditional NRMM method", uses a 4th-order Butterworth filter at 30 Hz; the same defaults
// here). The filter removes the contact "ringing" a rigid-body seat model would not transmit to
// an occupant, and makes the peak independent of the time step.
//
//   a_f = LP(a),  peak up = max_k a_f,k (the criterion: an upward jolt),  peak = max_k |a_f,k|
//
// `a` is the kinematic acceleration (gravity excluded: 0 at rest), as tvd simulate reports it.
#pragma once

#include <optional>

#include "tracked_vehicle_dynamics/dynamics/comfort.h"
#include "tracked_vehicle_dynamics/types.h"  // kStandardGravity, the "g" of the limits

namespace tracked_vehicle_dynamics {
namespace dynamics {

struct ShockOptions {
  int lowpass_order = 4;            ///< Butterworth order, 1..12
  double lowpass_corner_hz = 30.0;  ///< [Hz], below fs/2; 0 = unfiltered
};

/// Online: one sample per time step, O(1).
class ShockMeter {
 public:
  /// sample_rate [Hz]. Throws InputError for a corner at or above fs / 2, a negative corner or
  /// a bad order (butterworth.h).
  explicit ShockMeter(double sample_rate, const ShockOptions& options = {});

  /// Adds one acceleration sample [m/s^2]; throws InputError if it is not finite (nothing kept).
  void add(double acceleration);
  /// Forgets every sample; the filter back to rest.
  void reset();

  /// Largest filtered upward acceleration [m/s^2] (0 before the first sample, never negative:
  /// the signal starts at 0 from rest).
  double peakUp() const { return peak_up_; }
  /// Largest filtered |acceleration| [m/s^2].
  double peakAbsolute() const { return peak_abs_; }

 private:
  std::optional<WeightingFilter> lowpass_;
  double peak_up_ = 0.0;
  double peak_abs_ = 0.0;
};

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
