// What the node's source files share about logging and kept inputs (vehicle_dynamics_node*.cpp).
#pragma once

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

}  // namespace node_logging
}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
