// The system clock stepped under a node on real time (an NTP or chrony step, `date -s`): ROS
// time is the system clock, the tick timer and ~speed_timeout run on the monotonic one. The
// step is the change of their offset between two ticks,
//   Δ = (t_ros − t_steady)_now − (t_ros − t_steady)_before,
// which stays zero while the clock runs (an NTP slew changes it by 0.5 ms/s at most). The
// vehicle's motion does not depend on which time base labels it: its time moves by Δ, and with
// it everything kept in ROS time (the stamped speeds waiting for their stamps, the stamp of the
// one in force, the run's start), so the vehicle drives on as if the clock had not stepped.
// Before, a step back left the stamped speeds sent ahead waiting Δ longer and dropped every new
// one as older than the one in force until the clock caught up; a step forward was stepped (up
// to ~catch_up_limit of motion in one tick) or skipped as "behind ROS time".
#include <cstdio>
#include <cstdlib>
#include <string>

#include "tracked_vehicle_dynamics/ros/vehicle_dynamics_node.h"

#include "node_logging.h"

namespace tracked_vehicle_dynamics {
namespace ros_layer {
namespace {

// A change of the offset beyond this [ns] between two ticks is a step of the clock. Far above
// a slew's (0.5 ms/s) and the reading's error (readClocks: under kPairSpreadNs), far below the
// steps NTP daemons make (ntpd steps beyond 128 ms; smaller offsets are slewed).
constexpr std::int64_t kClockStepNs = 20'000'000;
// ROS time is read between two readings of the monotonic clock at most this far apart [ns]: a
// preemption between the readings would look like a step.
constexpr std::int64_t kPairSpreadNs = 1'000'000;

ros::Time shifted(const ros::Time& t, std::int64_t ns) {
  // Zero means "none" (no stamped speed in force, no run yet): it stays so.
  return t.isZero() ? t : ros::Time().fromNSec(static_cast<std::uint64_t>(t.toNSec() + ns));
}

}  // namespace

bool VehicleDynamicsNode::readClocks(ros::Time* ros_now, ros::SteadyTime* steady_now) {
  if (use_sim_time_) {
    *ros_now = now();
    *steady_now = ros::SteadyTime::now();
    return false;
  }
  // ROS time bracketed by the monotonic clock, the pair taken at the bracket's middle: a few
  // tries find one not split by a preemption.
  for (int attempt = 0;; ++attempt) {
    const ros::SteadyTime before = ros::SteadyTime::now();
    *ros_now = ros::Time::now();
    const ros::SteadyTime after = ros::SteadyTime::now();
    const std::int64_t spread = (after - before).toNSec();
    *steady_now = before + ros::WallDuration().fromNSec(spread / 2);
    if (spread <= kPairSpreadNs)
      return true;
    if (attempt == 2) {
      // No pair: the offset is judged afresh from the next one. A step meanwhile is then taken
      // as before (a step back re-anchors the time in advanceTo, one forward is caught up).
      clock_offset_known_ = false;
      return false;
    }
  }
}

void VehicleDynamicsNode::followClockStep(const ros::Time& ros_now,
                                          const ros::SteadyTime& steady_now) {
  const std::int64_t offset =
      static_cast<std::int64_t>(ros_now.toNSec()) - static_cast<std::int64_t>(steady_now.toNSec());
  const bool known = clock_offset_known_;
  const std::int64_t step = offset - clock_offset_ns_;
  clock_offset_ns_ = offset;
  clock_offset_known_ = true;
  if (known && clock_started_ && std::llabs(step) > kClockStepNs)
    moveTime(step, ros_now);
}

void VehicleDynamicsNode::moveTime(std::int64_t step_ns, const ros::Time& ros_now) {
  ++events_.clock_steps;
  // Fixed decimals: epoch-sized times lose everything in 6 digits.
  char text[160];
  std::snprintf(text, sizeof(text), "%+.3f s at ROS time %.3f s", step_ns * 1e-9, ros_now.toSec());
  last_clock_step_ = text;
  // Said every time, as a jump back of simulated time is: each one moves every stamp published.
  const std::string waiting = pending_speeds_.empty()
                                  ? std::string()
                                  : "; the " + std::to_string(pending_speeds_.size()) +
                                        " stamped speeds waiting for their stamps move with it";
  ROS_WARN(
      "%s: the system clock stepped %s by %.3f s (an NTP correction, or set by hand): the "
      "vehicle's time steps with it and its motion goes on%s",
      nodeName(), step_ns < 0 ? "back" : "forward", std::llabs(step_ns) * 1e-9, waiting.c_str());
  sample_time_ = shifted(sample_time_, step_ns);
  run_start_ = shifted(run_start_, step_ns);
  applied_speed_stamp_ = shifted(applied_speed_stamp_, step_ns);
  last_speed_taken_ = shifted(last_speed_taken_, step_ns);
  last_speed_time_ = shifted(last_speed_time_, step_ns);
  next_diagnostics_ = shifted(next_diagnostics_, step_ns);
  for (PendingSpeed& pending : pending_speeds_)
    pending.stamp = shifted(pending.stamp, step_ns);
}

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
