// Where the bodies a user looks at are on the undeformed vehicle: the hull's CoG, the road-wheel
// centres and the named points, in the description's frame (base_link: x forward, y left, z up,
// origin on the ground plane under the centre of the wheelbase). The ROS node places its frames
// there; `tvd simulate` reads the road under each wheel centre.
#pragma once

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/types.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

struct VehicleModel;  // vehicle_model.h

/// Static positions [m] of the hull CoG, the road-wheel centres and the named points.
struct VehicleGeometry {
  struct Body {
    std::string name;
    Vector3 position = Vector3::Zero();  ///< undeformed [m]
  };
  std::string vehicle_name;
  Vector3 cog = Vector3::Zero();  ///< hull centre of gravity p_G [m]
  std::vector<Body> wheels;       ///< road-wheel centres, left 1..n then right 1..n
  std::vector<Body> points;       ///< named points of the description
};

/// The geometry of a description, from its untracked FE model (the wheel centres are the same in
/// both variants). Throws InputError like buildVehicleModel().
VehicleGeometry vehicleGeometry(const VehicleDescription& description);

/// The same from a model already built from `description` (either variant), so a caller that
/// needs the model anyway (the node, for the contacts' pads) builds it once.
VehicleGeometry vehicleGeometry(const VehicleDescription& description, const VehicleModel& built);

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
