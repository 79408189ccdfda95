// Ground loads of a vehicle at rest: the vertical reaction under each track assembly standing on
// the road (from the static solution, StaticSummary::pad_loads), and the ground-pressure figures
// tracked-vehicle engineers quote beside them.
//
//   nominal ground pressure   NGP = W / (2 b L)                      b track width, L ground run
//   assembly pressure         p_k = F_k / (b t)                     F_k its reaction, t the pitch
//   mean maximum pressure     MMP = 1.26 W / (2 n b sqrt(t D))      Rowland (1972), empirical:
//                             n road wheels per side, D their diameter; W in N, lengths in m,
//                             MMP in Pa (the formula's kN and kPa scaled alike)
//   its FE counterpart        mean over the road wheels of the largest p_k within half an axle
//                             spacing of the wheel (the pressure peaks under the wheels, which
//                             Rowland's formula estimates)
//
// NGP and MMP take the description's dimensions and the model's weight (StaticSummary::weight:
// the un-tracked model, without most of the chain, the sprockets and idlers, is lighter); p_k is
// what the static solution says: with bonded contacts (computeStaticSummary) a negative F_k is an
// assembly the model holds down that would lift off; with unilateral ones (computeContactStatics)
// none is negative.
#pragma once

#include <vector>

#include "tracked_vehicle_dynamics/vehicle/static_summary.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

/// The vertical ground reaction under one track assembly on the road.
struct AssemblyGroundLoad {
  int side = 0;           ///< 0 left (+y), 1 right (-y)
  int assembly = 0;       ///< its position k (AssemblyRecord::index; model name track_<side>_<k>):
                          ///< tracked 0 at the rear end of the ground run, un-tracked the axle
  double x = 0.0;         ///< mean station of its road inputs [m]
  double load = 0.0;      ///< sum of its road inputs' reactions [N] (positive: upwards)
  double inner = 0.0;     ///< of which under the inner pad row (towards the hull centre line) [N]
  double outer = 0.0;     ///< of which under the outer pad row [N]
  double pressure = 0.0;  ///< load / (track width x pitch) [Pa]
};

struct GroundPressure {
  /// Left side front to rear, then the right side front to rear.
  std::vector<AssemblyGroundLoad> assemblies;
  double side_load[2] = {0.0, 0.0};  ///< sum per side [N]
  double nominal_pressure = 0.0;     ///< NGP [Pa]
  /// Rowland's empirical estimate of the mean maximum pressure, MMP [Pa] (the FE model's own
  /// figure is mean_peak_pressure).
  double rowland_mean_maximum_pressure = 0.0;
  /// Per road wheel (VehicleLayout::wheels order): the largest assembly pressure on its side within
  /// half an axle spacing of its centre's x [Pa].
  std::vector<double> wheel_peak_pressure;
  std::vector<double> wheel_x;      ///< per road wheel: its centre's station [m]
  double mean_peak_pressure = 0.0;  ///< their mean: the FE model's mean maximum pressure [Pa]
  int peak = -1;                    ///< index into `assemblies` of the largest pressure
  int lifting = 0;                  ///< assemblies with a downward (negative) reaction
};

/// Groups the static ground reactions by assembly and computes the pressures. `statics` must be a
/// summary of `vehicle` (computeStaticSummary, or computeContactStatics' summary with its
/// vehicle); `description` is the one it was built from. Throws
/// std::logic_error when the reactions do not match the model's road inputs.
GroundPressure groundPressure(const VehicleModel& vehicle, const VehicleDescription& description,
                              const StaticSummary& statics);

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
