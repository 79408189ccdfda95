// The node's speed inputs: `speed` (std_msgs/Float64, taken when it arrives) and `speed_stamped`
// (geometry_msgs/TwistStamped, taken at its header.stamp), the speed timeout's bookkeeping, and
// what a jump back of simulated time (a bag loop) re-applies of them.
//
// A stamped speed applies from the first step that starts at or after its stamp: a speed sent
// ahead waits for its time; one that arrives after it (the vehicle's sample already past the
// stamp) applies at once and is counted late, unless an even newer stamped speed is in force
// (then it is dropped), and makes up the steps it missed if the vehicle stood still meanwhile
// (OnlineVehicle::setSpeedSince). So a bag replay drives the vehicle through the same stations
// every time, whatever the order in which its /clock and speed messages reach the node on their
// separate connections (the unstamped speed applies at the next tick, so its station wanders by
// the /clock period's worth of Δv, 10 ms at rosbag's default 100 Hz clock).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/ros/vehicle_dynamics_node.h"

#include "node_logging.h"

namespace tracked_vehicle_dynamics {
namespace ros_layer {
namespace {

using node_logging::kRewindWindow;
using node_logging::kWarnPeriod;

// A speed change a driver would feel [m/s at once, or m/s per second between messages], which
// without a slew carries no travel inertia: warned about once.
constexpr double kUnslewedChange = 0.5;

// A negative speed this close to zero is a stopped vehicle as a physics engine reports it
// (-1e-6 m/s), not reverse driving: taken as 0. Refused as reverse, it kept the last speed and
// the vehicle crept on at it while the simulator stood still (review 125).
constexpr double kStandstillNoise = 1e-3;  // [m/s]

// A stamp further than this [s] from ROS time now is not a schedule but another time base (wall
// time stamps on simulated time, or the reverse): the speed is taken when it arrives, as an
// unstamped one, and the mismatch said. Speeds are sent at tens of Hz; a second covers any
// delivery delay and a catch-up.
constexpr double kStampRange = 1.0;

// Stamped speeds kept waiting for their stamps at most: a second of them at 1 kHz. Only a source
// sending ahead while ROS time stands still (a paused /clock) fills it; beyond, refused.
constexpr std::size_t kMaxPendingSpeeds = 1000;

double standstill(double v) {
  return v < 0.0 && v >= -kStandstillNoise ? 0.0 : v;
}

}  // namespace

std::string VehicleDynamicsNode::speedProblem(double v) const {
  if (!std::isfinite(v))
    return "speed is not finite";
  if (v < 0.0)
    return "negative speed " + brief(v) + " m/s (reverse driving is not modelled)";
  if (v > params_.max_speed) {
    return "speed " + brief(v) + " m/s above ~max_speed " + brief(params_.max_speed) + " m/s";
  }
  return "";
}

std::string VehicleDynamicsNode::speedFrameProblem(const std::string& frame) const {
  // twist.linear.x is the speed along the hull's path only in a frame whose x axis is the
  // vehicle's heading: base_link, or the footprint. Another frame's x (odom, map) is the speed
  // along that frame's axis, not the travel speed. Unprefixed names pass, as for terrain: a
  // source that knows of no ~frame_prefix.
  const std::string& prefix = params_.frame_prefix;
  if (frame.empty() || frame == "/" ||
      node_logging::namesOwnFrame(frame, params_.base_frame, prefix) ||
      node_logging::namesOwnFrame(frame, params_.footprint_frame, prefix))
    return "";
  std::string allowed = "'" + params_.base_frame + "'";
  if (!params_.footprint_frame.empty())
    allowed += " or '" + params_.footprint_frame + "'";
  if (!prefix.empty())
    allowed += " (with or without '" + prefix + "')";
  return "speed_stamped in frame '" + frame + "': its twist.linear.x is taken as the forward " +
         "speed, which it is in " + allowed + " or an empty frame_id only";
}

void VehicleDynamicsNode::rejectSpeed(const std::string& why) {
  ++events_.speeds_rejected;
  last_speed_error_ = why;
  // The last valid speed is kept: the commanded one (with a slew the current speed is still on
  // its way there).
  TVD_WARN_THROTTLE(kWarnPeriod, "%s: %s; keeping %.3f m/s", nodeName(), why.c_str(),
                    vehicle_->commandedSpeed());
}

void VehicleDynamicsNode::noteSpeedSource(bool stamped) {
  (stamped ? stamped_speed_seen_ : unstamped_speed_seen_) = true;
  if (speed_sources_warned_ || !stamped_speed_seen_ || !unstamped_speed_seen_)
    return;
  speed_sources_warned_ = true;
  ROS_WARN(
      "%s: speeds arrive on both speed (std_msgs/Float64) and speed_stamped "
      "(geometry_msgs/TwistStamped): each is taken as it comes, the stamped ones at their stamp, "
      "so the two sources override each other; publish on one (said once)",
      nodeName());
}

void VehicleDynamicsNode::onSpeed(const std_msgs::Float64::ConstPtr& msg) {
  const double v = standstill(msg->data);
  const std::string why = speedProblem(v);
  if (!why.empty()) {
    rejectSpeed(why);
    return;
  }
  noteSpeedSource(false);
  const ros::Time t = now();
  takeSpeed(v, t);
  ++events_.speeds_accepted;
  markSpeedTime(t);
  recent_speed_ = v;
  recent_speed_arrival_ = ros::SteadyTime::now();
}

void VehicleDynamicsNode::onSpeedStamped(const geometry_msgs::TwistStamped::ConstPtr& msg) {
  const double v = standstill(msg->twist.linear.x);
  std::string why = speedFrameProblem(msg->header.frame_id);
  if (why.empty()) {
    why = speedProblem(v);
    if (!why.empty())
      why = "speed_stamped: " + why;
  }
  if (why.empty() && pending_speeds_.size() >= kMaxPendingSpeeds)
    why = "speed_stamped: " + std::to_string(kMaxPendingSpeeds) +
          " speeds already wait for their stamps (is ROS time standing still?)";
  if (!why.empty()) {
    rejectSpeed(why);
    return;
  }
  noteSpeedSource(true);
  const ros::Time t = now();
  const ros::Time& stamp = msg->header.stamp;
  ++events_.speeds_accepted;
  ++events_.speeds_stamped;
  // Unstamped (0, "no time" in ROS), or before the vehicle's time started (simulated time with
  // no /clock yet): taken now, as a Float64.
  if (stamp.isZero() || t.isZero() || !clock_started_) {
    takeSpeed(v, t);
    markSpeedTime(t);
    return;
  }
  const ros::SteadyTime arrival = ros::SteadyTime::now();
  // In seconds as doubles: ros::Time's difference throws beyond 2^31 s, and a wild stamp must
  // be judged, not end the callback.
  const double ahead = stamp.toSec() - t.toSec();
  if (use_sim_time_ && !last_jump_arrival_.isZero() &&
      arrival - last_jump_arrival_ < ros::WallDuration(kRewindWindow) &&
      stamp <= last_jump_old_time_ &&
      std::abs(stamp.toSec() - last_jump_old_time_.toSec()) <
          std::abs(stamp.toSec() - last_jump_new_time_.toSec())) {
    // Just after a jump back, one stamped nearer the time it left than the time it went to, and
    // not after it: a late message of the pass before, whose speed is not the new pass's. (One
    // stamped after the old pass's last sample was sent ahead for the new pass, a plan.)
    ++events_.speeds_of_pass_before;
    return;
  }
  if (std::abs(ahead) > kStampRange) {
    // On simulated time a stamp far behind may be a bag loop's next pass, sent before the /clock
    // message that jumps back: kept, and judged when the jump re-applies it or its window closes
    // without one (expireRecentSpeeds).
    if (use_sim_time_ && ahead < 0.0) {
      recent_stamped_speeds_.push_back({v, stamp, t, arrival, true});
      return;
    }
    takeSpeedOfOtherTimeBase(v, stamp, t);
    return;
  }
  // The driver is alive (~speed_timeout) when the message arrives, whenever it applies.
  markSpeedTime(t);
  if (use_sim_time_) {
    expireRecentSpeeds();
    recent_stamped_speeds_.push_back({v, stamp, t, arrival, false});
  }
  alignRestart(stamp);  // a bag loop's first speed after the jump back: the loop's start
  scheduleSpeed(v, stamp);
}

void VehicleDynamicsNode::scheduleSpeed(double v, const ros::Time& stamp) {
  // Older than the stamped speed in force: a stale command (reordered on the way, or from a
  // second sender), which must not replace the newer one.
  if (!applied_speed_stamp_.isZero() && stamp < applied_speed_stamp_) {
    ++events_.speeds_superseded;
    return;
  }
  // Kept in stamp order (a source may send out of order); a second speed for the same stamp
  // replaces the first (a re-sent plan).
  const auto at =
      std::lower_bound(pending_speeds_.begin(), pending_speeds_.end(), stamp,
                       [](const PendingSpeed& p, const ros::Time& s) { return p.stamp < s; });
  if (at != pending_speeds_.end() && at->stamp == stamp)
    at->speed = v;
  else
    pending_speeds_.insert(at, {v, stamp});
  if (hold_.active)
    hold_.speed = true;  // it applies during the held steps, at its stamp
  if (stamp <= sample_time_) {
    // The step at or after the stamp has been taken: applied at once, from the current sample,
    // with any other one now due, in stamp order (an older one still waiting for the next step
    // must not override it then).
    const std::int64_t late_ns = (sample_time_ - stamp).toNSec();
    if (late_ns >= step_ns_) {
      ++events_.speeds_late;
      max_speed_lateness_ = std::max(max_speed_lateness_, late_ns * 1e-9);
    }
    applyDueSpeeds();
  }
}

void VehicleDynamicsNode::applyDueSpeeds() {
  while (!pending_speeds_.empty() && pending_speeds_.front().stamp <= sample_time_) {
    const PendingSpeed due = pending_speeds_.front();
    pending_speeds_.pop_front();
    // Late by whole steps to a vehicle standing still since before its stamp (and since the
    // run's start), without a slew: the steps it missed are made up at once (setSpeedSince), so
    // a standing start that learns of its speed a few steps late (a replay's first speed behind
    // the first /clock) drives on from where, and as, it would have on level ground.
    const ros::Time from = std::max(due.stamp, run_start_);
    const std::int64_t missed = from < sample_time_ ? (sample_time_ - from).toNSec() / step_ns_ : 0;
    const bool standing = !vehicle_->slews() && vehicle_->speed() == 0.0 &&
                          vehicle_->commandedSpeed() == 0.0 && last_speed_taken_ <= due.stamp;
    takeSpeed(due.speed, due.stamp, standing ? missed : std::int64_t{0});
    applied_speed_stamp_ = due.stamp;
  }
}

void VehicleDynamicsNode::takeSpeed(double v, const ros::Time& t, std::int64_t catch_up_steps) {
  warnOfUnslewedSpeedChange(v, t);
  if (catch_up_steps > 0) {
    vehicle_->setSpeedSince(v, static_cast<long>(catch_up_steps));
    ++events_.speeds_caught_up;
  } else {
    vehicle_->setSpeed(v);
  }
  last_speed_taken_ = t;
  speed_message_in_run_ = true;
  if (hold_.active)
    hold_.speed = true;
  stopped_by_timeout_ = false;
}

void VehicleDynamicsNode::takeSpeedOfOtherTimeBase(double v, const ros::Time& stamp,
                                                   const ros::Time& t) {
  ++events_.speeds_other_time_base;
  const double ahead = stamp.toSec() - t.toSec();
  // Fixed decimals: epoch-sized times (wall-clock stamps) lose everything in 6 digits.
  char text[160];
  std::snprintf(text, sizeof(text), "stamp %.3f s is %.3f s %s ROS time %.3f s", stamp.toSec(),
                std::abs(ahead), ahead > 0.0 ? "ahead of" : "behind", t.toSec());
  last_other_time_base_ = text;
  TVD_WARN_THROTTLE(kWarnPeriod,
                    "%s: speed_stamped: %s, more than %g s apart: another time base (a sender on "
                    "wall time while this node is on /clock, or the reverse?); taken now, as an "
                    "unstamped speed",
                    nodeName(), last_other_time_base_.c_str(), kStampRange);
  takeSpeed(v, t);
  markSpeedTime(t);
}

void VehicleDynamicsNode::expireRecentSpeeds() {
  const ros::SteadyTime oldest = ros::SteadyTime::now() - ros::WallDuration(kRewindWindow);
  while (!recent_stamped_speeds_.empty() && recent_stamped_speeds_.front().arrival < oldest) {
    const RecentSpeed recent = recent_stamped_speeds_.front();
    recent_stamped_speeds_.pop_front();
    // Far behind, and no jump back came for it: not a bag loop's next pass after all.
    if (recent.deferred)  // judged against the ROS time it arrived at
      takeSpeedOfOtherTimeBase(recent.speed, recent.stamp, recent.ros_arrival);
  }
}

void VehicleDynamicsNode::forgetRecentSpeeds() {
  recent_stamped_speeds_.clear();
  recent_speed_arrival_ = ros::SteadyTime();
}

void VehicleDynamicsNode::reapplyRecentSpeeds(const ros::Time& now) {
  const ros::SteadyTime oldest = ros::SteadyTime::now() - ros::WallDuration(kRewindWindow);
  // std_msgs/Float64 carries no stamp: the last speed is taken if it arrived just before the
  // jump (rosbag sends a loop's first speed with its first patches).
  if (!recent_speed_arrival_.isZero() && recent_speed_arrival_ >= oldest) {
    vehicle_->setSpeed(recent_speed_);
    last_speed_taken_ = now;
    speed_message_in_run_ = true;
    stopped_by_timeout_ = false;
    markSpeedTime(now);
    ++events_.speeds_reapplied;
  }
  recent_speed_arrival_ = ros::SteadyTime();
  // A stamped speed of the new time (stamped nearer it than the ROS time it arrived at, as a
  // patch is judged) applies at its stamp: now if that has passed, later if it lies ahead.
  // scheduleSpeed() keeps them in stamp order, those not after `now` applied at once.
  for (const RecentSpeed& recent : recent_stamped_speeds_) {
    if (recent.arrival < oldest || !node_logging::ofNewTime(recent.stamp, recent.ros_arrival, now))
      continue;  // the old pass's: gone with it
    stopped_by_timeout_ = false;
    markSpeedTime(now);
    ++events_.speeds_reapplied;
    scheduleSpeed(recent.speed, recent.stamp);
  }
  recent_stamped_speeds_.clear();
}

void VehicleDynamicsNode::warnOfUnslewedSpeedChange(double v, const ros::Time& t) {
  // Without a slew (~max_acceleration and ~max_deceleration 0, the default) a new speed applies
  // at once and carries no travel inertia: odom's twist follows a braking source, the IMU and the
  // hull's pitch do not (review 130: a fused localisation saw the two disagree). Said once, at
  // the first change a driver would feel: by more than kUnslewedChange at once, or at more than
  // kUnslewedChange per second over the time since the previous speed took effect.
  const online::OnlineVehicleOptions& o = params_.vehicle_options;
  if (unslewed_change_warned_ || o.max_acceleration > 0.0 || o.max_deceleration > 0.0 ||
      last_speed_taken_.isZero())
    return;
  const double change = std::abs(v - vehicle_->commandedSpeed());
  const double dt = (t - last_speed_taken_).toSec();
  if (change <= kStandstillNoise || (change <= kUnslewedChange && change <= kUnslewedChange * dt))
    return;
  unslewed_change_warned_ = true;
  const std::string over =
      dt > 0.0 ? "over " + brief(std::round(dt * 1000.0) / 1000.0) + " s" : "at once";
  ROS_WARN(
      "%s: the speed changes from %.3f to %.3f m/s %s, and without a slew (~max_acceleration and "
      "~max_deceleration 0) it applies at once with no travel inertia: odom follows it, the IMU "
      "and the hull's pitch do not; set both to the vehicle's limits to feel braking and "
      "accelerating (said once)",
      nodeName(), vehicle_->commandedSpeed(), v, over.c_str());
}

void VehicleDynamicsNode::markSpeedTime(const ros::Time& now) {
  last_speed_time_ = now;
  last_speed_steady_ = ros::SteadyTime::now();
}

double VehicleDynamicsNode::secondsSinceSpeed(const ros::Time& now,
                                              const ros::SteadyTime& steady) const {
  // On real time ROS time is the system clock, which an NTP correction steps (back: the vehicle
  // would drive on for the step's length; forward: stop at once): the monotonic clock instead.
  return use_sim_time_ ? (now - last_speed_time_).toSec() : (steady - last_speed_steady_).toSec();
}

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
