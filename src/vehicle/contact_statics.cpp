#include "tracked_vehicle_dynamics/vehicle/contact_statics.h"

#include <stdexcept>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"

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

namespace {

// When every pad on the ground of an un-tracked vehicle stands on one column of soles (a line
// across the track: the inner and outer soles at one station), or has lifted entirely: those pads
// named, e.g. "track_left_0 at x = 2.34 m (front column)", and how many in *count; else "".
std::string padsOnOneColumn(const VehicleModel& vehicle, const std::vector<bool>& released,
                            int* count) {
  *count = 0;
  const VehicleLayout& layout = vehicle.layout;
  if (layout.variant != Variant::Untracked)
    return "";
  // Per assembly: bit c set when a sole of column c still presses.
  std::vector<int> pressed(layout.assemblies.size(), 0);
  for (std::size_t i = 0; i < layout.road_inputs.size(); ++i) {
    if (released[i])
      continue;
    const RoadInput& in = layout.road_inputs[i];
    const TrackAssemblyNodes& nodes =
        layout.assemblies[static_cast<std::size_t>(in.assembly)].nodes;
    for (std::size_t j = 0; j < nodes.soles.size(); ++j)
      if (nodes.soles[j] == in.node)
        pressed[static_cast<std::size_t>(in.assembly)] |= 1 << (j % 3);
  }
  for (std::size_t a = 0; a < pressed.size(); ++a) {
    const int bits = pressed[a];
    if (layout.assemblies[a].on_ground && bits != 0 && bits != 1 && bits != 2 && bits != 4)
      return "";  // a pad on two columns or more holds the hull
  }
  const auto node_index = vehicle.model.nodeIndex();
  // Along e1, forward on the ground run.
  const char* const column_names[3] = {"rear", "middle", "front"};
  std::string names;
  int lifted = 0;
  constexpr int kNamesShown = 4;
  for (std::size_t a = 0; a < pressed.size(); ++a) {
    const int bits = pressed[a];
    if (!layout.assemblies[a].on_ground)
      continue;
    if (bits == 0) {
      ++lifted;
      continue;
    }
    if ((*count)++ >= kNamesShown)
      continue;
    const AssemblyRecord& rec = layout.assemblies[a];
    const double x = vehicle.model.nodes[node_index.at(rec.nodes.linkCentre())].position.x();
    const int column = bits == 1 ? 0 : bits == 2 ? 1 : 2;
    names += std::string(names.empty() ? "" : ", ") + assemblyName(rec.side, rec.index) +
             " at x = " + brief(x) + " m (" + column_names[column] + " column)";
  }
  if (*count > kNamesShown)
    names += " and " + std::to_string(*count - kNamesShown) + " more";
  if (lifted > 0)
    names += "; " + std::to_string(lifted) + " lifted entirely";
  return names;
}

}  // namespace

ContactStatics computeContactStatics(const VehicleModel& vehicle, double forward_acceleration) {
  const std::vector<fem::UnilateralSpring> contacts = unilateralContacts(vehicle);
  fem::UnilateralStaticResult r;
  try {
    r = fem::solveUnilateralStatic(vehicle.model, contacts, fem::kMaxActiveSetSolves,
                                   fem::ActiveSetUpdate::AllViolated, forward_acceleration);
  } catch (const fem::UnilateralFreeMotionError& e) {
    // Un-tracked, a pad left on one column of soles can rock about it: the road wheel touches its
    // link at one point, which carries no moment, and no neighbouring link holds it. While some
    // pad keeps two columns it holds the hull; once none does, the hull can move with every pad
    // rocking about its column (one free motion: a dense eigen-decomposition of K shows one zero
    // eigenvalue, every assembly turning alike). The load then has no equilibrium: the pads
    // would roll onto their edges, which soles at three stations cannot represent.
    int count = 0;
    const std::string names = padsOnOneColumn(vehicle, e.released, &count);
    if (count == 0)
      throw;
    throw fem::UnilateralFreeMotionError(
        "no static equilibrium with contacts that cannot pull: every pad on the road has lifted "
        "but for one column of soles (" +
            std::to_string(count) + " track assemblies: " + names +
            "), and together they let the hull move, each pad rocking about its column: a road "
            "wheel touches its link at one point, which carries no moment, and soles at three "
            "stations cannot represent a pad rolling onto its edge",
        e.released);
  }
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
