// rostest tier 2 on simulated time (node_initial_speed.test, use_sim_time): ~initial_speed v0.
// The test owns /clock and sends flat terrain but no speed message. Every run — the start,
// ~reset, a jump back of /clock (a bag loop) — starts at station 0 at time t0 at v0, at rest
// relative to it, and takes v0 as a speed message at t0, so that ~speed_timeout T then brakes it
// at ~max_deceleration D. In each run, with h = 1 / rate and every sample recorded:
//   cruise    t <= t0 + T: speed v0, station v0 (t - t0), hull/accel x 0 (no travel acceleration:
//             not accelerated from rest through the slew)
//   timeout   the first slower sample at t0 + T + h (the step after the timeout passed)
//   braking   v(t) = max(0, v0 - D (t - t_b)) from the step t_b - h that started braking, and the
//             station advancing by the trapezoid (v_k + v_{k+1}) h / 2
// A run whose timeout counted from an earlier time (the start's, not the reset's or the jump's)
// would brake at once after ~reset, or not for 50 s after the jump back.
// ~reset clears the terrain, and the jump back leaves none (an unstamped patch is not re-applied):
// the restarted vehicle, moving, is held (nothing published) until the test sends terrain
// covering its contacts 20 ms of simulated time later (after ~reset, a patch to station 0 first),
// then steps those 20 ms on it, so no step runs with its contacts off the terrain.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <geometry_msgs/AccelStamped.h>
#include <std_srvs/Empty.h>

#include "node_test_utils.h"
#include "tracked_vehicle_dynamics/RoadWheels.h"

using namespace tracked_vehicle_dynamics;
using namespace tracked_vehicle_dynamics::ros_layer;

namespace {

constexpr double kStation = 1e-9;  // accumulated station rounding [m]
constexpr double kSpeed = 1e-9;    // speed rounding of the slew's steps [m/s]
// hull/accel at a steady speed on flat ground: the equilibrium to rounding [m/s^2]
constexpr double kAtRest = 1e-6;

struct Sample {
  ros::Time stamp;
  double station, speed;
};

class NodeInitialSpeed : public ::testing::Test {
 protected:
  NodeInitialSpeed()
      : private_nh_("~"),
        diagnostics_(nh_),
        v0_(test::requiredParam<double>(private_nh_, "initial_speed")),
        decel_(test::requiredParam<double>(private_nh_, "max_deceleration")),
        timeout_(test::requiredParam<double>(private_nh_, "speed_timeout")),
        h_(1.0 / test::requiredParam<double>(private_nh_, "rate")) {
    clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
    terrain_pub_ = nh_.advertise<TerrainProfile>("terrain_profile", 10, true);
    wheels_sub_ = nh_.subscribe<RoadWheels>(
        "road_wheels", 10000,
        [this](const RoadWheels::ConstPtr& msg) {
          samples_.push_back({msg->header.stamp, msg->station, msg->speed});
        },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
    accel_sub_ = nh_.subscribe<geometry_msgs::AccelStamped>(
        "hull/accel", 10000,
        [this](const geometry_msgs::AccelStamped::ConstPtr& msg) {
          accel_x_.emplace_back(msg->header.stamp, msg->accel.linear.x);
        },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
  }

  /// Moves the clock to `t` and waits for the node's sample at `t`.
  bool advanceTo(const ros::Time& t) {
    test::publishClock(clock_pub_, t);
    return test::spinUntil([&] { return !samples_.empty() && samples_.back().stamp == t; }, 10.0);
  }

  /// Runs the clock on by `seconds` a step at a time (the timeout is checked at every tick: a
  /// step per /clock puts its onset on the step after it passes).
  bool runFor(double seconds) {
    // A whole number of steps: a /clock between two steps would wait for a sample never published.
    const ros::Duration whole = ros::Duration(h_) * static_cast<double>(std::lround(seconds / h_));
    return test::runClockFor(clock_pub_, &t_, whole.toSec(), h_, [&](const ros::Time& t) {
      return !samples_.empty() && samples_.back().stamp == t;
    });
  }

  /// Runs the clock on by `steps` steps while the node holds its restart for the terrain (it
  /// publishes nothing: returns false if it does), then sends the terrain.
  /// With `partial`, a patch under its rear half that does not reach its front contacts comes
  /// first: the hold goes on through it.
  bool holdFor(int steps, bool partial = false) {
    const std::size_t before = samples_.size();
    if (partial)
      terrain_pub_.publish(test::flatProfile(-10.0, 0.0));
    for (int k = 0; k < steps; ++k) {
      t_ += ros::Duration(h_);
      test::publishClock(clock_pub_, t_);
      test::spinFor(0.005);
    }
    test::spinFor(0.3);
    const bool held = samples_.size() == before;
    terrain_pub_.publish(terrain_);
    return held;
  }

  /// Checks the run whose samples start at index `first`, started at `t0` (station 0, speed v0).
  void checkRun(std::size_t first, const ros::Time& t0, const std::string& run) const {
    SCOPED_TRACE(run);
    ASSERT_LT(first, samples_.size());
    std::size_t cruise = 0, braking = 0, stopped = 0;
    ros::Time onset;  // the first sample slower than v0
    for (std::size_t i = first; i < samples_.size(); ++i) {
      const Sample& s = samples_[i];
      const double tau = (s.stamp - t0).toSec();
      if (onset.isZero() && s.speed < v0_)
        onset = s.stamp;
      if (onset.isZero()) {
        ++cruise;
        ASSERT_LE(tau, timeout_ + 1e-9) << "still at v0 after the timeout, at " << tau << " s";
        ASSERT_EQ(s.speed, v0_) << "at " << tau << " s";
        ASSERT_NEAR(s.station, v0_ * tau, kStation) << "at " << tau << " s";
        continue;
      }
      // The step that ended at the onset started braking: its sample is v0 - D h.
      const double braking_time = (s.stamp - onset).toSec() + h_;
      const double expected = std::max(0.0, v0_ - decel_ * braking_time);
      ASSERT_NEAR(s.speed, expected, kSpeed) << "at " << tau << " s";
      const Sample& before = samples_[i - 1];
      ASSERT_NEAR(s.station - before.station, 0.5 * (s.speed + before.speed) * h_, kStation)
          << "at " << tau << " s";
      ++(s.speed > 0.0 ? braking : stopped);
    }
    ASSERT_FALSE(onset.isZero()) << "never braked: the timeout did not count from the run's start";
    // Stopped ~speed_timeout after the run's start, not earlier (a timeout counted from an
    // earlier run's start) nor later.
    EXPECT_NEAR((onset - t0).toSec(), timeout_ + h_, 0.5 * h_);
    EXPECT_GT(cruise, static_cast<std::size_t>(0.9 * timeout_ / h_));
    EXPECT_GT(braking, static_cast<std::size_t>(0.9 * v0_ / decel_ / h_));
    EXPECT_GT(stopped, 0u);
    // At rest relative to its speed from the start: no travel acceleration while cruising.
    for (const auto& [stamp, ax] : accel_x_) {
      if (stamp > t0 && stamp <= t0 + ros::Duration(timeout_) && stamp >= samples_[first].stamp) {
        ASSERT_NEAR(ax, 0.0, kAtRest) << "hull/accel x at " << (stamp - t0).toSec() << " s";
      }
    }
  }

  /// The whole run: the timeout, the braking and a little at rest.
  double runLength() const { return timeout_ + v0_ / decel_ + 0.1; }

  ros::NodeHandle nh_, private_nh_;
  test::DiagnosticsCache diagnostics_;
  const double v0_, decel_, timeout_, h_;
  ros::Publisher clock_pub_, terrain_pub_;
  const TerrainProfile terrain_ = test::flatProfile(-10.0, 30.0);  // all a run covers
  ros::Subscriber wheels_sub_, accel_sub_;
  ros::Time t_{100.0};
  std::vector<Sample> samples_;
  std::vector<std::pair<ros::Time, double>> accel_x_;
};

TEST_F(NodeInitialSpeed, EveryRunStartsAtTheInitialSpeedAndTimesOutFromItsStart) {
  ASSERT_GT(v0_, 0.0);
  // The start: the terrain is there before simulated time runs (latched), once the node has
  // loaded its model.
  terrain_pub_.publish(terrain_);
  ASSERT_TRUE(test::tickClockUntil(
      clock_pub_, &t_, [&] { return !samples_.empty(); }, 45.0))
      << "the node published nothing";
  ASSERT_TRUE(advanceTo(t_));
  // The run started at the node's first /clock t0, at station 0: this test's subscription may
  // have connected a few samples later, so t0 is found from the first sample received.
  const Sample first = samples_.front();
  ASSERT_EQ(first.speed, v0_) << "the first sample is not at ~initial_speed";
  const ros::Time start = first.stamp - ros::Duration(first.station / v0_);
  ASSERT_TRUE(runFor(runLength() - (t_ - start).toSec()));
  checkRun(0, start, "start");
  // Whether the start's patch came in time or not (held at most 50 ms, then on flat ground): what
  // the runs after it add is compared with this.
  // (The start's patch, latched, may be in before the first step: no step held, not counted.)
  const std::string held_runs = "runs at ~initial_speed held for their first patch (total)";
  ASSERT_TRUE(
      test::spinUntil([&] { return !std::isnan(diagnostics_.value(": loop", held_runs)); }, 10.0))
      << diagnostics_.describe();
  const double held_at_start = diagnostics_.value(": loop", held_runs);
  const double uncovered_at_start =
      diagnostics_.value(": terrain", "steps with uncovered contacts (total)");
  const double expired_at_start =
      diagnostics_.value(": loop", "start holds ended without terrain (total)");

  // ~reset: station 0 at v0 again, the timeout counted from the reset.
  ASSERT_TRUE(ros::service::waitForService("/vehicle_dynamics/reset", ros::Duration(10.0)));
  std_srvs::Empty reset;
  const std::size_t reset_first = samples_.size();
  const ros::Time reset_time = t_;
  ASSERT_TRUE(ros::service::call("/vehicle_dynamics/reset", reset));
  // Moving, on the cleared terrain: held until the terrain comes again, 20 steps later; a patch
  // under its rear half, not reaching its front contacts, does not end the hold.
  ASSERT_TRUE(holdFor(20, true)) << "the reset vehicle stepped before its terrain came";
  ASSERT_TRUE(runFor(runLength() - 0.020));
  ASSERT_EQ(samples_[reset_first].stamp, reset_time + ros::Duration(h_));
  checkRun(reset_first, reset_time, "~reset");

  // ~reset again, and 0.3 s at v0 on the terrain: a run moved by the initial speed alone, which
  // the jump back below ends while it cruises.
  ASSERT_TRUE(ros::service::call("/vehicle_dynamics/reset", reset));
  ASSERT_TRUE(holdFor(20)) << "the reset vehicle stepped before its terrain came";
  ASSERT_TRUE(runFor(0.3 - 0.020));
  ASSERT_EQ(samples_.back().speed, v0_);

  // /clock jumps back 50 s (a bag loop): the node restarts at the new time, at v0, and publishes
  // the restart at once. The run before had terrain from its start: the restart is held as a
  // loop's, for the new pass's terrain, and not for a speed message (the run before had none:
  // waiting for one, the hold would run out at half ~catch_up_limit, 50 steps, and the test's
  // step-by-step clock would find no sample).
  const std::size_t jump_first = samples_.size();
  t_ -= ros::Duration(50.0);
  ASSERT_TRUE(advanceTo(t_));
  EXPECT_EQ(samples_[jump_first].station, 0.0);
  EXPECT_EQ(samples_[jump_first].speed, v0_);
  const ros::Time jump_time = t_;
  ASSERT_TRUE(holdFor(20)) << "the restarted vehicle stepped before its terrain came";
  ASSERT_TRUE(runFor(runLength() - 0.020));
  ASSERT_EQ(samples_[jump_first + 1].stamp, jump_time + ros::Duration(h_));
  checkRun(jump_first, jump_time, "jump back");

  // Three stops by the timeout, each said; the restarts held until their terrain came, none
  // running out, and no step with its contacts off the terrain.
  EXPECT_TRUE(test::spinUntil(
      [&] {
        return diagnostics_.value(": speed", "stops after the speed timeout (total)") == 3.0 &&
               diagnostics_.value(": loop", "time jumps back (total)") == 1.0;
      },
      10.0))
      << diagnostics_.describe();
  struct Count {
    std::string status, key;
    double expected;
  };
  const std::vector<Count> counts = {
      {": loop", held_runs, held_at_start + 2.0},
      {": loop", "holds ended without a speed (total)", 0.0},
      {": loop", "start holds ended without terrain (total)", expired_at_start},
      {": loop", "restarts held for the loop's terrain (total)", 1.0},
      {": loop", "holds ended without terrain (total)", 0.0},
      {": terrain", "steps with uncovered contacts (total)", uncovered_at_start}};
  for (const Count& c : counts)
    EXPECT_EQ(diagnostics_.value(c.status, c.key), c.expected) << c.key << "\n"
                                                               << diagnostics_.describe();
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "node_initial_speed_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
