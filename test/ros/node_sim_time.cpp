// rostest tier 2 on simulated time (node_sim_time.test, use_sim_time): the test owns /clock. The
// node steps exactly as the clock advances (every fixed step, caught up when the clock moves in
// bursts), resynchronises after a jump longer than ~catch_up_limit, and resets when time goes
// backwards (a bag loop) — each with a diagnostics entry, always publishing finite values. No
// stamp is published twice in a row (~reset included: tf2 would drop the second as
// TF_REPEATED_DATA).
#include <gtest/gtest.h>

#include <cmath>

#include <rosgraph_msgs/Clock.h>
#include <std_msgs/Float64.h>
#include <std_srvs/Empty.h>
#include <tf2_msgs/TFMessage.h>

#include "node_test_utils.h"
#include "tracked_vehicle_dynamics/RoadWheels.h"

using namespace tracked_vehicle_dynamics;
using namespace tracked_vehicle_dynamics::ros_layer;

namespace {

constexpr double kStation = 1e-9;      // accumulated station rounding [m]
constexpr double kEquilibrium = 1e-9;  // rounding of a step at rest [m]

class NodeSimTime : public ::testing::Test {
 protected:
  NodeSimTime() : private_nh_("~"), diagnostics_(nh_) {
    clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
    wheels_sub_ = nh_.subscribe("road_wheels", 10000, &NodeSimTime::onWheels, this,
                                ros::TransportHints().tcpNoDelay());
    tf_sub_ =
        nh_.subscribe("/tf", 10000, &NodeSimTime::onTf, this, ros::TransportHints().tcpNoDelay());
    terrain_pub_ = nh_.advertise<TerrainProfile>("terrain_profile", 10, true);
    speed_pub_ = nh_.advertise<std_msgs::Float64>("speed", 10, true);
    tf_static_sub_ = nh_.subscribe<tf2_msgs::TFMessage>(
        "/tf_static", 10,
        [this](const tf2_msgs::TFMessage::ConstPtr& msg) {
          for (const auto& t : msg->transforms)
            static_stamps_.push_back(t.header.stamp);
        },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
  }

  void onWheels(const RoadWheels::ConstPtr& msg) {
    if (messages_ == 0)
      first_stamp_ = msg->header.stamp;
    if (msg->header.stamp.isZero())
      ++zero_stamps_;
    if (messages_ > 0 && msg->header.stamp == last_.header.stamp)
      ++repeated_wheel_stamps_;
    last_ = *msg;
    ++messages_;
    for (const auto& w : msg->wheels) {
      if (!std::isfinite(w.displacement) || !std::isfinite(w.acceleration))
        ++non_finite_;
    }
  }

  void onTf(const tf2_msgs::TFMessage::ConstPtr& msg) {
    for (const auto& t : msg->transforms) {
      if (t.child_frame_id != "base_link")
        continue;
      if (tf_messages_ > 0 && t.header.stamp == last_tf_stamp_)
        ++repeated_tf_stamps_;
      last_tf_stamp_ = t.header.stamp;
      ++tf_messages_;
    }
  }

  void setClock(const ros::Time& t) { test::publishClock(clock_pub_, t); }

  /// Moves the clock to `t` and waits until the node has published its sample at `t`.
  bool advanceTo(const ros::Time& t) {
    setClock(t);
    return test::spinUntil([&] { return messages_ > 0 && last_.header.stamp == t; }, 10.0);
  }

  ros::NodeHandle nh_, private_nh_;
  test::DiagnosticsCache diagnostics_;
  ros::Publisher clock_pub_, terrain_pub_, speed_pub_;
  ros::Subscriber wheels_sub_, tf_sub_, tf_static_sub_;
  RoadWheels last_;
  ros::Time first_stamp_;                 // of the node's first sample
  std::vector<ros::Time> static_stamps_;  // of the /tf_static transforms received
  std::size_t messages_ = 0, non_finite_ = 0;
  ros::Time last_tf_stamp_;
  std::size_t tf_messages_ = 0, repeated_wheel_stamps_ = 0, repeated_tf_stamps_ = 0;
  std::size_t zero_stamps_ = 0;  // samples stamped 0.0 ("no time" in ROS)
};

// Before the first /clock, ROS time stands at 0 and reports paced on ROS time would say nothing;
// the node reports why on wall time. (Runs first: no /clock has been published yet.)
TEST_F(NodeSimTime, DiagnosticsSayWaitingBeforeTheClock) {
  // (diagnostic_updater's own "Node starting up" comes first, while the model loads.)
  ASSERT_TRUE(test::spinUntil(
      [&] {
        return diagnostics_.describe().find("loop [1] waiting for ROS time (/clock)") !=
               std::string::npos;
      },
      45.0))
      << "no WARN 'waiting for ROS time' before the first /clock:\n"
      << diagnostics_.describe();
  EXPECT_EQ(messages_, 0u);
  // A speed sent before simulated time starts (a stack that commands it once, then starts its
  // clock): its ~speed_timeout counts from the first /clock, so the vehicle drives off with it
  // (the next test's first samples) instead of stopping at once for "no speed message for 100 s".
  std_msgs::Float64 v;
  v.data = test::requiredParam<double>(private_nh_, "speed");
  speed_pub_.publish(v);
  test::spinFor(0.5);  // delivered before this fixture, and its latched publisher, go
  // Given a speed but no /clock, the vehicle has not moved: its terrain status, reported after
  // the speed came, says it waits for ROS time, not "moving on flat ground" (review 130).
  const std::size_t reports = diagnostics_.arrays();
  ASSERT_TRUE(test::spinUntil([&] { return diagnostics_.arrays() >= reports + 2; }, 10.0));
  const std::string said = diagnostics_.describe();
  EXPECT_NE(said.find("waiting for terrain: standing on flat ground until ROS time (/clock) "
                      "starts"),
            std::string::npos)
      << said;
  EXPECT_EQ(said.find("moving on flat ground"), std::string::npos) << said;
}

TEST_F(NodeSimTime, StepsFollowTheClockCatchUpResynchroniseAndResetOnLoop) {
  const double speed = test::requiredParam<double>(private_nh_, "speed");
  const double catch_up_limit = test::requiredParam<double>(private_nh_, "catch_up_limit");
  const double speed_timeout = test::requiredParam<double>(private_nh_, "speed_timeout");
  // Simulated time runs once the node has loaded its model and published its first sample.
  ros::Time t(100.0);
  ASSERT_TRUE(test::tickClockUntil(
      clock_pub_, &t, [&] { return messages_ > 0; }, 45.0))
      << "the node published nothing";
  // The named points' static frames come with the first sample, stamped with its time (not 0:
  // ROS time before the first /clock). This test's road_wheels subscription may connect a few
  // samples after the node's first one (the node publishes only to connected subscribers), so
  // the first sample received is that one or a whole number of steps later.
  ASSERT_TRUE(test::spinUntil([&] { return !static_stamps_.empty(); }, 5.0))
      << "nothing on /tf_static";
  const double step = 1.0 / test::requiredParam<double>(private_nh_, "rate");
  for (const ros::Time& stamp : static_stamps_) {
    EXPECT_GE(stamp, ros::Time(100.0)) << "stamped before the first /clock";
    EXPECT_LE(stamp, first_stamp_);
    const double steps = (first_stamp_ - stamp).toSec() / step;
    EXPECT_NEAR(steps, std::round(steps), 1e-6) << "not on the node's step grid";
  }
  ASSERT_TRUE(advanceTo(t + ros::Duration(0.001)));
  t = last_.header.stamp;
  const ros::Time t0 = t;
  // ~diagnostic_period is read once: diagnostic_updater re-read it at every report, and 1e10 set
  // while the node runs threw out of each one (the diagnostics checked below stopped) and, at the
  // jump back below, out of the /clock callback (the node died).
  ros::param::set("/vehicle_dynamics/diagnostic_period", 1e10);
  // Driving at the speed sent before the clock started (previous test), not stopped by the
  // speed timeout at the first /clock.
  EXPECT_EQ(last_.speed, speed);
  EXPECT_GT(last_.station, 0.0);
  const double station0 = last_.station;
  terrain_pub_.publish(test::flatProfile(-10.0, 40.0));
  std_msgs::Float64 v;
  v.data = speed;
  speed_pub_.publish(v);
  test::spinFor(0.5);  // both delivered before the clock moves

  // 0.2 s in bursts of 1 .. 100 ms: every step is taken, station = v t exactly.
  for (int burst : {1, 1, 2, 5, 20, 1, 3, 7, 10, 50, 100}) {
    t += ros::Duration(burst * 1e-3);
    ASSERT_TRUE(advanceTo(t)) << "no sample at " << t;
  }
  EXPECT_NEAR(last_.station - station0, speed * (t - t0).toSec(), kStation);
  EXPECT_EQ(last_.speed, speed);

  // A jump longer than ~catch_up_limit: only catch_up_limit is simulated.
  const double station_before = last_.station;
  t += ros::Duration(1.0);
  ASSERT_TRUE(advanceTo(t));
  EXPECT_NEAR(last_.station - station_before, speed * catch_up_limit, kStation);

  // A clock that steps back by less than a step (a jittery source) is the sample already taken:
  // no reset (the count of jumps back stays 1 below), nothing published, the next step goes on
  // from the station.
  const double station_held = last_.station;
  const std::size_t before_jitter = messages_;
  setClock(t - ros::Duration(0.0005));
  test::spinFor(0.1);
  EXPECT_EQ(messages_, before_jitter);
  t += ros::Duration(0.001);
  ASSERT_TRUE(advanceTo(t));
  EXPECT_NEAR(last_.station - station_held, speed * 0.001, kStation);

  // Time going backwards (a bag loop): reset to station 0 at the new time (the node restarts on
  // the /clock message itself). Just before it, the next loop's first patch arrives, stamped at
  // the new time and in absolute altitudes (250 m): re-applied after the restart, it is judged
  // against the restarted vehicle's flat ground and named until a reset clears it.
  TerrainPatch altitudes;
  altitudes.start_station = 30.0;
  altitudes.spacing = 0.05;
  altitudes.lateral = Vector::LinSpaced(11, -2.5, 2.5);
  altitudes.heights = Matrix::Constant(11, 101, 250.0);
  TerrainProfile next_loop;
  toMsg(altitudes, &next_loop);
  next_loop.header.frame_id = "odom";
  next_loop.header.stamp = t0;
  // Two patches that must not be re-applied: one unstamped (it cannot be told apart) and one
  // stamped at the old time (the old pass's last). Both lie under the restarted vehicle, 0.2 m
  // high: re-applied, they would lift its wheels (checked at 0 below).
  TerrainPatch under;
  under.start_station = -5.0;
  under.spacing = 0.05;
  under.lateral = Vector::LinSpaced(11, -2.5, 2.5);
  under.heights = Matrix::Constant(11, 201, 0.2);
  TerrainProfile unstamped, old_pass;
  toMsg(under, &unstamped);
  unstamped.header.frame_id = "odom";
  old_pass = unstamped;
  old_pass.header.stamp = t;
  terrain_pub_.publish(unstamped);
  terrain_pub_.publish(old_pass);
  terrain_pub_.publish(next_loop);
  test::spinFor(0.05);  // within the node's 0.25 s rewind window
  t = t0;
  setClock(t);
  test::spinFor(0.05);
  t += ros::Duration(0.001);
  ASSERT_TRUE(advanceTo(t));
  EXPECT_EQ(last_.station, 0.0);
  for (const auto& w : last_.wheels)
    EXPECT_NEAR(w.displacement, 0.0, kEquilibrium) << w.name;
  ASSERT_TRUE(test::spinUntil(
      [&] {
        return diagnostics_.text(": terrain", "step off the ground since the start or reset")
                       .find("starts 250 m above the flat ground") != std::string::npos &&
               diagnostics_.value(": loop", "patches re-applied after a jump back (total)") >= 1;
      },
      5.0))
      << diagnostics_.describe();
  EXPECT_NE(diagnostics_.text(": terrain", "step off the ground since the start or reset")
                .find("re-applied after the time jump back"),
            std::string::npos);
  EXPECT_EQ(diagnostics_.value(": loop", "patches re-applied after a jump back (total)"), 1.0)
      << diagnostics_.describe();

  // And it runs on from there (speed is zero after the reset until a new speed message).
  speed_pub_.publish(v);
  test::spinFor(0.3);
  t += ros::Duration(0.05);
  ASSERT_TRUE(advanceTo(t));
  EXPECT_NEAR(last_.station, speed * 0.05, kStation);

  // ~reset: back to station 0 from wherever the vehicle is.
  speed_pub_.publish(v);
  test::spinFor(0.3);
  t += ros::Duration(0.02);
  ASSERT_TRUE(advanceTo(t));
  ASSERT_GT(last_.station, 0.0);
  const std::size_t before_reset = messages_;
  std_srvs::Empty reset;
  ASSERT_TRUE(ros::service::call("/vehicle_dynamics/reset", reset));
  test::spinFor(0.2);  // anything the reset publishes arrives
  EXPECT_TRUE(test::spinUntil(
      [&] {
        return diagnostics_.text(": terrain", "step off the ground since the start or reset") ==
               "none";
      },
      5.0))
      << diagnostics_.describe();
  // That report (on wall time: the clock stands still here) has the loop's step count and
  // simulated time restarted with the vehicle (the restart after the jump back was the first
  // reset).
  EXPECT_EQ(diagnostics_.value(": loop", "resets (total)"), 2.0) << diagnostics_.describe();
  EXPECT_EQ(diagnostics_.value(": loop", "steps"), 0.0);
  EXPECT_EQ(diagnostics_.value(": loop", "simulated time [s]"), 0.0);
  // The reset state goes out with the next sample, at a new stamp; nothing is published at the
  // stamp already used.
  EXPECT_EQ(messages_, before_reset);
  t += ros::Duration(0.001);
  ASSERT_TRUE(advanceTo(t));
  EXPECT_EQ(last_.station, 0.0);
  EXPECT_EQ(last_.speed, 0.0);
  EXPECT_EQ(repeated_wheel_stamps_, 0u) << "road_wheels published a stamp twice in a row";
  EXPECT_GT(tf_messages_, 0u);
  EXPECT_EQ(repeated_tf_stamps_, 0u) << "/tf published base_link twice at one stamp";

  // ~speed_timeout: a driver that stops publishing stops the vehicle where it is (without it, the
  // jump below would drive on by speed x catch_up_limit).
  speed_pub_.publish(v);
  test::spinFor(0.3);
  t += ros::Duration(0.01);
  ASSERT_TRUE(advanceTo(t));
  EXPECT_EQ(last_.speed, speed);
  const double moving_station = last_.station;
  t += ros::Duration(speed_timeout + 1.0);
  ASSERT_TRUE(advanceTo(t));
  EXPECT_EQ(last_.speed, 0.0);
  EXPECT_EQ(last_.station, moving_station);
  speed_pub_.publish(v);  // and the next speed message moves it again
  test::spinFor(0.3);
  t += ros::Duration(0.01);
  ASSERT_TRUE(advanceTo(t));
  EXPECT_NEAR(last_.station - moving_station, speed * 0.01, kStation);

  EXPECT_EQ(non_finite_, 0u);
  t += ros::Duration(2.0);  // let the diagnostics period pass on simulated time
  setClock(t);
  ASSERT_TRUE(test::spinUntil(
      [&] {
        return diagnostics_.value(": loop", "time jumps back (total)") >= 1 &&
               diagnostics_.value(": loop", "resynchronisations (total)") >= 1 &&
               diagnostics_.value(": speed", "stops after the speed timeout (total)") >= 1;
      },
      10.0))
      << diagnostics_.describe();
  EXPECT_EQ(diagnostics_.value(": loop", "time jumps back (total)"), 1.0);
  EXPECT_EQ(diagnostics_.value(": speed", "stops after the speed timeout (total)"), 1.0);
  // The test publishes no more /clock: a stopped simulator is said on wall time, not left at
  // "running" with a frozen step count.
  EXPECT_TRUE(test::spinUntil(
      [&] {
        return diagnostics_.describe().find("loop [1] /clock has not advanced for") !=
               std::string::npos;
      },
      10.0))
      << diagnostics_.describe();

  // The clock reset to 0 (a simulator's world reset): the vehicle restarts, publishes nothing
  // stamped 0.0 ("no time"), says it waits for the clock, and its first sample is stamped when
  // the clock runs again, at station 0.
  const std::size_t before_zero = messages_;
  setClock(ros::Time(0.0));
  EXPECT_TRUE(test::spinUntil(
      [&] {
        return diagnostics_.describe().find("loop [1] waiting for ROS time (/clock)") !=
               std::string::npos;
      },
      5.0))
      << diagnostics_.describe();
  EXPECT_EQ(messages_, before_zero);
  ASSERT_TRUE(advanceTo(ros::Time(3.0)));
  EXPECT_EQ(last_.station, 0.0);
  EXPECT_EQ(zero_stamps_, 0u);
  t = ros::Time(3.0) + ros::Duration(0.01);
  ASSERT_TRUE(advanceTo(t));
  EXPECT_EQ(zero_stamps_, 0u);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "node_sim_time_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
