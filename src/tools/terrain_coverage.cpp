#include "terrain_coverage.h"

#include <sstream>

#include "tracked_vehicle_dynamics/terrain/tracks.h"

namespace tracked_vehicle_dynamics {
namespace tools {

std::optional<std::string> terrainCoverageWarning(const std::string& track, const terrain::Terrain& terrain,
                                                  const dynamics::RoadExcitation& road) {
  if (terrain::isBuiltInTrack(track) || terrain.lateral().size() < 2) return std::nullopt;
  const double y_min = road.inputY().minCoeff(), y_max = road.inputY().maxCoeff();
  const double t_min = terrain.lateral()(0), t_max = terrain.lateral()(terrain.lateral().size() - 1);
  if (y_min >= t_min - 1e-9 && y_max <= t_max + 1e-9) return std::nullopt;
  std::ostringstream w;
  w << "the contacts span y = " << y_min << " .. " << y_max << " m but the terrain's lines only " << t_min
    << " .. " << t_max << " m; contacts outside take the edge line's heights";
  return w.str();
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
