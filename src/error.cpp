#include "tracked_vehicle_dynamics/error.h"

#include <cstdio>
#include <cstdlib>

namespace tracked_vehicle_dynamics {

std::string brief(double value) {
  // Six digits, unless the value is exactly one of up to ten: a value the user typed (200.0001
  // against a bound of 200) must not be shown as the bound it breaks, while a computed value
  // (0.1 + 0.2), which no short decimal gives exactly, keeps its six.
  char buffer[64];
  for (int digits = 6; digits <= 10; ++digits) {
    std::snprintf(buffer, sizeof(buffer), "%.*g", digits, value);
    if (std::strtod(buffer, nullptr) == value)
      return buffer;
  }
  std::snprintf(buffer, sizeof(buffer), "%.6g", value);
  return buffer;
}

std::string beyond(double value, double bound) {
  const std::string shown_bound = brief(bound);
  std::string shown = brief(value);
  char buffer[64];
  for (int digits = 7; shown == shown_bound && value != bound && digits <= 17; ++digits) {
    std::snprintf(buffer, sizeof(buffer), "%.*g", digits, value);
    shown = buffer;
  }
  return shown;
}

}  // namespace tracked_vehicle_dynamics
