// Every parameter of vehicle_dynamics_node, read once at construction by readParameters()
// (STYLE.md #4). Defaults come from the core's option structs (OnlineVehicleOptions,
// VehicleReductionOptions); config/vehicle_dynamics.yaml documents each key with unit and default.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include <ros/node_handle.h>

#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "tracked_vehicle_dynamics/ros/online_names.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace ros_layer {

/// A missing or invalid parameter; the message starts with the parameter's resolved name.
class ParameterError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// ~variance/*: the diagonals the node writes into the covariances of odom and imu/<point>. The
/// values are exact model outputs; 0 leaves a covariance all zeros, which sensor_msgs/Imu defines
/// as "unknown" and nav_msgs/Odometry not at all (robot_localization clamps such a variance to
/// 1e-9): a stack that fuses them sets what its filter should assume.
struct MeasurementVariances {
  double odom_pose = 0.0;                ///< [m^2] and [rad^2], pose diagonal of odom
  double odom_twist = 0.0;               ///< [(m/s)^2] and [(rad/s)^2], twist diagonal of odom
  double imu_orientation = 0.0;          ///< [rad^2]
  double imu_angular_velocity = 0.0;     ///< [(rad/s)^2]
  double imu_linear_acceleration = 0.0;  ///< [(m/s^2)^2]
};

struct NodeParameters {
  std::string vehicle;  ///< ~vehicle: description YAML file (required)
  vehicle::Variant variant = vehicle::Variant::Tracked;  ///< ~variant
  std::string cache_dir;  ///< ~cache_dir; default $ROS_HOME/tracked_vehicle_dynamics (~/.ros/...)
  /// ~rate, ~method, ~hold, ~lateral_offset, ...; its rate is the one stepped, 1e9 / floor(1e9 /
  /// ~rate) (whole nanoseconds a step, never below ~rate).
  OnlineVehicleOptions vehicle_options;
  double requested_rate = 0.0;                           ///< ~rate as given [Hz]
  reduction::VehicleReductionOptions reduction_options;  ///< ~reduction/*
  /// ~reduced_model: a file written by `tvd reduce --out`, run instead of the cache (its own
  /// reduction options replace ~reduction/*); empty: the cache.
  std::string reduced_model;
  double publish_rate = 0.0;   ///< ~publish_rate [Hz], default ~rate
  double comfort_rate = 10.0;  ///< ~comfort_rate [Hz]
  /// ~comfort_point was set (vehicle_options.comfort_point holds it). Unset, that stays empty and
  /// the node watches the description's `crew_seat` point when it names one, else the hull's CoG
  /// (online::resolveComfortPoint()).
  bool comfort_point_given = false;
  /// ~ground_contact_rate [Hz]: how often the contact forces are checked for a pull (the bonded
  /// model beyond its range, OnlineVehicle::checkGroundContact); 0: never.
  double ground_contact_rate = 50.0;
  double max_speed = 30.0;  ///< ~max_speed [m/s]; faster speed messages are rejected
  /// ~initial_speed [m/s], at most ~max_speed: the speed a run starts at (the start, ~reset and a
  /// jump back of simulated time), as if a speed message had set it then: a replay entered at
  /// speed, braking with its travel inertia (a slew) without first accelerating from rest.
  double initial_speed = 0.0;
  /// ~speed_timeout [s] of ROS time without a valid speed message after which the vehicle stops
  /// where it is (a driver that died must not leave it driving on); 0: never.
  double speed_timeout = 0.0;
  double catch_up_limit = 0.1;      ///< ~catch_up_limit [s] of simulated time caught up at once
  std::string odom_frame = "odom";  ///< ~frame_prefix + ~odom_frame
  std::string base_frame = "base_link";  ///< ~frame_prefix + ~base_frame
  std::string frame_prefix;  ///< ~frame_prefix, before every frame id (odom, base, wheels, points)
  /// ~footprint_frame (~frame_prefix + it): when set, odom -> footprint carries the travel along
  /// the path, (s, 0, 0), and footprint -> base_link the hull's motion on it (REP-120's
  /// base_footprint); empty: odom -> base_link in one transform.
  std::string footprint_frame;
  /// ~publish_odom_tf: publish the transform whose parent is ~odom_frame (another source, e.g.
  /// the simulator's own vehicle pose or a localisation filter, may own it).
  bool publish_odom_tf = true;
  /// ~points: named points published as frames; empty: all points of the description.
  std::vector<std::string> points;
  bool publish_points_all = true;  ///< true when ~points was not given
  /// ~imu_points: named points (published as frames) with a simulated IMU, sensor_msgs/Imu on
  /// imu/<point>; empty: none.
  std::vector<std::string> imu_points;
  MeasurementVariances variances;  ///< ~variance/*
  /// ~diagnostic_period [s]; diagnostic_updater reads the key itself, the node validates it.
  double diagnostic_period = 1.0;
  /// Private parameters set but not read by the node (misspelt or unknown), each as "~key"
  /// with the nearest known one when close: the node warns about them at start-up.
  std::vector<std::string> unknown_parameters;
  /// Values accepted but likely not meant (e.g. a ~frame_prefix without its trailing '/'), each
  /// naming the parameter: the node warns about them at start-up.
  std::vector<std::string> warnings;
};

/// $ROS_HOME/tracked_vehicle_dynamics, or $HOME/.ros/tracked_vehicle_dynamics.
std::string defaultCacheDirectory();

/// Reads every parameter from the private node handle. Throws ParameterError naming the
/// parameter for a missing ~vehicle, a wrong type or an out-of-range value.
NodeParameters readParameters(const ros::NodeHandle& private_nh);

/// "modal" / "exact" -> method; "first_order" / "zero_order" -> hold (dynamics::methodName,
/// dynamics::holdName: the inverse). Throw ParameterError naming the parameter `name`.
dynamics::DiscretizationMethod parseMethod(const std::string& text, const std::string& name);
dynamics::InputHold parseHold(const std::string& text, const std::string& name);

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
