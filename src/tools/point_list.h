// The --points option of frf and ride: one parse, one message for an empty name.
#pragma once

#include <string>
#include <vector>

namespace tracked_vehicle_dynamics {
namespace tools {

/// The names of `specs` (each comma-separated; the option may be repeated), in order. Throws
/// InputError "<command>: --points: an empty name in '<spec>'" for an empty spec, an empty entry
/// ("a,,b") or a leading or trailing comma: each would silently mean "every point" or be dropped.
std::vector<std::string> splitPointList(const std::string& command,
                                        const std::vector<std::string>& specs);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
