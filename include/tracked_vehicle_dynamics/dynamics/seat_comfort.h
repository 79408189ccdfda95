// Ride comfort of a seated person at one point of a rigid hull, over every axis ISO 2631-1:1997
// rates at the supporting seat surface (8.2, comfort), sample by sample (e.g. at 1 kHz):
//   translations  a_wx, a_wy (Wd), a_wz (Wk; with the VDV, MTVV and the absorbed power)
//                 a_v = sqrt(a_wx^2 + a_wy^2 + a_wz^2)                              (8.2.3, k = 1)
//   rotations     a_wrx, a_wry, a_wrz (We) of roll, pitch and yaw [rad/s^2]
//                 a_r = sqrt((0.63 a_wrx)^2 + (0.40 a_wry)^2 + (0.20 a_wrz)^2)     [m/s^2]
//   six axes      sqrt(a_v^2 + a_r^2)                                                [m/s^2]
// (comfort.h: the weightings, SeatRotationFactors and the totals.) The standard's overall value
// also sums the seat back and the feet, which a hull point does not have: the six-axis total is
// the seat surface's share. A tracked hull pitches and rolls at 1-2 Hz, where We weights most
// (0.94 at 0.8 Hz).
#pragma once

#include "tracked_vehicle_dynamics/dynamics/comfort.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// One sample of the accelerations at the seat: translations [m/s^2], rotations [rad/s^2].
struct SeatAcceleration {
  double x = 0.0, y = 0.0, z = 0.0;
  double roll = 0.0, pitch = 0.0, yaw = 0.0;
};

class SeatComfortMeter {
 public:
  /// sample_rate [Hz]; running_rms_time τ [s] of every meter's running r.m.s. Throws InputError
  /// as ComfortMeter (a rate too low for Wk, a τ not positive).
  explicit SeatComfortMeter(double sample_rate, double running_rms_time = 1.0);

  /// Adds one sample. Throws InputError for a non-finite value (the metrics then unchanged).
  void add(const SeatAcceleration& a);
  /// Forgets all samples.
  void reset();

  /// The vertical meter (Wk, with the absorbed power) and the others.
  const ComfortMeter& vertical() const { return vertical_; }
  const ComfortMeter& longitudinal() const { return longitudinal_; }
  const ComfortMeter& lateral() const { return lateral_; }
  const ComfortMeter& roll() const { return roll_; }
  const ComfortMeter& pitch() const { return pitch_; }
  const ComfortMeter& yaw() const { return yaw_; }

  /// a_v [m/s^2].
  double translationalTotalValue() const;
  /// a_r [m/s^2].
  double rotationalTotalValue() const;
  /// sqrt(a_v^2 + a_r^2) [m/s^2].
  double seatSurfaceTotalValue() const;

 private:
  ComfortMeter vertical_, longitudinal_, lateral_;
  ComfortMeter roll_, pitch_, yaw_;
};

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
