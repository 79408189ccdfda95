#include "track_option.h"

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/terrain/terrain_io.h"

namespace tracked_vehicle_dynamics {
namespace tools {

terrain::Terrain loadTrackOption(const std::string& command, const std::string& spec) {
  try {
    return terrain::loadTrack(spec);
  } catch (const InputError& e) {
    throw InputError(command + ": --track: " + e.what());
  }
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
