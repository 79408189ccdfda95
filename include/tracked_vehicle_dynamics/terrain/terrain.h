// A terrain height field h(x, y) on a grid: x is the station along the vehicle path [m]
// (strictly increasing, usually uniform), y the lateral position [m] (y left, REP-103).
//
// Between grid points h is bilinear. Outside the grid it is held constant: in x this gives a flat
// run-in and run-out at the edge heights, in y the nearest lateral line is used (clamp). A grid
// with a single lateral line is uniform across the width.
//
// The road input of the dynamics is u = h(x_q(t), y_q) at each contact point q, and its rate
// u' = v dh/dx (vehicle speed v), hence slope().
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace terrain {

/// Heights beyond +-10 km (above any road's altitude) are a unit or format mistake; left in, they
/// reached the ride metrics as overflowed accelerations [m].
constexpr double kMaxTerrainHeight = 1e4;
/// Stations and lateral positions beyond +-1e8 m (100,000 km, more than twice round the Earth)
/// are a mistake too; near the double range they overflowed the track's length to inf [m].
constexpr double kMaxTerrainCoordinate = 1e8;
/// Stations (and lateral lines) closer than 1 um are a mistake as well: at 1e-320 m the slope
/// between them was infinite and the run failed late, naming no file [m].
constexpr double kMinTerrainSpacing = 1e-6;

/// Whether consecutive stations (or lateral lines) `before` < `after` lie closer than
/// kMinTerrainSpacing, to the round-off of stations written as start + k spacing: 3e-6 - 2e-6 is
/// 9.999999999999999e-7, and far out a station's last bit is worth more (1.5e-8 m at 1e8 m).
inline bool closerThanMinSpacing(double before, double after) {
  const double round_off =
      4.0 * std::numeric_limits<double>::epsilon() * std::max(std::abs(before), std::abs(after));
  return after - before < kMinTerrainSpacing * (1.0 - 1e-9) - round_off;
}

class Terrain {
 public:
  /// stations [n_x] strictly increasing [m]; lateral [n_y] strictly increasing [m];
  /// heights [n_y x n_x] [m], row j is the longitudinal profile at y = lateral(j).
  /// Throws InputError (naming the offending index) for empty or mismatched sizes, non-finite
  /// values, duplicate or decreasing stations or lateral positions, heights beyond
  /// kMaxTerrainHeight, stations or lateral positions beyond kMaxTerrainCoordinate.
  Terrain(Vector stations, Vector lateral, Matrix heights, std::string name = "terrain");

  /// Height at station x [m], lateral position y [m] -> [m]. NaN in either gives NaN.
  double height(double x, double y) const;

  /// Where a lateral position falls between the lines: line j and weight w of line j + 1
  /// (0 <= w <= 1, y clamped to the lines). For callers sampling one y many times.
  struct LateralCell {
    Eigen::Index line = 0;
    double weight = 0.0;
  };
  LateralCell lateralCellOf(double y) const;
  /// height(x, y) with y's lateral cell already found (by this terrain's lateralCellOf(y)):
  /// the same value, bit for bit.
  double height(double x, const LateralCell& cell) const;
  /// Where a station falls between the samples: cell i and weight wx of sample i + 1, or a held
  /// edge (before the first sample, after the last). For callers sampling several lateral
  /// positions at one station.
  struct StationWeight {
    Eigen::Index cell = 0;
    double weight = 0.0;
    int edge = 0;  ///< -1: x < first station, +1: x >= last station, 0: inside
  };
  /// x must not be NaN.
  StationWeight stationWeightOf(double x) const;
  /// height(x, cell) with x's station weight already found (by this terrain's
  /// stationWeightOf(x)): the same value, bit for bit.
  double height(const StationWeight& station, const LateralCell& cell) const {
    if (station.edge < 0)
      return sampleHeight(0, cell);
    if (station.edge > 0)
      return sampleHeight(stations_.size() - 1, cell);
    return blend(sampleHeight(station.cell, cell), sampleHeight(station.cell + 1, cell),
                 station.weight);
  }
  /// The end of the flat run from station sample i: the last station x_k such that samples
  /// i..k are equal on every lateral line (x_i when sample i + 1 differs). Over [x_i, x_k]
  /// height(x, y) is, exactly, the height of sample i at y.
  double flatRunEnd(Eigen::Index i) const {
    return stations_(flat_end_[static_cast<std::size_t>(i)]);
  }
  /// dh/dx at (x, y) [m/m]: the slope of the bilinear cell, 0 outside the stations (held edge).
  /// On a station x_i it is the slope of the cell ahead, [x_i, x_{i+1}] (the one a contact moving
  /// forward crosses next).
  double slope(double x, double y) const;
  /// slope(x, cell) with x's station weight already found (stationWeightOf(x)): inside the
  /// stations (edge 0) the same value as slope(x, y), bit for bit; 0 at a held edge.
  double slope(const StationWeight& station, const LateralCell& cell) const {
    return station.edge != 0 ? 0.0 : cellSlope(station.cell, cell);
  }
  /// Both: h = height(x, y), dhdx = slope(x, y) (the interface RoadExcitation samples).
  void heightAndSlope(double x, double y, double& h, double& dhdx) const {
    h = height(x, y);
    dhdx = slope(x, y);
  }
  /// The longitudinal profile at lateral position y [m], one value per station [m].
  Vector profile(double y) const;

  const std::string& name() const { return name_; }
  const Vector& stations() const { return stations_; }
  const Vector& lateral() const { return lateral_; }
  /// [n_y x n_x] [m].
  const Matrix& heights() const { return heights_; }
  double startStation() const { return stations_(0); }
  double endStation() const { return stations_(stations_.size() - 1); }
  /// endStation() - startStation() [m].
  double length() const { return endStation() - startStation(); }
  /// True when the stations are equally spaced (to 1e-9 relative); spacing() is then valid.
  bool isUniform() const { return uniform_; }
  /// Station spacing [m] of a uniform grid, the mean spacing otherwise (0 for one station).
  double spacing() const { return spacing_; }

  /// Writes the CSV format read by loadTerrainCsv() (terrain_io.h), at full precision.
  /// Throws InputError when the file cannot be written.
  void saveCsv(const std::string& path) const;
  /// Writes the YAML format read by loadTerrainYaml() (terrain_io.h), at full precision.
  /// Throws InputError when the file cannot be written.
  void saveYaml(const std::string& path) const;

 private:
  /// Index i of the station cell [x_i, x_{i+1}] holding x, for x inside the stations.
  Eigen::Index stationCell(double x) const;
  /// Lateral cell index j and weight w of line j+1 (0 <= w <= 1), y clamped to the lines.
  void lateralCell(double y, Eigen::Index* j, double* w) const;
  /// The height of station sample i on a lateral cell (its two lines blended).
  // (1 - w) a + w b, and a itself where b == a: (1 - w) a + w a may round off a, and equal
  // samples must give their value bit for bit (flat runs, laterally uniform tracks whose pad
  // rows share one input channel in TerrainLines).
  static double blend(double a, double b, double w) { return a == b ? a : (1.0 - w) * a + w * b; }
  double sampleHeight(Eigen::Index i, const LateralCell& cell) const {
    const Eigen::Index j = cell.line;
    const double wy = cell.weight;
    return wy == 0.0 ? heights_(j, i) : blend(heights_(j, i), heights_(j + 1, i), wy);
  }
  /// dh/dx over station cell [x_i, x_{i+1}] on a lateral cell: each line's slope, blended.
  double cellSlope(Eigen::Index i, const LateralCell& cell) const {
    const auto line_slope = [&](Eigen::Index line) {
      return (heights_(line, i + 1) - heights_(line, i)) / (stations_(i + 1) - stations_(i));
    };
    return cell.weight == 0.0
               ? line_slope(cell.line)
               : blend(line_slope(cell.line), line_slope(cell.line + 1), cell.weight);
  }

  Vector stations_;
  Vector lateral_;
  Matrix heights_;
  std::string name_;
  bool uniform_ = false;
  double spacing_ = 0.0;
  std::vector<Eigen::Index> flat_end_;  // flatRunEnd(): the index k for each i
};

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
