// rostest tier 2 on simulated time (node_speed_stamped.test, use_sim_time): speed_stamped
// (geometry_msgs/TwistStamped) through the running node. The test owns /clock, so every step's
// time is known: a speed stamped at s applies from the first step starting at a sample time
// t_k >= s, and the sample t_k + h is the first to carry it (road_wheels.speed), whenever the
// message arrived before that step. Cases, each from the sample the last one ended on:
//   schedule   two speeds sent 0.15 and 0.30 s ahead, the later one first, off the 1 ms grid:
//              0 until the sample after the first stamp's grid point, then 3, then 6 m/s
//   late       stamped 50 ms before the current sample: the next sample carries it; counted
//   frame      frame_id odom: refused naming the frame, the speed kept
//   time base  stamped 100 s ahead: taken at once, warned ("another time base"); 100 s behind
//              (simulated time: maybe a bag loop's next pass, so held for 0.25 s of wall time
//              for a jump back that does not come): taken then, warned
//   order      a speed arriving after its stamp, while an older one still waits for the next
//              step, is applied after that one, not overridden by it
//   reset      a speed due after ~reset is dropped with the run it belonged to
//   standing   a speed 30 ms late to a vehicle at rest since before its stamp makes up the
//              30 steps it missed (the station jumps by them, the motion goes on alike)
//   timeout    (a second node, ~speed_timeout 0.5 s) the driver dies with a speed sent 0.8 s
//              ahead: the vehicle stops at the timeout and the speed sent ahead never applies
//   mixed      a std_msgs/Float64 on speed as well: taken, and the mix warned about once
//   pass before  after a jump back of the clock, a late speed of the pass before is dropped
#include <gtest/gtest.h>

#include <cstdio>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <geometry_msgs/TwistStamped.h>
#include <rosgraph_msgs/Log.h>
#include <std_msgs/Float64.h>
#include <std_srvs/Empty.h>

#include "node_test_utils.h"
#include "tracked_vehicle_dynamics/RoadWheels.h"

using namespace tracked_vehicle_dynamics;
using namespace tracked_vehicle_dynamics::ros_layer;

namespace {

constexpr double kBurst = 0.02;  // [s] of simulated time per /clock message
// The first node's speed status (the second is timeout_dynamics).
const std::string kSpeedStatus = "vehicle_dynamics: speed";

class NodeSpeedStamped : public ::testing::Test {
 protected:
  NodeSpeedStamped() : private_nh_("~"), diagnostics_(nh_) {
    const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
    clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
    wheels_sub_ = nh_.subscribe("road_wheels", 20000, &NodeSpeedStamped::onWheels, this, hints);
    timeout_wheels_sub_ = nh_.subscribe<RoadWheels>(
        "timeout/road_wheels", 20000,
        [this](const RoadWheels::ConstPtr& m) { timeout_speeds_[m->header.stamp] = m->speed; },
        ros::VoidConstPtr(), hints);
    timeout_stamped_pub_ = nh_.advertise<geometry_msgs::TwistStamped>("timeout/speed_stamped", 10);
    rosout_sub_ = nh_.subscribe<rosgraph_msgs::Log>(
        "/rosout", 1000, [this](const rosgraph_msgs::Log::ConstPtr& m) { log_.push_back(*m); });
    // A queue for a whole burst (the bound's case below): none lost on a loaded machine.
    stamped_pub_ = nh_.advertise<geometry_msgs::TwistStamped>("speed_stamped", 1100);
    speed_pub_ = nh_.advertise<std_msgs::Float64>("speed", 10);
    terrain_pub_ = nh_.advertise<TerrainProfile>("terrain_profile", 10, true);
    // Every summary of the speed status (a WARN lasts one report).
    diagnostics_sub_ = nh_.subscribe<diagnostic_msgs::DiagnosticArray>(
        "/diagnostics", 100, [this](const diagnostic_msgs::DiagnosticArray::ConstPtr& m) {
          for (const auto& status : m->status)
            if (status.name == kSpeedStatus)
              speed_summaries_.insert(status.message);
        });
  }

  void onWheels(const RoadWheels::ConstPtr& m) {
    speeds_[m->header.stamp] = m->speed;
    stations_[m->header.stamp] = m->station;
  }

  bool advanceTo(const ros::Time& t) {
    test::publishClock(clock_pub_, t);
    return test::spinUntil([&] { return speeds_.count(t) > 0; }, 10.0);
  }
  /// The clock on by `seconds` in bursts; false when a sample is missing.
  bool runFor(double seconds) {
    return test::runClockFor(clock_pub_, &t_, seconds, kBurst,
                             [&](const ros::Time& t) { return speeds_.count(t) > 0; });
  }
  /// Sends a stamped speed; it reaches the node before the clock moves on.
  void send(double v, const ros::Time& stamp, const std::string& frame = "base_link") {
    sendOn(stamped_pub_, v, stamp, frame);
  }
  void sendOn(const ros::Publisher& pub, double v, const ros::Time& stamp,
              const std::string& frame = "base_link") {
    ASSERT_TRUE(test::spinUntil([&] { return pub.getNumSubscribers() > 0; }, 10.0));
    geometry_msgs::TwistStamped msg;
    msg.header.stamp = stamp;
    msg.header.frame_id = frame;
    msg.twist.linear.x = v;
    msg.twist.angular.z = 0.3;  // a turning vehicle: ignored (the model drives straight)
    pub.publish(msg);
    test::spinFor(0.3);
  }
  /// The first logged message of node `name` containing `text`; empty when none.
  std::string logged(const std::string& text, const std::string& name = "/vehicle_dynamics") const {
    for (const auto& m : log_)
      if (m.name == name && m.msg.find(text) != std::string::npos)
        return m.msg;
    return "";
  }
  /// A counter of the node's `speed` diagnostics, once a report at or after `t_` is in.
  double speedCounter(const std::string& key) {
    EXPECT_TRUE(runFor(0.25));  // two reports at 0.1 s
    return diagnostics_.value(kSpeedStatus, key);
  }
  /// The speed of every sample in (from, to], in order.
  std::vector<std::pair<ros::Time, double>> between(const ros::Time& from,
                                                    const ros::Time& to) const {
    std::vector<std::pair<ros::Time, double>> out;
    for (auto it = speeds_.upper_bound(from); it != speeds_.end() && it->first <= to; ++it)
      out.emplace_back(it->first, it->second);
    return out;
  }

  ros::NodeHandle nh_, private_nh_;
  test::DiagnosticsCache diagnostics_;
  ros::Publisher clock_pub_, stamped_pub_, speed_pub_, terrain_pub_, timeout_stamped_pub_;
  ros::Subscriber wheels_sub_, rosout_sub_, diagnostics_sub_, timeout_wheels_sub_;
  std::map<ros::Time, double> timeout_speeds_;  // the second node's
  std::set<std::string> speed_summaries_;
  std::vector<rosgraph_msgs::Log> log_;
  std::map<ros::Time, double> speeds_, stations_;
  ros::Time t_{1000.0};
};

TEST_F(NodeSpeedStamped, StampedSpeedsApplyAtTheStepOfTheirStamp) {
  const double h = 1.0 / test::requiredParam<double>(private_nh_, "rate");
  const ros::Duration step(h);
  ASSERT_TRUE(test::tickClockUntil(
      clock_pub_, &t_, [&] { return !speeds_.empty(); }, 60.0))
      << "the node published nothing";
  t_ += step;
  ASSERT_TRUE(advanceTo(t_));
  terrain_pub_.publish(test::flatProfile(-20.0, 300.0));
  test::spinFor(0.3);
  ASSERT_TRUE(runFor(10 * h));
  ASSERT_EQ(speeds_.at(t_), 0.0);

  // --- schedule: the later stamp sent first; both off the grid (0.4 us past a step).
  {
    SCOPED_TRACE("schedule");
    const ros::Time t0 = t_;
    const ros::Time first = t0 + ros::Duration(0.1504), second = t0 + ros::Duration(0.3004);
    send(6.0, second);
    send(3.0, first);
    ASSERT_TRUE(runFor(0.5));
    // The grid point at or after each stamp starts the step the speed drives; the sample after
    // it is the first to carry it.
    const ros::Time first_sample = t0 + ros::Duration(0.151) + step;
    const ros::Time second_sample = t0 + ros::Duration(0.301) + step;
    std::size_t checked = 0;
    for (const auto& [t, v] : between(t0, t_)) {
      const double expected = t < first_sample ? 0.0 : t < second_sample ? 3.0 : 6.0;
      EXPECT_EQ(v, expected) << "sample at " << (t - t0).toSec() << " s";
      ++checked;
    }
    EXPECT_EQ(checked, static_cast<std::size_t>(std::lround(0.5 / h)));
    std::printf(
        "[ measured ] schedule: 3 m/s from the sample %.4f s after the start (stamp "
        "%.4f s), 6 m/s from %.4f s (stamp %.4f s)\n",
        (first_sample - t0).toSec(), (first - t0).toSec(), (second_sample - t0).toSec(),
        (second - t0).toSec());
    EXPECT_EQ(speedCounter("stamped speeds late (total)"), 0.0);
  }

  // --- late: stamped 50 ms before the current sample.
  {
    SCOPED_TRACE("late");
    const ros::Time t0 = t_;
    send(2.0, t0 - ros::Duration(0.05));
    ASSERT_TRUE(runFor(0.05));
    EXPECT_EQ(speeds_.at(t0), 6.0);
    EXPECT_EQ(speeds_.at(t0 + step), 2.0);  // at once: the next sample
    EXPECT_EQ(speedCounter("stamped speeds late (total)"), 1.0);
    // Stamped less than a step before the sample: the step at or after its stamp, the one
    // from this sample, is still to come: on time, not late.
    const ros::Time t1 = t_;
    send(2.0, t1 - ros::Duration(0.4 * h));
    ASSERT_TRUE(runFor(0.05));
    EXPECT_EQ(speeds_.at(t1 + step), 2.0);
    EXPECT_EQ(speedCounter("stamped speeds late (total)"), 1.0);
  }

  // --- frame: odom's x is not the heading; refused naming the frame, the speed kept.
  {
    SCOPED_TRACE("frame");
    const double rejected = diagnostics_.value(kSpeedStatus, "speeds rejected (total)");
    send(9.0, t_, "odom");
    ASSERT_TRUE(runFor(0.05));
    EXPECT_EQ(speeds_.at(t_), 2.0);
    EXPECT_EQ(speedCounter("speeds rejected (total)"), rejected + 1.0);
    EXPECT_EQ(diagnostics_.text(kSpeedStatus, "last rejection"),
              "speed_stamped in frame 'odom': its twist.linear.x is taken as the forward speed, "
              "which it is in 'base_link' or an empty frame_id only");
    EXPECT_NE(logged("speed_stamped in frame 'odom'"), "");
  }

  // --- another time base, ahead: taken at once.
  {
    SCOPED_TRACE("time base ahead");
    const ros::Time t0 = t_;
    send(4.0, t0 + ros::Duration(100.0));
    ASSERT_TRUE(runFor(0.05));
    EXPECT_EQ(speeds_.at(t0 + step), 4.0);
    EXPECT_EQ(speedCounter("stamped speeds in another time base (total)"), 1.0);
    EXPECT_EQ(speed_summaries_.count("speed_stamped stamped in another time base: taken on "
                                     "arrival"),
              1u);
    EXPECT_NE(logged("s ahead of ROS time"), "");
  }

  // --- another time base, behind: held for a jump back (0.25 s of wall time; send() waits
  // 0.3 s, and the node's loop looks every 50 ms), then taken.
  {
    SCOPED_TRACE("time base behind");
    const ros::Time t0 = t_;
    send(1.0, t0 - ros::Duration(100.0));
    test::spinFor(0.2);
    ASSERT_TRUE(runFor(0.05));
    EXPECT_EQ(speeds_.at(t0 + step), 1.0);
    EXPECT_EQ(speedCounter("stamped speeds in another time base (total)"), 2.0);
    // The warning is throttled (the one above was said less than 5 s ago): the status names it.
    EXPECT_NE(
        diagnostics_.text(kSpeedStatus, "last in another time base").find("s behind ROS time"),
        std::string::npos)
        << diagnostics_.text(kSpeedStatus, "last in another time base");
  }

  // --- order: A stamped 15.5 ms on is still waiting when the sample at 16 ms is taken (a step
  // applies the speeds due at its start, 15 ms); B, stamped 15.8 ms, arrives then: due at once,
  // it is applied after A, and the step from 16 ms runs at B.
  {
    SCOPED_TRACE("order");
    const ros::Time t0 = t_;
    send(5.0, t0 + ros::Duration(0.0155));
    t_ = t0 + ros::Duration(0.016);
    ASSERT_TRUE(advanceTo(t_));
    send(0.5, t0 + ros::Duration(0.0158));
    ASSERT_TRUE(runFor(0.01));
    EXPECT_EQ(speeds_.at(t0 + ros::Duration(0.016)), 1.0);  // the speed before both
    EXPECT_EQ(speeds_.at(t0 + ros::Duration(0.017)), 0.5);
    EXPECT_EQ(speeds_.at(t_), 0.5);
    // Older than B, which is in force: stale (reordered, or a second sender), dropped.
    send(9.0, t0 + ros::Duration(0.0157));
    ASSERT_TRUE(runFor(0.01));
    EXPECT_EQ(speeds_.at(t_), 0.5);
    EXPECT_EQ(speedCounter("stamped before the stamped speed in force, dropped (total)"), 1.0);
  }

  // --- timeout (the second node): the driver sends 4 m/s now and 8 m/s for 0.8 s on, then dies.
  {
    SCOPED_TRACE("timeout");
    const ros::Time t0 = t_;
    // runFor() waits for the first node's samples: the second may lag a few /clock ticks behind
    // on a loaded machine (it once had not published t0 yet). Its sample at t0 also puts its
    // ROS time at t0 when the speed arrives, from which ~speed_timeout counts.
    const auto second_at = [&](const ros::Time& t) {
      return test::spinUntil([&] { return timeout_speeds_.count(t) > 0; }, 10.0);
    };
    ASSERT_TRUE(second_at(t0)) << "the second node published nothing";
    sendOn(timeout_stamped_pub_, 4.0, t0);
    sendOn(timeout_stamped_pub_, 8.0, t0 + ros::Duration(0.8));
    ASSERT_TRUE(runFor(1.2));
    ASSERT_TRUE(second_at(t_)) << "the second node fell behind the clock";
    const auto samples = std::vector<std::pair<ros::Time, double>>(timeout_speeds_.upper_bound(t0),
                                                                   timeout_speeds_.upper_bound(t_));
    ASSERT_FALSE(samples.empty());
    double stopped_at = -1.0;
    for (const auto& [t, v] : samples) {
      EXPECT_NE(v, 8.0) << "the dead driver's speed applied at " << (t - t0).toSec() << " s";
      if (v == 0.0 && stopped_at < 0.0)
        stopped_at = (t - t0).toSec();
    }
    EXPECT_EQ(samples.front().second, 4.0);
    EXPECT_NEAR(stopped_at, 0.5, 0.002);  // the first step after 0.5 s without a message
    EXPECT_EQ(samples.back().second, 0.0);
    EXPECT_NE(logged("dropping the 1 stamped speeds still waiting for their stamps",
                     "/timeout/timeout_dynamics"),
              "");
  }

  // --- reset: the schedule belongs to the run it ends.
  {
    SCOPED_TRACE("reset");
    send(5.0, t_ + ros::Duration(0.2));
    std_srvs::Empty srv;
    ASSERT_TRUE(ros::service::waitForService("vehicle_dynamics/reset", 10000));
    ASSERT_TRUE(ros::service::call("vehicle_dynamics/reset", srv));
    const ros::Time t0 = t_;
    ASSERT_TRUE(runFor(0.4));
    for (const auto& [t, v] : between(t0, t_))
      EXPECT_EQ(v, 0.0) << "sample at " << (t - t0).toSec() << " s after the reset";
    EXPECT_EQ(speedCounter("stamped speeds waiting for their stamp"), 0.0);
  }

  // --- standing: at rest since the reset, a speed stamped 30 ms before the current sample
  // makes up the 30 steps it missed: the next sample is 31 steps of it on.
  {
    SCOPED_TRACE("standing");
    const ros::Time t0 = t_;
    ASSERT_EQ(speeds_.at(t0), 0.0);
    send(2.0, t0 - ros::Duration(0.03));
    ASSERT_TRUE(runFor(0.02));
    EXPECT_NEAR(stations_.at(t0 + step) - stations_.at(t0), 2.0 * 31 * h, 1e-9);
    EXPECT_NEAR(stations_.at(t0 + step + step) - stations_.at(t0 + step), 2.0 * h, 1e-9);
    EXPECT_EQ(speedCounter("late to a vehicle standing still, the missed steps made up (total)"),
              1.0);
  }

  // --- mixed: a Float64 as well, taken at the next sample; the mix said once.
  {
    SCOPED_TRACE("mixed");
    EXPECT_EQ(logged("speeds arrive on both"), "");
    std_msgs::Float64 msg;
    msg.data = 2.5;
    ASSERT_TRUE(test::spinUntil([&] { return speed_pub_.getNumSubscribers() > 0; }, 10.0));
    speed_pub_.publish(msg);
    test::spinFor(0.3);
    const ros::Time t0 = t_;
    ASSERT_TRUE(runFor(0.05));
    EXPECT_EQ(speeds_.at(t0 + step), 2.5);
    ASSERT_TRUE(test::spinUntil([&] { return !logged("speeds arrive on both").empty(); }, 5.0));
  }

  // --- pass before: the clock jumps back 0.5 s (a loop); then a late speed of the pass before,
  // stamped at the time the clock left, arrives: dropped, not scheduled 0.5 s into the new pass.
  {
    SCOPED_TRACE("pass before");
    const ros::Time old = t_;
    t_ = old - ros::Duration(0.5);
    speeds_.erase(speeds_.lower_bound(t_), speeds_.end());  // wait for the restart's sample
    ASSERT_TRUE(advanceTo(t_));
    send(9.0, old);
    ASSERT_TRUE(runFor(0.6));  // past the old time
    for (const auto& [t, v] : between(old - ros::Duration(0.5), t_))
      EXPECT_EQ(v, 0.0) << "sample at " << (t - old).toSec() << " s from the old time";
    EXPECT_EQ(speedCounter("stamped in the pass before a jump back, dropped (total)"), 1.0);
  }

  // --- bound: while ROS time stands still, 1000 speeds (the bound) wait for their stamps, all
  // within a second ahead; the 1001st is refused, named, the waiting ones kept.
  {
    SCOPED_TRACE("bound");
    const double rejected = diagnostics_.value(kSpeedStatus, "speeds rejected (total)");
    ASSERT_TRUE(test::spinUntil([&] { return stamped_pub_.getNumSubscribers() > 0; }, 10.0));
    geometry_msgs::TwistStamped msg;
    msg.header.frame_id = "base_link";
    msg.twist.linear.x = 0.0;  // the speed in force: the run goes on as it was
    for (int k = 0; k <= 1000; ++k) {
      msg.header.stamp = t_ + ros::Duration(0.0009 * (k + 1));
      stamped_pub_.publish(msg);
      if (k % 10 == 9)
        test::spinFor(0.02);  // the node takes them as they come (its queue: 1000)
    }
    test::spinFor(1.0);  // on wall time: ROS time must stand still until all have arrived
    EXPECT_EQ(speedCounter("speeds rejected (total)"), rejected + 1.0);
    EXPECT_EQ(diagnostics_.text(kSpeedStatus, "last rejection"),
              "speed_stamped: 1000 speeds already wait for their stamps (is ROS time standing "
              "still?)");
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "node_speed_stamped");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
