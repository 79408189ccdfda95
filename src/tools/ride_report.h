// What both methods of `tvd ride` report alike: the points rated and the limit speeds found.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/dynamics/limit_crossing.h"
#include "tracked_vehicle_dynamics/io/json_writer.h"

namespace tracked_vehicle_dynamics {
namespace tools {

/// The points the user asked for (`spec`, comma-separated), or "hull" and every named point when
/// `spec` is empty. Throws InputError for a point the model lacks, one listed twice or an empty
/// name.
std::vector<std::string> choosePoints(const std::string& spec, const std::vector<std::string>& named);

/// The lowest speed at which `metric` reaches `limit` over EVERY speed evaluated so far, not only
/// the sweep's: the bisections of other points and limits add runs, and one of them may already
/// lie above the limit below the sweep's first bracket. `known_speeds()` lists the evaluated
/// speeds in increasing order; `metric(v)` evaluates (or reads the run at) speed v, adding it to
/// the known ones. dynamics::findLimitCrossing runs over the known speeds until its bisection
/// adds none (at most twice: the second pass finds the first pass's final bracket again, no wider
/// than the tolerance); the refinements of both passes are counted.
dynamics::LimitCrossing lowestCrossing(const std::function<std::vector<double>()>& known_speeds,
                                       const std::function<double(double)>& metric, double limit,
                                       double tolerance);

/// {limit, unit, status, speed_kmh, bracket_kmh, refinements} of one crossing.
void writeLimitJson(io::JsonWriter& json, const dynamics::LimitCrossing& c, double limit, const char* unit);

/// "6 W at 14.03 km/h (between 14.00 and 14.06)", "... already at the lowest speed, ...",
/// "... not reached up to ... km/h"; `what` names the limit ("6 W").
std::string describeLimit(const dynamics::LimitCrossing& c, const std::string& what);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
