#include "tracked_vehicle_dynamics/dynamics/ground_contact.h"

#include <string>

#include "tracked_vehicle_dynamics/dynamics/validation.h"
#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

const char* contactSideName(ContactSide side) {
  switch (side) {
    case ContactSide::Left:
      return "left";
    case ContactSide::Right:
      return "right";
    case ContactSide::Centre:
      return "centre";
  }
  return "centre";
}

std::vector<GroundContact> groundContacts(const SecondOrderSystem& system, DofIndex road_inputs) {
  const DofIndex n_u = system.inputCount();
  if (road_inputs < 0)
    road_inputs = n_u;
  if (road_inputs > n_u)
    throw InputError("ground contacts: " + std::to_string(road_inputs) +
                     " road inputs asked for, the system has " + std::to_string(n_u));
  // Every matrix's size and the input positions' lengths (a short input_lateral would silently
  // put every contact at the centre, outside both side totals).
  validateSystem(system);
  const bool has_lateral = system.input_lateral.size() == n_u;
  std::vector<GroundContact> contacts;
  contacts.reserve(static_cast<std::size_t>(road_inputs));
  for (DofIndex i = 0; i < road_inputs; ++i) {
    const std::string which = "ground contacts: road input " + std::to_string(i);
    // Column i of K_u must be k_i e_m: exactly one non-zero, positive (a spring, not a lever).
    DofIndex m = -1;
    for (DofIndex r = 0; r < system.size(); ++r) {
      if (system.input_stiffness(r, i) == 0.0)
        continue;
      if (m >= 0)
        throw InputError(
            which + " acts on coordinates " + std::to_string(m) + " and " + std::to_string(r) +
            " (K_u column not of the form k e_m: not a spring on one coordinate, e.g. a "
            "ground DOF that is not a master)");
      m = r;
    }
    if (m < 0)
      throw InputError(which + " has a zero K_u column (no ground spring)");
    GroundContact c;
    c.input = i;
    c.coordinate = m;
    c.stiffness = system.input_stiffness(m, i);
    if (!(c.stiffness > 0.0))
      throw InputError(which + ": ground stiffness " + brief(c.stiffness) + " N/m on coordinate " +
                       std::to_string(m) + " is not positive");
    for (DofIndex r = 0; r < system.size(); ++r)
      if (r != m && system.input_damping(r, i) != 0.0)
        throw InputError(which + ": C_u acts on coordinate " + std::to_string(r) + ", K_u on " +
                         std::to_string(m) + " (the damper must sit beside the spring)");
    c.damping = system.input_damping(m, i);
    if (!(c.damping >= 0.0))
      throw InputError(which + ": ground damping " + brief(c.damping) + " N s/m is negative");
    c.lateral = has_lateral ? system.input_lateral(i) : 0.0;
    c.side = c.lateral > 0   ? ContactSide::Left
             : c.lateral < 0 ? ContactSide::Right
                             : ContactSide::Centre;
    contacts.push_back(c);
  }
  return contacts;
}

void contactForces(const std::vector<GroundContact>& contacts,
                   const Eigen::Ref<const Vector>& state, const Eigen::Ref<const Vector>& input,
                   DofIndex input_count, Eigen::Ref<Vector> forces, const char* where) {
  const DofIndex n = state.size() / 2;
  if (state.size() % 2 != 0 || input.size() != 2 * input_count ||
      forces.size() != static_cast<DofIndex>(contacts.size()))
    throw InputError(
        std::string(where) + ": state of " + std::to_string(state.size()) + ", input of " +
        std::to_string(input.size()) + " and " + std::to_string(forces.size()) + " forces for " +
        std::to_string(contacts.size()) + " contacts and " + std::to_string(input_count) +
        " inputs (expected [q; q'], [u; u'] and one force per contact)");
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const GroundContact& c = contacts[i];
    if (c.coordinate < 0 || c.coordinate >= n || c.input < 0 || c.input >= input_count)
      throw InputError(std::string(where) + ": contact " + std::to_string(i) + " on coordinate " +
                       std::to_string(c.coordinate) + " and input " + std::to_string(c.input) +
                       " outside a state of " + std::to_string(n) + " coordinates and " +
                       std::to_string(input_count) + " inputs");
    forces(static_cast<DofIndex>(i)) =
        c.stiffness * (input(c.input) - state(c.coordinate)) +
        c.damping * (input(input_count + c.input) - state(n + c.coordinate));
  }
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
