// rostest tier 2 on real time (node_clock_step.test): the system clock stepped under a running
// node. The node's system clock is offset by the seconds in ~offset_file (libfaketime), which
// the test rewrites; the test stamps its speeds in the node's time (its own clock plus the
// offset) and reads the node's samples (road_wheels: stamp, speed, station) with their arrival
// on the monotonic clock, which no step moves.
//   back     the clock steps back 10 s while a speed stamped 0.6 s ahead waits: a speed stamped
//            after the step, in the new time, is taken at once (before: dropped as older than
//            the one in force until the clock caught up), the one that waited applies 0.6 s
//            after it was sent (before: 10.6 s); the samples' stamps step back 10 s once, their
//            stations go on.
//   forward  the clock steps forward 1 s, within ~catch_up_limit (2 s): the stamps step with
//            it, the station does not (before: 1 s of motion stepped in one tick, 3 m at 3 m/s)
//   said     two system clock steps in the loop diagnostics, the last +1.000 s, its WARN, no
//            jump back of ROS time (no reset), a WARN line for each step.
//   standing the vehicle stopped, the clock steps back 5 s: a speed stamped 0.2 s before now
//            finds it standing since before its stamp and makes up the steps it missed.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <geometry_msgs/TwistStamped.h>
#include <rosgraph_msgs/Log.h>

#include "node_test_utils.h"
#include "tracked_vehicle_dynamics/RoadWheels.h"

using namespace tracked_vehicle_dynamics;
using namespace tracked_vehicle_dynamics::ros_layer;

namespace {

constexpr double kBack = -10.0;         // [s] the first step of the node's clock
constexpr double kForward = 1.0;        // [s] the second
constexpr double kAhead = 0.6;          // [s] how far ahead the waiting speed is stamped
constexpr double kLatency = 0.4;        // [s] a loaded machine's delivery and scheduling delays
constexpr double kStandingBack = -5.0;  // [s] a third step, back, with the vehicle standing
constexpr double kLate = 0.2;           // [s] how late the speed after it is stamped

struct Sample {
  ros::Time stamp;
  double speed, station;
  ros::SteadyTime arrival;
};

class NodeClockStep : public ::testing::Test {
 protected:
  NodeClockStep() : private_nh_("~"), diagnostics_(nh_) {
    const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
    wheels_sub_ = nh_.subscribe<RoadWheels>(
        "road_wheels", 20000,
        [this](const RoadWheels::ConstPtr& m) {
          samples_.push_back({m->header.stamp, m->speed, m->station, ros::SteadyTime::now()});
        },
        ros::VoidConstPtr(), hints);
    rosout_sub_ = nh_.subscribe<rosgraph_msgs::Log>(
        "/rosout", 1000, [this](const rosgraph_msgs::Log::ConstPtr& m) { log_.push_back(*m); });
    stamped_pub_ = nh_.advertise<geometry_msgs::TwistStamped>("speed_stamped", 10);
    terrain_pub_ = nh_.advertise<TerrainProfile>("terrain_profile", 10, true);
    // Every summary of the loop status (a WARN lasts one report).
    diagnostics_sub_ = nh_.subscribe<diagnostic_msgs::DiagnosticArray>(
        "/diagnostics", 100, [this](const diagnostic_msgs::DiagnosticArray::ConstPtr& m) {
          for (const auto& status : m->status)
            if (status.name == "vehicle_dynamics: loop")
              loop_summaries_.push_back(status.message);
        });
    offset_file_ = test::requiredParam<std::string>(private_nh_, "offset_file");
  }

  // The run's own offset file goes with it (the node is stopped after the test).
  ~NodeClockStep() override { std::remove(offset_file_.c_str()); }

  /// Steps the node's system clock to `offset` [s] from the true one.
  void setOffset(double offset) {
    const std::string tmp = offset_file_ + ".test";
    {
      std::ofstream out(tmp);
      char text[32];
      std::snprintf(text, sizeof(text), "%+.3f\n", offset);
      out << text;
    }
    ASSERT_EQ(std::rename(tmp.c_str(), offset_file_.c_str()), 0) << offset_file_;
    offset_ = offset;
  }
  /// ROS time now as the node reads it.
  ros::Time nodeNow() const { return ros::Time::now() + ros::Duration(offset_); }
  void send(double v, const ros::Time& stamp) {
    geometry_msgs::TwistStamped msg;
    msg.header.stamp = stamp;
    msg.header.frame_id = "base_link";
    msg.twist.linear.x = v;
    stamped_pub_.publish(msg);
  }
  /// Waits until a sample carries `speed`; the arrival of the first that does (zero: none).
  ros::SteadyTime awaitSpeed(double speed, double timeout) {
    const std::size_t from = samples_.size();
    ros::SteadyTime at;
    test::spinUntil(
        [&] {
          for (std::size_t i = from; i < samples_.size() && at.isZero(); ++i)
            if (samples_[i].speed == speed)
              at = samples_[i].arrival;
          return !at.isZero();
        },
        timeout);
    return at;
  }
  /// The last sample that arrived before `t`.
  const Sample& lastBefore(const ros::SteadyTime& t) const {
    std::size_t i = 0;
    while (i + 1 < samples_.size() && samples_[i + 1].arrival < t)
      ++i;
    return samples_[i];
  }
  bool loopSaid(const std::string& text) const {
    for (const auto& m : loop_summaries_)
      if (m.find(text) != std::string::npos)
        return true;
    return false;
  }
  bool logged(const std::string& text) const {
    for (const auto& m : log_)
      if (m.name == "/vehicle_dynamics" && m.msg.find(text) != std::string::npos)
        return true;
    return false;
  }

  ros::NodeHandle nh_, private_nh_;
  test::DiagnosticsCache diagnostics_;
  ros::Subscriber wheels_sub_, rosout_sub_, diagnostics_sub_;
  std::vector<std::string> loop_summaries_;
  ros::Publisher stamped_pub_, terrain_pub_;
  std::vector<Sample> samples_;
  std::vector<rosgraph_msgs::Log> log_;
  std::string offset_file_;
  double offset_ = 0.0;
};

TEST_F(NodeClockStep, TheVehicleFollowsAStepOfTheSystemClock) {
  ASSERT_TRUE(test::spinUntil(
      [&] {
        return !samples_.empty() && stamped_pub_.getNumSubscribers() > 0 &&
               terrain_pub_.getNumSubscribers() > 0;
      },
      60.0))
      << "the node published nothing";
  // The node's clock is the test's (the wrapper wrote +0): its samples are stamped near now.
  EXPECT_NEAR((samples_.back().stamp - ros::Time::now()).toSec(), 0.0, 1.0);
  terrain_pub_.publish(test::flatProfile(-20.0, 500.0));
  test::spinFor(0.2);
  send(2.0, nodeNow());
  ASSERT_FALSE(awaitSpeed(2.0, 5.0).isZero()) << "the first stamped speed was not taken";

  // --- back: 10 s, while a speed stamped kAhead on waits.
  const ros::SteadyTime sent_ahead = ros::SteadyTime::now();
  send(3.0, nodeNow() + ros::Duration(kAhead));
  test::spinFor(0.05);
  const std::size_t before_back = samples_.size();
  setOffset(kBack);
  test::spinFor(0.1);
  const ros::SteadyTime sent_after = ros::SteadyTime::now();
  send(4.0, nodeNow());
  const ros::SteadyTime took_after = awaitSpeed(4.0, kAhead);
  ASSERT_FALSE(took_after.isZero())
      << "a speed stamped after the clock stepped back was not taken (dropped as older than the "
         "one in force?)";
  EXPECT_LT((took_after - sent_after).toSec(), kLatency);
  const ros::SteadyTime took_ahead = awaitSpeed(3.0, kAhead + 3.0);
  ASSERT_FALSE(took_ahead.isZero()) << "the speed sent ahead did not apply within 3 s of its time";
  const double waited = (took_ahead - sent_ahead).toSec();
  EXPECT_GT(waited, kAhead - 0.05);
  EXPECT_LT(waited, kAhead + kLatency);
  std::printf(
      "[ measured ] clock back %.0f s: the speed after it taken %.3f s after it was sent, "
      "the one sent %.1f s ahead applied %.3f s after it was sent\n",
      -kBack, (took_after - sent_after).toSec(), kAhead, waited);
  // The samples' stamps step back once, by the step; the stations go on.
  int backs = 0;
  for (std::size_t i = before_back; i < samples_.size(); ++i) {
    const Sample &a = samples_[i - 1], &b = samples_[i];
    EXPECT_GE(b.station, a.station) << "sample " << i;
    EXPECT_LT(b.station - a.station, 0.1) << "sample " << i;
    if (b.stamp < a.stamp) {
      ++backs;
      EXPECT_NEAR((b.stamp - a.stamp).toSec(), kBack, 0.05);
    }
  }
  EXPECT_EQ(backs, 1);

  // --- forward: 1 s at 3 m/s; the station follows the monotonic clock, not the stamps.
  test::spinFor(0.3);
  const ros::SteadyTime forward_at = ros::SteadyTime::now();
  const std::size_t before_forward = samples_.size();
  setOffset(kBack + kForward);
  test::spinFor(0.5);
  const Sample s0 = lastBefore(forward_at);
  const Sample s1 = samples_.back();
  const double moved = s1.station - s0.station, expected = 3.0 * (s1.arrival - s0.arrival).toSec();
  std::printf(
      "[ measured ] clock forward %.0f s: the station moved %.3f m while 3 m/s for the "
      "samples' arrival times gives %.3f m\n",
      kForward, moved, expected);
  EXPECT_NEAR(moved, expected, 3.0 * kLatency) << "the forward step was driven, not followed";
  int forwards = 0;
  for (std::size_t i = before_forward; i < samples_.size(); ++i) {
    const double gap = (samples_[i].stamp - samples_[i - 1].stamp).toSec();
    if (gap > 0.5) {
      ++forwards;
      EXPECT_NEAR(gap, kForward, 0.05);
      EXPECT_LT(samples_[i].station - samples_[i - 1].station, 0.1);
    }
  }
  EXPECT_EQ(forwards, 1);

  // --- said: counted, the last step named, no jump back of ROS time (a reset), a WARN line each.
  ASSERT_TRUE(test::spinUntil(
      [&] { return diagnostics_.value(": loop", "system clock steps (total)") == 2.0; }, 5.0))
      << diagnostics_.describe();
  EXPECT_EQ(diagnostics_.text(": loop", "last system clock step").rfind("+1.000 s at ROS time", 0),
            0u)
      << diagnostics_.text(": loop", "last system clock step");
  EXPECT_EQ(diagnostics_.value(": loop", "time jumps back (total)"), 0.0);
  EXPECT_EQ(diagnostics_.value(": loop", "resets (total)"), 0.0);
  EXPECT_TRUE(loopSaid("the system clock stepped (+1.000 s at ROS time"));
  EXPECT_TRUE(loopSaid("the system clock stepped (-10.000 s at ROS time"));
  EXPECT_TRUE(test::spinUntil(
      [&] {
        return logged("the system clock stepped back by 10.000 s") &&
               logged("the system clock stepped forward by 1.000 s");
      },
      5.0));

  // --- standing through a step back: stopped before the clock steps back kStandingBack, the
  // vehicle has stood since before a speed stamped kLate ago in the new time, which therefore
  // makes up the steps it missed (the time of the last speed taken moved with the clock: left in
  // the old time, kStandingBack ahead, the vehicle would count as moving since then and set off
  // from the speed's arrival instead, about kLate v short).
  send(0.0, nodeNow());
  ASSERT_FALSE(awaitSpeed(0.0, 5.0).isZero()) << "the stop was not taken";
  test::spinFor(0.2);
  const ros::Time before_step = samples_.back().stamp;
  setOffset(offset_ + kStandingBack);
  ASSERT_TRUE(test::spinUntil(
      [&] { return samples_.back().stamp < before_step + ros::Duration(kStandingBack + 1.0); },
      5.0))
      << "the node's samples did not step back with its clock";
  test::spinFor(0.1);
  const double stood_at = samples_.back().station;
  const ros::Time stamp = nodeNow() - ros::Duration(kLate);
  const std::size_t before_late = samples_.size();
  send(2.0, stamp);
  ASSERT_FALSE(awaitSpeed(2.0, 5.0).isZero()) << "the late speed was not taken";
  const Sample* first = nullptr;
  for (std::size_t i = before_late; i < samples_.size() && first == nullptr; ++i)
    if (samples_[i].speed == 2.0)
      first = &samples_[i];
  ASSERT_NE(first, nullptr);
  // Moving since the stamp: within two steps (1 ms each) of 2 m/s.
  EXPECT_NEAR(first->station - stood_at, 2.0 * (first->stamp - stamp).toSec(), 2.0 * 2.0 * 0.001)
      << "the steps missed since the speed's stamp were not made up";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "node_clock_step");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
