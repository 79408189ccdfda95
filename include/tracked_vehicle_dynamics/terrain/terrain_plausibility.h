// Whether a terrain looks like ground a tracked vehicle drives on, or like a unit mistake
// (heights in millimetres read as metres). Such terrain still runs: the linear model takes any
// heights, but its small-angle kinematics and bonded ground say nothing true there, so the user
// is told.
#pragma once

#include <optional>
#include <string>

#include "tracked_vehicle_dynamics/terrain/terrain.h"

namespace tracked_vehicle_dynamics {
namespace terrain {

/// Steepest |dh/dx| taken as ground [m/m]: 2 (63 degrees). The paper's steepest test track,
/// oop_waves (0.6 m deep at 1.2 m wavelength, smoothed over 0.2 m), reaches 1.5; a 10 m bump
/// over a few metres, or a 0.15 m wave written in mm, reaches far beyond.
constexpr double kSteepestPlausibleSlope = 2.0;

/// The steepest slope of the grid: |h(x_{i+1}) - h(x_i)| / (x_{i+1} - x_i) over every line.
struct SteepestSlope {
  double slope = 0.0;    ///< [m/m], >= 0
  double station = 0.0;  ///< x_i of the interval [m]
  double lateral = 0.0;  ///< the line's y [m]
};
SteepestSlope steepestSlope(const Terrain& terrain);

/// The warning to print when the steepest slope exceeds kSteepestPlausibleSlope, naming `name`
/// (the track or file), the slope, its angle and where; nothing otherwise.
std::optional<std::string> slopeWarning(const std::string& name, const Terrain& terrain);

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
