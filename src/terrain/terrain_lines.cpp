#include "tracked_vehicle_dynamics/terrain/terrain_lines.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tracked_vehicle_dynamics {
namespace terrain {

TerrainLines::TerrainLines(const Terrain& terrain, const Vector& lateral) : terrain_(terrain) {
  const Vector& x = terrain.stations();
  x0_ = x(0);
  x_end_ = x(x.size() - 1);
  inverse_dx_ = terrain.isUniform() && terrain.spacing() > 0 ? 1.0 / terrain.spacing() : 0.0;
  for (Eigen::Index q = 0; q < lateral.size(); ++q) {
    if (!std::isfinite(lateral(q)) || find(lateral(q)) != nullptr) continue;
    Line line;
    line.y = lateral(q);
    line.heights = terrain.profile(line.y);
    if (x.size() > 1)
      line.slopes = (line.heights.tail(x.size() - 1) - line.heights.head(x.size() - 1)).cwiseQuotient(
          x.tail(x.size() - 1) - x.head(x.size() - 1));
    lines_.push_back(std::move(line));
  }
}

const TerrainLines::Line* TerrainLines::find(double y) const {
  for (const Line& line : lines_)
    if (line.y == y) return &line;
  return nullptr;
}

Eigen::Index TerrainLines::cell(double x) const {
  const Vector& stations = terrain_.stations();
  const Eigen::Index last = stations.size() - 2;
  Eigen::Index i = 0;
  if (inverse_dx_ > 0) {
    i = std::clamp<Eigen::Index>(static_cast<Eigen::Index>((x - x0_) * inverse_dx_), 0, last);
    // (x - x0) / dx may round one cell off; the grid values decide, as in Terrain.
    if (i < last && x >= stations(i + 1)) ++i;
    if (i > 0 && x < stations(i)) --i;
  } else {
    const double* begin = stations.data();
    i = static_cast<Eigen::Index>(std::upper_bound(begin, begin + stations.size(), x) - begin) - 1;
    i = std::clamp<Eigen::Index>(i, 0, last);
  }
  return i;
}

double TerrainLines::height(double x, double y) const {
  double h = 0.0, dhdx = 0.0;
  heightAndSlope(x, y, h, dhdx);
  return h;
}

double TerrainLines::slope(double x, double y) const {
  double h = 0.0, dhdx = 0.0;
  heightAndSlope(x, y, h, dhdx);
  return dhdx;
}

void TerrainLines::heightAndSlope(double x, double y, double& h, double& dhdx) const {
  const Line* line = find(y);
  if (line == nullptr || std::isnan(x)) {
    h = terrain_.height(x, y);
    dhdx = terrain_.slope(x, y);
    return;
  }
  if (x <= x0_ || x >= x_end_) {
    h = x <= x0_ ? line->heights(0) : line->heights(line->heights.size() - 1);
    dhdx = x == x0_ && line->slopes.size() != 0 ? line->slopes(0) : 0.0;
    return;
  }
  const Eigen::Index i = cell(x);
  dhdx = line->slopes(i);
  h = line->heights(i) + (x - terrain_.stations()(i)) * dhdx;
}

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
