#include "tracked_vehicle_dynamics/vehicle/track_tension.h"

#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

namespace {

constexpr int kLanes = 3;

}  // namespace

void addChainTension(fem::Model& model, const ChainLoop& chain, NodeId hull, double tension) {
  if (!(tension > 0.0) || chain.assemblies.empty())
    return;
  const double lane_force = tension / kLanes;
  std::map<std::pair<NodeId, NodeId>, std::size_t> beam_of;
  for (std::size_t i = 0; i < model.beams.size(); ++i)
    beam_of[{model.beams[i].n1, model.beams[i].n2}] = i;
  const auto index = model.nodeIndex();
  auto at = [&](NodeId id) -> const Vector3& { return model.nodes[index.at(id)].position; };

  // Each tensioned member pulls its end nodes towards each other; summed per node this is the
  // load the wheels must hold where the loop turns (zero along a straight run).
  std::map<NodeId, Vector3> pull;
  auto tension_between = [&](NodeId a, NodeId b) {
    const Vector3 e = (at(b) - at(a)).normalized();
    auto add = [&](NodeId n, const Vector3& f) {
      auto [it, inserted] = pull.emplace(n, f);
      if (!inserted)
        it->second += f;
    };
    add(a, lane_force * e);
    add(b, -lane_force * e);
  };
  auto member = [&](NodeId a, NodeId b) {
    const auto it = beam_of.find({a, b});
    if (it == beam_of.end())
      throw std::logic_error("addChainTension: no link member between nodes " + std::to_string(a) +
                             " and " + std::to_string(b));
    model.beams[it->second].axial_force = lane_force;
    tension_between(a, b);
  };

  const std::size_t count = chain.assemblies.size();
  for (std::size_t k = 0; k < count; ++k) {
    const TrackAssemblyNodes& n = chain.assemblies[k];
    const TrackAssemblyNodes& next = chain.assemblies[(k + 1) % count];
    for (int lane = 0; lane < kLanes; ++lane) {
      member(n.rear_pin[lane], n.laneLink(lane));
      member(n.laneLink(lane), n.front_pin[lane]);
      fem::Tie tie;
      tie.n1 = n.front_pin[lane];
      tie.n2 = next.rear_pin[lane];
      tie.force = lane_force;
      tie.name = std::string("chain_") + chain.side + "_joint_" + std::to_string(k) + "_tension";
      model.ties.push_back(tie);
      tension_between(tie.n1, tie.n2);
    }
  }

  fem::BodyPreload body;
  body.node = hull;
  body.name = std::string("chain_") + chain.side + "_tension_on_hull";
  for (const auto& [node, f] : pull) {
    if (f.squaredNorm() == 0.0)
      continue;
    body.points.push_back(at(node));
    body.forces.push_back(f);
  }
  model.body_preloads.push_back(std::move(body));
}

double modelTrackTension(const VehicleDescription& description, Variant variant) {
  return variant == Variant::Tracked ? description.track_assembly.static_tension.value_or(0.0)
                                     : 0.0;
}

std::string trackTensionText(const VehicleDescription& description, Variant variant) {
  if (!description.track_assembly.static_tension)
    return "";
  const std::string value = brief(*description.track_assembly.static_tension) + " N";
  if (variant != Variant::Tracked)
    return "track tension (track_assembly.static_tension " + value +
           ") not used: the un-tracked variant has no chain loop";
  if (*description.track_assembly.static_tension == 0.0)
    return "track tension 0 N: the chain is a free-length beam loop";
  return "track tension " + value +
         " per chain, a pre-stress: its stiffness is in the model (the chain's members turning "
         "under it); its forces on the sprocket, idler and end road wheels are not in the static "
         "loads";
}

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
