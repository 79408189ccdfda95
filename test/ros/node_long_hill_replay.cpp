// rostest tier 3 (end to end): a long-hill bag replayed with `rosbag play --clock` through the
// node gives the hull heave, hull pitch and road-wheel displacements of an offline run of the same
// core Simulator on the same track, within a fraction of the peak (node_long_hill_replay.test
// holds the expected values and tolerances), and on imu/<point> the specific force an accelerometer
// at that named point reads in the offline run.
//
// Samples are matched by station: with a constant speed v the node's k-th moving step is at
// s = k v h whenever it started moving, exactly as the offline run's k-th step.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Imu.h>
#include <tf2_msgs/TFMessage.h>

#include "node_test_utils.h"
#include "tracked_vehicle_dynamics/RoadWheels.h"
#include "tracked_vehicle_dynamics/dynamics/ground_contact.h"
#include "tracked_vehicle_dynamics/dynamics/output_layout.h"
#include "tracked_vehicle_dynamics/dynamics/road_excitation.h"
#include "tracked_vehicle_dynamics/dynamics/simulator.h"
#include "tracked_vehicle_dynamics/dynamics/static_equilibrium.h"
#include "tracked_vehicle_dynamics/ros/conversions.h"
#include "tracked_vehicle_dynamics/ros/node_parameters.h"
#include "tracked_vehicle_dynamics/ros/online_names.h"
#include "tracked_vehicle_dynamics/terrain/tracks.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

using namespace tracked_vehicle_dynamics;
using namespace tracked_vehicle_dynamics::ros_layer;

namespace {

// A node station must be within this of k v h to be matched [m].
constexpr double kStationMatch = 1e-6;

struct NodeSample {
  double station = 0.0;
  std::vector<double> wheels;  // displacement from static [m]
  bool has_pose = false;
  RigidPose pose;
  bool has_imu = false;
  Vector3 specific_force = Vector3::Zero();  // imu/<point> linear_acceleration [m/s^2]
  Vector3 body_rate = Vector3::Zero();       // imu/<point> angular_velocity [rad/s]
  Eigen::Quaterniond orientation;            // imu/<point> orientation
  bool has_odom = false;
  Vector6 odom_twist = Vector6::Zero();  // odom twist {linear; angular}
};

/// The offline run: hull heave, pitch and wheel displacements per step k (station k v h).
struct Reference {
  std::vector<double> heave, pitch;
  std::vector<std::vector<double>> wheels;  // [k][wheel]
  std::vector<Vector3> specific_force;      // [k] at the IMU point, in its axes [m/s^2]
  std::vector<Vector3> body_rate;           // [k] [rad/s]
  std::vector<Vector6> odom_twist;          // [k] base_link's twist in its axes
  double twist_peak = 0.0;                  // max |odom linear velocity - travel speed| [m/s]
  double rate_peak = 0.0;                   // max |body rate| [rad/s]
  double heave_peak = 0.0, pitch_peak = 0.0, wheel_peak = 0.0;
  double vibration_peak = 0.0;  // max |f - f at rest| [m/s^2]
  // Ground contact (ground_contact.h): per step k, whether a contact that pressed at rest pulls.
  std::vector<bool> beyond_range;
  long first_beyond = -1;  // the first such step, -1: none
  // The same for a whole pad (the sum of its soles' forces) pressed at rest.
  std::vector<bool> pad_beyond_range;
  long first_pad_beyond = -1;
};

Reference offlineRun(const reduction::ReducedModel& model, const VehicleGeometry& geometry,
                     const terrain::Terrain& track, double v, double rate, double end_station,
                     dynamics::DiscretizationMethod method, dynamics::InputHold hold,
                     double lateral_offset, const std::string& imu_point,
                     const std::vector<int>& pads) {
  const dynamics::SecondOrderSystem& sys = model.system;
  dynamics::SimulatorOptions options;
  options.time_step = 1.0 / rate;
  options.hold = hold;
  options.method = method;
  options.generalized_force = model.gravity_load;
  // As the node by default (~max_mode_frequency = ~rate / 2): modes above respond quasi-statically.
  if (method == dynamics::DiscretizationMethod::ModalDecoupled)
    options.max_mode_frequency_hz = 0.5 * rate;
  options.quantities = {dynamics::OutputQuantity::Displacement, dynamics::OutputQuantity::Velocity,
                        dynamics::OutputQuantity::Acceleration};
  dynamics::Simulator sim(sys, options);
  const Eigen::Index n = sys.inputCount();
  const Vector z0 = dynamics::staticEquilibrium(sys, Vector::Zero(n), model.gravity_load);
  sim.reset(z0, Vector::Zero(2 * n));
  const dynamics::OutputLayout layout(sys.output_names, options.quantities);
  const Eigen::Index heave_row = layout.row("hull uz", dynamics::OutputQuantity::Displacement);
  const Eigen::Index pitch_row = layout.row("hull ry", dynamics::OutputQuantity::Displacement);
  // Hull displacement, velocity and acceleration rows; the IMU point's acceleration rows.
  using Q = dynamics::OutputQuantity;
  const auto rows = [&](const std::string& body, const std::vector<const char*>& dofs, Q q) {
    std::vector<Eigen::Index> out;
    for (const char* dof : dofs)
      out.push_back(layout.row(body + " " + dof, q));
    return out;
  };
  const std::vector<const char*> six = {"ux", "uy", "uz", "rx", "ry", "rz"};
  const auto hull_u = rows("hull", six, Q::Displacement), hull_v = rows("hull", six, Q::Velocity),
             hull_a = rows("hull", six, Q::Acceleration);
  const auto imu_a = rows(imu_point, {"ux", "uy", "uz"}, Q::Acceleration);
  Vector3 imu_position = Vector3::Zero();
  for (const auto& p : geometry.points)
    if (p.name == imu_point)
      imu_position = p.position;
  std::vector<Eigen::Index> wheel_rows;
  for (const auto& w : geometry.wheels) {
    wheel_rows.push_back(layout.row(w.name + " uz", dynamics::OutputQuantity::Displacement));
  }
  const Vector rest = sim.outputs();
  Reference ref;
  auto record = [&] {
    const Vector& y = sim.outputs();
    ref.heave.push_back(y(heave_row));
    ref.pitch.push_back(y(pitch_row));
    std::vector<double> wheels;
    for (Eigen::Index r : wheel_rows)
      wheels.push_back(y(r) - rest(r));
    ref.wheels.push_back(wheels);
    ref.heave_peak = std::max(ref.heave_peak, std::abs(y(heave_row) - rest(heave_row)));
    ref.pitch_peak = std::max(ref.pitch_peak, std::abs(y(pitch_row) - rest(pitch_row)));
    for (double w : wheels)
      ref.wheel_peak = std::max(ref.wheel_peak, std::abs(w));
    Vector6 u, du, ddu;
    for (std::size_t i = 0; i < 6; ++i) {
      u(static_cast<Eigen::Index>(i)) = y(hull_u[i]);
      du(static_cast<Eigen::Index>(i)) = y(hull_v[i]);
      ddu(static_cast<Eigen::Index>(i)) = y(hull_a[i]);
    }
    // The point's acceleration as the node takes it: exact rigid part + the model's elastic part.
    const Vector3 r = imu_position - geometry.cog;
    const Vector3 model_a(y(imu_a[0]), y(imu_a[1]), y(imu_a[2]));
    const Vector3 a = rigidPointAcceleration(geometry.cog, u, du, ddu, imu_position) + model_a -
                      (ddu.head<3>() + ddu.tail<3>().cross(r));
    ref.specific_force.push_back(specificForce(hullPose(0.0, geometry.cog, u).rotation, a));
    ref.vibration_peak = std::max(ref.vibration_peak,
                                  (ref.specific_force.back() - ref.specific_force.front()).norm());
    ref.body_rate.push_back(bodyRate(u.tail<3>(), du.tail<3>()));
    ref.rate_peak = std::max(ref.rate_peak, ref.body_rate.back().norm());
    const bool moving = !ref.odom_twist.empty();  // record() runs once at rest first
    ref.odom_twist.push_back(baseLinkTwist(moving ? v : 0.0, geometry.cog, u, du));
    Vector3 vibration = ref.odom_twist.back().head<3>();
    vibration(0) -= moving ? v : 0.0;
    ref.twist_peak = std::max(ref.twist_peak, vibration.norm());
  };
  // The contact forces from the full state, F_i = k_i (u_i - q_m(i)) + c_i (u_i' - q_m(i)').
  const std::vector<dynamics::GroundContact> contacts = dynamics::groundContacts(sys);
  Vector forces(static_cast<Eigen::Index>(contacts.size()));
  std::vector<bool> pressed_at_rest;
  const int pad_count = pads.empty() ? 0 : *std::max_element(pads.begin(), pads.end()) + 1;
  Vector pad_forces(pad_count);
  std::vector<bool> pad_pressed_at_rest;
  auto recordContacts = [&] {
    dynamics::contactForces(contacts, sim.state(), sim.input(), n, forces, "offline run");
    if (pressed_at_rest.empty()) {
      for (Eigen::Index i = 0; i < forces.size(); ++i)
        pressed_at_rest.push_back(forces(i) >= 0.0);
    }
    bool beyond = false;
    for (Eigen::Index i = 0; i < forces.size(); ++i)
      beyond = beyond || (pressed_at_rest[static_cast<std::size_t>(i)] && forces(i) < 0.0);
    if (beyond && ref.first_beyond < 0)
      ref.first_beyond = static_cast<long>(ref.beyond_range.size());
    ref.beyond_range.push_back(beyond);
    pad_forces.setZero();
    for (std::size_t i = 0; i < contacts.size(); ++i)
      if (pads[static_cast<std::size_t>(contacts[i].input)] >= 0)
        pad_forces(pads[static_cast<std::size_t>(contacts[i].input)]) +=
            forces(static_cast<Eigen::Index>(i));
    if (pad_pressed_at_rest.empty())
      for (Eigen::Index g = 0; g < pad_count; ++g)
        pad_pressed_at_rest.push_back(pad_forces(g) >= 0.0);
    bool pad_beyond = false;
    for (Eigen::Index g = 0; g < pad_count; ++g)
      pad_beyond =
          pad_beyond || (pad_pressed_at_rest[static_cast<std::size_t>(g)] && pad_forces(g) < 0.0);
    if (pad_beyond && ref.first_pad_beyond < 0)
      ref.first_pad_beyond = static_cast<long>(ref.pad_beyond_range.size());
    ref.pad_beyond_range.push_back(pad_beyond);
  };
  record();
  recordContacts();
  const dynamics::RoadExcitation road(sys.input_stations, sys.input_lateral, lateral_offset);
  Vector w;
  const double h = 1.0 / rate;
  const auto steps = static_cast<long>(std::ceil(end_station / (v * h))) + 10;
  for (long k = 1; k <= steps; ++k) {
    road.sample(track, static_cast<double>(k) * v * h, v, w);
    sim.step(w);
    record();
    recordContacts();
  }
  return ref;
}

class LongHillReplay : public ::testing::Test {
 protected:
  LongHillReplay() : private_nh_("~"), diagnostics_(nh_) {
    tf_sub_ = nh_.subscribe("/tf", 10000, &LongHillReplay::onTf, this,
                            ros::TransportHints().tcpNoDelay());
    wheels_sub_ = nh_.subscribe("road_wheels", 10000, &LongHillReplay::onWheels, this,
                                ros::TransportHints().tcpNoDelay());
    imu_point_ = test::requiredParam<std::string>(private_nh_, "imu_point");
    imu_sub_ = nh_.subscribe<sensor_msgs::Imu>(
        "imu/" + imu_point_, 10000,
        [this](const sensor_msgs::Imu::ConstPtr& msg) {
          NodeSample& s = samples_[msg->header.stamp];
          s.specific_force = fromMsg(msg->linear_acceleration);
          s.body_rate = fromMsg(msg->angular_velocity);
          s.orientation = fromMsg(msg->orientation);
          s.has_imu = true;
        },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
    odom_sub_ = nh_.subscribe<nav_msgs::Odometry>(
        "odom", 10000,
        [this](const nav_msgs::Odometry::ConstPtr& msg) {
          NodeSample& s = samples_[msg->header.stamp];
          s.odom_twist.head<3>() = fromMsg(msg->twist.twist.linear);
          s.odom_twist.tail<3>() = fromMsg(msg->twist.twist.angular);
          s.has_odom = true;
        },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
  }
  void onTf(const tf2_msgs::TFMessage::ConstPtr& msg) {
    for (const auto& t : msg->transforms) {
      if (t.child_frame_id != "base_link")
        continue;
      NodeSample& s = samples_[t.header.stamp];
      s.pose = fromMsg(t.transform);
      s.has_pose = true;
    }
    last_message_ = ros::WallTime::now();
  }
  void onWheels(const RoadWheels::ConstPtr& msg) {
    NodeSample& s = samples_[msg->header.stamp];
    s.station = msg->station;
    s.wheels.clear();
    for (const auto& w : msg->wheels)
      s.wheels.push_back(w.displacement);
    max_station_ = std::max(max_station_, msg->station);
    last_message_ = ros::WallTime::now();
  }

  ros::NodeHandle nh_, private_nh_;
  test::DiagnosticsCache diagnostics_;
  ros::Subscriber tf_sub_, wheels_sub_, imu_sub_, odom_sub_;
  std::string imu_point_;
  std::map<ros::Time, NodeSample> samples_;
  double max_station_ = 0.0;
  ros::WallTime last_message_;
};

TEST_F(LongHillReplay, HeavePitchAndWheelsMatchTheOfflineSimulator) {
  const std::string track_name = test::requiredParam<std::string>(private_nh_, "track");
  const double v = test::requiredParam<double>(private_nh_, "speed_kmh") / 3.6;
  const double rate = test::requiredParam<double>(private_nh_, "rate");
  const double tolerance = test::requiredParam<double>(private_nh_, "tolerance_of_peak");
  const double rate_tolerance = test::requiredParam<double>(private_nh_, "rate_tolerance_of_peak");
  const double covered_from = test::requiredParam<double>(private_nh_, "covered_from");
  const double covered_until = test::requiredParam<double>(private_nh_, "covered_until");
  const double heave_peak_expected = test::requiredParam<double>(private_nh_, "heave_peak");
  const double heave_peak_tolerance =
      test::requiredParam<double>(private_nh_, "heave_peak_tolerance");
  const double time_limit = test::requiredParam<double>(private_nh_, "time_limit");
  const auto method = parseMethod(private_nh_.param<std::string>("method", "modal"), "method");
  const auto hold = parseHold(private_nh_.param<std::string>("hold", "first_order"), "hold");
  const double lateral_offset = private_nh_.param("lateral_offset", 0.0);

  // The replay: wait for the node to pass the end of the covered range, then for silence.
  const bool finished = test::spinUntil(
      [&] {
        return max_station_ >= covered_until &&
               (ros::WallTime::now() - last_message_).toSec() > 1.0;
      },
      time_limit);
  ASSERT_TRUE(finished) << "replay did not reach station " << covered_until << " (max "
                        << max_station_ << " m, " << samples_.size() << " samples)";

  // The offline reference, on the node's own cached model.
  const auto [model, geometry, pads] = test::nodeModel(private_nh_);
  ASSERT_FALSE(pads.empty()) << "the node's model has no pads";
  const terrain::Terrain track = terrain::makeTrack(track_name);
  const Reference ref = offlineRun(model, geometry, track, v, rate, max_station_, method, hold,
                                   lateral_offset, imu_point_, pads);
  ASSERT_GT(ref.heave_peak, 0.0);

  double heave_error = 0.0, pitch_error = 0.0, wheel_error = 0.0, imu_error = 0.0;
  double rate_error = 0.0, orientation_error = 0.0, twist_error = 0.0;
  std::size_t imu_compared = 0, odom_compared = 0, odom_seen = 0;
  double node_heave_peak = 0.0;
  double min_station = 1e9, max_station = -1e9;
  std::size_t compared = 0;
  const double vh = v / rate;
  const double rest_heave = ref.heave.front();
  for (const auto& [stamp, s] : samples_) {
    if (!s.has_pose || s.wheels.empty())
      continue;  // only one of the two messages arrived
    const long k = std::lround(s.station / vh);
    ASSERT_NEAR(s.station, k * vh, kStationMatch) << "station off the step grid";
    if (k < 0 || k >= static_cast<long>(ref.heave.size()))
      continue;
    const Vector6 u = hullDisplacement(s.station, geometry.cog, s.pose);
    heave_error = std::max(heave_error, std::abs(u(2) - ref.heave[k]));
    pitch_error = std::max(pitch_error, std::abs(u(4) - ref.pitch[k]));
    ASSERT_EQ(s.wheels.size(), ref.wheels[k].size());
    for (std::size_t i = 0; i < s.wheels.size(); ++i) {
      wheel_error = std::max(wheel_error, std::abs(s.wheels[i] - ref.wheels[k][i]));
    }
    if (s.has_imu) {
      imu_error = std::max(imu_error, (s.specific_force - ref.specific_force[k]).norm());
      rate_error = std::max(rate_error, (s.body_rate - ref.body_rate[k]).norm());
      orientation_error =
          std::max(orientation_error, s.orientation.angularDistance(s.pose.rotation));
      ++imu_compared;
    }
    odom_seen += s.has_odom ? 1 : 0;
    if (s.has_odom && k > 0) {  // moving (at k = 0 the node may or may not have its speed yet)
      twist_error = std::max(twist_error, (s.odom_twist - ref.odom_twist[k]).head<3>().norm());
      rate_error = std::max(rate_error, (s.odom_twist - ref.odom_twist[k]).tail<3>().norm());
      ++odom_compared;
    }
    node_heave_peak = std::max(node_heave_peak, std::abs(u(2) - rest_heave));
    min_station = std::min(min_station, s.station);
    max_station = std::max(max_station, s.station);
    ++compared;
  }
  RecordProperty("compared_samples", static_cast<int>(compared));
  std::printf("compared %zu samples, stations %.3f .. %.3f m\n", compared, min_station,
              max_station);
  std::printf("heave: peak %.4f m, max error %.3g m (%.3g of peak)\n", ref.heave_peak, heave_error,
              heave_error / ref.heave_peak);
  std::printf("pitch: peak %.4f rad, max error %.3g rad (%.3g of peak)\n", ref.pitch_peak,
              pitch_error, pitch_error / ref.pitch_peak);
  std::printf("wheels: peak %.4f m, max error %.3g m (%.3g of peak)\n", ref.wheel_peak, wheel_error,
              wheel_error / ref.wheel_peak);
  std::printf(
      "imu/%s: %zu samples, vibration peak %.3f m/s^2, max error %.3g m/s^2 (%.3g of "
      "peak); body rate error %.3g rad/s; orientation vs /tf %.3g rad\n",
      imu_point_.c_str(), imu_compared, ref.vibration_peak, imu_error,
      imu_error / ref.vibration_peak, rate_error, orientation_error);
  std::printf(
      "odom: %zu samples, linear velocity peak (less the travel speed) %.3f m/s, max "
      "error %.3g m/s; body rate peak %.3f rad/s\n",
      odom_compared, ref.twist_peak, twist_error, ref.rate_peak);
  EXPECT_LE(min_station, covered_from) << "the replay's start was not seen";
  EXPECT_GE(max_station, covered_until);
  EXPECT_LE(heave_error, tolerance * ref.heave_peak);
  EXPECT_LE(pitch_error, tolerance * ref.pitch_peak);
  EXPECT_LE(wheel_error, tolerance * ref.wheel_peak);
  // Every sample of the pose and wheels came with an IMU reading and an odom message.
  EXPECT_EQ(imu_compared, compared) << "imu/" << imu_point_ << " samples missing";
  EXPECT_EQ(odom_seen, compared) << "odom samples missing";
  EXPECT_GT(odom_compared, compared - 100);
  EXPECT_GT(ref.vibration_peak, 1.0);  // the hill shakes the point
  EXPECT_LE(imu_error, rate_tolerance * ref.vibration_peak);
  EXPECT_LE(rate_error, rate_tolerance * ref.rate_peak);  // the IMU's and odom's
  EXPECT_LE(orientation_error, 1e-12);                    // the IMU's orientation is the /tf pose's
  EXPECT_LE(twist_error, rate_tolerance * ref.twist_peak);
  // At rest before the hill the accelerometer reads gravity (static attitude: about +g0 up).
  EXPECT_NEAR(ref.specific_force.front().z(), kStandardGravity, 1e-3);
  EXPECT_NEAR(node_heave_peak, heave_peak_expected, heave_peak_tolerance);

  // Ground contact: the offline run pulls on a contact pressed at rest from the hill's foot on
  // (README, Ground contact); the node, checking every few steps (~ground_contact_rate), reports
  // its first such check: at or after the offline first step, at a step where the offline run
  // pulls too.
  ASSERT_GE(ref.first_beyond, 0) << "the offline run stays in range";
  const double offline_first = static_cast<double>(ref.first_beyond) * vh;
  ASSERT_TRUE(test::spinUntil(
      [&] {
        return diagnostics_.value(": ground contact", "first beyond the range: station [m]") > 0.0;
      },
      5.0))
      << diagnostics_.describe();
  const double node_first =
      diagnostics_.value(": ground contact", "first beyond the range: station [m]");
  std::printf(
      "ground contact: first pull (pressed at rest) offline at %.4f m, node's first check at %.4f "
      "m\n",
      offline_first, node_first);
  const long node_step = std::lround(node_first / vh);
  EXPECT_GE(node_step, ref.first_beyond);
  ASSERT_LT(node_step, static_cast<long>(ref.beyond_range.size()));
  EXPECT_TRUE(ref.beyond_range[static_cast<std::size_t>(node_step)])
      << "node reports a pull at step " << node_step;
  // Checked every 20 steps at the default 50 Hz (0.17 m at 30 km/h): the node cannot lag by many
  // checks.
  EXPECT_LE(node_first - offline_first, 0.5);
  EXPECT_GT(diagnostics_.value(": ground contact",
                               "checks beyond the range (since the last start or reset)"),
            0.0);

  // Whole pads (the node groups the soles by track assembly): the same, a pad's force the sum of
  // its soles'; the hill lifts a whole pad too (README, Ground contact).
  EXPECT_EQ(diagnostics_.value(": ground contact", "pads"),
            static_cast<double>(*std::max_element(pads.begin(), pads.end()) + 1));
  ASSERT_GE(ref.first_pad_beyond, 0) << "no whole pad pulls offline";
  ASSERT_TRUE(test::spinUntil(
      [&] {
        return diagnostics_.value(": ground contact", "first pad pulling: station [m]") > 0.0;
      },
      5.0))
      << diagnostics_.describe();
  const double node_pad_first =
      diagnostics_.value(": ground contact", "first pad pulling: station [m]");
  const double offline_pad_first = static_cast<double>(ref.first_pad_beyond) * vh;
  std::printf(
      "ground contact: first whole pad pulling offline at %.4f m, node's first check at %.4f m\n",
      offline_pad_first, node_pad_first);
  const long node_pad_step = std::lround(node_pad_first / vh);
  EXPECT_GE(node_pad_step, ref.first_pad_beyond);
  ASSERT_LT(node_pad_step, static_cast<long>(ref.pad_beyond_range.size()));
  EXPECT_TRUE(ref.pad_beyond_range[static_cast<std::size_t>(node_pad_step)])
      << "node reports a whole pad pulling at step " << node_pad_step;
  EXPECT_LE(node_pad_first - offline_pad_first, 0.5);
  // What a diagnostic aggregator (or an operator's rqt_robot_monitor) sees: the report after
  // that check is a WARN saying the model left its range.
  EXPECT_EQ(diagnostics_.highestLevel(": ground contact"), 1) << diagnostics_.describe();
  EXPECT_EQ(
      diagnostics_.highestMessage(": ground contact").rfind("beyond the linear model's range", 0),
      0u)
      << diagnostics_.highestMessage(": ground contact");
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "long_hill_replay_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
