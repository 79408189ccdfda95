// Conversions between the package's ROS messages and the core's values, in one place so that the
// node stays thin and each conversion is tested by a round trip (core -> msg -> core).
#pragma once

#include <string>
#include <vector>

#include <geometry_msgs/Pose.h>
#include <geometry_msgs/Quaternion.h>
#include <geometry_msgs/Transform.h>
#include <geometry_msgs/Vector3.h>

#include "tracked_vehicle_dynamics/Comfort.h"
#include "tracked_vehicle_dynamics/RoadWheels.h"
#include "tracked_vehicle_dynamics/TerrainProfile.h"
#include "tracked_vehicle_dynamics/dynamics/seat_comfort.h"
#include "tracked_vehicle_dynamics/ros/online_names.h"

namespace tracked_vehicle_dynamics {
namespace ros_layer {

/// TerrainProfile -> patch. Throws InputError naming the field when the sizes disagree
/// (heights.size() != lateral.size() * samples) or a dimension is zero. The values themselves
/// (finite, increasing lateral positions, spacing > 0) are checked by TerrainBuffer::addPatch.
TerrainPatch fromMsg(const TerrainProfile& msg);
/// Patch -> TerrainProfile (header untouched).
void toMsg(const TerrainPatch& patch, TerrainProfile* msg);

/// Wheel states, station [m] and speed [m/s] -> RoadWheels (header untouched); each wheel's name
/// is `name_prefix` + its name, i.e. its tf frame id (the node's ~frame_prefix). Reuses the
/// message's storage when the wheel count is unchanged.
void toMsg(const std::vector<WheelState>& wheels, double station, double speed, RoadWheels* msg,
           const std::string& name_prefix = "");
/// RoadWheels -> wheel states (station and speed through the pointers, when given).
std::vector<WheelState> fromMsg(const RoadWheels& msg, double* station = nullptr,
                                double* speed = nullptr);

/// What the comfort topic carries, in core terms.
struct ComfortReport {
  std::string point;                 ///< output whose accelerations are weighted
  dynamics::ComfortMetrics metrics;  ///< vertical: weighted r.m.s., VDV, MTVV, absorbed power
  double running_rms = 0.0;          ///< [m/s^2]
  double running_rms_time = 1.0;     ///< [s]
  double peak_acceleration = 0.0;    ///< [m/s^2]
  /// The other axes (Wd, We) and the totals (dynamics/seat_comfort.h).
  double weighted_rms_x = 0.0, weighted_rms_y = 0.0, vibration_total_value = 0.0;    ///< [m/s^2]
  double weighted_rms_roll = 0.0, weighted_rms_pitch = 0.0, weighted_rms_yaw = 0.0;  ///< [rad/s^2]
  double rotational_total_value = 0.0, seat_surface_total_value = 0.0;               ///< [m/s^2]
};
/// The report of a seat comfort meter watching `point`.
ComfortReport comfortReport(const dynamics::SeatComfortMeter& meter, const std::string& point,
                            double running_rms_time, double peak_acceleration);
/// Report -> Comfort (header untouched; weighting "Wk").
void toMsg(const ComfortReport& report, Comfort* msg);
ComfortReport fromMsg(const Comfort& msg);

/// Pose <-> geometry_msgs/Transform and geometry_msgs/Pose.
void toMsg(const RigidPose& pose, geometry_msgs::Transform* msg);
RigidPose fromMsg(const geometry_msgs::Transform& msg);
void toMsg(const RigidPose& pose, geometry_msgs::Pose* msg);
RigidPose fromMsg(const geometry_msgs::Pose& msg);

/// Eigen quaternion <-> geometry_msgs/Quaternion.
geometry_msgs::Quaternion toMsg(const Eigen::Quaterniond& q);
Eigen::Quaterniond fromMsg(const geometry_msgs::Quaternion& msg);

/// Eigen vector <-> geometry_msgs/Vector3.
geometry_msgs::Vector3 toMsg(const Vector3& v);
Vector3 fromMsg(const geometry_msgs::Vector3& msg);

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
