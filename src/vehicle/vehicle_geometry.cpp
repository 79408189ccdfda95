#include "tracked_vehicle_dynamics/vehicle/vehicle_geometry.h"

#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

VehicleGeometry vehicleGeometry(const VehicleDescription& description) {
  // Building the untracked model takes milliseconds and is the one place the positions are
  // computed, so they cannot drift from the model's.
  return vehicleGeometry(description, buildVehicleModel(description, Variant::Untracked));
}

VehicleGeometry vehicleGeometry(const VehicleDescription& description, const VehicleModel& built) {
  const auto index = built.model.nodeIndex();
  auto position = [&](NodeId id) { return built.model.nodes.at(index.at(id)).position; };
  VehicleGeometry geometry;
  geometry.vehicle_name = description.name;
  geometry.cog = position(built.layout.hull);
  for (const WheelStation& wheel : built.layout.wheels)
    geometry.wheels.push_back({wheel.name, position(wheel.centre)});
  for (const NamedPoint& point : description.named_points)
    geometry.points.push_back({point.name, point.position});
  return geometry;
}

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
