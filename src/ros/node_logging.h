// What the node's source files share about logging, kept inputs and frame names
// (vehicle_dynamics_node*.cpp).
#pragma once

#include <cmath>
#include <string>

#include <ros/console.h>
#include <ros/time.h>

// ROS_WARN_THROTTLE on the monotonic wall clock. rosconsole's throttle reads ros::Time, which on
// simulated time is the simulator's: a /clock that jumps back (two clock sources, a bag looping
// fast) re-opens it at every jump, and the "throttled" warning floods the log; a paused clock would
// hold it shut. One throttle per call site, as ROS_WARN_THROTTLE has.
#define TVD_LOG_THROTTLE(log, period, ...)                                              \
  do {                                                                                  \
    static double tvd_warn_last_ = -1e300;                                              \
    const double tvd_warn_now_ = ::ros::SteadyTime::now().toSec();                      \
    if (tvd_warn_now_ >= tvd_warn_last_ + (period) || tvd_warn_now_ < tvd_warn_last_) { \
      tvd_warn_last_ = tvd_warn_now_;                                                   \
      log(__VA_ARGS__);                                                                 \
    }                                                                                   \
  } while (false)
#define TVD_WARN_THROTTLE(period, ...) TVD_LOG_THROTTLE(ROS_WARN, period, __VA_ARGS__)
#define TVD_ERROR_THROTTLE(period, ...) TVD_LOG_THROTTLE(ROS_ERROR, period, __VA_ARGS__)

namespace tracked_vehicle_dynamics {
namespace ros_layer {
namespace node_logging {

// Wall time [s] between two throttled warnings of one kind.
constexpr double kWarnPeriod = 5.0;

// Wall time [s] for which inputs are kept in case simulated time jumps back to them. rosbag
// play -l publishes a loop's first messages and its first /clock within milliseconds, on
// separate connections, so either may arrive first.
constexpr double kRewindWindow = 0.25;

/// Whether an input kept over a jump back of ROS time to `now` belongs to the new time: stamped
/// nearer `now` than the ROS time it arrived at (a bag's next loop, sent before the jump, is
/// stamped near its start; a message of the old pass near the old time). In double seconds:
/// ros::Time's difference throws beyond 2^31 s, for a wild stamp. Stamp 0 never does.
inline bool ofNewTime(const ros::Time& stamp, const ros::Time& ros_arrival, const ros::Time& now) {
  const double s = stamp.toSec();
  return !stamp.isZero() && std::abs(s - now.toSec()) < std::abs(s - ros_arrival.toSec());
}

/// Whether header.frame_id `frame` names `own` (a frame id with ~frame_prefix `prefix`): with or
/// without a leading '/' (tf1 style), and with or without the prefix (a source that knows of
/// none, or a bag made by tvd_make_bag).
inline bool namesOwnFrame(const std::string& frame, const std::string& own,
                          const std::string& prefix) {
  const std::string bare = !frame.empty() && frame.front() == '/' ? frame.substr(1) : frame;
  return !own.empty() &&
         (bare == own || (!prefix.empty() && own.compare(0, prefix.size(), prefix) == 0 &&
                          bare == own.substr(prefix.size())));
}

}  // namespace node_logging
}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
