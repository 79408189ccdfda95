// Shared steps of the vehicle subcommands: build a variant, assemble, statics and modes.
#pragma once

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/vehicle/mode_classification.h"
#include "tracked_vehicle_dynamics/vehicle/static_summary.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace tools {

struct VehicleAnalysis {
  vehicle::VehicleModel vehicle;
  fem::System system;
  fem::ModalBasis modes;
  std::vector<vehicle::ModeClass> classes;
  vehicle::StaticSummary statics;  ///< equilibrium under gravity
  double statics_seconds = 0.0;
  double build_seconds = 0.0;  ///< vehicle build + assembly [s]
  /// What the statics and modes gave to warn of (said on stderr as they arose).
  std::vector<std::string> warnings;
};

/// Loads a vehicle description and prints its physical warnings (vehicle::descriptionWarnings)
/// on stderr as "tvd: warning: FILE: ..."; appends them to `warnings` when given.
vehicle::VehicleDescription loadVehicle(const std::string& file,
                                        std::vector<std::string>* warnings = nullptr);

/// Builds, assembles, solves statics and the lowest `count` modes, and classifies them; its
/// warnings are printed on stderr and kept in VehicleAnalysis::warnings.
VehicleAnalysis analyseVehicle(const vehicle::VehicleDescription& description,
                               vehicle::Variant variant, int count);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
