// Ride comfort of the accelerations at one point of the hull over a `tvd simulate` run.
#pragma once

#include <ostream>
#include <string>

#include "output_row.h"
#include "tracked_vehicle_dynamics/dynamics/comfort.h"
#include "tracked_vehicle_dynamics/io/json_writer.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace tools {

// Vertically: ISO 2631-1 a_w (Wk), VDV, MTVV and the absorbed power (comfort.h); horizontally
// a_w (Wd) in x and y; and the ISO 2631-1 (8.2.3) vibration total value
//   a_v = sqrt(a_wx^2 + a_wy^2 + a_wz^2)   (seated comfort: k_x = k_y = k_z = 1).
class PointComfort {
 public:
  /// x_row, y_row, z_row: the point's acceleration columns in the simulator's output rows;
  /// dt [s] the sample interval.
  PointComfort(std::string point, DofIndex x_row, DofIndex y_row, DofIndex z_row, double dt);

  /// One output row of the simulator (all outputs at one sample).
  void add(const OutputRow& outputs);
  double totalValue() const;
  /// The vertical (Wk, absorbed power) meter.
  const dynamics::ComfortMeter& vertical() const { return vertical_; }
  void writeJson(io::JsonWriter& json) const;
  void writeText(std::ostream& out) const;

 private:
  std::string point_;
  DofIndex x_row_, y_row_, z_row_;
  dynamics::ComfortMeter vertical_, longitudinal_, lateral_;
};

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
