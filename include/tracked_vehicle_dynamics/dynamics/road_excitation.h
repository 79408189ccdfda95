// Road inputs of a vehicle travelling over a height field (paper §4.2.1): every ground input q
// samples the terrain at its own position as the vehicle advances,
//   u_q(t)  = h(s(t) + x_q, y_q + y_0)
//   u_q'(t) = v(t) dh/dx(s(t) + x_q, y_q + y_0)
// with s(t) = integral of v dt the travelled station [m], (x_q, y_q) the input's position in the
// vehicle frame [m] (x forward, y left) and y_0 the lateral offset of the path [m]. The four
// profile lines of the paper's Fig. 17 (left/right x inner/outer pads) follow from the inputs'
// own y_q.
#pragma once

#include <cmath>
#include <string>

#include "tracked_vehicle_dynamics/dynamics/held_input_series.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace terrain {
class TerrainLines;
}
namespace dynamics {

class RoadExcitation {
 public:
  /// input_x, input_y [m]: one entry per road input (e.g. SecondOrderSystem::input_stations,
  /// input_lateral). Throws InputError for different lengths or non-finite positions.
  RoadExcitation(const Vector& input_x, const Vector& input_y, double lateral_offset = 0.0)
      : x_(input_x), y_(input_y.array() + lateral_offset) {
    if (input_x.size() != input_y.size())
      throw InputError("road excitation: " + std::to_string(input_x.size()) +
                       " input stations but " + std::to_string(input_y.size()) +
                       " lateral positions");
    if (!input_x.allFinite() || !input_y.allFinite() || !std::isfinite(lateral_offset))
      throw InputError("road excitation: input positions must be finite");
  }

  DofIndex inputCount() const { return x_.size(); }
  /// w = [u; u'] [2 n_inputs] into `w` (resized once) at station s [m] and speed v [m/s].
  /// `terrain` is any height source with heightAndSlope(x, y, h, dhdx) [m, -] (Terrain,
  /// TerrainLines).
  template <typename HeightSource>
  void sample(const HeightSource& terrain, double station, double speed, Vector& w) const {
    const DofIndex n = x_.size();
    if (w.size() != 2 * n)
      w.resize(2 * n);
    for (DofIndex q = 0; q < n; ++q)
      sampleOne(terrain, station + x_(q), y_(q), speed, w(q), w(n + q));
  }

  /// The input series of a run: row j is sample() at station stations(j) [m] and speed
  /// speeds(j) [m/s]. [rows x 2 n_inputs].
  template <typename HeightSource>
  Matrix sampleSeries(const HeightSource& terrain, const Vector& stations,
                      const Vector& speeds) const {
    if (stations.size() != speeds.size())
      throw InputError("road excitation: " + std::to_string(stations.size()) + " stations but " +
                       std::to_string(speeds.size()) + " speeds");
    const DofIndex n = x_.size();
    const Eigen::Index count = stations.size();
    Matrix series(count, 2 * n);
    // Input by input: the series is column-major, so each input's samples are contiguous.
    for (DofIndex q = 0; q < n; ++q) {
      double* u = series.col(q).data();
      double* rate = series.col(n + q).data();
      for (Eigen::Index j = 0; j < count; ++j)
        sampleOne(terrain, stations(j) + x_(q), y_(q), speeds(j), u[j], rate[j]);
    }
    return series;
  }

  /// The input series of a constant-speed run for Simulator::simulate(): row j is w at time
  /// (first + j) dt, station s = station0 + speed (first + j) dt. [count x 2 n_inputs].
  /// Row j equals sample() at that station.
  template <typename HeightSource>
  Matrix sampleSeries(const HeightSource& terrain, double station0, double speed, double dt,
                      long first, long count) const {
    Vector stations(count);
    for (long j = 0; j < count; ++j)
      stations(j) = station0 + speed * static_cast<double>(first + j) * dt;
    return sampleSeries(terrain, stations, Vector::Constant(count, speed));
  }

  /// The same series as sampleSeries(lines, ...), row for row and bit for bit, stored by its
  /// changes (held_input_series.h): a contact is sampled only where its profile line is not flat
  /// (TerrainLines::sampleRun), and contacts at the same station on lines with the same profile
  /// share one channel. Needs speed > 0 and dt > 0 for skipping (otherwise every sample is
  /// taken). Inputs whose lateral position is not one of the lines' are sampled at every step.
  HeldInputSeries sampleHeldSeries(const terrain::TerrainLines& lines, double station0,
                                   double speed, double dt, long first, long count) const;

  const Vector& inputX() const { return x_; }
  const Vector& inputY() const { return y_; }  ///< including the lateral offset

 private:
  template <typename HeightSource>
  static void sampleOne(const HeightSource& terrain, double x, double y, double speed, double& u,
                        double& rate) {
    double slope = 0.0;
    terrain.heightAndSlope(x, y, u, slope);
    rate = speed * slope;
  }

  Vector x_;
  Vector y_;
};

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
