// Kinematics of the frames the node publishes, from the outputs of the reduced model. ROS-free
// (plain Eigen), so it is tested without a master and shared with the tests' offline reference.
//
// Frames (REP-103: x forward, y left, z up; REP-105: odom -> base_link):
//   odom       the path frame: x is the station along the path travelled by the vehicle
//              reference point, z = 0 is the undeformed ground plane.
//   base_link  rigid with the hull; its origin is the vehicle reference point of the description
//              (on the ground plane, under the centre of the road-wheel wheelbase, on the centre
//              line), so every position of the description is a static base_link position.
//
// The hull is rigid: its centre-of-gravity (CoG, at p_G in base_link) displaces by u_G [m] and
// rotates by theta = (rx, ry, rz) [rad] (outputs "hull ux" .. "hull rz"). The pose of base_link in
// odom is then
//   R = Rz(rz) Ry(ry) Rx(rx)            (roll rx, pitch ry, yaw rz; exact for small angles)
//   t = (s, 0, 0) + p_G + u_G - R p_G   (the CoG lands at (s, 0, 0) + p_G + u_G)
// with s the station. Wheel centres and named points are given relative to the hull, to first
// order in theta: a point rigid with the hull at p would displace by
//   u_hull(p) = u_G + theta x (p - p_G),
// so a point whose displacement is u_p sits in base_link at p + (u_p - u_hull(p)).
//
// Rates. The published orientation is R(theta) with theta = (roll, pitch, yaw) read as the
// Z-Y-X Euler angles of R, so the body-axis angular velocity of the published frames is
//   omega_b = E(theta) theta',  E = [1, 0, -sin(pitch);
//                                    0, cos(roll), sin(roll) cos(pitch);
//                                    0, -sin(roll), cos(roll) cos(pitch)]
// (= theta' to first order), and base_link's origin moves at
//   t' = (v, 0, 0) + u_G' - omega x (R p_G)     (omega = R omega_b, in odom axes)
// with v the travel speed: the exact time derivative of the pose above, so a twist integrated
// reproduces the published poses. Differentiating once more,
//   alpha_b = E theta'' + E' theta'     (E' = dE/dt, the body-axis angular acceleration)
// and a point rigid with the hull at p (at t + R p in odom) accelerates at
//   a_p = u_G'' + R (alpha_b x r + omega_b x (omega_b x r)),  r = p - p_G,
// the exact second derivative of its published position (the travel acceleration aside: the
// caller adds a = dv/dt along the path's x while the speed slews, online_vehicle.h). The linear
// model's own point acceleration u_G'' + theta'' x r drops the centripetal and Euler-rate terms
// (about 2 m/s^2 at the sensor mount on the long hill at 30 km/h).
//
// An accelerometer at a point reads the specific force f = R^T (a - g), g = (0, 0, -g0) in odom
// axes: +g0 along the sensor's z at rest on level ground, -g0 sin(pitch) along x nose down.
#pragma once

#include <Eigen/Geometry>

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace online {

/// A child frame's pose in its parent: p_parent = rotation * p_child + translation.
struct RigidPose {
  Vector3 translation = Vector3::Zero();                         ///< [m]
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();  ///< unit quaternion
};

/// Rotation Rz(yaw) Ry(pitch) Rx(roll) [rad].
Eigen::Quaterniond rotationFromRollPitchYaw(double roll, double pitch, double yaw);
/// (roll, pitch, yaw) [rad] of a rotation, pitch in [-pi/2, pi/2].
Vector3 rollPitchYaw(const Eigen::Quaterniond& rotation);

/// base_link in odom for station s [m], CoG position p_G [m] in base_link and hull CoG
/// displacement {u_G [m]; theta [rad]} (equations above).
RigidPose hullPose(double station, const Vector3& cog, const Vector6& hull_displacement);
/// base_link relative to the path frame at station s [m] (REP-120's base_footprint: at (s, 0, 0)
/// in odom, unrotated): the pose less the travel, so path(s) * relativeToPath(pose, s) = pose.
RigidPose relativeToPath(const RigidPose& pose, double station);

/// The inverse of hullPose(): {u_G; theta} from the pose, the station and p_G.
Vector6 hullDisplacement(double station, const Vector3& cog, const RigidPose& pose);

/// u_hull(p) = u_G + theta x (p - p_G) [m]: the displacement a point rigid with the hull at p
/// [m] would have (first order in theta).
Vector3 hullPointDisplacement(const Vector3& cog, const Vector6& hull_displacement,
                              const Vector3& point);

/// Position in base_link [m] of a point whose static (undeformed) position is `point` [m] and
/// whose displacement is `displacement` [m]: p + (u_p - u_hull(p)).
Vector3 relativePosition(const Vector3& cog, const Vector6& hull_displacement, const Vector3& point,
                         const Vector3& displacement);

/// Body-axis angular velocity omega_b = E(theta) theta' [rad/s] of the rotation of Euler angles
/// theta = (roll, pitch, yaw) [rad] changing at theta' [rad/s] (equation above).
Vector3 bodyRate(const Vector3& roll_pitch_yaw, const Vector3& roll_pitch_yaw_rate);

/// The velocity of base_link in its own axes: {linear velocity of its origin [m/s]; angular
/// velocity [rad/s]}, the time derivative of hullPose() at travel speed `speed` [m/s] for the hull
/// CoG displacement {u_G; theta} and its rate {u_G'; theta'} (equations above). What
/// nav_msgs/Odometry's twist holds (child frame base_link).
Vector6 baseLinkTwist(double speed, const Vector3& cog, const Vector6& hull_displacement,
                      const Vector6& hull_velocity);

/// Body-axis angular acceleration alpha_b = E theta'' + E' theta' [rad/s^2], the time derivative
/// of bodyRate() (equations above).
Vector3 bodyAcceleration(const Vector3& roll_pitch_yaw, const Vector3& roll_pitch_yaw_rate,
                         const Vector3& roll_pitch_yaw_acceleration);

/// Acceleration [m/s^2, odom axes] of a point rigid with the hull at `point` [m, base_link]:
/// u_G'' + R (alpha_b x r + omega_b x (omega_b x r)), r = point - cog, for the hull CoG
/// displacement {u_G; theta}, its rate and its acceleration (equations above): the second time
/// derivative of the point's published position, the travel acceleration aside.
Vector3 rigidPointAcceleration(const Vector3& cog, const Vector6& hull_displacement,
                               const Vector6& hull_velocity, const Vector6& hull_acceleration,
                               const Vector3& point);

/// Specific force [m/s^2] in the axes of a frame at `rotation` (in odom) of a point accelerating
/// at `acceleration` [m/s^2] in odom axes: f = R^T (a - g), g = (0, 0, -kStandardGravity). What
/// an accelerometer there reads (sensor_msgs/Imu linear_acceleration, REP-145).
Vector3 specificForce(const Eigen::Quaterniond& rotation, const Vector3& acceleration);

}  // namespace online
}  // namespace tracked_vehicle_dynamics
