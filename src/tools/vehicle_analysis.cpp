#include "vehicle_analysis.h"

#include <chrono>
#include <cmath>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/vehicle/track_tension.h"
#include "tracked_vehicle_dynamics/vehicle/wheel_rate_estimate.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {
using Clock = std::chrono::steady_clock;
}  // namespace

vehicle::VehicleDescription loadVehicle(const std::string& file,
                                        std::vector<std::string>* warnings) {
  vehicle::VehicleDescription description = vehicle::loadVehicleDescription(file);
  for (const std::string& w : vehicle::descriptionWarnings(description)) {
    std::cerr << "tvd: warning: " << file << ": " << w << "\n";
    if (warnings)
      warnings->push_back(file + ": " + w);
  }
  return description;
}

VehicleAnalysis analyseVehicle(const vehicle::VehicleDescription& description,
                               vehicle::Variant variant, int count) {
  VehicleAnalysis a;
  const auto t0 = Clock::now();
  a.vehicle = vehicle::buildVehicleModel(description, variant);
  a.system = fem::assemble(a.vehicle.model);
  a.build_seconds = std::chrono::duration<double>(Clock::now() - t0).count();

  const auto t1 = Clock::now();
  a.statics = vehicle::computeStaticSummary(a.vehicle, a.system);
  std::vector<std::string> warnings = vehicle::staticWarnings(a.statics, description);
  for (std::string& w :
       vehicle::restWarnings(a.statics.hull_sag, a.statics.hull_pitch, description, variant))
    warnings.push_back(std::move(w));
  for (const std::string& w : warnings)
    std::cerr << "tvd: warning: " << w << "\n";
  a.statics_seconds = std::chrono::duration<double>(Clock::now() - t1).count();

  fem::ModalRequest request;
  request.count = count;
  a.modes = fem::solveModes(a.system.stiffness, a.system.mass, request);
  const std::string missed = fem::missedModesWarning(a.modes);
  if (!missed.empty())
    std::cerr << "tvd: warning: " << missed << "\n";
  // A vehicle's only compressive pre-load is the hull's, which a track tension far beyond its
  // suspension's hold turns into a pitch instability.
  const std::string unstable = fem::unstableModesWarning(a.modes);
  if (!unstable.empty()) {
    const double tension = vehicle::modelTrackTension(description, variant);
    std::cerr << "tvd: warning: " << unstable
              << (tension > 0.0 ? "; here track_assembly.static_tension (" + brief(tension) + " N)"
                                : std::string())
              << "\n";
  }
  a.classes = vehicle::classifyModes(a.vehicle, a.system, a.modes);
  const std::string stiff =
      vehicle::bounceWarning(description, variant, a.classes, a.modes.frequencies_hz);
  if (!stiff.empty())
    std::cerr << "tvd: warning: " << stiff << "\n";
  return a;
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
