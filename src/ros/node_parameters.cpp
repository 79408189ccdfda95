#include "tracked_vehicle_dynamics/ros/node_parameters.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

#include <ros/names.h>

#include "tracked_vehicle_dynamics/dynamics/comfort.h"
#include "tracked_vehicle_dynamics/dynamics/running_window.h"
#include "tracked_vehicle_dynamics/dynamics/speed_profile.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/home_path.h"
#include "tracked_vehicle_dynamics/io/number_text.h"

namespace tracked_vehicle_dynamics {
namespace ros_layer {
namespace {

// The highest ~rate the node accepts [Hz] (a 10 us step).
constexpr double kMaxRateHz = 1e5;
// The longest ~catch_up_limit [s]. A tick replays the whole catch-up before it returns (on real
// time in roscpp's network thread, which meanwhile serves no message) and the publishers' queues
// hold all of it: 10 s is 10,000 steps at 1 kHz, about 0.1 s of work, and far beyond any
// stall worth replaying rather than skipping.
constexpr double kMaxCatchUpLimit = 10.0;
// Publishing and check rates below this [Hz] (once in 11.6 days) are a slip: ~rate / 1e-20
// overflowed the step count (llround) into "every step", the opposite of what was asked.
constexpr double kMinDerivedRateHz = 1e-6;
// The longest ~diagnostic_period [s]: a day. diagnostic_updater adds it to ros::Time::now(),
// whose 32-bit seconds overflow (a FATAL that named no parameter) for a period of about 2e9 s.
constexpr double kMaxDiagnosticPeriod = 86400.0;

// Reads the parameters of one node handle; every error names the resolved parameter.
class Reader {
 public:
  explicit Reader(const ros::NodeHandle& nh) : nh_(nh) {}

  std::string name(const std::string& key) const { return nh_.resolveName(key); }
  bool has(const std::string& key) const {
    seen_.insert(key);
    return nh_.hasParam(key);
  }

  ParameterError error(const std::string& key, const std::string& what) const {
    return ParameterError(name(key) + ": " + what);
  }

  /// True and the value when set; throws when set with the wrong type.
  template <typename T>
  bool read(const std::string& key, T* value, const char* type) const {
    if (!has(key))
      return false;
    if (!nh_.getParam(key, *value))
      throw error(key, std::string("must be ") + type + got(key));
    return true;
  }

  /// ", got <what the parameter server holds>" for a value of the wrong type: the user sees
  /// what was read (a quoted "30" from a launch file reads as a string).
  std::string got(const std::string& key) const {
    XmlRpc::XmlRpcValue raw;
    if (!nh_.getParam(key, raw))
      return std::string();
    switch (raw.getType()) {
      case XmlRpc::XmlRpcValue::TypeString:
        return ", got the string '" + static_cast<std::string>(raw) + "'";
      case XmlRpc::XmlRpcValue::TypeBoolean:
        return std::string(", got the boolean ") + (static_cast<bool>(raw) ? "true" : "false");
      case XmlRpc::XmlRpcValue::TypeInt:
        return ", got the integer " + std::to_string(static_cast<int>(raw));
      case XmlRpc::XmlRpcValue::TypeDouble:
        return ", got the number " + text(static_cast<double>(raw));
      case XmlRpc::XmlRpcValue::TypeArray:
        return ", got a list of " + std::to_string(raw.size()) + " items";
      case XmlRpc::XmlRpcValue::TypeStruct:
        return ", got a dictionary";
      default:
        return std::string();
    }
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

  /// An integer in [minimum, maximum]; `why` follows the message of one above maximum.
  int integer(const std::string& key, int fallback, int minimum,
              int maximum = std::numeric_limits<int>::max(), const std::string& why = "") const {
    // Read as XmlRpc: roscpp's getParam(int&) rounds a double (2.5 -> 3) without a word, which
    // would build another model than the one written.
    int value = fallback;
    XmlRpc::XmlRpcValue raw;
    if (has(key) && nh_.getParam(key, raw)) {
      if (raw.getType() == XmlRpc::XmlRpcValue::TypeInt) {
        value = static_cast<int>(raw);
      } else if (raw.getType() == XmlRpc::XmlRpcValue::TypeDouble &&
                 std::floor(static_cast<double>(raw)) == static_cast<double>(raw) &&
                 std::abs(static_cast<double>(raw)) < 1e9) {
        value = static_cast<int>(static_cast<double>(raw));
      } else {
        throw error(key, "must be an integer" + got(key));
      }
    }
    if (maximum == std::numeric_limits<int>::max()) {
      if (value < minimum)
        throw error(key,
                    "must be >= " + std::to_string(minimum) + ", got " + std::to_string(value));
    } else if (value < minimum || value > maximum) {
      // As tvd's --global-modes says it.
      throw error(key, "must be an integer in [" + std::to_string(minimum) + ", " +
                           std::to_string(maximum) + "], got " + std::to_string(value) +
                           (value > maximum ? why : ""));
    }
    return value;
  }

  /// A frame id (or prefix) tf2 accepts: no leading '/' (tf2 refuses it) and no whitespace.
  std::string frame(const std::string& key, const std::string& fallback, bool may_be_empty) const {
    const std::string value = string(key, fallback);
    if (value.empty() && !may_be_empty)
      throw error(key, "must not be empty");
    if (!value.empty() && value.front() == '/')
      throw error(key, "'" + value + "' must not start with '/' (tf2 refuses such frame ids)");
    if (value.find_first_of(" \t\n") != std::string::npos)
      throw error(key, "'" + value + "' must not contain whitespace");
    // An empty name segment: tf2 takes 'veh1//odom', but no tool lists it as 'veh1/odom', so a
    // listener asking for the frame it expects never finds it.
    if (value.find("//") != std::string::npos)
      throw error(key, "'" + value + "' must not contain '//' (an empty name between slashes)");
    return value;
  }

  /// The node's private parameters that no read asked for (misspelt or unknown), relative to
  /// the private namespace, e.g. "speed_timout".
  std::vector<std::string> unread() const {
    std::vector<std::string> names, out;
    nh_.getParamNames(names);
    const std::string prefix = nh_.getNamespace() + "/";
    for (const std::string& full : names) {
      if (full.compare(0, prefix.size(), prefix) != 0)
        continue;
      const std::string key = full.substr(prefix.size());
      if (seen_.count(key) == 0)
        out.push_back(key);
    }
    std::sort(out.begin(), out.end());
    return out;
  }

  /// The read key nearest to `key` by edit distance, when at most 2 edits away; else "".
  std::string nearest(const std::string& key) const {
    std::string best;
    std::size_t best_distance = 3;
    for (const std::string& known : seen_) {
      const std::size_t d = editDistance(key, known);
      if (d < best_distance) {
        best_distance = d;
        best = known;
      }
    }
    return best;
  }

  static std::string text(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
  }

 private:
  const ros::NodeHandle& nh_;
  mutable std::set<std::string> seen_;  // every key asked for
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
  if (const std::optional<dynamics::DiscretizationMethod> method = dynamics::methodFromName(text))
    return *method;
  throw ParameterError(name + ": unknown method '" + text + "' (modal or exact)");
}

dynamics::InputHold parseHold(const std::string& text, const std::string& name) {
  if (const std::optional<dynamics::InputHold> hold = dynamics::holdFromName(text))
    return *hold;
  throw ParameterError(name + ": unknown hold '" + text + "' (first_order or zero_order)");
}

namespace {

// A file parameter given as a relative path that is not there: roslaunch runs a node in
// $ROS_HOME, not where the launch was started, so say where it was looked for and what works.
void requireFoundFile(const Reader& in, const std::string& key, const std::string& path) {
  std::error_code ec;
  const std::filesystem::path file(path);
  if (file.is_absolute() || std::filesystem::exists(file, ec))
    return;
  throw in.error(key, path + ": file not found relative to the node's working directory " +
                          std::filesystem::current_path(ec).string() +
                          " (roslaunch runs nodes in $ROS_HOME): give an absolute path, e.g. "
                          "$(find my_package)/" +
                          path + " in a launch file");
}

// roslaunch passes a path as written: "~/x" would name a directory "~" in $ROS_HOME. Expanded
// as a shell would (io/home_path.h).
std::string expandedPath(const Reader& in, const std::string& key, const std::string& path) {
  try {
    return io::expandHome(path, "the path");
  } catch (const InputError& e) {
    throw in.error(key, e.what());
  }
}

}  // namespace

NodeParameters readParameters(const ros::NodeHandle& private_nh) {
  const Reader in(private_nh);
  NodeParameters p;

  if (!in.read("vehicle", &p.vehicle, "a string") || p.vehicle.empty()) {
    throw in.error("vehicle", "required: the vehicle description file (e.g. " +
                                  std::string("config/vehicles/paper_vehicle.yaml)"));
  }
  p.vehicle = expandedPath(in, "vehicle", p.vehicle);
  requireFoundFile(in, "vehicle", p.vehicle);
  const std::string variant = in.string("variant", vehicle::variantName(p.variant));
  try {
    p.variant = vehicle::parseVariant(variant);
  } catch (const InputError& e) {
    throw in.error("variant", e.what());
  }
  p.cache_dir = in.string("cache_dir", defaultCacheDirectory());
  if (p.cache_dir.empty())
    throw in.error("cache_dir", "must not be empty");
  p.cache_dir = expandedPath(in, "cache_dir", p.cache_dir);

  OnlineVehicleOptions& v = p.vehicle_options;
  v.rate = in.positive("rate", v.rate, "Hz");
  // A step of the reduced vehicle takes tens of microseconds (OnlineVehicle::step, 31-44 us on
  // the bundled one): a rate far above 1/step cannot be kept and only stalls the node in its
  // catch-up (1e9 Hz pegged a core and ignored SIGINT).
  if (v.rate > kMaxRateHz)
    throw in.error("rate", "must not exceed " + Reader::text(kMaxRateHz) +
                               " Hz (a step of the model takes tens of microseconds: the node "
                               "could not keep up), got " +
                               Reader::text(v.rate));
  // The node steps on whole nanoseconds of ROS time (ros::Duration): the model integrates with
  // that step, or its clock would run off the stamps by the rounding of 1e9 / rate ns a step
  // (30 kHz: 1e-5, 36 ms an hour, and the odometry ahead with it). Rounded down, so the rate
  // stepped is never below the one asked for, which every check here compares with (a
  // ~publish_rate equal to ~rate, ~rate just above the Wk filter's 25 Hz).
  p.requested_rate = v.rate;
  const auto step_ns = static_cast<long long>(std::floor(1e9 / v.rate));
  const double stepped = 1e9 / static_cast<double>(step_ns);
  if (stepped != v.rate) {
    p.warnings.push_back(in.name("rate") + " " + io::formatC("%.10g", v.rate) +
                         " Hz is not a whole number of nanoseconds a step: stepping every " +
                         std::to_string(step_ns) + " ns, at " + io::formatC("%.10g", stepped) +
                         " Hz");
    v.rate = stepped;
  }
  // The comfort meter filters the vertical acceleration at ~rate (ISO 2631-1 Wk needs more than
  // 25 Hz): refused here, naming ~rate, rather than later as an error of the vehicle.
  try {
    dynamics::ComfortMeter(v.rate, dynamics::ComfortOptions{});
  } catch (const InputError& e) {
    throw in.error("rate", e.what());
  }
  const auto notTooSlow = [&](const std::string& key, double value, bool zero_allowed) {
    if (value < kMinDerivedRateHz && !(zero_allowed && value == 0.0))
      throw in.error(key, "must be at least " + Reader::text(kMinDerivedRateHz) +
                              " Hz (once in 11.6 days" + (zero_allowed ? "; 0 turns it off" : "") +
                              "), got " + Reader::text(value));
    return value;
  };
  p.publish_rate = notTooSlow("publish_rate", in.positive("publish_rate", v.rate, "Hz"), false);
  if (p.publish_rate > v.rate) {
    throw in.error("publish_rate", "must not exceed ~rate (" + Reader::text(v.rate) + " Hz), got " +
                                       Reader::text(p.publish_rate));
  }
  // Unset, the derived rates are their defaults capped at ~rate (a 5 Hz ~rate runs; it cannot
  // publish comfort at 10 Hz); set above ~rate, they are refused.
  const auto derivedRate = [&](const std::string& key, double fallback, bool zero_allowed) {
    const double value =
        notTooSlow(key,
                   zero_allowed ? in.nonNegative(key, std::min(fallback, v.rate), "Hz")
                                : in.positive(key, std::min(fallback, v.rate), "Hz"),
                   zero_allowed);
    if (value > v.rate)
      throw in.error(key, "must not exceed ~rate (" + Reader::text(v.rate) + " Hz), got " +
                              Reader::text(value));
    return value;
  };
  p.comfort_rate = derivedRate("comfort_rate", p.comfort_rate, false);
  p.ground_contact_rate = derivedRate("ground_contact_rate", p.ground_contact_rate, true);
  // Defaults: OnlineVehicleOptions' own, by name (every tunable lives once).
  v.method = parseMethod(in.string("method", dynamics::methodName(v.method)), in.name("method"));
  v.hold = parseHold(in.string("hold", dynamics::holdName(v.hold)), in.name("hold"));
  if (in.has("max_mode_frequency"))  // unset: OnlineVehicleOptions' default (rate / 2)
    v.max_mode_frequency_hz = in.nonNegative("max_mode_frequency", 0.0, "Hz");
  v.lateral_offset = in.number("lateral_offset", v.lateral_offset);
  p.comfort_point_given = in.has("comfort_point");
  v.comfort_point = in.string("comfort_point", v.comfort_point);
  // Unset it stays empty, OnlineVehicle's "crew_seat if the vehicle names it, else the hull";
  // set, it names a point.
  if (p.comfort_point_given && v.comfort_point.empty())
    throw in.error("comfort_point", "must not be empty");
  v.comfort_running_rms_time =
      in.positive("comfort_running_rms_time", v.comfort_running_rms_time, "s");
  // Its linear form keeps the last rate x time squares (running_window.h): a time in ms typed
  // as s (1000) at 1 kHz is a million; beyond ten million the meter refuses, named here (its
  // window checked alone: not a whole meter built and dropped, nor its other checks named so).
  try {
    dynamics::LinearRunningMeanSquare::windowSamples(v.rate, v.comfort_running_rms_time);
  } catch (const InputError& e) {
    throw in.error("comfort_running_rms_time", e.what());
  }
  v.terrain_keep_behind = in.nonNegative("terrain_keep_behind", v.terrain_keep_behind, "m");
  v.terrain_max_memory_mb = in.positive("terrain_max_memory", v.terrain_max_memory_mb, "MB");
  if (v.terrain_max_memory_mb < online::OnlineVehicleOptions::kMinTerrainMemoryMb ||
      v.terrain_max_memory_mb > online::OnlineVehicleOptions::kMaxTerrainMemoryMb)
    throw in.error("terrain_max_memory",
                   "must be within 1 .. 1e9 MB, got " + Reader::text(v.terrain_max_memory_mb));
  // Speed slew (online_vehicle.h): 0 and 0 = a new speed applies at once, without travel inertia.
  v.max_acceleration = in.nonNegative("max_acceleration", v.max_acceleration, "m/s^2");
  v.max_deceleration = in.nonNegative("max_deceleration", v.max_deceleration, "m/s^2");

  p.max_speed = in.positive("max_speed", p.max_speed, "m/s");
  // The tools' limit (speed_profile.h): beyond it the model describes nothing a vehicle does.
  if (p.max_speed > dynamics::kMaxSpeedKmh / kKmhPerMs)
    throw in.error("max_speed", "must be at most " + brief(dynamics::kMaxSpeedKmh / kKmhPerMs) +
                                    " m/s (" + brief(dynamics::kMaxSpeedKmh) +
                                    " km/h, as tvd's --speed-kmh), got " + brief(p.max_speed));
  // Within 0 .. ~max_speed, as a speed message (speedProblem), but without its standstill noise
  // (-0.0005 is a typed value, not a physics engine's stopped vehicle).
  p.initial_speed = in.nonNegative("initial_speed", p.initial_speed, "m/s");
  if (p.initial_speed > p.max_speed)
    throw in.error("initial_speed", "must be at most ~max_speed (" + brief(p.max_speed) +
                                        " m/s), got " + brief(p.initial_speed));
  p.speed_timeout = in.nonNegative("speed_timeout", p.speed_timeout, "s");
  p.catch_up_limit = in.nonNegative("catch_up_limit", p.catch_up_limit, "s");
  // Less than one step would skip time at every tick that is a step late (on real time, most).
  // (to rounding: 0.000333333 typed for one step at 3000 Hz is one step)
  if (p.catch_up_limit * v.rate < 1.0 - 1e-6)
    throw in.error("catch_up_limit",
                   "must be at least one step, 1 / ~rate = " + brief(1.0 / v.rate) + " s, got " +
                       brief(p.catch_up_limit));
  // 1e300 ("never skip") overflowed the step count into "skip at every late tick".
  if (p.catch_up_limit > kMaxCatchUpLimit)
    throw in.error("catch_up_limit", "must be at most " + brief(kMaxCatchUpLimit) +
                                         " s (a tick replays it all before it returns), got " +
                                         brief(p.catch_up_limit));

  p.odom_frame = in.frame("odom_frame", p.odom_frame, false);
  p.base_frame = in.frame("base_frame", p.base_frame, false);
  p.frame_prefix = in.frame("frame_prefix", p.frame_prefix, true);
  // tf2 ids join with '/': "veh1" gives "veh1odom", which nothing else in a tree will match.
  if (!p.frame_prefix.empty() && p.frame_prefix.back() != '/')
    p.warnings.push_back(in.name("frame_prefix") + ": '" + p.frame_prefix +
                         "' has no trailing '/': the frames read '" + p.frame_prefix + "odom', '" +
                         p.frame_prefix + "base_link' (give '" + p.frame_prefix + "/' for '" +
                         p.frame_prefix + "/odom')");
  // Namespaces do not reach tf frame ids: two vehicles pushed into /veh1 and /veh2 without a
  // prefix both publish odom -> base_link -> road_wheel_left_1 into one tree, silently.
  const std::string ns = ros::names::parentNamespace(private_nh.getNamespace());
  if (p.frame_prefix.empty() && ns != "/" && !ns.empty())
    p.warnings.push_back(
        in.name("frame_prefix") + " is empty while the node runs in the namespace " + ns +
        ": its frames (" + p.odom_frame + ", " + p.base_frame +
        ", road_wheel_left_1, ...) are those of any other vehicle in the tf tree, where they "
        "would collide; give frame_prefix:=" +
        ns.substr(1) + "/ for a tree of its own (a vehicle alone in the tree may ignore this)");
  if (p.odom_frame == p.base_frame)
    throw in.error("base_frame", "must differ from ~odom_frame");
  // The prefix names one vehicle's whole tree (REP-105 per robot: veh1/odom -> veh1/base_link
  // -> veh1/road_wheel_left_1), so that two nodes in one tf tree never share a frame.
  p.footprint_frame = in.frame("footprint_frame", "", true);
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
  // ros::Duration holds 32-bit seconds; a day is already more than anyone waits for a report.
  if (p.diagnostic_period > kMaxDiagnosticPeriod)
    throw in.error("diagnostic_period", "must be at most " + brief(kMaxDiagnosticPeriod) +
                                            " s (a day), got " + brief(p.diagnostic_period));

  reduction::VehicleReductionOptions& r = p.reduction_options;
  const std::string rule = in.string("reduction/rule", reduction::modeRuleName(r.rule));
  const std::optional<reduction::VehicleModeRule> named_rule = reduction::modeRuleFromName(rule);
  if (!named_rule)
    throw in.error("reduction/rule", "unknown rule '" + rule + "' (mac or band)");
  r.rule = *named_rule;
  // The command line's ranges (vehicle_reduction.h).
  r.global_modes = in.integer("reduction/global_modes", r.global_modes, 1,
                              reduction::kMaxGlobalModes, reduction::kMaxGlobalModesReason);
  r.band_hz = in.positive("reduction/band_hz", r.band_hz, "Hz");
  r.mac_threshold = in.positive("reduction/mac_threshold", r.mac_threshold, "");
  if (r.mac_threshold > 1.0)
    throw in.error("reduction/mac_threshold", "must be <= 1");
  r.mogesec_masters =
      in.integer("reduction/mogesec_masters", r.mogesec_masters, 0, reduction::kMaxReductionCount);
  r.mode_count = in.integer("reduction/mode_count", r.mode_count, 0, reduction::kMaxReductionCount);
  p.reduced_model = in.string("reduced_model", "");
  if (!p.reduced_model.empty()) {
    p.reduced_model = expandedPath(in, "reduced_model", p.reduced_model);
    requireFoundFile(in, "reduced_model", p.reduced_model);
  }
  // Every key above has been asked for: what else is set in the private namespace is unknown
  // (a misspelt ~speed_timout would leave the dead-driver stop off without a word).
  for (const std::string& key : in.unread()) {
    // tf_prefix is ROS 1's retired convention for what ~frame_prefix does here (no spelling is
    // near it).
    const std::string near = key == "tf_prefix" ? "frame_prefix" : in.nearest(key);
    p.unknown_parameters.push_back("~" + key +
                                   (near.empty() ? "" : " (did you mean ~" + near + "?)"));
  }
  return p;
}

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
