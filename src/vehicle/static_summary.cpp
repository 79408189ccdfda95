#include "tracked_vehicle_dynamics/vehicle/static_summary.h"

#include <algorithm>
#include <cmath>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/spring_element.h"
#include "tracked_vehicle_dynamics/fem/static_solver.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

double StaticSummary::balanceError() const {
  return weight > 0.0 ? std::abs(ground_reaction - weight) / weight : 0.0;
}

StaticSummary computeStaticSummary(const VehicleModel& vehicle, const fem::System& system,
                                   double forward_acceleration) {
  return staticSummaryOf(vehicle, system,
                         fem::solveStatic(system, system.steadyLoad(forward_acceleration)));
}

StaticSummary staticSummaryOf(const VehicleModel& vehicle, const fem::System& system,
                              const fem::StaticResult& r) {
  const Vector u = system.dofs.transformation() * r.displacement;
  auto nodal = [&](NodeId id) -> Vector6 {
    return u.segment<kDofsPerNode>(system.dofs.physical(id, 0));
  };
  StaticSummary s;
  s.residual = r.residual;
  const Vector6 hull = nodal(vehicle.layout.hull);
  s.hull_sag = hull(2);
  s.hull_roll = hull(3);
  s.hull_pitch = hull(4);
  s.weight = vehicle.model.totalMass() * vehicle.model.gravity.norm();

  const auto& springs = vehicle.model.springs;
  for (const RoadInput& in : vehicle.layout.road_inputs) {
    // Force of the ground on the node: -K_p q (the grounded bushing acts at its node).
    const fem::Spring& g = springs[in.spring];
    const Vector6 f = -fem::bushingMatrix(g.stiffness, g.frame) * nodal(in.node);
    s.pad_loads.push_back(f(2));
    s.ground_reaction += f(2);
    s.ground_reaction_x += f(0);
  }
  for (const WheelStation& w : vehicle.layout.wheels) {
    // Contact between coincident nodes (wheel side n1, link side n2): force on the link -K d,
    // d = q2 - q1; the wheel load is its downward component.
    const fem::Spring& c = springs[w.contact_spring];
    const Vector6 f = -fem::bushingMatrix(c.stiffness, c.frame) * (nodal(c.n2) - nodal(c.n1));
    s.wheel_loads.push_back(-f(2) + 0.0);  // + 0.0: a released contact reads 0, not -0
  }
  for (const ChainWheelContact& w : vehicle.layout.chain_wheel_contacts) {
    // The same bushing in the link's frame, diagonal there: N = k_z z . (u_link - u_wheel), z
    // the inward normal. Taken from k_z directly, not as z . (K d), so a released contact
    // (k_z = 0) reads exactly 0 rather than the round-off of its turned tangential stiffness.
    const fem::Spring& c = springs[w.spring];
    const Vector3 d = (nodal(c.n2) - nodal(c.n1)).head<3>();
    s.chain_wheel_loads.push_back(c.stiffness(2) * c.frame.col(2).dot(d) + 0.0);
    // Its vertical force on the link (n2), as for the road wheels above.
    s.chain_wheel_vertical -=
        (fem::bushingMatrix(c.stiffness, c.frame) * (nodal(c.n2) - nodal(c.n1)))(2);
  }
  return s;
}

std::vector<std::string> staticWarnings(const StaticSummary& summary,
                                        const VehicleDescription& description) {
  std::vector<std::string> out;
  // A linear model's deflections grow with load / stiffness without bound; a trailing arm turns
  // through a fraction of a radian. Beyond that the numbers are a description's typo (5.2e2 for
  // 5.2e5 N m/rad), not a vehicle.
  const SuspensionDescription& arm = description.suspension;
  // The arm's static rotation: the torsion bar carries the wheel's load on the lever
  // a cos(beta), theta = F a cos(beta) / k_t. In the tracked model the chain can carry the
  // hull with the arms turned through many radians and the hull barely lower, so the hull's sag
  // alone does not show it.
  double largest_load = 0.0;
  for (double load : summary.wheel_loads)
    largest_load = std::max(largest_load, std::abs(load));
  const double rotation =
      largest_load * arm.arm_length * std::cos(arm.arm_angle) / arm.torsion_bar_stiffness;
  if (rotation > kMaxStaticArmRotation)
    out.push_back("the most loaded road wheel's arm turns " + brief(rotation) +
                  " rad under its static load (" + brief(largest_load) +
                  " N x arm_length x cos(arm_angle) / torsion_bar_stiffness), more than " +
                  brief(kMaxStaticArmRotation) +
                  " rad: check suspension.torsion_bar_stiffness and the masses; the linear "
                  "model's results mean little this far from its geometry");
  // The hull lower by more than an arm's length: no trailing arm travels that far.
  if (std::abs(summary.hull_sag) > arm.arm_length)
    out.push_back("static hull sag " + brief(std::abs(summary.hull_sag)) +
                  " m is more than the road-wheel arm's length (suspension.arm_length " +
                  brief(arm.arm_length) +
                  " m), which no trailing arm travels: check suspension.torsion_bar_stiffness "
                  "and the masses");
  return out;
}

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
