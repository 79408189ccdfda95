// Ride comfort of the accelerations at one point of the hull over a `tvd simulate` run.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "output_row.h"
#include "tracked_vehicle_dynamics/dynamics/seat_comfort.h"
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

// ISO 2631-1:1997 (seated, comfort) at one point of the supporting seat surface over a run
// (dynamics/seat_comfort.h): every axis, their totals, and the vertical's VDV, MTVV and absorbed
// power; written as the JSON and text of `tvd simulate` and read by `tvd ride`.
class PointComfort {
 public:
  /// dt [s] the sample interval.
  PointComfort(std::string point, const ComfortRows& rows, double dt);

  /// One output row of the simulator (all outputs at one sample).
  void add(const OutputRow& outputs);
  const dynamics::SeatComfortMeter& meter() const { return meter_; }
  void writeJson(io::JsonWriter& json) const;
  void writeText(std::ostream& out) const;

 private:
  std::string point_;
  ComfortRows rows_;
  dynamics::SeatComfortMeter meter_;
};

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
