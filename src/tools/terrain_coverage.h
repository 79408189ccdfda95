// Whether a terrain file covers the vehicle's contacts laterally.
#pragma once

#include <optional>
#include <string>

#include "tracked_vehicle_dynamics/dynamics/road_excitation.h"
#include "tracked_vehicle_dynamics/terrain/terrain.h"

namespace tracked_vehicle_dynamics {
namespace tools {

/// Contacts beyond the terrain's outermost lines take the edge line's heights (terrain.h). For a
/// terrain file (`track` not a built-in name) with more than one line, the warning to print when
/// the contacts reach beyond those lines; a terrain narrower than the vehicle is more often a
/// mistake than a choice. (The built-in oop_waves, 5 m wide and driven 1 m off centre as in the
/// paper, leaves the left outer pad row 5.5 cm beyond its edge: README, time domain.)
std::optional<std::string> terrainCoverageWarning(const std::string& track, const terrain::Terrain& terrain,
                                                  const dynamics::RoadExcitation& road);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
