#include "terrain_coverage.h"

#include <algorithm>
#include <sstream>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/terrain/tracks.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {

constexpr double kEdgeTolerance = 1e-9;  // [m]

// Contacts at lateral positions y beyond the lines [t_min, t_max], and how far the farthest is.
struct Overhang {
  Eigen::Index outside = 0, left = 0, right = 0;
  double farthest = 0.0;  // [m] beyond the nearer edge line
};

Overhang overhang(const Vector& y, double t_min, double t_max) {
  Overhang o;
  for (Eigen::Index i = 0; i < y.size(); ++i) {
    const double beyond = std::max(t_min - y(i), y(i) - t_max);
    if (beyond > kEdgeTolerance) {
      ++o.outside;
      (y(i) > t_max ? o.left : o.right) += 1;
      o.farthest = std::max(o.farthest, beyond);
    }
  }
  return o;
}

}  // namespace

std::optional<std::string> terrainCoverageWarning(const std::string& track,
                                                  const terrain::Terrain& terrain,
                                                  const dynamics::RoadExcitation& road,
                                                  double lateral_offset) {
  const Vector& y = road.inputY();
  if (terrain.lateral().size() < 2 || y.size() == 0)  // (no input: nothing to cover)
    return std::nullopt;
  const double y_min = y.minCoeff(), y_max = y.maxCoeff();
  const double t_min = terrain.lateral()(0),
               t_max = terrain.lateral()(terrain.lateral().size() - 1);
  const auto [outside, left, right, farthest] = overhang(y, t_min, t_max);
  if (outside == 0)
    return std::nullopt;
  std::ostringstream where;
  where << "the contacts span y = " << y_min << " .. " << y_max
        << " m but the terrain's lines only " << t_min << " .. " << t_max << " m";
  // Every contact beyond the same edge line: the run would drive beside the terrain, not over it
  // (a terrain narrower than the vehicle but under it, each side reading its own edge, is
  // warned about below).
  if (left == y.size() || right == y.size())
    throw InputError(
        track + ": every contact (" + std::to_string(outside) + ") lies off the terrain" +
        (lateral_offset != 0.0 ? " at --lateral-offset " + brief(lateral_offset) + " m" : "") +
        ": " + where.str());
  // The built-in oop_waves, driven at its own 1 m offset, leaves the left outer pad row 5.5 cm
  // beyond its edge as in the paper: on a built-in only what the user's offset adds (more
  // contacts outside, or farther) is reported.
  if (terrain::isBuiltInTrack(track)) {
    const Overhang own = overhang(y.array() - lateral_offset, t_min, t_max);
    if (outside <= own.outside && farthest <= own.farthest + kEdgeTolerance)
      return std::nullopt;
  }
  std::ostringstream w;
  w << where.str() << ": " << outside << " of " << y.size() << " contacts lie outside, up to "
    << farthest << " m beyond"
    << (lateral_offset != 0.0 ? " (--lateral-offset " + brief(lateral_offset) + " m)" : "")
    << "; contacts outside take the edge line's heights";
  return w.str();
}

void refuseDrivingBesideTerrain(const std::string& track, const terrain::Terrain& terrain,
                                const vehicle::VehicleDescription& description,
                                double lateral_offset) {
  if (terrain.lateral().size() < 2)
    return;
  const double half = 0.5 * description.running_gear.track_centre_distance;
  const double e = description.track_assembly.pad_lateral_offset;
  Vector rows(4);
  rows << half + e, half - e, -half + e, -half - e;
  rows.array() += lateral_offset;
  const double t_min = terrain.lateral()(0),
               t_max = terrain.lateral()(terrain.lateral().size() - 1);
  const Overhang o = overhang(rows, t_min, t_max);
  if (o.left < rows.size() && o.right < rows.size())
    return;
  std::ostringstream m;
  m << track << ": every contact (the 4 pad rows) lies off the terrain"
    << (lateral_offset != 0.0 ? " at --lateral-offset " + brief(lateral_offset) + " m" : "")
    << ": the pad rows lie at y = " << rows.minCoeff() << " .. " << rows.maxCoeff()
    << " m but the terrain's lines only " << t_min << " .. " << t_max << " m";
  throw InputError(m.str());
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
