// Whether a terrain file covers the vehicle's contacts laterally.
#pragma once

#include <optional>
#include <string>

#include "tracked_vehicle_dynamics/dynamics/road_excitation.h"
#include "tracked_vehicle_dynamics/terrain/terrain.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"

namespace tracked_vehicle_dynamics {
namespace tools {

/// Contacts beyond the terrain's outermost lines take the edge line's heights (terrain.h). For a
/// terrain with more than one line, the warning to print when contacts reach beyond those lines
/// (how many, and how far): for a terrain file always, a terrain narrower than the vehicle being
/// more often a mistake than a choice; for a built-in track when `lateral_offset` [m] (the
/// user's --lateral-offset) is not 0 (the built-in oop_waves, 5 m wide and driven 1 m off centre
/// as in the paper, leaves the left outer pad row 5.5 cm beyond its edge: README, time domain).
/// Throws InputError naming `track` when every contact lies beyond the same edge (beside the
/// terrain).
std::optional<std::string> terrainCoverageWarning(const std::string& track,
                                                  const terrain::Terrain& terrain,
                                                  const dynamics::RoadExcitation& road,
                                                  double lateral_offset);

/// The refusal of terrainCoverageWarning, made from the description before the model is obtained
/// (a reduction may take seconds): the ground contacts of both variants lie on the pad rows
/// y = ±(b/2 ± e) (b = running_gear.track_centre_distance, e = track_assembly.pad_lateral_offset),
/// so when every row, moved by `lateral_offset` [m], lies beyond the same edge line, so does every
/// contact. Throws InputError naming `track`; returns otherwise.
void refuseDrivingBesideTerrain(const std::string& track, const terrain::Terrain& terrain,
                                const vehicle::VehicleDescription& description,
                                double lateral_offset);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
