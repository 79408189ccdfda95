// rostest tier 2 on real time (node_real_time.test): ~speed_timeout measured on the monotonic
// clock and the thinned publishing rates, through two running nodes on flat ground.
//   stopping  ~speed_timeout T, no slew, ~publish_rate 100 Hz, ~comfort_rate 5 Hz: while speed
//             messages arrive (20 Hz, far more often than T) it drives on; after the last one
//             it stops at once, T (+ a sample, + the machine's latency) later, its station frozen
//             from then on; `speed` diagnostics WARN "vehicle stopped" until the next speed
//             message moves it again. Its road_wheels stamps are 10 steps apart, comfort's 200.
//   braking   ~speed_timeout T and ~max_deceleration D (so ~max_acceleration D too): after the
//             timeout the speed falls by D h per step, v_k = max(0, v0 - D k h), and the station
//             advances by the trapezoid (v_{k-1} + v_k) h / 2, until it stands.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iterator>
#include <map>
#include <string>
#include <tuple>
#include <vector>

#include <std_msgs/Float64.h>

#include "node_test_utils.h"
#include "tracked_vehicle_dynamics/Comfort.h"
#include "tracked_vehicle_dynamics/RoadWheels.h"

using namespace tracked_vehicle_dynamics;
using namespace tracked_vehicle_dynamics::ros_layer;

namespace {

constexpr double kRounding = 1e-9;        // [m, m/s] accumulated rounding of speed and station
constexpr double kStampTolerance = 1e-6;  // [s] stamps are whole steps; ros::Time keeps ns

struct Sample {
  double speed, station;
  ros::Time arrival;  // when it reached the test (real time)
};

/// One node's road_wheels and comfort stamps, and its speed publisher.
class Recorder {
 public:
  Recorder(ros::NodeHandle& nh, const std::string& ns) {
    const ros::TransportHints hints = ros::TransportHints().tcpNoDelay();
    wheels_sub_ = nh.subscribe(ns + "/road_wheels", 20000, &Recorder::onWheels, this, hints);
    comfort_sub_ = nh.subscribe<Comfort>(
        ns + "/comfort", 1000,
        [this](const Comfort::ConstPtr& m) { comfort_stamps_.push_back(m->header.stamp); },
        ros::VoidConstPtr(), hints);
    speed_pub_ = nh.advertise<std_msgs::Float64>(ns + "/speed", 10);
    terrain_pub_ = nh.advertise<TerrainProfile>(ns + "/terrain_profile", 10, true);
  }

  bool ready() const {
    return !samples_.empty() && speed_pub_.getNumSubscribers() > 0 &&
           terrain_pub_.getNumSubscribers() > 0;
  }
  void publishSpeed(double v) const {
    std_msgs::Float64 msg;
    msg.data = v;
    speed_pub_.publish(msg);
  }
  const ros::Publisher& terrainPublisher() const { return terrain_pub_; }
  const std::map<ros::Time, Sample>& samples() const { return samples_; }
  const std::vector<ros::Time>& comfortStamps() const { return comfort_stamps_; }
  /// The first sample stamped after `from` whose speed is below `speed`; end() when none.
  std::map<ros::Time, Sample>::const_iterator firstBelow(const ros::Time& from,
                                                         double speed) const {
    return std::find_if(samples_.upper_bound(from), samples_.end(),
                        [&](const auto& s) { return s.second.speed < speed; });
  }

 private:
  void onWheels(const RoadWheels::ConstPtr& m) {
    samples_[m->header.stamp] = {m->speed, m->station, ros::Time::now()};
  }

  ros::Subscriber wheels_sub_, comfort_sub_;
  ros::Publisher speed_pub_, terrain_pub_;
  std::map<ros::Time, Sample> samples_;
  std::vector<ros::Time> comfort_stamps_;
};

/// Differences [s] between consecutive stamps (in order) from `from` on.
std::vector<double> intervals(const std::vector<ros::Time>& stamps, const ros::Time& from) {
  std::vector<double> out;
  const auto first = std::lower_bound(stamps.begin(), stamps.end(), from);
  for (auto it = first; it != stamps.end() && std::next(it) != stamps.end(); ++it)
    out.push_back((*std::next(it) - *it).toSec());
  return out;
}
std::vector<ros::Time> stampsOf(const std::map<ros::Time, Sample>& samples) {
  std::vector<ros::Time> out;
  for (const auto& s : samples)
    out.push_back(s.first);
  return out;
}
double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

class NodeRealTime : public ::testing::Test {
 protected:
  NodeRealTime()
      : private_nh_("~"),
        diagnostics_(nh_),
        stopping_(nh_, "stopping"),
        braking_(nh_, "braking"),
        rate_(test::requiredParam<double>(private_nh_, "rate")),
        timeout_(test::requiredParam<double>(private_nh_, "speed_timeout")),
        decel_(test::requiredParam<double>(private_nh_, "max_deceleration")),
        speed_(test::requiredParam<double>(private_nh_, "speed")),
        late_(test::requiredParam<double>(private_nh_, "late_tolerance")) {}

  /// Publishes speed `v` to both nodes at 20 Hz for `seconds` of wall time; whether `seen()`
  /// held at some point meanwhile.
  bool drive(
      double v, double seconds, const std::function<bool()>& seen = [] { return false; }) {
    bool held = false;
    const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(seconds);
    while (ros::ok() && ros::WallTime::now() < end) {
      stopping_.publishSpeed(v);
      braking_.publishSpeed(v);
      const ros::Time now = ros::Time::now();
      if (!last_publish_.isZero())
        longest_gap_ = std::max(longest_gap_, (now - last_publish_).toSec());
      last_publish_ = now;
      test::spinFor(0.05);
      held = held || seen();
    }
    return held;
  }

  /// The sample of `r` at which the timeout took effect: the first below v0 after it had reached
  /// v0 (from `start`), ~speed_timeout after the last speed message (within late_tolerance: not
  /// before, while messages were still due, nor late). end() when there is none.
  std::map<ros::Time, Sample>::const_iterator timedOut(const Recorder& r, const ros::Time& start,
                                                       const ros::Time& last_message) const {
    const auto& samples = r.samples();
    const auto moving = std::find_if(samples.lower_bound(start), samples.end(),
                                     [&](const auto& s) { return s.second.speed == speed_; });
    if (moving == samples.end()) {
      ADD_FAILURE() << "never reached the commanded speed";
      return samples.end();
    }
    const auto changed = r.firstBelow(moving->first, speed_);
    if (changed == samples.end()) {
      ADD_FAILURE() << "did not slow down after ~speed_timeout";
      return samples.end();
    }
    // Not before the timeout: the sample that shows it left the node after the node had gone
    // without a speed message for T (its stamp may lie further back: a late tick takes its
    // missed steps after the decision). Not late: its stamp, the step it took effect at.
    EXPECT_GE((changed->second.arrival - last_message).toSec(), timeout_ - 0.005)
        << "slowed down while speed messages were still due";
    EXPECT_LE((changed->first - last_message).toSec(), timeout_ + late_) << "slowed down late";
    return changed;
  }

  /// The `speed` diagnostics of the node in namespace `ns` come to WARN "vehicle stopped", its
  /// one stop counted.
  void expectStoppedStatus(const std::string& ns) {
    const std::string status = ns + "/vehicle_dynamics: speed";
    ASSERT_TRUE(test::spinUntil(
        [&] {
          return diagnostics_.message(status) ==
                 "no speed message within ~speed_timeout: vehicle stopped";
        },
        5.0))
        << diagnostics_.describe();
    EXPECT_EQ(diagnostics_.level(status), 1);
    EXPECT_EQ(diagnostics_.value(status, "stops after the speed timeout (total)"), 1.0);
  }

  ros::NodeHandle nh_, private_nh_;
  test::DiagnosticsCache diagnostics_;
  Recorder stopping_, braking_;
  double rate_, timeout_, decel_, speed_, late_;
  ros::Time last_publish_;    // just after the last speed message was sent
  double longest_gap_ = 0.0;  // [s] between two of the test's speed messages
};

TEST_F(NodeRealTime, NoSpeedMessageForTheTimeoutStopsOrBrakesTheVehicle) {
  const double h = 1.0 / rate_;
  ASSERT_TRUE(test::spinUntil([&] { return stopping_.ready() && braking_.ready(); }, 60.0))
      << "the nodes published nothing, or do not listen";
  for (const Recorder* r : {&stopping_, &braking_})
    r->terrainPublisher().publish(test::flatProfile(-20.0, 200.0));
  test::spinFor(0.3);

  // Driving, messages every 50 ms: never timed out (the braking node reaches v0 at D).
  const ros::Time start = ros::Time::now();
  drive(speed_, test::requiredParam<double>(private_nh_, "drive_time"));
  const ros::Time last_message = last_publish_;
  // A test that stalled longer than the timeout between its own messages tests nothing.
  ASSERT_LT(longest_gap_, timeout_) << "the test stalled between its speed messages";
  // Both stopped (braking takes v0 / D of steps taken, however late they run).
  EXPECT_TRUE(test::spinUntil(
      [&] {
        for (const Recorder* r : {&stopping_, &braking_})
          if (r->samples().empty() || r->samples().rbegin()->first < last_message ||
              r->samples().rbegin()->second.speed != 0.0)
            return false;
        return true;
      },
      timeout_ + speed_ / decel_ + 20.0));
  test::spinFor(0.3);  // samples at rest after the stop

  // --- stopping: v0 until the timeout, then 0 at once, the station frozen.
  {
    SCOPED_TRACE("stopping");
    const auto& samples = stopping_.samples();
    const auto stop = timedOut(stopping_, start, last_message);
    ASSERT_NE(stop, samples.end());
    const double after = (stop->first - last_message).toSec();
    for (auto it = stop; it != samples.end(); ++it) {
      EXPECT_EQ(it->second.speed, 0.0);
      EXPECT_EQ(it->second.station, stop->second.station) << "moved after the stop";
    }
    EXPECT_GT(stop->second.station, speed_ * (last_message - start).toSec() * 0.5);
    std::printf(
        "[ measured ] stopping: stopped %.3f s after the last speed message "
        "(~speed_timeout %.3f s) at station %.3f m\n",
        after, timeout_, stop->second.station);

    // ~publish_rate: road_wheels every round(rate / publish_rate) steps, stamps whole steps
    // apart; ~comfort_rate likewise (a catch-up skip on a loaded machine lengthens an interval
    // by whole steps, never shortens one).
    for (const auto& [name, stamps, every] :
         {std::tuple<const char*, std::vector<ros::Time>, double>{
              "road_wheels", stampsOf(samples),
              std::round(rate_ / test::requiredParam<double>(private_nh_, "publish_rate"))},
          {"comfort", stopping_.comfortStamps(),
           std::round(rate_ / test::requiredParam<double>(private_nh_, "comfort_rate"))}}) {
      SCOPED_TRACE(name);
      const std::vector<double> dt = intervals(stamps, start);
      ASSERT_GT(dt.size(), 5u);
      for (double d : dt) {
        EXPECT_GE(d, every * h - kStampTolerance);
        EXPECT_NEAR(d * rate_, std::round(d * rate_), kStampTolerance * rate_);
      }
      EXPECT_NEAR(median(dt), every * h, kStampTolerance);
    }

    ASSERT_NO_FATAL_FAILURE(expectStoppedStatus("stopping"));
  }

  // --- braking: from the timeout on, v_k = max(0, v0 - D k h) and the trapezoid's station.
  {
    SCOPED_TRACE("braking");
    const auto& samples = braking_.samples();
    const auto braking = timedOut(braking_, start, last_message);
    ASSERT_NE(braking, samples.end());
    const double after = (braking->first - last_message).toSec();
    const double s0 = std::prev(braking)->second.station;
    // Counted in steps, not stamps: a catch-up skip moves the stamps on, not the vehicle.
    double worst_speed = 0.0, worst_station = 0.0;
    int k = 1;
    for (auto it = braking; it != samples.end(); ++it, ++k) {
      const double tau = std::min(k * h, speed_ / decel_);
      const double v = std::max(0.0, speed_ - decel_ * k * h);
      const double s = s0 + speed_ * tau - 0.5 * decel_ * tau * tau;
      worst_speed = std::max(worst_speed, std::abs(it->second.speed - v));
      worst_station = std::max(worst_station, std::abs(it->second.station - s));
    }
    EXPECT_LE(worst_speed, kRounding);
    EXPECT_LE(worst_station, kRounding);
    EXPECT_EQ(std::prev(samples.end())->second.speed, 0.0) << "still braking";
    std::printf(
        "[ measured ] braking: braked from %.3f s after the last speed message; "
        "|v - max(0, v0 - D k h)| %.3g m/s, |s - trapezoid| %.3g m over %d samples\n",
        after, worst_speed, worst_station, k - 1);
    ASSERT_NO_FATAL_FAILURE(expectStoppedStatus("braking"));
  }

  // The next speed message moves the stopped vehicle again, and the WARN clears while the
  // messages keep coming (the diagnostics report every ~diagnostic_period).
  const ros::Time resumed = ros::Time::now();
  const bool cleared = drive(1.0, 2.5, [&] {
    return diagnostics_.level("stopping/vehicle_dynamics: speed") == 0 &&
           diagnostics_.level("braking/vehicle_dynamics: speed") == 0;
  });
  EXPECT_TRUE(cleared) << diagnostics_.describe();
  const auto moving =
      std::find_if(stopping_.samples().upper_bound(resumed), stopping_.samples().end(),
                   [](const auto& s) { return s.second.speed == 1.0; });
  EXPECT_NE(moving, stopping_.samples().end()) << "a new speed did not move it again";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "node_real_time_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
