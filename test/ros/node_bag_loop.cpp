// rostest tier 2 on simulated time (node_bag_loop.test, use_sim_time): a bag loop. The test owns
// /clock and plays the same short "bag" four times: the first patches and the speed, stamped
// with the start time, then the clock from there in bursts. On the loops after the first the
// clock jumps back to the start time, and the inputs are sent
//   - before the /clock message of the jump, with no pause in between (what `rosbag play -l`
//     does: its time publisher is already past the first messages' time; the connections may
//     still deliver either first),
//   - before it, with a pause that makes sure the node has them first (the order that lost
//     them), or
//   - after it, or
//   - after it and after the clock has run on for a few steps (a loaded machine: the node holds
//     the restarted vehicle for them, then steps the held time on them);
// and a last loop sends no inputs: the hold ends after half ~catch_up_limit.
// Each loop must give the first loop's samples: the same stamps (none dropped on catch-up
// bursts), stations and wheel displacements.
// Then the same loops with the speed on speed_stamped, and a speed change in the middle of each
// loop sent with its first messages (stamped ahead): each loop again gives the first stamped
// loop's samples, the change at the same step, however the inputs and the jump interleave; also
// when the jump lands a few ms past the loop's start, as rosbag play's clock does.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include <geometry_msgs/TwistStamped.h>
#include <rosgraph_msgs/Clock.h>
#include <std_msgs/Float64.h>

#include "node_test_utils.h"
#include "tracked_vehicle_dynamics/RoadWheels.h"

using namespace tracked_vehicle_dynamics;
using namespace tracked_vehicle_dynamics::ros_layer;

namespace {

struct Sample {
  double station = 0.0;
  std::vector<double> wheels;  // vertical displacement [m]
};
using LoopRun = std::map<std::int64_t, Sample>;  // by nanoseconds since the loop's start

/// A patch from `from` to `to` [m] on a 1 cm grid, flat but for a cosine bump of `height` [m]
/// between `bump_from` and `bump_from` + `bump_length` on every line.
TerrainProfile bumpProfile(double from, double to, double bump_from, double bump_length,
                           double height) {
  TerrainProfile msg = test::flatProfile(from, to, 0.01);
  for (std::size_t j = 0; j < msg.lateral.size(); ++j) {
    for (std::uint32_t k = 0; k < msg.samples; ++k) {
      const double x = (msg.start_station + k * msg.spacing - bump_from) / bump_length;
      if (x > 0.0 && x < 1.0)
        msg.heights[j * msg.samples + k] = 0.5 * height * (1.0 - std::cos(2.0 * M_PI * x));
    }
  }
  return msg;
}

void expectSameRun(const LoopRun& first, const LoopRun& loop, double tolerance, const char* what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(loop.size(), first.size()) << "samples in the loop and in the first run";
  std::size_t missing = 0, compared = 0;
  double worst = 0.0, worst_station = 0.0;
  for (const auto& [ns, reference] : first) {
    const auto it = loop.find(ns);
    if (it == loop.end()) {
      ++missing;
      continue;
    }
    ++compared;
    worst_station = std::max(worst_station, std::abs(it->second.station - reference.station));
    ASSERT_EQ(it->second.wheels.size(), reference.wheels.size());
    for (std::size_t i = 0; i < reference.wheels.size(); ++i)
      worst = std::max(worst, std::abs(it->second.wheels[i] - reference.wheels[i]));
  }
  EXPECT_EQ(missing, 0u) << "samples of the first run missing in the loop";
  ASSERT_GT(compared, 0u);
  EXPECT_LE(worst_station, tolerance) << "largest station difference [m]";
  EXPECT_LE(worst, tolerance) << "largest wheel displacement difference [m]";
}

class NodeBagLoop : public ::testing::Test {
 protected:
  NodeBagLoop() : private_nh_("~"), diagnostics_(nh_) {
    clock_pub_ = nh_.advertise<rosgraph_msgs::Clock>("/clock", 10);
    wheels_sub_ = nh_.subscribe("road_wheels", 100000, &NodeBagLoop::onWheels, this,
                                ros::TransportHints().tcpNoDelay());
    terrain_pub_ = nh_.advertise<TerrainProfile>("terrain_profile", 10);
    speed_pub_ = nh_.advertise<std_msgs::Float64>("speed", 10);
    stamped_pub_ = nh_.advertise<geometry_msgs::TwistStamped>("speed_stamped", 10);
  }

  void onWheels(const RoadWheels::ConstPtr& msg) {
    last_ = *msg;
    ++messages_;
    if (recording_ && msg->header.stamp >= start_) {
      Sample& s = (*recording_)[(msg->header.stamp - start_).toNSec()];
      s.station = msg->station;
      s.wheels.clear();
      for (const auto& w : msg->wheels)
        s.wheels.push_back(w.displacement);
    }
  }

  void setClock(const ros::Time& t) { test::publishClock(clock_pub_, t); }

  bool waitForSample(const ros::Time& t) {
    return test::spinUntil([&] { return messages_ > 0 && last_.header.stamp == t; }, 10.0);
  }

  /// The loop's first messages, stamped with its start time.
  void publishInputs() {
    for (TerrainProfile patch : patches_) {
      patch.header.stamp = start_;
      terrain_pub_.publish(patch);
    }
    if (change_at_ > 0.0) {
      // The loop's speed, then its change, each stamped with the time it applies from.
      geometry_msgs::TwistStamped v;
      v.header.frame_id = "base_link";
      v.header.stamp = start_;
      v.twist.linear.x = speed_;
      stamped_pub_.publish(v);
      v.header.stamp = start_ + ros::Duration(change_at_);
      v.twist.linear.x = changed_speed_;
      stamped_pub_.publish(v);
      return;
    }
    std_msgs::Float64 v;
    v.data = speed_;
    speed_pub_.publish(v);
  }

  /// The clock from the loop's start on, in bursts of 1 to 100 steps; every sample is recorded.
  /// With late_inputs, the inputs come only after the first `late_inputs` bursts, whose samples
  /// the node must hold back until then.
  /// Bursts ending at or before `from` are not sent (the clock is already there).
  void play(LoopRun* run, std::size_t late_inputs = 0, const ros::Time& from = ros::Time()) {
    recording_ = run;
    ros::Time t = start_;
    for (std::size_t b = 0; b < bursts_.size(); ++b) {
      t += ros::Duration(bursts_[b] * 1e-3);
      if (t <= from)
        continue;
      setClock(t);
      if (b + 1 < late_inputs)
        continue;
      if (b + 1 == late_inputs) {
        test::spinFor(0.1);
        EXPECT_EQ(last_.header.stamp, start_) << "a step before the loop's first patch";
        publishInputs();
        test::spinFor(0.1);
        setClock(t + ros::Duration(1e-9));  // wakes the held node at the same step
      }
      ASSERT_TRUE(waitForSample(t)) << "no sample at " << t;
    }
    test::spinFor(0.1);  // the last messages of a burst
    recording_ = nullptr;
  }

  /// Two loops with the inputs sent before the /clock message of the jump back: with no pause
  /// (either may reach the node first), then with one (the inputs surely handled first). Each
  /// must repeat `reference`.
  void loopsWithInputsFirst(const LoopRun& reference, double tolerance, const std::string& what) {
    for (const double pause : {0.0, 0.05}) {
      LoopRun inputs_first;
      publishInputs();
      if (pause > 0.0)
        test::spinFor(pause);
      setClock(start_);
      ASSERT_TRUE(waitForSample(start_));
      test::spinFor(0.1);
      play(&inputs_first);
      expectSameRun(reference, inputs_first, tolerance,
                    (what + (pause > 0.0 ? "inputs handled before the jump back"
                                         : "inputs before the jump back"))
                        .c_str());
    }
  }
  /// A loop with the jump back, then 4 ms of clock (the first three bursts), then the inputs:
  /// the node holds the restarted vehicle for them. It must repeat `reference`.
  void loopWithLateInputs(const LoopRun& reference, double tolerance, const std::string& what) {
    LoopRun late;
    setClock(start_);
    ASSERT_TRUE(waitForSample(start_));
    play(&late, 3);
    expectSameRun(reference, late, tolerance, (what + "inputs 4 ms after the jump back").c_str());
  }

  ros::NodeHandle nh_, private_nh_;
  test::DiagnosticsCache diagnostics_;
  ros::Publisher clock_pub_, terrain_pub_, speed_pub_, stamped_pub_;
  ros::Subscriber wheels_sub_;
  RoadWheels last_;
  std::size_t messages_ = 0;
  LoopRun* recording_ = nullptr;
  ros::Time start_;
  double speed_ = 0.0;
  // Stamped speeds (> 0): the change's time after the loop's start [s], and its speed [m/s].
  double change_at_ = 0.0, changed_speed_ = 0.0;
  std::vector<TerrainProfile> patches_;
  std::vector<int> bursts_;
};

TEST_F(NodeBagLoop, EveryLoopGivesTheFirstLoopsSamples) {
  speed_ = test::requiredParam<double>(private_nh_, "speed");
  const double tolerance = test::requiredParam<double>(private_nh_, "tolerance");
  const double rate = test::requiredParam<double>(private_nh_, "rate");
  const double min_displacement = test::requiredParam<double>(private_nh_, "min_displacement");
  ASSERT_EQ(rate, 1000.0) << "the bursts are in 1 ms steps";
  // 0.7 s, with bursts as long as ~catch_up_limit (0.1 s = 100 steps).
  bursts_ = {1, 1, 2, 5, 10, 20, 50, 100, 3, 7, 100, 1, 100, 50, 100, 20, 30, 100};
  // The first patches, as a bag sends them: a 5 cm bump under the vehicle at 0.5-1.5 m (the
  // pads on the ground span -2.4..2.4 m), another at 4-5 m (the front road wheels are at
  // 2.34 m), flat beyond. At the end of a loop (7 m at 10 m/s) the first patch lies wholly
  // behind the vehicle: sent before the jump back, it is dropped, and must be re-applied.
  patches_ = {bumpProfile(-5.0, 2.0, 0.5, 1.0, 0.05), bumpProfile(2.01, 6.0, 4.0, 1.0, 0.05),
              bumpProfile(6.01, 14.0, 4.0, 1.0, 0.05)};

  // Simulated time runs once the node has loaded its model and published its first sample.
  ros::Time t(200.0);
  ASSERT_TRUE(test::tickClockUntil(
      clock_pub_, &t, [&] { return messages_ > 0; }, 45.0))
      << "the node published nothing";
  ASSERT_TRUE(test::spinUntil(
      [&] { return terrain_pub_.getNumSubscribers() > 0 && speed_pub_.getNumSubscribers() > 0; },
      5.0));
  t += ros::Duration(0.001);
  setClock(t);
  ASSERT_TRUE(waitForSample(t));
  start_ = t;

  // First loop: the inputs reach the node before its clock moves.
  LoopRun first;
  publishInputs();
  test::spinFor(0.5);
  play(&first);
  ASSERT_FALSE(HasFailure());
  double peak = 0.0;
  for (const auto& [ns, s] : first) {
    for (double w : s.wheels)
      peak = std::max(peak, std::abs(w));
  }
  EXPECT_GE(peak, min_displacement) << "the bump must move the wheels";
  // Every step of the loop was published (a catch-up burst of 100 samples included).
  EXPECT_EQ(first.size(),
            static_cast<std::size_t>(std::accumulate(bursts_.begin(), bursts_.end(), 0)));

  // Second and third loops: the first patches and the speed before the clock jumps back.
  loopsWithInputsFirst(first, tolerance, "");

  // Fourth loop: the jump back first, then the inputs.
  LoopRun clock_first;
  setClock(start_);
  ASSERT_TRUE(waitForSample(start_));
  publishInputs();
  test::spinFor(0.1);
  play(&clock_first);
  expectSameRun(first, clock_first, tolerance, "inputs after the jump back");

  // Fifth loop: the jump back, then 4 ms of clock, then the inputs.
  loopWithLateInputs(first, tolerance, "");

  // Sixth loop: the jump back and no inputs at all. The hold ends after half ~catch_up_limit
  // (50 ms) of clock: the vehicle then steps on (on the restart's flat ground), every step
  // published, the last clock's included. (After 0.3 s of wall time: the node keeps what it
  // received for 0.25 s, and would re-apply the fifth loop's patches, stamped with the start.)
  test::spinFor(0.3);
  setClock(start_);
  ASSERT_TRUE(waitForSample(start_));
  ros::Time tick = start_;
  for (int k = 0; k < 60; ++k) {
    tick += ros::Duration(1e-3);
    setClock(tick);
    if (k == 40) {
      test::spinFor(0.05);
      EXPECT_EQ(last_.header.stamp, start_) << "a step during the hold";
    }
  }
  EXPECT_TRUE(waitForSample(tick)) << "the hold did not end";

  // The stamped loops: speed_ from the start, changed_speed_ from 0.3037 s (off the 1 ms grid).
  // Their own first loop (the jump back, then the inputs) is the reference.
  change_at_ = 0.3037;
  changed_speed_ = 0.5 * speed_;
  test::spinFor(0.3);  // the sixth loop's kept inputs expire
  ASSERT_TRUE(test::spinUntil([&] { return stamped_pub_.getNumSubscribers() > 0; }, 5.0));
  LoopRun stamped_first;
  setClock(start_);
  ASSERT_TRUE(waitForSample(start_));
  publishInputs();
  test::spinFor(0.1);
  play(&stamped_first);
  ASSERT_FALSE(stamped_first.empty());
  // The change applies from the step that starts at the grid point after its stamp (0.304 s):
  // the step to 0.305 s is the first to advance the station at it (v h, no slew).
  const auto at = [&](int ms) { return stamped_first.find(std::int64_t{ms} * 1'000'000); };
  ASSERT_TRUE(at(303) != stamped_first.end() && at(304) != stamped_first.end() &&
              at(305) != stamped_first.end());
  EXPECT_NEAR(at(304)->second.station - at(303)->second.station, speed_ * 1e-3, 1e-12);
  EXPECT_NEAR(at(305)->second.station - at(304)->second.station, changed_speed_ * 1e-3, 1e-12);
  loopsWithInputsFirst(stamped_first, tolerance, "stamped: ");
  loopWithLateInputs(stamped_first, tolerance, "stamped: ");

  // rosbag play's clock: the first /clock after a loop's jump back is a few ms past the loop's
  // start (6.3 ms here, off the step grid; 6 to 9 ms measured). The restart moves back to the
  // loop's first inputs' stamp, so the loop runs on the first loop's grid and repeats its
  // samples: with the inputs sent before the jump (re-applied), then after it (before the clock
  // moves on). Without the move, every sample 6.3 ms late: 63 mm of station at 10 m/s.
  const ros::Time jump = start_ + ros::Duration(0.0063);
  for (const bool inputs_first : {true, false}) {
    LoopRun offset;
    recording_ = &offset;  // the steps up to the jump's clock come with it
    if (inputs_first) {
      publishInputs();
      test::spinFor(0.05);  // surely handled before the jump
    }
    setClock(jump);
    // Inputs first: the restart at the start, stepped at once to the jump's clock (6 steps).
    // Inputs after: the restart at the jump's clock, moved back when they come.
    ASSERT_TRUE(waitForSample(inputs_first ? start_ + ros::Duration(0.006) : jump));
    if (!inputs_first)
      publishInputs();
    test::spinFor(0.1);
    play(&offset, 0, jump);
    offset.erase(0);  // the restart's sample at the start, or at the jump's clock
    offset.erase((jump - start_).toNSec());
    expectSameRun(stamped_first, offset, tolerance,
                  inputs_first ? "stamped, the jump 6.3 ms past the start: inputs before it"
                               : "stamped, the jump 6.3 ms past the start: inputs after it");
  }

  t = start_ + ros::Duration(5.0);  // let the diagnostics period pass on simulated time
  setClock(t);
  ASSERT_TRUE(test::spinUntil(
      [&] {
        return diagnostics_.value(": loop", "time jumps back (total)") >= 9 &&
               diagnostics_.value(": speed", "stamped speeds (total)") >= 8 &&
               diagnostics_.value(": loop", "holds ended without terrain (total)") >= 1;
      },
      10.0))
      << diagnostics_.describe();
  // The third loop's inputs were re-applied after the jump (the second's may have been).
  EXPECT_GE(diagnostics_.value(": loop", "patches re-applied after a jump back (total)"),
            static_cast<double>(patches_.size()));
  // The third loop's speed, and the stamped third loop's two.
  EXPECT_GE(diagnostics_.value(": loop", "speeds re-applied after a jump back (total)"), 3.0);
  // The fifth, sixth and the last stamped loops were held (the fourth's inputs may have come
  // before its first step); only the sixth's hold ran out.
  EXPECT_GE(diagnostics_.value(": loop", "restarts held for the loop's terrain (total)"), 3.0);
  EXPECT_EQ(diagnostics_.value(": loop", "holds ended without terrain (total)"), 1.0);
  // The patches that arrived behind the vehicle before a jump were all re-applied: none is
  // counted (nor warned) as dropped, so a healthy loop keeps the terrain status OK.
  EXPECT_EQ(diagnostics_.value(": terrain", "patches behind the vehicle, dropped (total)"), 0.0);
  // Every stamped speed was judged of its loop: none taken as another time base's.
  EXPECT_EQ(diagnostics_.value(": speed", "stamped speeds in another time base (total)"), 0.0);
  std::printf("%s", diagnostics_.describe().c_str());
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "node_bag_loop_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
