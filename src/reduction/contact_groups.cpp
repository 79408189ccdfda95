#include "tracked_vehicle_dynamics/reduction/contact_groups.h"

#include <map>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

int groupContactsByAssembly(const vehicle::VehicleModel& vehicle, const ReducedModel& model,
                            std::vector<dynamics::GroundContact>* contacts) {
  std::map<NodeId, int> assembly_of;  // road-input node -> its track assembly
  for (const vehicle::RoadInput& r : vehicle.layout.road_inputs)
    assembly_of[r.node] = r.assembly;
  std::map<int, int> group_of;  // track assembly -> group number
  for (dynamics::GroundContact& c : *contacts) {
    c.group = -1;
    if (c.coordinate < 0 || c.coordinate >= model.masterCount())
      continue;
    const auto it = assembly_of.find(model.masters[static_cast<std::size_t>(c.coordinate)].node);
    if (it == assembly_of.end())
      continue;
    c.group = group_of.emplace(it->second, static_cast<int>(group_of.size())).first->second;
  }
  return static_cast<int>(group_of.size());
}

std::vector<int> roadInputGroups(const vehicle::VehicleModel& vehicle, const ReducedModel& model) {
  std::vector<dynamics::GroundContact> contacts;
  try {
    contacts = dynamics::groundContacts(model.system);
  } catch (const InputError&) {
    return {};
  }
  groupContactsByAssembly(vehicle, model, &contacts);
  std::vector<int> groups(static_cast<std::size_t>(model.system.inputCount()), -1);
  for (const dynamics::GroundContact& c : contacts)
    groups[static_cast<std::size_t>(c.input)] = c.group;
  return groups;
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
