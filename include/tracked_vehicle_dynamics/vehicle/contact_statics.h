// The vehicle at rest with contacts that push but cannot pull. The linear model (paper §2) bonds
// every pad to the road and every road wheel to its link; in the tracked model the chain then
// pulls on the road between the wheels and the rearmost wheels pull on the chain (statics of the
// linear model: doc/vehicle_model.md). Here the pads' ground springs, the road wheels' contact
// patches and the links' contacts with the sprockets, idlers and return rollers are unilateral in
// their normal (fem::solveUnilateralStatic): those in tension are released until the rest carry
// the vehicle in compression; their tangential ties stay, as the guide horns do. A released chain
// wheel contact leaves no mechanism: the link still hangs in the chain, a continuous beam through
// its rigid pin joints. For ground loads and pressures; the dynamics stay linear about the bonded
// equilibrium.
#pragma once

#include <vector>

#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/fem/unilateral_static.h"
#include "tracked_vehicle_dynamics/vehicle/static_summary.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

/// The unilateral contacts of a vehicle: every road input's ground spring (pushing its sole up),
/// then every road wheel's contact patch, then every sprocket, idler and return-roller contact
/// (each pushing the wheel away from the link, along the contact frame's z axis), in
/// VehicleLayout order.
std::vector<fem::UnilateralSpring> unilateralContacts(const VehicleModel& vehicle);

struct ContactStatics {
  VehicleModel vehicle;            ///< the model with the released contacts' normal stiffness 0
  fem::System system;              ///< it, assembled
  StaticSummary summary;           ///< its equilibrium (pad_loads 0 where a pad has lifted)
  std::vector<bool> pad_lifted;    ///< per road input
  std::vector<bool> wheel_lifted;  ///< per road wheel: its patch has left the link
  /// Per VehicleLayout::chain_wheel_contacts: the link has left its sprocket, idler or roller.
  std::vector<bool> chain_wheel_released;
  int iterations = 0;  ///< solves of the active-set iteration
};

/// Of one side's contacts with one kind of chain wheel: how many there are, how many released.
struct ChainWheelRelease {
  int released = 0;
  int contacts = 0;
};

/// Counts `released` (one flag per VehicleLayout::chain_wheel_contacts) for `side` and `wheel`.
/// Throws std::invalid_argument when the sizes differ.
ChainWheelRelease chainWheelRelease(const VehicleLayout& layout, const std::vector<bool>& released,
                                    int side, ChainWheel wheel);

/// Equilibrium under gravity with unilateral contacts, and under the travel inertia of a steady
/// forward acceleration [m/s^2] (braking < 0: the load moves to the front pads). Throws
/// SolverError as fem::solveUnilateralStatic does.
ContactStatics computeContactStatics(const VehicleModel& vehicle,
                                     double forward_acceleration = 0.0);

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
