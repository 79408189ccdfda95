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
#include "warning_list.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {
using Clock = std::chrono::steady_clock;
}  // namespace

vehicle::VehicleDescription loadVehicle(const std::string& file,
                                        std::vector<std::string>* warnings) {
  vehicle::VehicleDescription description = vehicle::loadVehicleDescription(file);
  std::vector<std::string> unkept;
  for (const std::string& w : vehicle::descriptionWarnings(description))
    warn(warnings ? warnings : &unkept, file + ": " + w);
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
  for (const std::string& w : vehicle::staticWarnings(a.statics, description))
    warn(&a.warnings, w);
  for (const std::string& w :
       vehicle::restWarnings(a.statics.hull_sag, a.statics.hull_pitch, description, variant))
    warn(&a.warnings, w);
  a.statics_seconds = std::chrono::duration<double>(Clock::now() - t1).count();

  fem::ModalRequest request;
  request.count = count;
  a.modes = fem::solveModes(a.system.stiffness, a.system.mass, request);
  warn(&a.warnings, fem::missedModesWarning(a.modes));
  // A vehicle's only compressive pre-load is the hull's, which a track tension far beyond its
  // suspension's hold turns into a pitch instability.
  const std::string unstable = fem::unstableModesWarning(a.modes);
  if (!unstable.empty()) {
    const double tension = vehicle::modelTrackTension(description, variant);
    warn(&a.warnings, unstable + (tension > 0.0 ? "; here track_assembly.static_tension (" +
                                                      brief(tension) + " N)"
                                                : std::string()));
  }
  a.classes = vehicle::classifyModes(a.vehicle, a.system, a.modes);
  warn(&a.warnings,
       vehicle::bounceWarning(description, variant, a.classes, a.modes.frequencies_hz));
  return a;
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
