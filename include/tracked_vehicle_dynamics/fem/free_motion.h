// Describes the free (zero-energy) motions of a structure, to name them in error messages.
#pragma once

#include <string>

#include "tracked_vehicle_dynamics/fem/system.h"

namespace tracked_vehicle_dynamics {
namespace fem {

/// Finds the zero-stiffness motions of K (up to 24) and describes them: each rigid-body motion of
/// the whole that is free ("rigid-body translation along x", "rigid-body rotation about z"), then
/// the rest as mechanisms by the DOFs they move ("2 mechanisms involving node 3 uy, node 4 uy").
std::string describeFreeMotions(const System& system);

/// The six rigid-body motions of the active DOFs about the centroid of the nodes [n x 6]
/// (translation x, y, z, rotation about x, y, z), built through the constraint transformation.
Matrix rigidBodyModes(const System& system);

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
