// rostest tier 2 on simulated time (node_speed_slew.test, use_sim_time): the speed slew
// (~max_acceleration A, ~max_deceleration D) through the running node. The test owns /clock and
// drives two nodes on flat ground with the same speed steps, 0 -> v, then v -> 0: `slewed/` with
// A and D, `unslewed/` with both 0 (the default). Every sample of both is recorded (publish rate =
// rate, h = 1 / rate) and compared with closed forms, from the first sample that saw a command
// (tau = h there):
//   speed     v(tau) = v0 + a tau until it reaches v1 at tau_r = |v1 - v0| / |a|, then v1
//   station   s(tau) = s0 + v0 tau + a tau^2 / 2, then + v1 (tau - tau_r): exact, as the node
//             advances by the trapezoid (v_k + v_{k+1}) h / 2 and tau_r is a whole number of steps
//   odom      its twist in odom axes less the hull's own motion on its path (the central difference
//             of the published base_footprint -> base_link) is (v(tau), 0, 0): the odom twist
//             carries the slewed speed, to within a step's a h (the twist itself, of base_link's
//             origin, also carries the hull's surge and pitch on its pads, which the onset of a
//             ramp sets ringing: 0.05 to 0.07 m/s here)
//   pitch     settled on the constant acceleration a (the ramp's last settled_window, where the
//             onset's transient has decayed: see the .test file), the hull pitch less its rest
//             pitch is the reduced model's static response a (H K^-1 f_a)_ry: nose up (< 0)
//             accelerating, nose down (> 0, REP-103) braking
//   IMU       settled, imu/<point> reads R^T ((a, 0, 0) - g): f_x = a cos(theta) - g sin(theta)
//             with the hull pitched by theta (a = -D braking), and hull/accel R^T (a, 0, 0)
// Without the slew the speed applies at the next sample, whole, and the hull stays at rest
// (no travel inertia: the IMU reads gravity only).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <geometry_msgs/AccelStamped.h>
#include <nav_msgs/Odometry.h>
#include <rosgraph_msgs/Log.h>
#include <sensor_msgs/Imu.h>
#include <std_msgs/Float64.h>
#include <tf2_msgs/TFMessage.h>

#include "node_test_utils.h"
#include "tracked_vehicle_dynamics/RoadWheels.h"
#include "tracked_vehicle_dynamics/ros/online_names.h"

using namespace tracked_vehicle_dynamics;
using namespace tracked_vehicle_dynamics::ros_layer;

namespace {

constexpr double kRounding = 1e-9;  // [m, m/s] accumulated rounding of speed and station
constexpr double kAtRest = 1e-9;    // [m/s] the unslewed hull's velocity on its path, flat ground
// [m/s^2] its IMU's departure from gravity: the simulator's rest state is the static equilibrium
// solved apart (LDL^T of K), to rounding (measured 4.8e-7; node_static allows 1e-6 as well)
constexpr double kAtRestAcceleration = 1e-6;
constexpr double kBurst = 0.02;  // [s] of simulated time per /clock message

/// Speed [m/s] and distance [m] `tau` seconds into a slew from v0 towards v1 at `rate` [m/s^2]
/// (> 0), uniformly accelerated until v1 is reached, then at v1.
struct Travel {
  double speed, distance;
};
Travel slew(double v0, double v1, double rate, double tau) {
  const double ramp = std::abs(v1 - v0) / rate;  // 0 for an infinite rate: no slew
  if (tau < ramp) {
    const double a = v1 > v0 ? rate : -rate;
    return {v0 + a * tau, v0 * tau + 0.5 * a * tau * tau};
  }
  return {v1, 0.5 * (v0 + v1) * ramp + v1 * (tau - ramp)};
}

/// What one node published at one stamp.
struct Sample {
  double speed = std::numeric_limits<double>::quiet_NaN();  // road_wheels [m/s]
  double station = std::numeric_limits<double>::quiet_NaN();
  std::optional<double> travel;                // odom -> base_footprint x [m]
  std::optional<RigidPose> on_path;            // base_footprint -> base_link
  std::optional<Vector3> twist;                // odom twist, linear [m/s], base_link axes
  std::optional<Eigen::Quaterniond> rotation;  // odom pose
  std::optional<Vector3> specific_force;       // imu/<point> [m/s^2]
  std::optional<Vector3> hull_accel;           // hull/accel, linear [m/s^2]

  bool complete() const {
    return std::isfinite(speed) && travel && on_path && twist && specific_force && hull_accel;
  }
};

/// The topics of one node (namespace `ns`, frames prefixed with `prefix`), recorded by stamp.
class Recorder {
 public:
  Recorder(ros::NodeHandle& nh, const std::string& ns, const std::string& prefix,
           const std::string& imu_point)
      : footprint_(prefix + "base_footprint"), base_(prefix + "base_link") {
    // Every sample is kept (the node's catch-up bursts included); no delay: the test waits for
    // each burst's last sample before moving the clock on.
    constexpr int kQueue = 20000;
    const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
    subs_ = {nh.subscribe(ns + "/road_wheels", kQueue, &Recorder::onWheels, this, hints),
             nh.subscribe("/tf", kQueue, &Recorder::onTf, this, hints),
             nh.subscribe(ns + "/odom", kQueue, &Recorder::onOdom, this, hints),
             nh.subscribe(ns + "/imu/" + imu_point, kQueue, &Recorder::onImu, this, hints),
             nh.subscribe(ns + "/hull/accel", kQueue, &Recorder::onAccel, this, hints)};
    speed_pub_ = nh.advertise<std_msgs::Float64>(ns + "/speed", 10, true);
    terrain_pub_ = nh.advertise<TerrainProfile>(ns + "/terrain_profile", 10, true);
  }

  bool has(const ros::Time& t) const {
    const auto it = samples_.find(t);
    return it != samples_.end() && it->second.complete();
  }
  /// Whether a sample with every topic arrived (each publisher is then connected).
  bool connected() const {
    return std::any_of(samples_.begin(), samples_.end(),
                       [](const auto& s) { return s.second.complete(); });
  }
  const std::map<ros::Time, Sample>& samples() const { return samples_; }
  void publishSpeed(double v) const {
    std_msgs::Float64 msg;
    msg.data = v;
    speed_pub_.publish(msg);
  }
  const ros::Publisher& speedPublisher() const { return speed_pub_; }
  const ros::Publisher& terrainPublisher() const { return terrain_pub_; }

 private:
  void onWheels(const RoadWheels::ConstPtr& m) {
    Sample& s = samples_[m->header.stamp];
    s.speed = m->speed;
    s.station = m->station;
  }
  void onOdom(const nav_msgs::Odometry::ConstPtr& m) {
    Sample& s = samples_[m->header.stamp];
    s.twist = fromMsg(m->twist.twist.linear);
    s.rotation = fromMsg(m->pose.pose.orientation);
  }
  void onImu(const sensor_msgs::Imu::ConstPtr& m) {
    samples_[m->header.stamp].specific_force = fromMsg(m->linear_acceleration);
  }
  void onAccel(const geometry_msgs::AccelStamped::ConstPtr& m) {
    samples_[m->header.stamp].hull_accel = fromMsg(m->accel.linear);
  }
  void onTf(const tf2_msgs::TFMessage::ConstPtr& msg) {
    for (const auto& t : msg->transforms) {
      if (t.child_frame_id == footprint_)
        samples_[t.header.stamp].travel = t.transform.translation.x;
      else if (t.child_frame_id == base_)
        samples_[t.header.stamp].on_path = fromMsg(t.transform);
    }
  }

  std::string footprint_, base_;
  std::vector<ros::Subscriber> subs_;
  ros::Publisher speed_pub_, terrain_pub_;
  std::map<ros::Time, Sample> samples_;
};

/// The first stamp after `from` whose speed differs from `speed`; `end` when none.
std::map<ros::Time, Sample>::const_iterator firstChange(const std::map<ros::Time, Sample>& samples,
                                                        const ros::Time& from, double speed) {
  return std::find_if(samples.lower_bound(from), samples.end(),
                      [&](const auto& s) { return s.second.speed != speed; });
}

/// Largest errors of one ramp against the closed forms.
struct RampErrors {
  double speed = 0.0, station = 0.0, travel = 0.0, odom = 0.0, odom_raw = 0.0;
  std::size_t samples = 0;
};

class NodeSpeedSlew : public ::testing::Test {
 protected:
  NodeSpeedSlew()
      : private_nh_("~"),
        imu_point_(test::requiredParam<std::string>(private_nh_, "imu_point")),
        slewed_(nh_, "slewed", "", imu_point_),
        unslewed_(nh_, "unslewed", "unslewed/", imu_point_) {
    clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
    rosout_sub_ = nh_.subscribe<rosgraph_msgs::Log>(
        "/rosout", 1000, [this](const rosgraph_msgs::Log::ConstPtr& m) { log_.push_back(*m); });
  }

  /// The first message logged by node `name` that contains `text`; empty when none.
  std::string logged(const std::string& name, const std::string& text) const {
    for (const auto& m : log_) {
      if (m.name == name && m.msg.find(text) != std::string::npos)
        return m.msg;
    }
    return "";
  }

  /// Moves the clock to `t` and waits for both nodes' complete samples at `t`.
  bool advanceTo(const ros::Time& t) {
    test::publishClock(clock_pub_, t);
    return test::spinUntil([&] { return has(t); }, 10.0);
  }
  bool has(const ros::Time& t) const { return slewed_.has(t) && unslewed_.has(t); }
  /// Runs the clock on by `seconds` in bursts of kBurst; false when a sample is missing.
  bool runFor(double seconds) {
    return test::runClockFor(clock_pub_, &t_, seconds, kBurst,
                             [&](const ros::Time& t) { return has(t); });
  }
  /// Sends speed `v` to both nodes; it reaches them before the clock moves on.
  void command(double v) {
    for (const Recorder* r : {&slewed_, &unslewed_}) {
      ASSERT_TRUE(
          test::spinUntil([&] { return r->speedPublisher().getNumSubscribers() > 0; }, 10.0));
      r->publishSpeed(v);
    }
    test::spinFor(0.5);
  }

  /// Checks the samples of `recorder` from `first` (the first that saw a command from v0 to v1;
  /// tau = h there) until `last` (excluded) against the closed forms of a slew at `rate`
  /// (infinite: no slew); returns the largest errors.
  RampErrors checkRamp(const Recorder& recorder, std::map<ros::Time, Sample>::const_iterator first,
                       std::map<ros::Time, Sample>::const_iterator last, double v0, double v1,
                       double rate) const {
    RampErrors e;
    const auto& samples = recorder.samples();
    EXPECT_NE(first, samples.begin());
    const Sample& before = std::prev(first)->second;
    EXPECT_EQ(before.speed, v0);
    const ros::Time t0 = std::prev(first)->first;
    for (auto it = first; it != last; ++it) {
      const double tau = (it->first - t0).toSec();
      const Travel expected = slew(v0, v1, rate, tau);
      const Sample& s = it->second;
      e.speed = std::max(e.speed, std::abs(s.speed - expected.speed));
      e.station = std::max(e.station, std::abs(s.station - before.station - expected.distance));
      e.travel = std::max(e.travel, std::abs(*s.travel - s.station));
      const Vector3 twist = *s.rotation * *s.twist;  // in odom axes
      e.odom_raw = std::max(e.odom_raw, std::abs(s.twist->x() - expected.speed));
      // The hull's own velocity on its path: the central difference of base_footprint ->
      // base_link (exact to O(h^2) of its third derivative).
      const auto next = std::next(it);
      if (it != samples.begin() && next != samples.end() && next != last) {
        const double h = (next->first - it->first).toSec();
        const Vector3 on_path =
            (next->second.on_path->translation - std::prev(it)->second.on_path->translation) /
            (2.0 * h);
        e.odom = std::max(e.odom, (twist - on_path - Vector3(expected.speed, 0.0, 0.0)).norm());
      }
      ++e.samples;
    }
    return e;
  }

  ros::NodeHandle nh_, private_nh_;
  std::string imu_point_;
  Recorder slewed_, unslewed_;
  ros::Publisher clock_pub_;
  ros::Subscriber rosout_sub_;
  std::vector<rosgraph_msgs::Log> log_;
  ros::Time t_{100.0};
};

TEST_F(NodeSpeedSlew, SpeedStepsSlewAtTheSetRatesWithTheTravelInertia) {
  const double rate = test::requiredParam<double>(private_nh_, "rate");
  const double accel = test::requiredParam<double>(private_nh_, "max_acceleration");
  const double decel = test::requiredParam<double>(private_nh_, "max_deceleration");
  const double v = test::requiredParam<double>(private_nh_, "speed");
  const double cruise = test::requiredParam<double>(private_nh_, "cruise_time");
  const double stopped = test::requiredParam<double>(private_nh_, "stopped_time");
  const double window = test::requiredParam<double>(private_nh_, "settled_window");
  const double pitch_tolerance = test::requiredParam<double>(private_nh_, "pitch_tolerance");
  const double acceleration_tolerance =
      test::requiredParam<double>(private_nh_, "acceleration_tolerance");
  const double h = 1.0 / rate;
  const double rise = v / accel, fall = v / decel;  // [s]
  // Whole numbers of steps: the ramp ends on a step, where the trapezoid is exact.
  ASSERT_NEAR(rise * rate, std::round(rise * rate), 1e-9);
  ASSERT_NEAR(fall * rate, std::round(fall * rate), 1e-9);
  ASSERT_LT(window, std::min(rise, fall));

  ASSERT_TRUE(test::tickClockUntil(
      clock_pub_, &t_, [&] { return slewed_.connected() && unslewed_.connected(); }, 60.0))
      << "the nodes published nothing (or not every topic)";
  t_ += ros::Duration(h);
  ASSERT_TRUE(advanceTo(t_));
  // Flat ground over the whole run (the vehicle's contacts span a few metres either side).
  const double distance = 0.5 * v * rise + v * cruise + 0.5 * v * fall;
  for (const Recorder* r : {&slewed_, &unslewed_})
    r->terrainPublisher().publish(test::flatProfile(-10.0, distance + 20.0));
  test::spinFor(0.5);
  ASSERT_TRUE(runFor(10 * h));

  // 0 -> v, at A; then v -> 0, at D.
  const ros::Time up = t_;
  ASSERT_NO_FATAL_FAILURE(command(v));
  // Half-way up, a bad speed: refused, the slew goes on towards v (the closed forms span it).
  ASSERT_TRUE(runFor(0.5 * rise));
  ASSERT_NO_FATAL_FAILURE(command(-1.0));
  ASSERT_TRUE(runFor(0.5 * rise + cruise));
  const ros::Time down = t_;
  ASSERT_NO_FATAL_FAILURE(command(0.0));
  ASSERT_TRUE(runFor(fall + stopped));

  // Every sample of both nodes: one per step.
  const auto expected_count = static_cast<std::size_t>(std::lround((t_ - up).toSec() * rate)) + 1;
  for (const Recorder* r : {&slewed_, &unslewed_}) {
    const auto& samples = r->samples();
    EXPECT_EQ(std::distance(samples.lower_bound(up), samples.end()),
              static_cast<std::ptrdiff_t>(expected_count));
  }

  // --- The slewed node. Each command is seen by the next sample (the command reached the node
  // before the clock moved on).
  const auto& samples = slewed_.samples();
  const auto accelerating = firstChange(samples, up, 0.0);
  const auto braking = firstChange(samples, down, v);
  ASSERT_NE(accelerating, samples.end());
  ASSERT_NE(braking, samples.end());
  EXPECT_EQ(accelerating->first, up + ros::Duration(h));
  EXPECT_EQ(braking->first, down + ros::Duration(h));
  EXPECT_NEAR(accelerating->second.speed, accel * h, kRounding);  // one step's A h, not v
  EXPECT_NEAR(braking->second.speed, v - decel * h, kRounding);

  const RampErrors rising = checkRamp(slewed_, accelerating, braking, 0.0, v, accel);
  const RampErrors falling = checkRamp(slewed_, braking, samples.end(), v, 0.0, decel);
  for (const auto& [name, e, a] :
       {std::tuple<const char*, RampErrors, double>{"0 -> v", rising, accel},
        {"v -> 0", falling, decel}}) {
    SCOPED_TRACE(name);
    EXPECT_LE(e.speed, kRounding);    // road_wheels' speed: min(v, A tau), max(0, v - D tau)
    EXPECT_LE(e.station, kRounding);  // and its station: the trapezoid's integral
    EXPECT_EQ(e.travel, 0.0);         // odom -> base_footprint carries that station exactly
    EXPECT_LE(e.odom, a * h);         // odom's twist carries the slewed speed
    std::printf(
        "[ measured ] slewed %s (%zu samples): |speed - closed form| %.3g m/s, |station - "
        "closed form| %.3g m, |odom twist - hull on its path - v| %.3g m/s (a h %.3g), "
        "|odom twist x - v| %.3g m/s (the hull's own motion)\n",
        name, e.samples, e.speed, e.station, e.odom, a * h, e.odom_raw);
  }
  EXPECT_EQ(std::prev(samples.end())->second.speed, 0.0);  // stopped, and stays there
  EXPECT_EQ(std::prev(samples.end())->second.station,
            samples.at(braking->first + ros::Duration(fall - h)).station);

  // Pitch and accelerometer, settled on each ramp's constant acceleration: the reduced model's
  // static response a (H K^-1 f_a) about the rest pose (the same cached model, loaded here).
  const test::NodeModel node = test::nodeModel(private_nh_);
  const reduction::ReducedModel& model = node.model;
  const OnlineVehicle reference(model, node.geometry);
  const double rest_pitch = rollPitchYaw(reference.hullPose().rotation)(1);
  const auto& names = model.system.output_names;
  const auto ry = std::find(names.begin(), names.end(), "hull ry") - names.begin();
  ASSERT_LT(ry, static_cast<std::ptrdiff_t>(names.size()));
  const double pitch_per_acceleration =  // [rad per m/s^2]
      (model.system.output * model.system.stiffness.ldlt().solve(model.travel_load))(ry);
  for (const auto& [name, start, ramp, a] : {std::tuple<const char*, ros::Time, double, double>{
                                                 "0 -> v", accelerating->first, rise, accel},
                                             {"v -> 0", braking->first, fall, -decel}}) {
    SCOPED_TRACE(name);
    const double static_pitch = a * pitch_per_acceleration;
    const ros::Time end = start + ros::Duration(ramp - h);  // the ramp's last sample
    double pitch_error = 0.0, force_error = 0.0, fx_error = 0.0, accel_error = 0.0;
    double min_pitch = std::numeric_limits<double>::infinity(), max_pitch = -min_pitch;
    for (auto it = samples.lower_bound(end - ros::Duration(window)); it != samples.upper_bound(end);
         ++it) {
      const Sample& s = it->second;
      const double pitch = rollPitchYaw(*s.rotation)(1) - rest_pitch;
      min_pitch = std::min(min_pitch, pitch);
      max_pitch = std::max(max_pitch, pitch);
      pitch_error = std::max(pitch_error, std::abs(pitch - static_pitch));
      // f = R^T ((a, 0, 0) - g): f_x = a cos(theta) - g sin(theta) for a pure pitch theta.
      const Vector3 force = specificForce(*s.rotation, Vector3(a, 0.0, 0.0));
      force_error = std::max(force_error, (*s.specific_force - force).norm());
      const double theta = rollPitchYaw(*s.rotation)(1);
      fx_error =
          std::max(fx_error, std::abs(s.specific_force->x() -
                                      (a * std::cos(theta) - kStandardGravity * std::sin(theta))));
      const Vector3 travel = s.rotation->conjugate() * Vector3(a, 0.0, 0.0);
      accel_error = std::max(accel_error, (*s.hull_accel - travel).norm());
    }
    // Nose up accelerating, nose down braking (REP-103: positive pitch about +y, y left).
    if (a > 0)
      EXPECT_LT(max_pitch, 0.0);
    else
      EXPECT_GT(min_pitch, 0.0);
    EXPECT_LE(pitch_error, pitch_tolerance * std::abs(static_pitch));
    EXPECT_LE(force_error, acceleration_tolerance * std::abs(a));
    EXPECT_LE(fx_error, acceleration_tolerance * std::abs(a));
    EXPECT_LE(accel_error, acceleration_tolerance * std::abs(a));
    const Sample& last = samples.at(end);
    const double theta = rollPitchYaw(*last.rotation)(1);
    std::printf(
        "[ measured ] slewed %s, last %.2f s of the ramp: static pitch %.4g mrad, pitch "
        "%.4g .. %.4g mrad (largest error %.3g of it); |IMU - R^T(a - g)| %.3g m/s^2 "
        "(%.3g of a), |f_x - (a cos(theta) - g sin(theta))| %.3g m/s^2, |hull/accel - R^T a| "
        "%.3g m/s^2; at the ramp's end f_x %.6f m/s^2, a cos(theta) - g sin(theta) %.6f\n",
        name, window, 1e3 * static_pitch, 1e3 * min_pitch, 1e3 * max_pitch,
        pitch_error / std::abs(static_pitch), force_error, force_error / std::abs(a), fx_error,
        accel_error, last.specific_force->x(),
        a * std::cos(theta) - kStandardGravity * std::sin(theta));
  }

  // The refusal's warning names the speed kept: the last valid one, v, which the slew was still
  // approaching (not the current v / 2).
  std::string refusal;
  EXPECT_TRUE(test::spinUntil(
      [&] { return !(refusal = logged("/slewed/vehicle_dynamics", "negative speed")).empty(); },
      10.0));
  char kept[64];
  std::snprintf(kept, sizeof kept, "keeping %.3f m/s", v);
  EXPECT_NE(refusal.find(kept), std::string::npos) << refusal;

  // --- The unslewed node: each speed applies whole at the next sample, without travel inertia.
  const auto& plain = unslewed_.samples();
  const auto started = firstChange(plain, up, 0.0);
  const auto stopping = firstChange(plain, down, v);
  ASSERT_NE(started, plain.end());
  ASSERT_NE(stopping, plain.end());
  EXPECT_EQ(started->first, up + ros::Duration(h));
  EXPECT_EQ(stopping->first, down + ros::Duration(h));
  EXPECT_EQ(started->second.speed, v);
  EXPECT_EQ(stopping->second.speed, 0.0);
  const double infinite = std::numeric_limits<double>::infinity();
  const RampErrors on = checkRamp(unslewed_, started, stopping, 0.0, v, infinite);
  const RampErrors off = checkRamp(unslewed_, stopping, plain.end(), v, 0.0, infinite);
  for (const RampErrors& e : {on, off}) {
    EXPECT_LE(e.speed, 0.0);
    EXPECT_LE(e.station, kRounding);
    EXPECT_EQ(e.travel, 0.0);
    EXPECT_LE(e.odom, kAtRest);  // odom's twist is R^T (v, 0, 0): the hull stays at rest
  }
  double imu_error = 0.0;
  for (auto it = plain.lower_bound(up); it != plain.end(); ++it) {
    const Sample& s = it->second;
    imu_error = std::max({imu_error,
                          (*s.specific_force - specificForce(*s.rotation, Vector3::Zero())).norm(),
                          s.hull_accel->norm()});
  }
  EXPECT_LE(imu_error, kAtRestAcceleration);  // gravity only: no travel inertia
  // Which the unslewed node says, once, at its first change of speed, naming the parameters;
  // the slewed node feels it and says nothing.
  std::string said;
  EXPECT_TRUE(test::spinUntil(
      [&] { return !(said = logged("/unslewed/vehicle_dynamics", "no travel inertia")).empty(); },
      10.0));
  EXPECT_NE(said.find("~max_acceleration and ~max_deceleration 0"), std::string::npos) << said;
  std::size_t times = 0;
  for (const auto& m : log_)
    times += m.name == "/unslewed/vehicle_dynamics" &&
             m.msg.find("no travel inertia") != std::string::npos;
  EXPECT_EQ(times, 1u);
  EXPECT_EQ(logged("/slewed/vehicle_dynamics", "no travel inertia"), "");
  std::printf(
      "[ measured ] unslewed: |station - v t| %.3g m, IMU and hull/accel off gravity "
      "only %.3g m/s^2\n",
      std::max(on.station, off.station), imu_error);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "node_speed_slew_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
