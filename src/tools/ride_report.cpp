#include "ride_report.h"

#include <algorithm>
#include <iomanip>
#include <limits>
#include <sstream>

#include "point_list.h"
#include "terrain_coverage.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/file_type.h"
#include "vehicle_analysis.h"

namespace tracked_vehicle_dynamics {
namespace tools {

RideModel loadRideModel(const RideOptions& opt, const terrain::Terrain* track,
                        std::vector<std::string>* warnings) {
  const vehicle::Variant variant = vehicle::parseVariant(opt.variant);
  const vehicle::VehicleDescription description = loadVehicle(opt.vehicle_file, warnings);
  std::vector<std::string> named;
  for (const vehicle::NamedPoint& p : description.named_points)
    named.push_back(p.name);
  std::vector<std::string> points =
      choosePoints(opt.points, opt.points_given, named);  // before any work
  if (track)
    refuseDrivingBesideTerrain(opt.track, *track, description, opt.lateral_offset);
  return {std::move(points),
          obtainReducedModel(description, variant, opt.variant_given, "ride", opt.reduced),
          description.name};
}

dynamics::LimitCrossing lowestCrossing(const std::function<std::vector<double>()>& known_speeds,
                                       const std::function<double(double)>& metric, double limit,
                                       double tolerance) {
  int refinements = 0;
  for (;;) {
    const std::vector<double> speeds = known_speeds();
    std::vector<double> values;
    for (double v : speeds)
      values.push_back(metric(v));
    dynamics::LimitCrossing c =
        dynamics::findLimitCrossing(speeds, values, limit, tolerance, metric);
    refinements += c.refinements;
    c.refinements = refinements;
    if (known_speeds().size() == speeds.size())
      return c;
  }
}

void checkMatColumns(const std::string& option, const std::string& file,
                     const std::vector<std::string>& columns) {
  constexpr std::size_t kMaxMatVariableName = 63;
  if (io::lowerExtension(file) != ".mat")
    return;
  for (const std::string& c : columns)
    if (c.size() > kMaxMatVariableName)
      throw InputError("ride: --" + option + " " + file + ": the column '" + c + "' (" +
                       std::to_string(c.size()) +
                       " characters) is longer than a MAT variable "
                       "name may be (63): write .csv, or shorten the point's name");
}

std::vector<std::string> choosePoints(const std::vector<std::string>& specs, bool given,
                                      const std::vector<std::string>& named) {
  std::vector<std::string> known = {"hull"};
  known.insert(known.end(), named.begin(), named.end());
  if (!given)
    return known;
  std::vector<std::string> chosen;
  for (const std::string& name : splitPointList("ride", specs)) {
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::string list;
      for (const std::string& k : known)
        list += (list.empty() ? "" : ", ") + k;
      throw InputError("ride: --points: unknown point '" + name + "' (the vehicle has: " + list +
                       ")");
    }
    if (std::find(chosen.begin(), chosen.end(), name) != chosen.end())
      throw InputError("ride: --points: point '" + name + "' is listed twice");
    chosen.push_back(name);
  }
  return chosen;
}

void writeLimitJson(io::JsonWriter& json, const dynamics::LimitCrossing& c, double limit,
                    const char* unit) {
  json.beginObject()
      .field("limit", limit)
      .field("unit", std::string(unit))
      .field("status", std::string(dynamics::limitStatusName(c.status)))
      // A speed only where the limit is crossed: the lowest (at_lowest_speed) or highest
      // (not_reached) speed run is no crossing speed, and a script reading speed_kmh alone
      // would take it for one (review 137). The bracket keeps the speeds run either way.
      .field("speed_kmh", c.status == dynamics::LimitCrossing::Status::Reached
                              ? c.speed
                              : std::numeric_limits<double>::quiet_NaN())
      .field("bracket_kmh", std::vector<double>{c.lower, c.upper})
      .field("refinements", static_cast<long long>(c.refinements))
      .endObject();
}

std::string describeLimit(const dynamics::LimitCrossing& c, const std::string& what) {
  std::ostringstream out;
  out << std::fixed << std::setprecision(2);
  switch (c.status) {
    case dynamics::LimitCrossing::Status::Reached:
      out << what << " at " << c.speed << " km/h (between " << c.lower << " and " << c.upper << ")";
      break;
    case dynamics::LimitCrossing::Status::AtLowest:
      out << what << " already at the lowest speed, " << c.speed << " km/h";
      break;
    case dynamics::LimitCrossing::Status::NotReached:
      out << what << " not reached up to " << c.speed << " km/h";
      break;
  }
  return out.str();
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
