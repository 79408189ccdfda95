// Static equilibrium of a vehicle model under its own weight (linear statics K x = f_g): hull
// sag and attitude, road-wheel and pad loads, and the balance of ground reactions and weight.
#pragma once

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/fem/static_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

struct StaticSummary {
  double hull_sag = 0.0;            ///< vertical displacement of the hull CoG [m] (negative: down)
  double hull_pitch = 0.0;          ///< rotation about +y [rad] (positive: nose down)
  double hull_roll = 0.0;           ///< rotation about +x [rad] (positive: left side up)
  std::vector<double> wheel_loads;  ///< normal force of each road wheel on the track [N]
                                    ///< (VehicleLayout::wheels order, positive: compression)
  std::vector<double> chain_wheel_loads;  ///< normal force of each sprocket, idler and roller
                                          ///< contact [N] (VehicleLayout::chain_wheel_contacts
                                          ///< order, positive: compression, the link pushing
                                          ///< the wheel)
  std::vector<double> pad_loads;          ///< vertical ground reaction at each road input [N]
                                          ///< (VehicleLayout::road_inputs order, positive: upwards)
  /// Vertical force of the sprockets, idlers and rollers on the chain, summed [N] (positive:
  /// up). The chain presses them, and so the hull, down by as much: with its own weight it is
  /// why the road-wheel loads need not sum to the weight. The chain's vertical balance,
  ///   ground_reaction + chain_wheel_vertical = sum(wheel_loads) + chain weight,
  /// holds to the static solve's tolerance. 0 for the un-tracked variant.
  double chain_wheel_vertical = 0.0;
  double ground_reaction = 0.0;  ///< sum of the vertical ground reactions [N]
  /// Sum of the longitudinal (x) ground reactions [N]: 0 at rest, m a under a steady forward
  /// acceleration a (the road holding the vehicle back while it brakes, a < 0).
  double ground_reaction_x = 0.0;
  double weight = 0.0;    ///< total weight m g [N]
  double residual = 0.0;  ///< ||K x - f|| / ||f|| of the static solve

  /// |ground_reaction - weight| / weight.
  double balanceError() const;
};

/// Solves the gravity load case of an assembled vehicle model, plus the travel inertia of a
/// steady forward acceleration [m/s^2] (f_g + a f_a; braking a < 0). Throws SolverError if the
/// model is not supported (a free rigid-body motion).
StaticSummary computeStaticSummary(const VehicleModel& vehicle, const fem::System& system,
                                   double forward_acceleration = 0.0);

/// The summary of a solution already computed (`solution` solves `system`, assembled from
/// `vehicle.model`, under its gravity load and any travel inertia).
StaticSummary staticSummaryOf(const VehicleModel& vehicle, const fem::System& system,
                              const fem::StaticResult& solution);

/// A road-wheel arm's static rotation beyond which the description is taken for a typo [rad]
/// (57 degrees: a torsion-bar arm's whole travel is about that, from full rebound to the bump
/// stop; the bundled vehicle's arms turn at most 0.09 rad).
constexpr double kMaxStaticArmRotation = 1.0;

/// What a solved equilibrium shows to be physically wrong with the description (a typo in a
/// stiffness or a mass that loading alone does not catch): a road-wheel arm turned by more than
/// kMaxStaticArmRotation under its static load, or a hull sag larger than the arm's length,
/// which no trailing arm travels. Empty when nothing is.
std::vector<std::string> staticWarnings(const StaticSummary& summary,
                                        const VehicleDescription& description);

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
