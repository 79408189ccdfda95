// The closed path of one track chain in the side (x-z) plane: the pitch line (pin axes) runs
// forward along the ground, up the front incline, around the front wheel, back along the top run,
// around the rear wheel and down the rear incline. The front wheel is the idler and the rear one
// the drive sprocket (rear drive, the paper's vehicle), or the other way round when the sprocket
// stands ahead of the ground run (front drive, sprocket.centre_x > 0). Straight segments are
// tangent to the wheel circles; the only corners are at the ends of the ground run, where an
// assembly joint lies.
#pragma once

#include <vector>

#include "tracked_vehicle_dynamics/types.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

using Vector2 = Eigen::Vector2d;

/// Which part of the loop a point lies on.
enum class ChainSegment { Ground, FrontIncline, Idler, TopRun, Sprocket, RearIncline };

/// Point of the path (x, z) and its unit tangent in the travel direction. The inward normal
/// (towards the wheels) is the tangent turned by +90 deg from x towards z: n = (-t_z, t_x).
struct ChainPoint {
  Vector2 position = Vector2::Zero();  ///< (x, z) [m]
  Vector2 tangent = Vector2::UnitX();
  ChainSegment segment = ChainSegment::Ground;
};

class ChainPath {
 public:
  /// Builds the loop for a given idler centre x [m]. Throws InputError naming the sprocket or
  /// idler key when the wheels cannot be wrapped (e.g. a wheel circle that reaches the ground run).
  ChainPath(const VehicleDescription& description, double idler_x);

  /// Total length of the pitch line [m].
  double length() const { return length_; }
  /// The point at arc length s from the rear end of the ground run (wrapped into [0, length)).
  ChainPoint at(double s) const;
  /// Arc-length interval [begin, end) of a segment.
  std::pair<double, double> interval(ChainSegment segment) const;

  Vector2 sprocketCentre() const { return sprocket_centre_; }
  Vector2 idlerCentre() const { return idler_centre_; }
  /// Height of the top run's pitch line at x [m].
  double topRunHeight(double x) const;

 private:
  struct Piece {
    ChainSegment segment = ChainSegment::Ground;
    bool arc = false;
    Vector2 a = Vector2::Zero(), b = Vector2::Zero();  // line: start, end
    Vector2 centre = Vector2::Zero();                  // arc
    double radius = 0, start_angle = 0, sweep = 0;
    double s0 = 0, len = 0;
  };
  std::vector<Piece> pieces_;
  double length_ = 0.0;
  Vector2 sprocket_centre_, idler_centre_;
};

/// The idler centre x at which the loop length equals count x pitch (the track tensioner's
/// setting), by bisection; the idler stands at the end opposite the sprocket. Throws InputError
/// "track_assembly.count" when the chain is too short to wrap the running gear or so long that
/// the idler would reach more than kWheelOverhang beyond the hull's end.
double solveIdlerX(const VehicleDescription& description);

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
