#include "tracked_vehicle_dynamics/error.h"

#include <cstdio>

namespace tracked_vehicle_dynamics {

std::string brief(double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof(buffer), "%.6g", value);
  return buffer;
}

}  // namespace tracked_vehicle_dynamics
