// A terrain cut along a few fixed lateral positions, for fast repeated sampling.
//
// A vehicle's road inputs sit on a handful of lateral lines (left/right x inner/outer pad rows)
// and sample them at every step. Terrain::height() finds the lateral cell and the station cell
// each time; here each line's profile h_j(x) = h(x, y_j) and its cell slopes are precomputed, so
// a sample is one index computation on a uniform grid:
//   i = floor((x - x_0) / dx),  h = h_i + (x - x_i) s_i,  s_i = (h_{i+1} - h_i) / dx.
// Same values as Terrain::height()/slope() (bilinear, held constant outside the stations).
#pragma once

#include <vector>

#include "tracked_vehicle_dynamics/terrain/terrain.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace terrain {

class TerrainLines {
 public:
  /// One line per distinct value of `lateral` [m]. Other lateral positions fall back to the
  /// terrain itself (kept by reference: it must outlive this object).
  TerrainLines(const Terrain& terrain, const Vector& lateral);

  /// h(x, y) [m] and dh/dx(x, y) [m/m], as Terrain::height() and slope().
  double height(double x, double y) const;
  double slope(double x, double y) const;
  /// Both at once (one line and cell lookup): h = height(x, y), dhdx = slope(x, y).
  void heightAndSlope(double x, double y, double& h, double& dhdx) const;

  /// Number of distinct lines.
  std::size_t lineCount() const { return lines_.size(); }

  /// For sampling only where the profile changes (RoadExcitation::sampleHeldSeries):
  /// the line holding y, as the index of the first line with the same profile bit for bit (so
  /// lines of a laterally uniform terrain share one index); -1 when y is not a line.
  int profileOf(double y) const;
  /// h and dh/dx at x on profile `profile` (profileOf) in one cell lookup, as heightAndSlope(x, y)
  /// for any y of that profile, bit for bit. Returns the end of the flat run at x: h and dh/dx
  /// are the same for every x' in [x, end); x itself when the profile is not flat at x (or x is
  /// NaN), +infinity when it stays flat to the end of the terrain.
  double sampleRun(int profile, double x, double& h, double& dhdx) const;

 private:
  struct Line {
    double y = 0.0;
    Vector heights;   ///< h(x_i, y) [n_x]
    Vector slopes;    ///< cell slopes [n_x - 1] (empty for a single station)
    int profile = 0;  ///< index of the first line with the same heights
    /// sampleRun(): for a flat cell i (slope 0), the first station index j > i whose cell is
    /// not flat (n_x - 1: flat to the end).
    std::vector<Eigen::Index> flat_end;
  };
  /// Line holding y exactly, or nullptr.
  const Line* find(double y) const;
  /// Cell index of x inside the stations (uniform or not).
  Eigen::Index cell(double x) const;

  const Terrain& terrain_;
  std::vector<Line> lines_;
  double x0_ = 0.0, x_end_ = 0.0, inverse_dx_ = 0.0;
};

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
