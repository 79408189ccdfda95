// File types by their extension, the way users name files ("Road.CSV", "run.MAT").
#pragma once

#include <string>

namespace tracked_vehicle_dynamics {
namespace io {

/// The extension of `path` in lower case, with its dot: ".csv" for "Road.CSV", "" for "road".
std::string lowerExtension(const std::string& path);

}  // namespace io
}  // namespace tracked_vehicle_dynamics
