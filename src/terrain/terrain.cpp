#include "tracked_vehicle_dynamics/terrain/terrain.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/terrain/terrain_io.h"

namespace tracked_vehicle_dynamics {
namespace terrain {
namespace {

// Stations closer to equal spacing than this (relative) use the O(1) cell lookup.
constexpr double kUniformTolerance = 1e-9;

void checkIncreasing(const Vector& values, const std::string& what, const std::string& name) {
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values(i))) {
      throw InputError("terrain '" + name + "': " + what + " " + std::to_string(i) + " is " +
                       brief(values(i)) + ", not a finite number");
    }
    if (!(std::abs(values(i)) <= kMaxTerrainCoordinate)) {
      throw InputError("terrain '" + name + "': " + what + " " + std::to_string(i) + " is " +
                       brief(values(i)) + " m, beyond +-" + brief(kMaxTerrainCoordinate) +
                       " m (positions are in m: mm, or a datum far away?)");
    }
    if (i > 0 && values(i) <= values(i - 1)) {
      throw InputError("terrain '" + name + "': " + what + " " + std::to_string(i) + " (" +
                       brief(values(i)) + " m) is not greater than " + what + " " +
                       std::to_string(i - 1) + " (" + brief(values(i - 1)) +
                       " m); they must be strictly increasing");
    }
    if (i > 0 && closerThanMinSpacing(values(i - 1), values(i))) {
      throw InputError("terrain '" + name + "': " + what + " " + std::to_string(i) + " (" +
                       brief(values(i)) + " m) is " + brief(values(i) - values(i - 1)) +
                       " m from " + what + " " + std::to_string(i - 1) + "; at least " +
                       brief(kMinTerrainSpacing) + " m apart");
    }
  }
}

}  // namespace

Terrain::Terrain(Vector stations, Vector lateral, Matrix heights, std::string name)
    : stations_(std::move(stations)),
      lateral_(std::move(lateral)),
      heights_(std::move(heights)),
      name_(std::move(name)) {
  if (stations_.size() == 0)
    throw InputError("terrain '" + name_ + "': no stations");
  if (lateral_.size() == 0)
    throw InputError("terrain '" + name_ + "': no lateral lines");
  if (heights_.rows() != lateral_.size() || heights_.cols() != stations_.size()) {
    throw InputError("terrain '" + name_ + "': heights are " + std::to_string(heights_.rows()) +
                     " x " + std::to_string(heights_.cols()) + ", expected " +
                     std::to_string(lateral_.size()) + " lateral lines x " +
                     std::to_string(stations_.size()) + " stations");
  }
  checkIncreasing(stations_, "station", name_);
  checkIncreasing(lateral_, "lateral line", name_);
  for (Eigen::Index j = 0; j < heights_.rows(); ++j) {
    for (Eigen::Index i = 0; i < heights_.cols(); ++i) {
      if (!(std::abs(heights_(j, i)) <= kMaxTerrainHeight)) {
        throw InputError("terrain '" + name_ + "': height at lateral line " + std::to_string(j) +
                         " (y = " + brief(lateral_(j)) + " m), station " + std::to_string(i) +
                         " (x = " + brief(stations_(i)) + " m) is " + brief(heights_(j, i)) +
                         " m; heights must be finite and within +-10000 m");
      }
    }
  }
  const Eigen::Index n = stations_.size();
  flat_end_.resize(static_cast<std::size_t>(n));
  flat_end_[static_cast<std::size_t>(n - 1)] = n - 1;
  for (Eigen::Index i = n - 2; i >= 0; --i) {
    const auto k = static_cast<std::size_t>(i);
    flat_end_[k] = heights_.col(i) == heights_.col(i + 1) ? flat_end_[k + 1] : i;
  }
  if (n > 1) {
    spacing_ = (stations_(n - 1) - stations_(0)) / static_cast<double>(n - 1);
    uniform_ = true;
    for (Eigen::Index i = 1; i < n && uniform_; ++i) {
      const double expected = stations_(0) + static_cast<double>(i) * spacing_;
      uniform_ = std::abs(stations_(i) - expected) <= kUniformTolerance * spacing_ * n;
    }
  }
}

Eigen::Index Terrain::stationCell(double x) const {
  const Eigen::Index last_cell = stations_.size() - 2;
  Eigen::Index i = 0;
  if (uniform_) {
    // Truncation is the floor for x >= x0, and below x0 the clamp gives cell 0 all the same.
    i = static_cast<Eigen::Index>((x - stations_(0)) / spacing_);
    i = std::clamp<Eigen::Index>(i, 0, last_cell);
    // Rounding of (x - x0) / dx may land one cell off; the grid values decide.
    if (i < last_cell && x >= stations_(i + 1))
      ++i;
    if (i > 0 && x < stations_(i))
      --i;
  } else {
    const double* begin = stations_.data();
    const double* end = begin + stations_.size();
    i = static_cast<Eigen::Index>(std::upper_bound(begin, end, x) - begin) - 1;
    i = std::clamp<Eigen::Index>(i, 0, last_cell);
  }
  return i;
}

void Terrain::lateralCell(double y, Eigen::Index* j, double* w) const {
  const Eigen::Index n = lateral_.size();
  if (n == 1 || y <= lateral_(0)) {
    *j = 0;
    *w = 0.0;
    return;
  }
  if (y >= lateral_(n - 1)) {
    *j = n - 2;
    *w = 1.0;
    return;
  }
  const double* begin = lateral_.data();
  *j = static_cast<Eigen::Index>(std::upper_bound(begin, begin + n, y) - begin) - 1;
  *w = (y - lateral_(*j)) / (lateral_(*j + 1) - lateral_(*j));
}

Terrain::LateralCell Terrain::lateralCellOf(double y) const {
  LateralCell cell;
  lateralCell(y, &cell.line, &cell.weight);
  return cell;
}

double Terrain::height(double x, double y) const {
  if (std::isnan(y))
    return std::numeric_limits<double>::quiet_NaN();
  return height(x, lateralCellOf(y));
}

double Terrain::height(double x, const LateralCell& cell) const {
  if (std::isnan(x))
    return std::numeric_limits<double>::quiet_NaN();
  return height(stationWeightOf(x), cell);
}

Terrain::StationWeight Terrain::stationWeightOf(double x) const {
  StationWeight station;
  const Eigen::Index n = stations_.size();
  // The first station is inside (cell 0, weight 0: its height exactly, and slope() the cell
  // ahead's, as slope(x, y)); a one-sample grid has no cell.
  if (x < stations_(0) || (n == 1 && x == stations_(0))) {
    station.edge = -1;
  } else if (x >= stations_(n - 1)) {
    station.edge = 1;
  } else {
    const Eigen::Index i = stationCell(x);
    station.cell = i;
    station.weight = (x - stations_(i)) / (stations_(i + 1) - stations_(i));
  }
  return station;
}

double Terrain::slope(double x, double y) const {
  if (std::isnan(x) || std::isnan(y))
    return std::numeric_limits<double>::quiet_NaN();
  const Eigen::Index n = stations_.size();
  if (n == 1 || x < stations_(0) || x >= stations_(n - 1))
    return 0.0;
  return cellSlope(stationCell(x), lateralCellOf(y));
}

Vector Terrain::profile(double y) const {
  Eigen::Index j = 0;
  double wy = 0.0;
  lateralCell(y, &j, &wy);
  if (wy == 0.0)
    return heights_.row(j).transpose();
  // blend() over the row: exact where the two lines agree.
  const auto a = heights_.row(j).array(), b = heights_.row(j + 1).array();
  return (a == b).select(a, (1.0 - wy) * a + wy * b).matrix().transpose();
}

void Terrain::saveCsv(const std::string& path) const {
  saveTerrainCsv(*this, path);
}

void Terrain::saveYaml(const std::string& path) const {
  saveTerrainYaml(*this, path);
}

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
