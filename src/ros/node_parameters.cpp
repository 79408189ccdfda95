#include "tracked_vehicle_dynamics/ros/node_parameters.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace ros_layer {
namespace {

// Reads the parameters of one node handle; every error names the resolved parameter.
class Reader {
 public:
  explicit Reader(const ros::NodeHandle& nh) : nh_(nh) {}

  std::string name(const std::string& key) const { return nh_.resolveName(key); }
  bool has(const std::string& key) const { return nh_.hasParam(key); }

  ParameterError error(const std::string& key, const std::string& what) const {
    return ParameterError(name(key) + ": " + what);
  }

  /// True and the value when set; throws when set with the wrong type.
  template <typename T>
  bool read(const std::string& key, T* value, const char* type) const {
    if (!nh_.hasParam(key))
      return false;
    if (!nh_.getParam(key, *value))
      throw error(key, std::string("must be ") + type);
    return true;
  }

  std::string string(const std::string& key, const std::string& fallback) const {
    std::string value = fallback;
    read(key, &value, "a string");
    return value;
  }

  double number(const std::string& key, double fallback) const {
    double value = fallback;
    read(key, &value, "a number");
    if (!std::isfinite(value))
      throw error(key, "must be finite");
    return value;
  }

  double positive(const std::string& key, double fallback, const char* unit) const {
    const double value = number(key, fallback);
    if (value <= 0.0)
      throw error(key, "must be > 0 " + std::string(unit) + ", got " + text(value));
    return value;
  }

  double nonNegative(const std::string& key, double fallback, const char* unit) const {
    const double value = number(key, fallback);
    if (value < 0.0) {
      throw error(key, "must be >= 0 " + std::string(unit) + ", got " + text(value));
    }
    return value;
  }

  int integer(const std::string& key, int fallback, int minimum) const {
    int value = fallback;
    read(key, &value, "an integer");
    if (value < minimum) {
      throw error(key, "must be >= " + std::to_string(minimum) + ", got " + std::to_string(value));
    }
    return value;
  }

  static std::string text(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
  }

 private:
  const ros::NodeHandle& nh_;
};

}  // namespace

std::string defaultCacheDirectory() {
  if (const char* ros_home = std::getenv("ROS_HOME"); ros_home != nullptr && *ros_home != '\0') {
    return std::string(ros_home) + "/tracked_vehicle_dynamics";
  }
  const char* home = std::getenv("HOME");
  return std::string(home != nullptr ? home : "/tmp") + "/.ros/tracked_vehicle_dynamics";
}

dynamics::DiscretizationMethod parseMethod(const std::string& text, const std::string& name) {
  if (text == "modal")
    return dynamics::DiscretizationMethod::ModalDecoupled;
  if (text == "exact")
    return dynamics::DiscretizationMethod::AugmentedExponential;
  throw ParameterError(name + ": unknown method '" + text + "' (modal or exact)");
}

dynamics::InputHold parseHold(const std::string& text, const std::string& name) {
  if (text == "first_order")
    return dynamics::InputHold::FirstOrder;
  if (text == "zero_order")
    return dynamics::InputHold::ZeroOrder;
  throw ParameterError(name + ": unknown hold '" + text + "' (first_order or zero_order)");
}

NodeParameters readParameters(const ros::NodeHandle& private_nh) {
  const Reader in(private_nh);
  NodeParameters p;

  if (!in.read("vehicle", &p.vehicle, "a string") || p.vehicle.empty()) {
    throw in.error("vehicle", "required: the vehicle description file (e.g. " +
                                  std::string("config/vehicles/paper_vehicle.yaml)"));
  }
  const std::string variant = in.string("variant", vehicle::variantName(p.variant));
  try {
    p.variant = vehicle::parseVariant(variant);
  } catch (const InputError& e) {
    throw in.error("variant", e.what());
  }
  p.cache_dir = in.string("cache_dir", defaultCacheDirectory());
  if (p.cache_dir.empty())
    throw in.error("cache_dir", "must not be empty");

  OnlineVehicleOptions& v = p.vehicle_options;
  v.rate = in.positive("rate", v.rate, "Hz");
  p.publish_rate = in.positive("publish_rate", v.rate, "Hz");
  if (p.publish_rate > v.rate) {
    throw in.error("publish_rate", "must not exceed ~rate (" + Reader::text(v.rate) + " Hz), got " +
                                       Reader::text(p.publish_rate));
  }
  p.comfort_rate = in.positive("comfort_rate", p.comfort_rate, "Hz");
  if (p.comfort_rate > v.rate)
    throw in.error("comfort_rate", "must not exceed ~rate");
  v.method = parseMethod(in.string("method", "modal"), in.name("method"));
  v.hold = parseHold(in.string("hold", "first_order"), in.name("hold"));
  if (in.has("max_mode_frequency"))  // unset: OnlineVehicleOptions' default (rate / 2)
    v.max_mode_frequency_hz = in.nonNegative("max_mode_frequency", 0.0, "Hz");
  v.lateral_offset = in.number("lateral_offset", v.lateral_offset);
  v.comfort_point = in.string("comfort_point", v.comfort_point);
  if (v.comfort_point.empty())
    throw in.error("comfort_point", "must not be empty");
  v.comfort_running_rms_time =
      in.positive("comfort_running_rms_time", v.comfort_running_rms_time, "s");
  v.terrain_keep_behind = in.nonNegative("terrain_keep_behind", v.terrain_keep_behind, "m");
  // Speed slew (online_vehicle.h): 0 and 0 = a new speed applies at once, without travel inertia.
  v.max_acceleration = in.nonNegative("max_acceleration", v.max_acceleration, "m/s^2");
  v.max_deceleration = in.nonNegative("max_deceleration", v.max_deceleration, "m/s^2");

  p.max_speed = in.positive("max_speed", p.max_speed, "m/s");
  p.speed_timeout = in.nonNegative("speed_timeout", p.speed_timeout, "s");
  p.catch_up_limit = in.nonNegative("catch_up_limit", p.catch_up_limit, "s");

  p.odom_frame = in.string("odom_frame", p.odom_frame);
  p.base_frame = in.string("base_frame", p.base_frame);
  p.frame_prefix = in.string("frame_prefix", p.frame_prefix);
  if (p.odom_frame.empty())
    throw in.error("odom_frame", "must not be empty");
  if (p.base_frame.empty())
    throw in.error("base_frame", "must not be empty");
  if (p.odom_frame == p.base_frame)
    throw in.error("base_frame", "must differ from ~odom_frame");
  // The prefix names one vehicle's whole tree (REP-105 per robot: veh1/odom -> veh1/base_link
  // -> veh1/road_wheel_left_1), so that two nodes in one tf tree never share a frame.
  p.footprint_frame = in.string("footprint_frame", "");
  if (!p.footprint_frame.empty() &&
      (p.footprint_frame == p.odom_frame || p.footprint_frame == p.base_frame))
    throw in.error("footprint_frame", "must differ from ~odom_frame and ~base_frame");
  in.read("publish_odom_tf", &p.publish_odom_tf, "a boolean");
  p.odom_frame = p.frame_prefix + p.odom_frame;
  p.base_frame = p.frame_prefix + p.base_frame;
  if (!p.footprint_frame.empty())
    p.footprint_frame = p.frame_prefix + p.footprint_frame;
  p.publish_points_all = !in.read("points", &p.points, "a list of strings");
  in.read("imu_points", &p.imu_points, "a list of strings");
  MeasurementVariances& var = p.variances;
  var.odom_pose = in.nonNegative("variance/odom_pose", var.odom_pose, "m^2 (rad^2)");
  var.odom_twist = in.nonNegative("variance/odom_twist", var.odom_twist, "(m/s)^2 ((rad/s)^2)");
  var.imu_orientation = in.nonNegative("variance/imu_orientation", var.imu_orientation, "rad^2");
  var.imu_angular_velocity =
      in.nonNegative("variance/imu_angular_velocity", var.imu_angular_velocity, "(rad/s)^2");
  var.imu_linear_acceleration =
      in.nonNegative("variance/imu_linear_acceleration", var.imu_linear_acceleration, "(m/s^2)^2");
  // <= 0 would make diagnostic_updater publish at every tick (1 kHz).
  p.diagnostic_period = in.positive("diagnostic_period", p.diagnostic_period, "s");

  reduction::VehicleReductionOptions& r = p.reduction_options;
  const std::string rule = in.string("reduction/rule", "mac");
  if (rule == "mac") {
    r.rule = reduction::VehicleModeRule::MacCorrelation;
  } else if (rule == "band") {
    r.rule = reduction::VehicleModeRule::Band;
  } else {
    throw in.error("reduction/rule", "unknown rule '" + rule + "' (mac or band)");
  }
  r.global_modes = in.integer("reduction/global_modes", r.global_modes, 1);
  r.band_hz = in.positive("reduction/band_hz", r.band_hz, "Hz");
  r.mac_threshold = in.positive("reduction/mac_threshold", r.mac_threshold, "");
  if (r.mac_threshold > 1.0)
    throw in.error("reduction/mac_threshold", "must be <= 1");
  r.mogesec_masters = in.integer("reduction/mogesec_masters", r.mogesec_masters, 0);
  r.mode_count = in.integer("reduction/mode_count", r.mode_count, 0);
  p.reduced_model = in.string("reduced_model", "");
  return p;
}

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
