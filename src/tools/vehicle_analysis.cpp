#include "vehicle_analysis.h"

#include <chrono>
#include <cmath>


namespace tracked_vehicle_dynamics {
namespace tools {

namespace {
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
  a.statics = vehicle::computeStaticSummary(a.vehicle, a.system);
  a.statics_seconds = std::chrono::duration<double>(Clock::now() - t1).count();

  fem::ModalRequest request;
  request.count = count;
  a.modes = fem::solveModes(a.system.stiffness, a.system.mass, request);
  a.classes = vehicle::classifyModes(a.vehicle, a.system, a.modes);
  return a;
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
