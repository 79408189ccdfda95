#include "tracked_vehicle_dynamics/ros/conversions.h"

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace ros_layer {

TerrainPatch fromMsg(const TerrainProfile& msg) {
  const std::size_t lines = msg.lateral.size();
  const std::size_t samples = msg.samples;
  if (lines == 0)
    throw InputError("TerrainProfile: lateral is empty");
  if (samples == 0)
    throw InputError("TerrainProfile: samples is 0");
  if (msg.heights.size() != lines * samples) {
    throw InputError("TerrainProfile: heights has " + std::to_string(msg.heights.size()) +
                     " values, expected lateral.size() x samples = " + std::to_string(lines) +
                     " x " + std::to_string(samples) + " = " + std::to_string(lines * samples));
  }
  TerrainPatch patch;
  patch.start_station = msg.start_station;
  patch.spacing = msg.spacing;
  patch.lateral = Eigen::Map<const Vector>(msg.lateral.data(), static_cast<Eigen::Index>(lines));
  // Row-major in the message, column-major in Eigen.
  patch.heights =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          msg.heights.data(), static_cast<Eigen::Index>(lines), static_cast<Eigen::Index>(samples));
  return patch;
}

void toMsg(const TerrainPatch& patch, TerrainProfile* msg) {
  msg->start_station = patch.start_station;
  msg->spacing = patch.spacing;
  msg->lateral.assign(patch.lateral.data(), patch.lateral.data() + patch.lateral.size());
  msg->samples = static_cast<std::uint32_t>(patch.heights.cols());
  msg->heights.resize(static_cast<std::size_t>(patch.heights.size()));
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      msg->heights.data(), patch.heights.rows(), patch.heights.cols()) = patch.heights;
}

void toMsg(const std::vector<WheelState>& wheels, double station, double speed, RoadWheels* msg,
           const std::string& name_prefix) {
  msg->station = station;
  msg->speed = speed;
  msg->wheels.resize(wheels.size());
  for (std::size_t i = 0; i < wheels.size(); ++i) {
    RoadWheelState& out = msg->wheels[i];
    const std::string& name = wheels[i].name;
    // Compared in place: the node publishes every sample and must not allocate for the names.
    const bool same = out.name.size() == name_prefix.size() + name.size() &&
                      out.name.compare(0, name_prefix.size(), name_prefix) == 0 &&
                      out.name.compare(name_prefix.size(), name.size(), name) == 0;
    if (!same)
      out.name = name_prefix + name;
    out.displacement = wheels[i].displacement;
    out.velocity = wheels[i].velocity;
    out.acceleration = wheels[i].acceleration;
  }
}

std::vector<WheelState> fromMsg(const RoadWheels& msg, double* station, double* speed) {
  if (station != nullptr)
    *station = msg.station;
  if (speed != nullptr)
    *speed = msg.speed;
  std::vector<WheelState> wheels(msg.wheels.size());
  for (std::size_t i = 0; i < wheels.size(); ++i) {
    wheels[i].name = msg.wheels[i].name;
    wheels[i].displacement = msg.wheels[i].displacement;
    wheels[i].velocity = msg.wheels[i].velocity;
    wheels[i].acceleration = msg.wheels[i].acceleration;
  }
  return wheels;
}

void toMsg(const ComfortReport& report, Comfort* msg) {
  msg->point = report.point;
  msg->weighting = "Wk";
  msg->weighted_rms = report.metrics.weighted_rms;
  msg->vdv = report.metrics.vdv;
  msg->mtvv = report.metrics.mtvv;
  msg->mtvv_linear = report.metrics.mtvv_linear;
  msg->peak_weighted = report.metrics.peak_weighted;
  msg->running_rms = report.running_rms;
  msg->running_rms_time = report.running_rms_time;
  msg->has_absorbed_power = report.metrics.absorbed_power.has_value();
  msg->absorbed_power = report.metrics.absorbed_power.value_or(0.0);
  msg->peak_acceleration = report.peak_acceleration;
  msg->duration = report.metrics.duration;
  msg->samples = report.metrics.samples;
  msg->weighted_rms_x = report.weighted_rms_x;
  msg->weighted_rms_y = report.weighted_rms_y;
  msg->vibration_total_value = report.vibration_total_value;
  msg->weighted_rms_roll = report.weighted_rms_roll;
  msg->weighted_rms_pitch = report.weighted_rms_pitch;
  msg->weighted_rms_yaw = report.weighted_rms_yaw;
  msg->rotational_total_value = report.rotational_total_value;
  msg->seat_surface_total_value = report.seat_surface_total_value;
}

ComfortReport comfortReport(const dynamics::SeatComfortMeter& meter, const std::string& point,
                            double running_rms_time, double peak_acceleration) {
  ComfortReport report;
  report.point = point;
  report.metrics = meter.vertical().metrics();
  report.running_rms = meter.vertical().runningRms();
  report.running_rms_time = running_rms_time;
  report.peak_acceleration = peak_acceleration;
  report.weighted_rms_x = meter.longitudinal().weightedRms();
  report.weighted_rms_y = meter.lateral().weightedRms();
  report.vibration_total_value = meter.translationalTotalValue();
  report.weighted_rms_roll = meter.roll().weightedRms();
  report.weighted_rms_pitch = meter.pitch().weightedRms();
  report.weighted_rms_yaw = meter.yaw().weightedRms();
  report.rotational_total_value = meter.rotationalTotalValue();
  report.seat_surface_total_value = meter.seatSurfaceTotalValue();
  return report;
}

ComfortReport fromMsg(const Comfort& msg) {
  ComfortReport report;
  report.point = msg.point;
  report.metrics.weighted_rms = msg.weighted_rms;
  report.metrics.vdv = msg.vdv;
  report.metrics.mtvv = msg.mtvv;
  report.metrics.mtvv_linear = msg.mtvv_linear;
  report.metrics.peak_weighted = msg.peak_weighted;
  if (msg.has_absorbed_power)
    report.metrics.absorbed_power = msg.absorbed_power;
  report.metrics.duration = msg.duration;
  report.metrics.samples = static_cast<std::size_t>(msg.samples);
  report.running_rms = msg.running_rms;
  report.running_rms_time = msg.running_rms_time;
  report.peak_acceleration = msg.peak_acceleration;
  report.weighted_rms_x = msg.weighted_rms_x;
  report.weighted_rms_y = msg.weighted_rms_y;
  report.vibration_total_value = msg.vibration_total_value;
  report.weighted_rms_roll = msg.weighted_rms_roll;
  report.weighted_rms_pitch = msg.weighted_rms_pitch;
  report.weighted_rms_yaw = msg.weighted_rms_yaw;
  report.rotational_total_value = msg.rotational_total_value;
  report.seat_surface_total_value = msg.seat_surface_total_value;
  return report;
}

geometry_msgs::Quaternion toMsg(const Eigen::Quaterniond& q) {
  geometry_msgs::Quaternion msg;
  msg.x = q.x();
  msg.y = q.y();
  msg.z = q.z();
  msg.w = q.w();
  return msg;
}

Eigen::Quaterniond fromMsg(const geometry_msgs::Quaternion& msg) {
  return Eigen::Quaterniond(msg.w, msg.x, msg.y, msg.z);
}

void toMsg(const RigidPose& pose, geometry_msgs::Transform* msg) {
  msg->translation = toMsg(pose.translation);
  msg->rotation = toMsg(pose.rotation);
}

RigidPose fromMsg(const geometry_msgs::Transform& msg) {
  RigidPose pose;
  pose.translation = fromMsg(msg.translation);
  pose.rotation = fromMsg(msg.rotation);
  return pose;
}

void toMsg(const RigidPose& pose, geometry_msgs::Pose* msg) {
  msg->position.x = pose.translation.x();
  msg->position.y = pose.translation.y();
  msg->position.z = pose.translation.z();
  msg->orientation = toMsg(pose.rotation);
}

RigidPose fromMsg(const geometry_msgs::Pose& msg) {
  RigidPose pose;
  pose.translation = Vector3(msg.position.x, msg.position.y, msg.position.z);
  pose.rotation = fromMsg(msg.orientation);
  return pose;
}

geometry_msgs::Vector3 toMsg(const Vector3& v) {
  geometry_msgs::Vector3 msg;
  msg.x = v.x();
  msg.y = v.y();
  msg.z = v.z();
  return msg;
}

Vector3 fromMsg(const geometry_msgs::Vector3& msg) {
  return Vector3(msg.x, msg.y, msg.z);
}

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
