// rostest tier 2 on simulated time (node_reset_to.test, use_sim_time): the test owns /clock.
// ~reset_to {station, speed 0, keep_terrain} on a plateau of height H around the station puts the
// vehicle there in static equilibrium on the plateau: odom -> base_link is the flat static pose
// moved by (station, 0, H) (a uniform road height lifts the linear model rigidly), every wheel is
// H above its flat static position. Nothing is published by the call itself, and no stamp twice.
// A bad request (negative speed, speed above ~max_speed, a station not finite or beyond 1e7 m) gets
// success = false with a message naming the field and leaves the vehicle where it was;
// keep_terrain false restarts on flat ground.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

#include <tf2_msgs/TFMessage.h>

#include "node_test_utils.h"
#include "tracked_vehicle_dynamics/ResetVehicle.h"
#include "tracked_vehicle_dynamics/RoadWheels.h"
#include "tracked_vehicle_dynamics/ros/online_names.h"

using namespace tracked_vehicle_dynamics;
using namespace tracked_vehicle_dynamics::ros_layer;

namespace {

constexpr double kRamp = 5.0;  // [m] from 0 to the plateau height, on either side

/// A plateau of `height` [m] over [centre - half, centre + half], ramps of kRamp down to 0 on
/// both sides, lines every 0.5 m across 5 m, samples every 5 cm.
TerrainProfile plateau(double centre, double half, double height) {
  const double spacing = 0.05;
  const double from = centre - half - kRamp;
  const auto samples = static_cast<Eigen::Index>(std::lround(2.0 * (half + kRamp) / spacing)) + 1;
  TerrainPatch patch;
  patch.start_station = from;
  patch.spacing = spacing;
  patch.lateral = Vector::LinSpaced(11, -2.5, 2.5);
  patch.heights.resize(11, samples);
  for (Eigen::Index j = 0; j < samples; ++j) {
    const double off = std::abs(from + j * spacing - centre) - half;  // > 0 on the ramps
    patch.heights.col(j).setConstant(off <= 0.0 ? height
                                                : height * std::max(0.0, 1.0 - off / kRamp));
  }
  TerrainProfile msg;
  msg.header.frame_id = "odom";
  toMsg(patch, &msg);
  return msg;
}

class NodeResetTo : public ::testing::Test {
 protected:
  NodeResetTo() : private_nh_("~"), diagnostics_(nh_) {
    clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
    wheels_sub_ = nh_.subscribe("road_wheels", 10000, &NodeResetTo::onWheels, this,
                                ros::TransportHints().tcpNoDelay());
    tf_sub_ =
        nh_.subscribe("/tf", 10000, &NodeResetTo::onTf, this, ros::TransportHints().tcpNoDelay());
    terrain_pub_ = nh_.advertise<TerrainProfile>("terrain_profile", 10, true);
  }

  void onWheels(const RoadWheels::ConstPtr& msg) {
    if (messages_ > 0 && msg->header.stamp == last_.header.stamp)
      ++repeated_stamps_;
    last_ = *msg;
    ++messages_;
  }
  void onTf(const tf2_msgs::TFMessage::ConstPtr& msg) {
    for (const auto& t : msg->transforms) {
      if (t.child_frame_id != "base_link")
        continue;
      if (tf_messages_ > 0 && t.header.stamp == pose_stamp_)
        ++repeated_stamps_;
      pose_stamp_ = t.header.stamp;
      pose_ = fromMsg(t.transform);
      ++tf_messages_;
    }
  }

  /// Moves the clock to `t` and waits for the node's road_wheels and base_link at `t`.
  bool advanceTo(const ros::Time& t) {
    test::publishClock(clock_pub_, t);
    return test::spinUntil(
        [&] { return messages_ > 0 && last_.header.stamp == t && pose_stamp_ == t; }, 10.0);
  }
  /// One step further on.
  bool step() {
    t_ += ros::Duration(0.001);
    return advanceTo(t_);
  }

  static ResetVehicle request(double station, double speed, bool keep_terrain) {
    ResetVehicle srv;
    srv.request.station = station;
    srv.request.speed = speed;
    srv.request.keep_terrain = keep_terrain;
    return srv;
  }

  ros::NodeHandle nh_, private_nh_;
  test::DiagnosticsCache diagnostics_;
  ros::Publisher clock_pub_, terrain_pub_;
  ros::Subscriber wheels_sub_, tf_sub_;
  ros::Time t_{100.0};
  RoadWheels last_;
  RigidPose pose_;
  ros::Time pose_stamp_;
  std::size_t messages_ = 0, tf_messages_ = 0, repeated_stamps_ = 0;
};

TEST_F(NodeResetTo, RestartsInEquilibriumOnTheTerrainAtTheStation) {
  const double station = test::requiredParam<double>(private_nh_, "station");
  const double height = test::requiredParam<double>(private_nh_, "plateau_height");
  const double half = test::requiredParam<double>(private_nh_, "plateau_half_length");
  const double tolerance = test::requiredParam<double>(private_nh_, "pose_tolerance");
  const std::string service = "/vehicle_dynamics/reset_to";

  ASSERT_TRUE(test::tickClockUntil(
      clock_pub_, &t_, [&] { return messages_ > 0; }, 45.0))
      << "the node published nothing";
  ASSERT_TRUE(step());
  // At rest at station 0 on flat ground (no terrain yet: u = 0): the flat static pose.
  ASSERT_EQ(last_.station, 0.0);
  const RigidPose flat = pose_;
  EXPECT_LT(flat.translation.z(), 0.0);  // the hull sags under gravity

  // Terrain 5 km ahead alone (a stack sending a map's x): the waiting says where it starts.
  terrain_pub_.publish(plateau(5000.0, half, 0.0));
  test::spinFor(0.5);
  for (int k = 0; k < 12; ++k)  // 1.2 s of steps: at least one diagnostics period
    ASSERT_TRUE(advanceTo(t_ += ros::Duration(0.1)));
  ASSERT_TRUE(test::spinUntil(
      [&] {
        return diagnostics_.message(": terrain")
                   .find(
                       "m ahead of the front contact: stations "
                       "along this vehicle's path from its start "
                       "(odom x), not a map's x?") != std::string::npos;
      },
      10.0))
      << diagnostics_.describe();
  EXPECT_NE(diagnostics_.message(": terrain").find("; the terrain starts 4978 m ahead"),
            std::string::npos)  // 5000 - 15 - the 5 m ramp, less the front contact at about 2.4 m
      << diagnostics_.describe();

  terrain_pub_.publish(plateau(station, half, height));
  test::spinFor(0.5);
  ASSERT_TRUE(step());  // the patch is in the buffer (it is far ahead: the vehicle does not move)
  ASSERT_EQ(last_.station, 0.0);
  // Standing at the start on its flat ground, the patch far ahead: its contacts are off the
  // terrain, but the vehicle waits as it does with no terrain (OK), not "underrun" (WARN).
  for (int k = 0; k < 12; ++k)  // 1.2 s of steps: at least one diagnostics period
    ASSERT_TRUE(advanceTo(t_ += ros::Duration(0.1)));
  const std::string waiting =
      "waiting for terrain under the contacts: standing on flat ground since the start or reset";
  ASSERT_TRUE(test::spinUntil([&] { return diagnostics_.message(": terrain") == waiting; }, 10.0))
      << diagnostics_.describe();
  EXPECT_EQ(diagnostics_.level(": terrain"), 0) << diagnostics_.describe();
  // Not counted as an underrun either (nor said in the log).
  EXPECT_EQ(diagnostics_.value(": terrain", "steps with uncovered contacts (total)"), 0.0)
      << diagnostics_.describe();
  ASSERT_EQ(last_.station, 0.0);
  ASSERT_TRUE(ros::service::waitForService(service, ros::Duration(10.0)));

  // To the plateau, terrain kept: nothing is published by the call itself.
  const std::size_t before = messages_;
  ResetVehicle srv = request(station, 0.0, true);
  ASSERT_TRUE(ros::service::call(service, srv));
  EXPECT_TRUE(srv.response.success) << srv.response.message;
  EXPECT_NE(srv.response.message.find("on the terrain there"), std::string::npos)
      << srv.response.message;
  test::spinFor(0.2);
  EXPECT_EQ(messages_, before) << "the call published a sample";

  // The next sample: at the station, lifted rigidly by the plateau height.
  ASSERT_TRUE(step());
  EXPECT_EQ(last_.station, station);
  EXPECT_EQ(last_.speed, 0.0);
  EXPECT_NEAR(pose_.translation.x(), flat.translation.x() + station, tolerance);
  EXPECT_NEAR(pose_.translation.y(), flat.translation.y(), tolerance);
  EXPECT_NEAR(pose_.translation.z(), flat.translation.z() + height, tolerance);
  EXPECT_NEAR(pose_.rotation.angularDistance(flat.rotation), 0.0, tolerance);
  ASSERT_FALSE(last_.wheels.empty());
  for (const auto& w : last_.wheels) {
    EXPECT_NEAR(w.displacement, height, tolerance) << w.name;
    EXPECT_NEAR(w.velocity, 0.0, tolerance) << w.name;
  }
  // In equilibrium: it stays there.
  for (int k = 0; k < 20; ++k)
    ASSERT_TRUE(step());
  EXPECT_NEAR(pose_.translation.z(), flat.translation.z() + height, tolerance);
  const RigidPose on_plateau = pose_;

  // Bad requests: refused with the field named, nothing changed.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Bad {
    double station, speed;
    const char* field;
  };
  for (const Bad& bad :
       {Bad{50.0, -1.0, "speed"}, Bad{50.0, 1000.0, "speed"}, Bad{50.0, nan, "speed"},
        Bad{nan, 0.0, "station"}, Bad{1e300, 0.0, "must not exceed"}}) {
    ResetVehicle refused = request(bad.station, bad.speed, false);
    ASSERT_TRUE(ros::service::call(service, refused));
    EXPECT_FALSE(refused.response.success) << bad.station << " m, " << bad.speed << " m/s";
    EXPECT_NE(refused.response.message.find(bad.field), std::string::npos)
        << "'" << refused.response.message << "' does not name " << bad.field;
  }
  ASSERT_TRUE(step());
  EXPECT_EQ(last_.station, station);
  EXPECT_EQ(last_.speed, 0.0);
  EXPECT_NEAR((pose_.translation - on_plateau.translation).norm(), 0.0, 1e-9);
  for (const auto& w : last_.wheels)
    EXPECT_NEAR(w.displacement, height, tolerance) << w.name;

  // keep_terrain false: flat ground at the new station, as ~reset but there.
  ResetVehicle flat_reset = request(station + 10.0, 0.0, false);
  ASSERT_TRUE(ros::service::call(service, flat_reset));
  EXPECT_TRUE(flat_reset.response.success) << flat_reset.response.message;
  ASSERT_TRUE(step());
  EXPECT_EQ(last_.station, station + 10.0);
  EXPECT_NEAR((pose_.translation - flat.translation - Vector3(station + 10.0, 0.0, 0.0)).norm(),
              0.0, tolerance);
  for (const auto& w : last_.wheels)
    EXPECT_NEAR(w.displacement, 0.0, tolerance) << w.name;

  // ~reset_to at a speed counts as a speed message for ~speed_timeout: the vehicle drives off
  // with it for the timeout (no speed message follows), then stops where it is.
  const double timeout = test::requiredParam<double>(private_nh_, "speed_timeout");
  const double v = 3.0;  // [m/s]
  ResetVehicle moving = request(station + 20.0, v, false);
  ASSERT_TRUE(ros::service::call(service, moving));
  EXPECT_TRUE(moving.response.success) << moving.response.message;
  // In bursts of 50 ms, within ~catch_up_limit: every step is taken.
  for (int k = 0; k < static_cast<int>(std::lround((timeout - 0.1) / 0.05)); ++k)
    ASSERT_TRUE(advanceTo(t_ += ros::Duration(0.05)));
  EXPECT_EQ(last_.speed, v);
  EXPECT_NEAR(last_.station, station + 20.0 + v * (timeout - 0.1), 1e-9);
  for (int k = 0; k < 4; ++k)  // past the timeout
    ASSERT_TRUE(advanceTo(t_ += ros::Duration(0.05)));
  EXPECT_EQ(last_.speed, 0.0);
  const double stopped_at = last_.station;
  // On simulated time exactly: at the clock message 2.0 s after the call the time without a speed
  // message is not yet beyond the timeout (the step to it is driven); at the next, 50 ms later,
  // it is, and the vehicle stops before that step.
  EXPECT_NEAR(stopped_at, station + 20.0 + v * timeout, 1e-9);
  ASSERT_TRUE(advanceTo(t_ += ros::Duration(0.5)));
  EXPECT_EQ(last_.station, stopped_at);
  std::printf(
      "[ measured ] ~reset_to at %.1f m/s: stopped at station %.4f m, %.3f s after the "
      "call (~speed_timeout %.1f s)\n",
      v, stopped_at, (stopped_at - station - 20.0) / v, timeout);

  EXPECT_EQ(repeated_stamps_, 0u) << "a stamp was published twice in a row";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "node_reset_to_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
