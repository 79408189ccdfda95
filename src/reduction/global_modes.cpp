#include "tracked_vehicle_dynamics/reduction/global_modes.h"

#include <algorithm>
#include <string>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/reduction/mac.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

std::vector<bool> globalModes(const std::vector<vehicle::ModeClass>& classes,
                              const Vector& frequencies_hz) {
  if (static_cast<Eigen::Index>(classes.size()) != frequencies_hz.size())
    throw InputError("globalModes: " + std::to_string(classes.size()) + " mode classes for " +
                     std::to_string(frequencies_hz.size()) + " frequencies");
  std::vector<bool> global(classes.size(), false);
  for (const auto& [first, end] : degenerateGroups(frequencies_hz)) {
    const bool any = std::any_of(classes.begin() + first, classes.begin() + end,
                                 [](const vehicle::ModeClass& c) {
                                   return c.hull_share + c.wheel_share >= kGlobalEnergyShare;
                                 });
    std::fill(global.begin() + first, global.begin() + end, any);
  }
  return global;
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
