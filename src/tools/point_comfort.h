// Ride comfort of the accelerations at one point of the hull over a `tvd simulate` run.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "output_row.h"
#include "tracked_vehicle_dynamics/dynamics/comfort.h"
#include "tracked_vehicle_dynamics/io/json_writer.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace tools {

/// The point's acceleration columns in the simulator's output rows: translations [m/s^2] and
/// the hull's rotations [rad/s^2] (rigid, so the same at every point of it).
struct ComfortRows {
  DofIndex x, y, z;
  DofIndex roll, pitch, yaw;
};

/// The rows of `point`'s accelerations and the hull's angular accelerations among the
/// simulator's output names; throws InputError naming a missing one and the `command`.
ComfortRows comfortRows(const std::vector<std::string>& names, const std::string& point,
                        const std::string& command);

// ISO 2631-1:1997 (seated, comfort) at one point of the supporting seat surface:
// - vertically a_w (Wk), VDV, MTVV and the absorbed power (comfort.h); horizontally a_w (Wd) in
//   x and y; the vibration total value of the translations (8.2.3, k_x = k_y = k_z = 1)
//     a_v = sqrt(a_wx^2 + a_wy^2 + a_wz^2);
// - rotationally a_w (We) of roll, pitch and yaw [rad/s^2], and their total with the standard's
//   rotational factors for the seat surface, k_rx = 0.63, k_ry = 0.40, k_rz = 0.20 m/rad
//   (dynamics::SeatRotationFactors),
//     a_r = sqrt((0.63 a_wrx)^2 + (0.40 a_wry)^2 + (0.20 a_wrz)^2)   [m/s^2];
// - the overall total of the seat surface's six axes, sqrt(a_v^2 + a_r^2) [m/s^2] (8.2.3 sums
//   the axes of every contact; the seat back and the feet are not modelled, so this is the
//   seat surface's share).
// A tracked hull pitches and rolls at 1-2 Hz, where We weights most (0.94 at 0.8 Hz): its
// rotations can add as much as a translation to what the crew feels.
class PointComfort {
 public:
  /// dt [s] the sample interval.
  PointComfort(std::string point, const ComfortRows& rows, double dt);

  /// One output row of the simulator (all outputs at one sample).
  void add(const OutputRow& outputs);
  /// a_v of the translations [m/s^2].
  double totalValue() const;
  /// a_r of the rotations [m/s^2].
  double rotationalTotalValue() const;
  /// sqrt(a_v^2 + a_r^2) [m/s^2].
  double overallTotalValue() const;
  /// The vertical (Wk, absorbed power) meter.
  const dynamics::ComfortMeter& vertical() const { return vertical_; }
  /// The hull's rotations (We) [rad/s^2].
  const dynamics::ComfortMeter& roll() const { return roll_; }
  const dynamics::ComfortMeter& pitch() const { return pitch_; }
  const dynamics::ComfortMeter& yaw() const { return yaw_; }
  void writeJson(io::JsonWriter& json) const;
  void writeText(std::ostream& out) const;

 private:
  std::string point_;
  ComfortRows rows_;
  dynamics::ComfortMeter vertical_, longitudinal_, lateral_;
  dynamics::ComfortMeter roll_, pitch_, yaw_;
};

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
