#include "tracked_vehicle_dynamics/online/vehicle_frames.h"

#include <algorithm>
#include <cmath>

namespace tracked_vehicle_dynamics {
namespace online {

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

RigidPose relativeToPath(const RigidPose& pose, double station) {
  RigidPose relative = pose;
  relative.translation.x() -= station;
  return relative;
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

namespace {

/// E(theta): body rate = E theta' (vehicle_frames.h).
Matrix3 eulerRateMatrix(const Vector3& roll_pitch_yaw) {
  const double sr = std::sin(roll_pitch_yaw(0)), cr = std::cos(roll_pitch_yaw(0));
  const double sp = std::sin(roll_pitch_yaw(1)), cp = std::cos(roll_pitch_yaw(1));
  Matrix3 e;
  e << 1.0, 0.0, -sp,    //
      0.0, cr, sr * cp,  //
      0.0, -sr, cr * cp;
  return e;
}

/// dE/dt for Euler angles theta changing at theta'.
Matrix3 eulerRateMatrixDerivative(const Vector3& roll_pitch_yaw, const Vector3& rate) {
  const double sr = std::sin(roll_pitch_yaw(0)), cr = std::cos(roll_pitch_yaw(0));
  const double sp = std::sin(roll_pitch_yaw(1)), cp = std::cos(roll_pitch_yaw(1));
  const double droll = rate(0), dpitch = rate(1);
  Matrix3 de;
  de << 0.0, 0.0, -cp * dpitch,                              //
      0.0, -sr * droll, cr * cp * droll - sr * sp * dpitch,  //
      0.0, -cr * droll, -sr * cp * droll - cr * sp * dpitch;
  return de;
}

}  // namespace

Vector3 bodyRate(const Vector3& roll_pitch_yaw, const Vector3& roll_pitch_yaw_rate) {
  return eulerRateMatrix(roll_pitch_yaw) * roll_pitch_yaw_rate;
}

Vector3 bodyAcceleration(const Vector3& roll_pitch_yaw, const Vector3& roll_pitch_yaw_rate,
                         const Vector3& roll_pitch_yaw_acceleration) {
  return eulerRateMatrix(roll_pitch_yaw) * roll_pitch_yaw_acceleration +
         eulerRateMatrixDerivative(roll_pitch_yaw, roll_pitch_yaw_rate) * roll_pitch_yaw_rate;
}

Vector3 rigidPointAcceleration(const Vector3& cog, const Vector6& hull_displacement,
                               const Vector6& hull_velocity, const Vector6& hull_acceleration,
                               const Vector3& point) {
  const Vector3 theta = hull_displacement.tail<3>();
  const Vector3 omega = bodyRate(theta, hull_velocity.tail<3>());
  const Vector3 alpha =
      bodyAcceleration(theta, hull_velocity.tail<3>(), hull_acceleration.tail<3>());
  const Vector3 r = point - cog;
  const Eigen::Quaterniond rotation = rotationFromRollPitchYaw(theta(0), theta(1), theta(2));
  return hull_acceleration.head<3>() + rotation * (alpha.cross(r) + omega.cross(omega.cross(r)));
}

Vector6 baseLinkTwist(double speed, const Vector3& cog, const Vector6& hull_displacement,
                      const Vector6& hull_velocity) {
  const Matrix3 r =
      rotationFromRollPitchYaw(hull_displacement(3), hull_displacement(4), hull_displacement(5))
          .toRotationMatrix();
  const Vector3 omega_body = bodyRate(hull_displacement.tail<3>(), hull_velocity.tail<3>());
  const Vector3 omega = r * omega_body;
  // t' = (v, 0, 0) + u_G' - omega x (R p_G), in odom axes; R^T t' in base_link axes.
  const Vector3 origin_velocity =
      Vector3(speed, 0.0, 0.0) + hull_velocity.head<3>() - omega.cross(r * cog);
  Vector6 twist;
  twist.head<3>().noalias() = r.transpose() * origin_velocity;
  twist.tail<3>() = omega_body;
  return twist;
}

Vector3 specificForce(const Eigen::Quaterniond& rotation, const Vector3& acceleration) {
  return rotation.conjugate() * (acceleration + Vector3(0.0, 0.0, kStandardGravity));
}

}  // namespace online
}  // namespace tracked_vehicle_dynamics
