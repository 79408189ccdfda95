// Which pad each ground contact of a reduced vehicle model belongs to.
//
// A track assembly's pad sole is a road input: a ground spring on a master coordinate of the
// reduced model (dynamics::groundContacts). The soles of one assembly are one rigid pad, so they
// carry its moments as opposite forces and one sole can pull while the pad as a whole presses
// (it would rock onto an edge); the sum of their forces pulling means the whole pad would leave
// the road. Grouping the contacts by assembly lets a monitor tell the two apart
// (GroundContact::group; GroundContactMonitor offline, GroundContactWatch online).
#pragma once

#include <vector>

#include "tracked_vehicle_dynamics/dynamics/ground_contact.h"
#include "tracked_vehicle_dynamics/reduction/reduced_model.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

/// Sets GroundContact::group of every contact of `model` (built from `vehicle`) to its track
/// assembly, numbered 0, 1, ... in the order the contacts first meet them; a contact whose
/// coordinate is no master, or whose master node is no road input of `vehicle`, keeps -1.
/// Returns the number of groups. `vehicle` must be the model the reduction started from (same
/// description and variant): the masters' node numbers are looked up in its layout.
int groupContactsByAssembly(const vehicle::VehicleModel& vehicle, const ReducedModel& model,
                            std::vector<dynamics::GroundContact>* contacts);

/// Per road input of model.system, the group groupContactsByAssembly() gives its contact (-1:
/// none). Empty when the model's road inputs are no ground springs on coordinates
/// (dynamics::groundContacts refuses them; a ground-contact check then says why).
std::vector<int> roadInputGroups(const vehicle::VehicleModel& vehicle, const ReducedModel& model);

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
