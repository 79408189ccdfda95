#include "tracked_vehicle_dynamics/ros/vehicle_frames.h"

#include <algorithm>
#include <cmath>

namespace tracked_vehicle_dynamics {
namespace ros_layer {

Eigen::Quaterniond rotationFromRollPitchYaw(double roll, double pitch, double yaw) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Vector3::UnitZ()) *
                            Eigen::AngleAxisd(pitch, Vector3::UnitY()) *
                            Eigen::AngleAxisd(roll, Vector3::UnitX()));
}

Vector3 rollPitchYaw(const Eigen::Quaterniond& rotation) {
  const Matrix3 r = rotation.normalized().toRotationMatrix();
  // R = Rz(yaw) Ry(pitch) Rx(roll): R(2,0) = -sin(pitch), R(2,1)/R(2,2) = tan(roll),
  // R(1,0)/R(0,0) = tan(yaw).
  const double pitch = std::asin(std::clamp(-r(2, 0), -1.0, 1.0));
  return Vector3(std::atan2(r(2, 1), r(2, 2)), pitch, std::atan2(r(1, 0), r(0, 0)));
}

RigidPose hullPose(double station, const Vector3& cog, const Vector6& hull_displacement) {
  RigidPose pose;
  pose.rotation =
      rotationFromRollPitchYaw(hull_displacement(3), hull_displacement(4), hull_displacement(5));
  pose.translation =
      Vector3(station, 0.0, 0.0) + cog + hull_displacement.head<3>() - pose.rotation * cog;
  return pose;
}

Vector6 hullDisplacement(double station, const Vector3& cog, const RigidPose& pose) {
  Vector6 u;
  u.head<3>() = pose.translation + pose.rotation * cog - cog - Vector3(station, 0.0, 0.0);
  u.tail<3>() = rollPitchYaw(pose.rotation);
  return u;
}

Vector3 hullPointDisplacement(const Vector3& cog, const Vector6& hull_displacement,
                              const Vector3& point) {
  const Vector3 theta = hull_displacement.tail<3>();
  return hull_displacement.head<3>() + theta.cross(point - cog);
}

Vector3 relativePosition(const Vector3& cog, const Vector6& hull_displacement, const Vector3& point,
                         const Vector3& displacement) {
  return point + displacement - hullPointDisplacement(cog, hull_displacement, point);
}

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
