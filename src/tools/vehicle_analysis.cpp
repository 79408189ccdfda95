#include "vehicle_analysis.h"

#include <chrono>
#include <cmath>

#include "tracked_vehicle_dynamics/fem/static_solver.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {
constexpr double kRadToDeg = 57.29577951308232;
using Clock = std::chrono::steady_clock;
}  // namespace

VehicleAnalysis analyseVehicle(const vehicle::VehicleDescription& description,
                               vehicle::Variant variant, int count) {
  VehicleAnalysis a;
  const auto t0 = Clock::now();
  a.vehicle = vehicle::buildVehicleModel(description, variant);
  a.system = fem::assemble(a.vehicle.model);
  a.build_seconds = std::chrono::duration<double>(Clock::now() - t0).count();

  const auto t1 = Clock::now();
  const fem::StaticResult st = fem::solveStatic(a.system, a.system.gravity_load);
  const NodeId hull = a.vehicle.layout.hull;
  a.statics.hull_sag = fem::physicalDisplacement(a.system, st.displacement, hull, 2);
  a.statics.hull_pitch_deg = fem::physicalDisplacement(a.system, st.displacement, hull, 4) * kRadToDeg;
  // The vertical force of ground spring q on the structure is -K_u,q^T x (spring_element.h);
  // in equilibrium their sum balances the weight.
  const Vector spring_forces = a.system.input_stiffness.transpose() * st.displacement;
  a.statics.ground_reaction = -spring_forces.sum();
  a.statics.weight = a.vehicle.model.totalMass() * std::abs(a.vehicle.model.gravity.z());
  a.statics.seconds = std::chrono::duration<double>(Clock::now() - t1).count();

  fem::ModalRequest request;
  request.count = count;
  a.modes = fem::solveModes(a.system.stiffness, a.system.mass, request);
  a.classes = vehicle::classifyModes(a.vehicle, a.system, a.modes);
  return a;
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
