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

 private:
  struct Line {
    double y = 0.0;
    Vector heights;  ///< h(x_i, y) [n_x]
    Vector slopes;   ///< cell slopes [n_x - 1] (empty for a single station)
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
