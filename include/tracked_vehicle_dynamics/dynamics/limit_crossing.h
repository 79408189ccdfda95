// The lowest speed at which a ride metric reaches its limit: the "6 W speed" (absorbed power at
// the driver's seat, comfort.h) and the "2.5 g speed" over an obstacle (shock_meter.h) by which
// mobility models rate a vehicle.
//
// The metric m(v) is known on a sweep v_0 < v_1 < ... < v_n (one simulation per speed). The
// crossing is looked for in the first interval with m(v_i) < L <= m(v_i+1), then narrowed by
// bisection, one more simulation per halving, until the bracket is no wider than the tolerance;
// the reported speed interpolates m linearly inside that last bracket:
//   v* = v_lo + (L - m_lo) / (m_hi - m_lo) (v_hi - v_lo).
// m need not be monotone (a resonance can make it fall again); the lowest crossing the sweep
// brackets is the one reported, since a driver reaches it first. A crossing and recrossing
// inside one sweep interval is invisible: the sweep must be fine enough for the metric.
#pragma once

#include <functional>
#include <vector>

namespace tracked_vehicle_dynamics {
namespace dynamics {

struct LimitCrossing {
  enum class Status {
    Reached,     ///< crossed between two sweep speeds: `speed` is the crossing
    AtLowest,    ///< already at or above the limit at the lowest speed: `speed` is that speed
    NotReached,  ///< below the limit at every speed: `speed` is the highest
  };
  Status status = Status::NotReached;
  double speed = 0.0;
  /// The final bracket and the metric at its ends (Reached); otherwise both ends are `speed`.
  double lower = 0.0, upper = 0.0, lower_value = 0.0, upper_value = 0.0;
  int refinements = 0;  ///< evaluations made by the bisection
};

/// `speeds` strictly increasing (any unit), `values` the metric at each; `limit` the threshold;
/// `tolerance` > 0 the width (same unit as the speeds) to which the bracket is narrowed (or until
/// its ends are adjacent doubles);
/// `evaluate(v)` the metric at speed v (a simulation). Throws InputError for fewer than one
/// speed, sizes that differ, speeds not strictly increasing, a non-finite limit or a non-positive
/// tolerance, and
/// for a non-finite value (naming its speed).
LimitCrossing findLimitCrossing(const std::vector<double>& speeds,
                                const std::vector<double>& values, double limit, double tolerance,
                                const std::function<double(double)>& evaluate);

/// "reached", "at_lowest_speed", "not_reached".
const char* limitStatusName(LimitCrossing::Status status);

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
