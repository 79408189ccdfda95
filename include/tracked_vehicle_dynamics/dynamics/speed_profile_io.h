// Speed profile files (speed_profile.h). CSV: a header `time_s,speed_kmh` (or `time_s,speed_m_s`),
// then one row per sample; blank lines and lines starting with '#' are skipped:
//   time_s,speed_kmh
//   0,50
//   2,50
//   4,10
#pragma once

#include <string>

#include "tracked_vehicle_dynamics/dynamics/speed_profile.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// Reads a CSV speed profile. Throws InputError naming the file, row and column.
SpeedProfile loadSpeedProfile(const std::string& path);

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
