#include "tracked_vehicle_dynamics/vehicle/contact_statics.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

std::vector<fem::UnilateralSpring> unilateralContacts(const VehicleModel& vehicle) {
  std::vector<fem::UnilateralSpring> contacts;
  // The road pushes each sole up (global z, the ground spring's frame).
  for (const RoadInput& in : vehicle.layout.road_inputs) contacts.push_back({in.spring, 2, 1.0});
  // The patch spring runs from the wheel (n1) to the link (n2); the link pushes the wheel along
  // the contact frame's z axis, the link's normal, away from the link.
  for (const WheelStation& w : vehicle.layout.wheels) contacts.push_back({w.contact_spring, 2, 1.0});
  return contacts;
}

ContactStatics computeContactStatics(const VehicleModel& vehicle) {
  const std::vector<fem::UnilateralSpring> contacts = unilateralContacts(vehicle);
  fem::UnilateralStaticResult r = fem::solveUnilateralStatic(vehicle.model, contacts);
  ContactStatics c;
  c.vehicle.layout = vehicle.layout;
  c.vehicle.model = std::move(r.model);
  c.system = std::move(r.system);
  c.summary = staticSummaryOf(c.vehicle, c.system, r.statics);
  const std::size_t pads = vehicle.layout.road_inputs.size();
  c.pad_lifted.assign(r.released.begin(), r.released.begin() + static_cast<std::ptrdiff_t>(pads));
  c.wheel_lifted.assign(r.released.begin() + static_cast<std::ptrdiff_t>(pads), r.released.end());
  c.iterations = r.iterations;
  return c;
}

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
