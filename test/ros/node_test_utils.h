// Helpers shared by the node's rostests: waiting on wall time while spinning, the latest
// diagnostics per status name, flat terrain patches, and the model the node runs.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <diagnostic_msgs/DiagnosticArray.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>

#include "tracked_vehicle_dynamics/TerrainProfile.h"
#include "tracked_vehicle_dynamics/reduction/contact_groups.h"
#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "tracked_vehicle_dynamics/ros/conversions.h"
#include "tracked_vehicle_dynamics/ros/online_names.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_geometry.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace ros_layer {
namespace test {

/// Spins until `done()` or `timeout` seconds of wall time; returns done().
inline bool spinUntil(const std::function<bool()>& done, double timeout) {
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(timeout);
  while (ros::ok() && !done() && ros::WallTime::now() < end) {
    ros::spinOnce();
    ros::WallDuration(0.001).sleep();
  }
  return done();
}

/// Publishes simulated time `t` on a /clock publisher.
inline void publishClock(const ros::Publisher& clock, const ros::Time& t) {
  rosgraph_msgs::Clock c;
  c.clock = t;
  clock.publish(c);
}

/// With use_sim_time: advances *t by 1 ms of simulated time per 10 ms of wall time (the node
/// loads its model meanwhile) until `started()`, at most `timeout` seconds; returns started().
inline bool tickClockUntil(const ros::Publisher& clock, ros::Time* t,
                           const std::function<bool()>& started, double timeout) {
  return spinUntil(
      [&] {
        *t += ros::Duration(0.001);
        publishClock(clock, *t);
        ros::WallDuration(0.01).sleep();
        return started();
      },
      timeout);
}

/// With use_sim_time: runs *t on by `seconds` of simulated time in /clock messages `burst` apart,
/// waiting after each for `has(t)` (the node's samples up to it); false when one does not come
/// within 10 s of wall time.
inline bool runClockFor(const ros::Publisher& clock, ros::Time* t, double seconds, double burst,
                        const std::function<bool(const ros::Time&)>& has) {
  const ros::Time end = *t + ros::Duration(seconds);
  while (*t < end) {
    *t = std::min(end, *t + ros::Duration(burst));
    publishClock(clock, *t);
    if (!spinUntil([&] { return has(*t); }, 10.0))
      return false;
  }
  return true;
}

/// Spins for `seconds` of wall time.
inline void spinFor(double seconds) {
  spinUntil([] { return false; }, seconds);
}

/// The latest status of every diagnostics name ("<node>: loop", ...).
class DiagnosticsCache {
 public:
  explicit DiagnosticsCache(ros::NodeHandle& nh)
      : sub_(nh.subscribe("/diagnostics", 100, &DiagnosticsCache::onArray, this)) {}

  bool has(const std::string& suffix) const { return find(suffix) != nullptr; }
  /// Level of the status whose name ends with `suffix`; -1 when none.
  int level(const std::string& suffix) const {
    const auto* s = find(suffix);
    return s == nullptr ? -1 : s->level;
  }
  /// Numeric value of key `key` in the status whose name ends with `suffix`; NaN when missing.
  double value(const std::string& suffix, const std::string& key) const {
    const auto* s = find(suffix);
    if (s == nullptr)
      return std::nan("");
    for (const auto& kv : s->values) {
      if (kv.key == key)
        return std::atof(kv.value.c_str());
    }
    return std::nan("");
  }
  /// Text of key `key` in the status whose name ends with `suffix`; empty when missing.
  std::string text(const std::string& suffix, const std::string& key) const {
    if (const auto* s = find(suffix))
      for (const auto& kv : s->values)
        if (kv.key == key)
          return kv.value;
    return "";
  }
  /// Summary message of the status whose name ends with `suffix`; empty when none.
  std::string message(const std::string& suffix) const {
    const auto* s = find(suffix);
    return s == nullptr ? std::string() : s->message;
  }
  /// The highest level any status whose name ends with `suffix` has reported (-1: none), and
  /// the summary it first reported it with: a WARN between two reads is not missed.
  int highestLevel(const std::string& suffix) const {
    const auto* s = find(suffix, highest_);
    return s == nullptr ? -1 : s->level;
  }
  std::string highestMessage(const std::string& suffix) const {
    const auto* s = find(suffix, highest_);
    return s == nullptr ? std::string() : s->message;
  }
  std::size_t arrays() const { return arrays_; }
  std::string describe() const {
    std::string out;
    for (const auto& [name, s] : latest_) {
      out += name + " [" + std::to_string(s.level) + "] " + s.message + "\n";
      for (const auto& kv : s.values)
        out += "  " + kv.key + ": " + kv.value + "\n";
    }
    return out;
  }

 private:
  void onArray(const diagnostic_msgs::DiagnosticArray::ConstPtr& msg) {
    ++arrays_;
    for (const auto& s : msg->status) {
      latest_[s.name] = s;
      const auto highest = highest_.find(s.name);
      if (highest == highest_.end() || s.level > highest->second.level)
        highest_[s.name] = s;
    }
  }
  using Statuses = std::map<std::string, diagnostic_msgs::DiagnosticStatus>;
  const diagnostic_msgs::DiagnosticStatus* find(const std::string& suffix) const {
    return find(suffix, latest_);
  }
  static const diagnostic_msgs::DiagnosticStatus* find(const std::string& suffix,
                                                       const Statuses& statuses) {
    for (const auto& [name, s] : statuses) {
      if (name.size() >= suffix.size() &&
          name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
        return &s;
      }
    }
    return nullptr;
  }

  ros::Subscriber sub_;
  Statuses latest_, highest_;
  std::size_t arrays_ = 0;
};

/// A flat (height 0) TerrainProfile from `from` to `to` [m], lines every 0.5 m across 5 m.
inline TerrainProfile flatProfile(double from, double to, double spacing = 0.05) {
  TerrainPatch patch;
  patch.start_station = from;
  patch.spacing = spacing;
  patch.lateral = Vector::LinSpaced(11, -2.5, 2.5);
  patch.heights =
      Matrix::Zero(11, static_cast<Eigen::Index>(std::lround((to - from) / spacing)) + 1);
  TerrainProfile msg;
  msg.header.frame_id = "odom";
  toMsg(patch, &msg);
  return msg;
}

/// Reads a required private parameter of the test.
template <typename T>
T requiredParam(const ros::NodeHandle& nh, const std::string& name) {
  T value{};
  if (!nh.getParam(name, value)) {
    ADD_FAILURE() << "missing test parameter ~" << name;
  }
  return value;
}

/// The reduced model the node runs and its geometry, from the test's private parameters `vehicle`,
/// `variant` and `cache_dir` (the node's own): loaded from the cache file the node wrote.
struct NodeModel {
  reduction::ReducedModel model;
  VehicleGeometry geometry;
  std::vector<int> pads;  ///< per road input, its pad (reduction::roadInputGroups), as the node's
};
inline NodeModel nodeModel(const ros::NodeHandle& nh) {
  const auto vehicle_file = requiredParam<std::string>(nh, "vehicle");
  const auto variant = vehicle::parseVariant(requiredParam<std::string>(nh, "variant"));
  const vehicle::VehicleDescription description = vehicle::loadVehicleDescription(vehicle_file);
  NodeModel out{reduction::loadOrReduceVehicle(vehicle_file, variant,
                                               requiredParam<std::string>(nh, "cache_dir")),
                vehicleGeometry(description),
                {}};
  out.pads =
      reduction::roadInputGroups(vehicle::buildVehicleModel(description, variant), out.model);
  return out;
}

}  // namespace test
}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
