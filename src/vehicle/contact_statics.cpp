#include "tracked_vehicle_dynamics/vehicle/contact_statics.h"

#include <stdexcept>
#include <string>

namespace tracked_vehicle_dynamics {
namespace vehicle {

std::vector<fem::UnilateralSpring> unilateralContacts(const VehicleModel& vehicle) {
  std::vector<fem::UnilateralSpring> contacts;
  // The road pushes each sole up (global z, the ground spring's frame).
  for (const RoadInput& in : vehicle.layout.road_inputs)
    contacts.push_back({in.spring, 2, 1.0});
  // The patch spring runs from the wheel (n1) to the link (n2); the link pushes the wheel along
  // the contact frame's z axis, the link's normal, away from the link.
  for (const WheelStation& w : vehicle.layout.wheels)
    contacts.push_back({w.contact_spring, 2, 1.0});
  // Sprocket, idler and rollers: the same spring from the wheel (n1) to the link (n2); the
  // frame's z axis is the loop's inward normal, from the link towards the wheel's centre, so the
  // link pushes the wheel along +z (on the ground run, the road wheels' case, it is global z).
  for (const ChainWheelContact& w : vehicle.layout.chain_wheel_contacts)
    contacts.push_back({w.spring, 2, 1.0});
  return contacts;
}

ContactStatics computeContactStatics(const VehicleModel& vehicle, double forward_acceleration) {
  const std::vector<fem::UnilateralSpring> contacts = unilateralContacts(vehicle);
  fem::UnilateralStaticResult r =
      fem::solveUnilateralStatic(vehicle.model, contacts, fem::kMaxActiveSetSolves,
                                 fem::ActiveSetUpdate::AllViolated, forward_acceleration);
  ContactStatics c;
  c.vehicle.layout = vehicle.layout;
  c.vehicle.model = std::move(r.model);
  c.system = std::move(r.system);
  c.summary = staticSummaryOf(c.vehicle, c.system, r.statics);
  const std::size_t pads = vehicle.layout.road_inputs.size();
  c.pad_lifted.assign(r.released.begin(), r.released.begin() + static_cast<std::ptrdiff_t>(pads));
  const auto wheels_end =
      r.released.begin() + static_cast<std::ptrdiff_t>(pads + vehicle.layout.wheels.size());
  c.wheel_lifted.assign(r.released.begin() + static_cast<std::ptrdiff_t>(pads), wheels_end);
  c.chain_wheel_released.assign(wheels_end, r.released.end());
  c.iterations = r.iterations;
  return c;
}

ChainWheelRelease chainWheelRelease(const VehicleLayout& layout, const std::vector<bool>& released,
                                    int side, ChainWheel wheel) {
  if (released.size() != layout.chain_wheel_contacts.size())
    throw std::invalid_argument("chainWheelRelease: " + std::to_string(released.size()) +
                                " flags for " + std::to_string(layout.chain_wheel_contacts.size()) +
                                " contacts");
  ChainWheelRelease count;
  for (std::size_t i = 0; i < released.size(); ++i) {
    const ChainWheelContact& c = layout.chain_wheel_contacts[i];
    if (c.side != side || c.wheel != wheel)
      continue;
    ++count.contacts;
    if (released[i])
      ++count.released;
  }
  return count;
}

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
