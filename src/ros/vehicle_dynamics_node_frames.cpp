// The node's frames, set up once the model is loaded: which named points are published (on
// /tf_static when rigid with the hull, else on /tf), their IMUs, and the frame ids of every
// transform and message (odom -> [footprint ->] base_link -> wheels and points).
#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <ros/names.h>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/ros/conversions.h"
#include "tracked_vehicle_dynamics/ros/online_names.h"
#include "tracked_vehicle_dynamics/ros/vehicle_dynamics_node.h"

namespace tracked_vehicle_dynamics {
namespace ros_layer {

std::size_t VehicleDynamicsNode::pointIndex(const std::string& name, const std::string& key) const {
  const auto& points = vehicle_->geometry().points;
  const auto it = std::find_if(points.begin(), points.end(),
                               [&](const VehicleGeometry::Body& b) { return b.name == name; });
  if (it == points.end()) {
    std::string known;
    for (const auto& p : points)
      known += (known.empty() ? "" : ", ") + p.name;
    throw ParameterError(private_nh_.resolveName(key) + ": unknown point '" + name +
                         "' (the description has: " + known + "); list only these in ~" + key +
                         " (launch argument " + key + ")");
  }
  return static_cast<std::size_t>(it - points.begin());
}

void VehicleDynamicsNode::setUpImus() {
  // An IMU reading is of its frame's origin, so the point must be one of the published frames
  // (published_points_ still holds every one of them here).
  for (const std::string& name : params_.imu_points) {
    const std::size_t i = pointIndex(name, "imu_points");
    const std::string key = private_nh_.resolveName("imu_points");
    if (std::find(published_points_.begin(), published_points_.end(), i) == published_points_.end())
      throw ParameterError(key + ": point '" + name +
                           "' is not published as a frame; add it to ~points (launch argument "
                           "points) or leave ~points unset");
    if (std::find(imu_points_.begin(), imu_points_.end(), i) != imu_points_.end())
      throw ParameterError(key + ": point '" + name + "' is listed twice");
    const std::string topic = "imu/" + name;
    std::string why;
    if (!ros::names::validate(topic, why))
      throw ParameterError(key + ": point '" + name + "' does not make a valid topic name " +
                           topic + " (" + why + ")");
    imu_points_.push_back(i);
    sensor_msgs::Imu& msg = imu_msgs_.emplace_back();
    msg.header.frame_id = params_.frame_prefix + name;
    const MeasurementVariances& v = params_.variances;
    for (int d = 0; d < 3; ++d) {
      msg.orientation_covariance[4 * d] = v.imu_orientation;
      msg.angular_velocity_covariance[4 * d] = v.imu_angular_velocity;
      msg.linear_acceleration_covariance[4 * d] = v.imu_linear_acceleration;
    }
  }
}

void VehicleDynamicsNode::setUpFrames() {
  const VehicleGeometry& geometry = vehicle_->geometry();
  // The hull's frames must not be one of the frames published under them (a base_frame named
  // crew_seat would publish crew_seat -> crew_seat).
  std::vector<std::string> children;
  for (const auto& wheel : geometry.wheels)
    children.push_back(params_.frame_prefix + wheel.name);
  for (const auto& point : geometry.points)
    children.push_back(params_.frame_prefix + point.name);
  for (const auto& [key, frame] :
       {std::pair<const char*, const std::string*>{"odom_frame", &params_.odom_frame},
        {"base_frame", &params_.base_frame},
        {"footprint_frame", &params_.footprint_frame}}) {
    if (std::find(children.begin(), children.end(), *frame) != children.end())
      throw ParameterError(private_nh_.resolveName(key) + ": '" + *frame +
                           "' is also the frame of a road wheel or named point of the description");
  }
  if (params_.publish_points_all) {
    for (std::size_t i = 0; i < geometry.points.size(); ++i)
      published_points_.push_back(i);
  } else {
    for (const std::string& name : params_.points) {
      const std::size_t i = pointIndex(name, "points");
      // As ~imu_points: a name given twice is a slip, said rather than guessed at.
      if (std::find(published_points_.begin(), published_points_.end(), i) !=
          published_points_.end())
        throw ParameterError(private_nh_.resolveName("points") + ": point '" + name +
                             "' is listed twice");
      published_points_.push_back(i);
    }
  }
  setUpImus();
  // Points rigid with the hull never move in base_link: /tf_static once, not /tf every sample.
  std::vector<std::size_t> moving;
  for (std::size_t i : published_points_)
    (vehicle_->pointIsRigid(i) ? static_points_ : moving).push_back(i);
  published_points_ = moving;
  if (!static_points_.empty()) {
    // Stamped with the ROS time of publication, as static_transform_publisher does: tf2 holds
    // static transforms for every time, but tools that show a transform's age (rviz, tf_monitor)
    // read the stamp, and 0 would show the age of the epoch.
    const ros::Time now = ros::Time::now();
    std::vector<geometry_msgs::TransformStamped> fixed(static_points_.size());
    for (std::size_t k = 0; k < static_points_.size(); ++k) {
      const VehicleGeometry::Body& point = geometry.points[static_points_[k]];
      fixed[k].header.stamp = now;
      fixed[k].header.frame_id = params_.base_frame;
      fixed[k].child_frame_id = params_.frame_prefix + point.name;
      RigidPose pose;
      pose.translation = point.position;
      toMsg(pose, &fixed[k].transform);
    }
    static_broadcaster_ = std::make_unique<tf2_ros::StaticTransformBroadcaster>();
    // On simulated time before the first /clock, ROS time is 0: they go out with the first
    // sample instead, stamped with its time (advanceTo), as everything else the node publishes.
    if (now.isZero())
      pending_static_ = std::move(fixed);
    else
      static_broadcaster_->sendTransform(fixed);
  }
  // The hull's transforms first: odom -> base_link, or odom -> footprint -> base_link, less the
  // one from odom when another source owns it (~publish_odom_tf false). publishState() fills
  // them from hull_links_, in this order.
  const bool footprint = !params_.footprint_frame.empty();
  if (params_.publish_odom_tf)
    hull_links_.push_back(footprint ? HullLink::Path : HullLink::Whole);
  if (footprint)
    hull_links_.push_back(HullLink::AbovePath);
  auto& transforms_ = tf_msg_.transforms;
  transforms_.resize(hull_links_.size() + geometry.wheels.size() + published_points_.size());
  std::size_t k = 0;
  for (HullLink link : hull_links_) {
    transforms_[k].header.frame_id =
        link == HullLink::AbovePath ? params_.footprint_frame : params_.odom_frame;
    transforms_[k++].child_frame_id =
        link == HullLink::Path ? params_.footprint_frame : params_.base_frame;
  }
  for (const auto& wheel : geometry.wheels) {
    transforms_[k].header.frame_id = params_.base_frame;
    transforms_[k++].child_frame_id = params_.frame_prefix + wheel.name;
  }
  for (std::size_t i : published_points_) {
    transforms_[k].header.frame_id = params_.base_frame;
    transforms_[k++].child_frame_id = params_.frame_prefix + geometry.points[i].name;
  }
  accel_msg_.header.frame_id = params_.base_frame;
  twist_msg_.header.frame_id = params_.base_frame;
  odom_msg_.header.frame_id = params_.odom_frame;
  odom_msg_.child_frame_id = params_.base_frame;
  for (int d = 0; d < 6; ++d) {
    odom_msg_.pose.covariance[7 * d] = params_.variances.odom_pose;
    odom_msg_.twist.covariance[7 * d] = params_.variances.odom_twist;
  }
  wheels_msg_.header.frame_id = params_.base_frame;
  // The comfort metrics are of the acceleration at the comfort point: its frame when it is
  // published as one, else the hull's (the "hull" point is the hull CoG, rigid in base_link).
  comfort_msg_.header.frame_id = params_.base_frame;
  for (const auto* points : {&published_points_, &static_points_}) {
    for (std::size_t i : *points) {
      if (geometry.points[i].name == vehicle_->comfortPoint())
        comfort_msg_.header.frame_id = params_.frame_prefix + geometry.points[i].name;
    }
  }
}

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
