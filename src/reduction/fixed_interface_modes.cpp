#include "tracked_vehicle_dynamics/reduction/fixed_interface_modes.h"

#include <string>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

FixedInterfaceModes fixedInterfaceModes(const ModeSelection& selection,
                                        const FixedInterfaceOptions& options) {
  FixedInterfaceModes request;
  switch (options.rule) {
    case FixedInterfaceRule::SameCount:
      if (options.extra_modes < 0)
        throw InputError("fixedInterfaceModes: extra_modes " + std::to_string(options.extra_modes) +
                         " is negative");
      request.count = selection.count() + options.extra_modes;
      break;
    case FixedInterfaceRule::UpToFrequency:
      if (!(options.frequency_margin >= 1.0))
        throw InputError("fixedInterfaceModes: frequency_margin " +
                         std::to_string(options.frequency_margin) + " is below 1");
      if (options.max_count <= 0)
        throw InputError("fixedInterfaceModes: max_count " + std::to_string(options.max_count) +
                         " is not positive");
      if (!(selection.highestFrequencyHz() > 0.0))
        throw InputError("fixedInterfaceModes: UpToFrequency needs a selected mode above 0 Hz");
      request.count = options.max_count;
      request.max_frequency_hz = options.frequency_margin * selection.highestFrequencyHz();
      break;
  }
  return request;
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
