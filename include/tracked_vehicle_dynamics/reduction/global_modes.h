// Which modes of a vehicle are global (paper §3.1.1: the MAC selection keeps the modes
// "significant for the global behaviour"): those with at least kGlobalEnergyShare of their
// kinetic energy in the vehicle, the hull and the running gear (vehicle::ModeClass::hull_share +
// wheel_share; vehicle::vehicleEnergy()).
//
// The MAC is blind to amplitude, so a mode of the track that barely moves the vehicle's DOFs
// correlates as fully as a hull mode. On the bundled vehicle the un-tracked assemblies' 107.72 Hz
// modes (0 % of their energy in the vehicle) paired tracked chain modes at 11.45 and 26.51 Hz
// (themselves 0 %) with MACs of 0.72 and 0.85, and the tracked chain mode at 22.94 Hz (0.002 %)
// the un-tracked yaw with 0.89; on the light 5-axle vehicle the un-tracked 136 Hz modes
// (0.02-0.07 %) paired tracked modes at 6.8-19.8 Hz. The hull and wheel modes hold 97 % and more
// (un-tracked) and 39-93 % (tracked); tracked chain modes that carry the hull along hold up to
// 19 %, and count.
#pragma once

#include <vector>

#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/types.h"
#include "tracked_vehicle_dynamics/vehicle/mode_classification.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

/// Share of a mode's kinetic energy in the hull and running gear from which it is global [-].
constexpr double kGlobalEnergyShare = 0.01;

/// Whether each mode of `modes` (of `system`, the assembled `vehicle`; frequencies ascending,
/// shapes M-orthonormal) is global. The modes of a repeated eigenvalue (degenerateGroups(),
/// mac.h) are one eigenspace to the MAC and any basis of it to the solver, so they are judged
/// together, by the largest share any mode of the eigenspace holds (the largest eigenvalue of
/// vehicle::vehicleEnergy() over the group): global together or not at all, whichever vectors the
/// solver returned. Throws InputError when the shapes do not fit the system.
std::vector<bool> globalModes(const vehicle::VehicleModel& vehicle, const fem::System& system,
                              const fem::ModalBasis& modes);

/// The pairing matrix of two variants: `mac` (rows: one variant's modes, columns: the other's,
/// e.g. eigenspaceMac()) with the rows and columns of the modes that are not global zeroed, so
/// that only global modes pair (Table 4 in `tvd mac`, the reduction's MAC mode selection).
/// Throws std::logic_error when the flags do not fit `mac`.
Matrix globalPairs(Matrix mac, const std::vector<bool>& row_global,
                   const std::vector<bool>& column_global);

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
