// A command's warnings: kept for its JSON (and text) output, and said on stderr as they arise
// ("tvd: warning: ..."), so that a run that fails later has still said them.
#pragma once

#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace tracked_vehicle_dynamics {
namespace tools {

/// Keeps `warning` in `warnings` and prints it; an empty warning is none.
inline void warn(std::vector<std::string>* warnings, const std::string& warning) {
  if (warning.empty())
    return;
  warnings->push_back(warning);
  std::cerr << "tvd: warning: " << warning << "\n";
}

/// The same for a check that may find nothing to say.
inline void warn(std::vector<std::string>* warnings, const std::optional<std::string>& warning) {
  if (warning)
    warn(warnings, *warning);
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
