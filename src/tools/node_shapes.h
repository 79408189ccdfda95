// The vehicle's mode shapes node by node, for drawing them (paper Fig. 11): every node's
// translation in every mode, rigid-joint slaves (wheel centres, named points, spider mounts)
// included through the constraint transformation.
#pragma once

#include <string>

#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace tools {

/// Writes `path` (CSV): one row per node of the model, sorted by id: node, part
/// (vehicle::nodePart), x_m, y_m, z_m (undeformed), then for each mode k mode_k_ux, mode_k_uy,
/// mode_k_uz (mass-normalised shape). Written through a temporary file and a rename; throws
/// InputError naming `path` when it cannot be written (no partial file is left).
void writeNodeShapes(const std::string& path, const vehicle::VehicleModel& vehicle,
                     const fem::System& system, const fem::ModalBasis& basis);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
