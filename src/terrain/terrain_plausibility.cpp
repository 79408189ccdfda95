#include "tracked_vehicle_dynamics/terrain/terrain_plausibility.h"

#include <cmath>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace terrain {

SteepestSlope steepestSlope(const Terrain& terrain) {
  SteepestSlope steepest;
  const Vector& x = terrain.stations();
  const Matrix& h = terrain.heights();
  for (Eigen::Index j = 0; j < h.rows(); ++j)
    for (Eigen::Index i = 0; i + 1 < x.size(); ++i) {
      const double slope = std::abs(h(j, i + 1) - h(j, i)) / (x(i + 1) - x(i));
      if (slope > steepest.slope)
        steepest = {slope, x(i), terrain.lateral()(j)};
    }
  return steepest;
}

std::optional<std::string> slopeWarning(const std::string& name, const Terrain& terrain) {
  const SteepestSlope s = steepestSlope(terrain);
  if (!(s.slope > kSteepestPlausibleSlope))
    return std::nullopt;
  const double degrees = std::atan(s.slope) * 180.0 / M_PI;
  return name + ": slopes up to " + brief(s.slope) + " m/m (" +
         brief(std::round(degrees * 10) / 10) + " deg) at x = " + brief(s.station) +
         " m, y = " + brief(s.lateral) +
         " m, steeper than ground a tracked vehicle drives on (the paper's steepest test track, "
         "oop_waves, reaches 1.5 m/m): heights in mm read as m? The linear model runs it, but its "
         "small-angle kinematics and bonded ground do not hold there";
}

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
