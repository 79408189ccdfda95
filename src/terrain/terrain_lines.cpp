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
    if (!std::isfinite(lateral(q)) || find(lateral(q)) != nullptr)
      continue;
    Line line;
    line.y = lateral(q);
    line.heights = terrain.profile(line.y);
    if (x.size() > 1)
      line.slopes = (line.heights.tail(x.size() - 1) - line.heights.head(x.size() - 1))
                        .cwiseQuotient(x.tail(x.size() - 1) - x.head(x.size() - 1));
    line.profile = static_cast<int>(lines_.size());
    for (const Line& other : lines_)
      if (other.heights.size() == line.heights.size() &&
          std::equal(other.heights.data(), other.heights.data() + other.heights.size(),
                     line.heights.data())) {
        line.profile = other.profile;
        break;
      }
    // Flat runs, from the last cell back: cell i is flat when h_{i+1} == h_i (slope exactly 0).
    const Eigen::Index cells = line.slopes.size();
    line.flat_end.assign(static_cast<std::size_t>(cells), cells);
    for (Eigen::Index i = cells - 2; i >= 0; --i)
      line.flat_end[static_cast<std::size_t>(i)] =
          line.slopes(i + 1) == 0.0 ? line.flat_end[static_cast<std::size_t>(i + 1)] : i + 1;
    lines_.push_back(std::move(line));
  }
}

int TerrainLines::profileOf(double y) const {
  const Line* line = find(y);
  return line == nullptr ? -1 : line->profile;
}

double TerrainLines::sampleRun(int profile, double x, double& h, double& dhdx) const {
  const Line& line = lines_.at(static_cast<std::size_t>(profile));
  constexpr double kForever = std::numeric_limits<double>::infinity();
  // The branches of heightAndSlope(), each with the end of the run it is on: h_0 and slope 0
  // before x_0, the last height and slope 0 from x_end on.
  if (std::isnan(x)) {
    heightAndSlope(x, line.y, h, dhdx);
    return x;
  }
  if (x <= x0_ || x >= x_end_) {
    h = x <= x0_ ? line.heights(0) : line.heights(line.heights.size() - 1);
    dhdx = x == x0_ && line.slopes.size() != 0 ? line.slopes(0) : 0.0;
    if (x >= x_end_ || line.slopes.size() == 0)
      return kForever;
    if (x < x0_ && line.slopes(0) != 0.0)
      return x0_;
    if (x == x0_ && dhdx != 0.0)
      return x;
  } else {
    const Eigen::Index i = cell(x);
    dhdx = line.slopes(i);
    h = line.heights(i) + (x - terrain_.stations()(i)) * dhdx;
    if (dhdx != 0.0)
      return x;
    const Eigen::Index j = line.flat_end[static_cast<std::size_t>(i)];
    return j >= line.slopes.size() ? kForever : terrain_.stations()(j);
  }
  // x <= x_0 on a profile whose first cell is flat.
  const Eigen::Index j = line.flat_end[0];
  return j >= line.slopes.size() ? kForever : terrain_.stations()(j);
}

const TerrainLines::Line* TerrainLines::find(double y) const {
  for (const Line& line : lines_)
    if (line.y == y)
      return &line;
  return nullptr;
}

Eigen::Index TerrainLines::cell(double x) const {
  const Vector& stations = terrain_.stations();
  const Eigen::Index last = stations.size() - 2;
  Eigen::Index i = 0;
  if (inverse_dx_ > 0) {
    i = std::clamp<Eigen::Index>(static_cast<Eigen::Index>((x - x0_) * inverse_dx_), 0, last);
    // (x - x0) / dx may round one cell off; the grid values decide, as in Terrain.
    if (i < last && x >= stations(i + 1))
      ++i;
    if (i > 0 && x < stations(i))
      --i;
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
