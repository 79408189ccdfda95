// A command's --track: a built-in track or a terrain file, loaded with errors that name the
// command and the option, as the terrain command's do ("simulate: --track: ...").
#pragma once

#include <string>

#include "tracked_vehicle_dynamics/terrain/terrain.h"

namespace tracked_vehicle_dynamics {
namespace tools {

/// terrain::loadTrack(spec); an InputError is re-thrown prefixed "<command>: --track: ".
terrain::Terrain loadTrackOption(const std::string& command, const std::string& spec);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
