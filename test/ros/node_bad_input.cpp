// rostest tier 2: bad input keeps the node alive, publishing finite values, with a diagnostics
// entry for each kind; the loop holds its rate (node_bad_input.test, real time). A bad parameter
// stops a second node at once with one FATAL line naming it.
#include <gtest/gtest.h>
#include <algorithm>
#include <array>

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <thread>
#include <vector>

#include <geometry_msgs/AccelStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <std_msgs/Float64.h>
#include <std_srvs/Empty.h>
#include <tf2_msgs/TFMessage.h>

#include "node_test_utils.h"
#include "tracked_vehicle_dynamics/RoadWheels.h"

using namespace tracked_vehicle_dynamics;
using namespace tracked_vehicle_dynamics::ros_layer;

namespace {

bool finite(const geometry_msgs::Vector3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

class NodeBadInput : public ::testing::Test {
 protected:
  NodeBadInput() : private_nh_("~"), diagnostics_(nh_) {
    tf_sub_ =
        nh_.subscribe("/tf", 10000, &NodeBadInput::onTf, this, ros::TransportHints().tcpNoDelay());
    wheels_sub_ = nh_.subscribe("road_wheels", 10000, &NodeBadInput::onWheels, this,
                                ros::TransportHints().tcpNoDelay());
    accel_sub_ = nh_.subscribe("hull/accel", 10000, &NodeBadInput::onAccel, this,
                               ros::TransportHints().tcpNoDelay());
    twist_sub_ = nh_.subscribe("hull/twist", 10000, &NodeBadInput::onTwist, this,
                               ros::TransportHints().tcpNoDelay());
    terrain_pub_ = nh_.advertise<TerrainProfile>("terrain_profile", 100);
    speed_pub_ = nh_.advertise<std_msgs::Float64>("speed", 100);
  }

  void onTf(const tf2_msgs::TFMessage::ConstPtr& msg) {
    for (const auto& t : msg->transforms) {
      const auto& tr = t.transform;
      if (!finite(tr.translation) || !std::isfinite(tr.rotation.w) ||
          !std::isfinite(tr.rotation.x) || !std::isfinite(tr.rotation.y) ||
          !std::isfinite(tr.rotation.z)) {
        ++non_finite_;
      }
    }
  }
  void onWheels(const RoadWheels::ConstPtr& msg) {
    ++wheel_messages_;
    last_speed_ = msg->speed;
    station_ = msg->station;
    for (const auto& w : msg->wheels) {
      if (!std::isfinite(w.displacement) || !std::isfinite(w.velocity) ||
          !std::isfinite(w.acceleration)) {
        ++non_finite_;
      }
    }
  }
  void onAccel(const geometry_msgs::AccelStamped::ConstPtr& msg) {
    if (!finite(msg->accel.linear) || !finite(msg->accel.angular))
      ++non_finite_;
  }
  void onTwist(const geometry_msgs::TwistStamped::ConstPtr& msg) {
    if (!finite(msg->twist.linear) || !finite(msg->twist.angular))
      ++non_finite_;
  }

  void publishSpeed(double v) {
    std_msgs::Float64 msg;
    msg.data = v;
    speed_pub_.publish(msg);
  }

  ros::NodeHandle nh_, private_nh_;
  test::DiagnosticsCache diagnostics_;
  ros::Subscriber tf_sub_, wheels_sub_, accel_sub_, twist_sub_;
  ros::Publisher terrain_pub_, speed_pub_;
  std::size_t wheel_messages_ = 0, non_finite_ = 0;
  double last_speed_ = -1.0, station_ = 0.0;
};

TEST_F(NodeBadInput, NodeStaysAliveFiniteAndDiagnosed) {
  const double rate = test::requiredParam<double>(private_nh_, "rate");
  const double min_rate_fraction = test::requiredParam<double>(private_nh_, "min_rate_fraction");
  const double speed = test::requiredParam<double>(private_nh_, "speed");
  const double terrain_end = test::requiredParam<double>(private_nh_, "terrain_end");

  ASSERT_TRUE(test::spinUntil([&] { return wheel_messages_ > 0; }, 45.0))
      << "the node published nothing";
  ASSERT_TRUE(test::spinUntil(
      [&] { return terrain_pub_.getNumSubscribers() > 0 && speed_pub_.getNumSubscribers() > 0; },
      5.0));
  // Standing still before any terrain is the normal start: OK, not a warning to aggregate.
  ASSERT_TRUE(test::spinUntil([&] { return diagnostics_.has(": terrain"); }, 10.0));
  EXPECT_EQ(diagnostics_.level(": terrain"),
            static_cast<int>(diagnostic_msgs::DiagnosticStatus::OK))
      << diagnostics_.describe();
  // ... but a source wrong from its first patch is a warning, not "waiting for terrain".
  TerrainProfile first = test::flatProfile(-10.0, terrain_end);
  first.heights[3] = std::numeric_limits<double>::quiet_NaN();
  terrain_pub_.publish(first);
  EXPECT_TRUE(test::spinUntil(
      [&] {
        return diagnostics_.value(": terrain", "patches rejected (total)") == 1.0 &&
               diagnostics_.level(": terrain") ==
                   static_cast<int>(diagnostic_msgs::DiagnosticStatus::WARN);
      },
      10.0))
      << diagnostics_.describe();

  // Good terrain up to terrain_end, then bad patches of every kind.
  terrain_pub_.publish(test::flatProfile(-10.0, terrain_end));
  TerrainProfile bad = test::flatProfile(terrain_end, terrain_end + 20.0);
  bad.heights[17] = std::numeric_limits<double>::quiet_NaN();
  terrain_pub_.publish(bad);
  bad.heights[17] = std::numeric_limits<double>::infinity();
  terrain_pub_.publish(bad);
  bad = test::flatProfile(terrain_end, terrain_end + 20.0);
  bad.heights.resize(bad.heights.size() - 3);  // mismatched size
  terrain_pub_.publish(bad);
  bad = test::flatProfile(terrain_end, terrain_end + 20.0);
  std::swap(bad.lateral[0], bad.lateral[1]);  // not increasing
  terrain_pub_.publish(bad);
  bad = test::flatProfile(terrain_end, terrain_end + 20.0);
  bad.spacing = 0.0;
  terrain_pub_.publish(bad);
  // Valid, but beyond ~terrain_max_memory (1 MB here): 12,501 samples x 11 lines, 1.2 MB, far
  // ahead (a map's x instead of the path's).
  terrain_pub_.publish(test::flatProfile(terrain_end + 2000.0, terrain_end + 2625.0));
  const int bad_patches = 7;  // with the first one
  // Valid, but 1 m wide: the road wheels at +-1.4 m would read its edge lines (a unit mistake).
  TerrainProfile narrow = test::flatProfile(terrain_end + 40.0, terrain_end + 50.0);
  narrow.lateral = {-0.5, 0.5};
  narrow.heights.resize(2 * (narrow.heights.size() / 11));
  terrain_pub_.publish(narrow);
  // One line is a road uniform across the width (a profile file's bag): no narrower warning.
  TerrainProfile uniform = test::flatProfile(terrain_end + 50.0, terrain_end + 60.0);
  uniform.lateral = {0.0};
  uniform.heights.resize(uniform.heights.size() / 11);
  terrain_pub_.publish(uniform);
  // Valid, far ahead, but altitudes: 250 m above the patch before it (a datum or unit mistake).
  TerrainProfile altitude = test::flatProfile(terrain_end + 1000.0, terrain_end + 1010.0);
  for (double& h : altitude.heights)
    h = 250.0;
  terrain_pub_.publish(altitude);

  publishSpeed(speed);
  test::spinFor(0.2);
  for (double v : {std::numeric_limits<double>::quiet_NaN(), -3.0, 1e4,
                   std::numeric_limits<double>::infinity()}) {
    publishSpeed(v);
  }
  const int bad_speeds = 4;

  // The loop's rate, over wall time, while driving into the terrain gap.
  const std::size_t before = wheel_messages_;
  const ros::WallTime start = ros::WallTime::now();
  test::spinFor(2.0);
  const double elapsed = (ros::WallTime::now() - start).toSec();
  const double received = static_cast<double>(wheel_messages_ - before);
  std::printf("road_wheels: %.0f messages in %.3f s (%.1f Hz)\n", received, elapsed,
              received / elapsed);
  EXPECT_GE(received, min_rate_fraction * rate * elapsed);

  // Still alive and finite, the last valid speed kept, past the end of the terrain.
  EXPECT_EQ(non_finite_, 0u);
  EXPECT_EQ(last_speed_, speed);
  EXPECT_GT(station_, terrain_end);
  // Valid, but wholly behind the vehicle now: dropped, and said so (it was counted accepted).
  terrain_pub_.publish(test::flatProfile(-10.0, -5.0));

  ASSERT_TRUE(test::spinUntil(
      [&] {
        return diagnostics_.value(": terrain", "patches rejected (total)") >= bad_patches &&
               diagnostics_.value(": speed", "speeds rejected (total)") >= bad_speeds &&
               diagnostics_.value(": terrain", "steps with uncovered contacts (total)") > 0 &&
               diagnostics_.value(": terrain", "patches narrower than the contacts (total)") > 0 &&
               diagnostics_.value(": terrain", "patches unlike ground (total)") > 0 &&
               diagnostics_.value(": terrain", "patches behind the vehicle, dropped (total)") > 0;
      },
      5.0))
      << diagnostics_.describe();
  EXPECT_EQ(diagnostics_.value(": terrain", "patches rejected (total)"), bad_patches);
  EXPECT_NE(diagnostics_.text(": terrain", "last rejection")
                .find("1.2 MB with the 34.7 kB stored (stations -10 .. 8 m) exceed the "
                      "terrain buffer's limit of 1 MB"),
            std::string::npos)
      << diagnostics_.describe();
  EXPECT_EQ(diagnostics_.value(": terrain", "stored limit [MB]"), 1.0);
  EXPECT_LT(diagnostics_.value(": terrain", "stored [MB]"), 1.0);
  EXPECT_EQ(diagnostics_.value(": speed", "speeds rejected (total)"), bad_speeds);
  EXPECT_EQ(diagnostics_.value(": terrain", "patches narrower than the contacts (total)"), 1.0);
  EXPECT_EQ(diagnostics_.value(": terrain", "patches behind the vehicle, dropped (total)"), 1.0);
  EXPECT_EQ(diagnostics_.value(": terrain", "patches unlike ground (total)"), 1.0);
  EXPECT_NE(diagnostics_.text(": terrain", "last patch unlike ground").find("starts 250 m above"),
            std::string::npos)
      << diagnostics_.describe();
  EXPECT_EQ(diagnostics_.level(": terrain"),
            static_cast<int>(diagnostic_msgs::DiagnosticStatus::WARN));
  // The step's offset stays in the terrain after it: named until a reset clears the terrain.
  EXPECT_NE(diagnostics_.text(": terrain", "step off the ground since the start or reset")
                .find("starts 250 m above"),
            std::string::npos)
      << diagnostics_.describe();
  EXPECT_EQ(diagnostics_.value(": loop", "non-finite resets (total)"), 0.0);
  std::printf("%s", diagnostics_.describe().c_str());
  // Stopped beyond the terrain's end (a driver gone, ~speed_timeout braking past the patches
  // sent ahead): standing is not an underrun; the count stops where driving off left it. The
  // stop comes as a physics engine reports standstill, -1e-6 m/s: taken as 0, not refused as
  // reverse (which kept the last speed, and the vehicle crept on).
  publishSpeed(-1e-6);
  ASSERT_TRUE(test::spinUntil([&] { return last_speed_ == 0.0; }, 5.0));
  EXPECT_EQ(diagnostics_.value(": speed", "speeds rejected (total)"), bad_speeds);
  // Terrain ahead of its rear contacts only: stored (the buffer not empty, which was always
  // "waiting"), the rear contacts still off it.
  terrain_pub_.publish(test::flatProfile(station_ + 1.0, station_ + 20.0));
  test::spinFor(1.5);  // a diagnostics period, for the last moving steps to be reported
  EXPECT_GT(diagnostics_.value(": terrain", "contacts off the terrain now"), 0.0)
      << diagnostics_.describe();
  const double uncovered = diagnostics_.value(": terrain", "steps with uncovered contacts (total)");
  EXPECT_GT(uncovered, 0.0);
  test::spinFor(2.5);
  EXPECT_EQ(diagnostics_.value(": terrain", "steps with uncovered contacts (total)"), uncovered)
      << diagnostics_.describe();
  std_srvs::Empty reset;
  ASSERT_TRUE(ros::service::call("/vehicle_dynamics/reset", reset));
  ASSERT_TRUE(test::spinUntil(
      [&] {
        return diagnostics_.text(": terrain", "step off the ground since the start or reset") ==
               "none";
      },
      5.0))
      << diagnostics_.describe();
}

struct NodeRun {
  int exit_status = -1;  // -1: killed or not exited
  std::string output;    // stdout and stderr
};

/// Runs vehicle_dynamics_node with `arguments` until it exits, under timeout(1) with `timeout`
/// as its arguments (e.g. "-k 20 --preserve-status 60"; the int overload: that many seconds).
/// The node is the one beside this test executable (both in the devel space's lib/<package>;
/// rosrun refuses to choose when several devel spaces hold the package).
NodeRun runNode(const std::string& arguments, const std::string& timeout) {
  const std::string self = std::filesystem::read_symlink("/proc/self/exe").string();
  const std::string node = self.substr(0, self.rfind('/') + 1) + "vehicle_dynamics_node";
  // Line-buffered stdout (rosconsole's own switch): its INFO lines go to stdout, whose buffer a
  // pipe would hold until `timeout` kills the node, losing them.
  const std::string command = "ROSCONSOLE_STDOUT_LINE_BUFFERED=1 timeout " + timeout + " " + node +
                              " " + arguments + " 2>&1";
  NodeRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr)
    return run;
  char buffer[4096];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr)
    run.output += buffer;
  const int status = pclose(pipe);
  if (WIFEXITED(status))
    run.exit_status = WEXITSTATUS(status);
  return run;
}
NodeRun runNode(const std::string& arguments, int timeout) {
  return runNode(arguments, std::to_string(timeout));
}

/// Runs the node named `name` on the test's ~vehicle and ~cache_dir with `arguments` (more
/// private parameters), for at most ~bad_parameter_timeout seconds.
NodeRun runNamed(const std::string& name, const std::string& arguments) {
  ros::NodeHandle private_nh("~");
  const std::string vehicle = test::requiredParam<std::string>(private_nh, "vehicle");
  const std::string cache_dir = test::requiredParam<std::string>(private_nh, "cache_dir");
  const int timeout = test::requiredParam<int>(private_nh, "bad_parameter_timeout");
  return runNode(
      "__name:=" + name + " _vehicle:=" + vehicle + " _cache_dir:=" + cache_dir + " " + arguments,
      timeout);
}

/// Runs the node as runNamed(); it must stop at start-up (exit status 1) saying `message`.
void expectRefused(const std::string& name, const std::string& arguments,
                   const std::string& message) {
  const NodeRun run = runNamed(name, arguments);
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_NE(run.output.find(message), std::string::npos) << run.output;
}

// ~terrain_max_memory: 1 .. 1e9 MB (less is more likely a value typed in GB).
TEST(NodeBadParameters, TerrainMaxMemoryOutOfRangeIsNamed) {
  expectRefused("small_terrain_memory", "_terrain_max_memory:=0.5",
                "/small_terrain_memory/terrain_max_memory: must be within 1 .. 1e9 MB, got 0.5");
  expectRefused("zero_terrain_memory", "_terrain_max_memory:=0",
                "/zero_terrain_memory/terrain_max_memory: must be > 0 MB");
}

// ~diagnostic_period <= 0 made diagnostic_updater publish at every tick; not finite is no period.
TEST(NodeBadParameters, DiagnosticPeriodMustBePositiveAndFinite) {
  int index = 0;
  // 3e9 s: beyond ros::Duration's 32-bit seconds, once a FATAL that named no parameter.
  for (const std::string value : {"0", "-1", "nan", "inf", "3e9", "86401"}) {
    SCOPED_TRACE("~diagnostic_period " + value);
    const std::string name = "bad_diagnostic_period_" + std::to_string(index++);
    const NodeRun run = runNamed(name, "_diagnostic_period:=" + value);
    EXPECT_EQ(run.exit_status, 1) << run.output;
    EXPECT_NE(run.output.find("FATAL"), std::string::npos) << run.output;
    // The line starts with the node's own name, not the executable's.
    EXPECT_NE(run.output.find("/" + name + ": /" + name + "/diagnostic_period: must be"),
              std::string::npos)
        << run.output;
  }
}

// An unknown ~comfort_point is that parameter's error (it once read as one of ~vehicle's).
TEST(NodeBadParameters, UnknownComfortPointIsNamed) {
  const NodeRun run = runNamed("bad_comfort_point", "_comfort_point:=nowhere");
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_NE(run.output.find("/bad_comfort_point/comfort_point: unknown point 'nowhere' (hull, "
                            "crew_seat, sensor_mount in "),
            std::string::npos)
      << run.output;
  // ... and says how to choose another (a vehicle without a crew_seat point needs it).
  EXPECT_NE(
      run.output.find("); set ~comfort_point (launch argument comfort_point) to one of these"),
      std::string::npos)
      << run.output;
}

// ~max_speed beyond the tools' 200 km/h: refused, with both units.
TEST(NodeBadParameters, MaxSpeedBeyondTheModelsRangeIsRefused) {
  expectRefused("bad_max_speed", "_max_speed:=100.0",
                "/bad_max_speed/max_speed: must be at most 55.5556 m/s (200 km/h, as tvd's "
                "--speed-kmh), got 100");
}

// Rates and frames that cannot be meant: each named (review 145).
TEST(NodeBadParameters, ImpossibleRatesFramesAndThresholdsAreNamed) {
  expectRefused("fast_publish", "_rate:=100 _publish_rate:=200",
                "/fast_publish/publish_rate: must not exceed ~rate (100 Hz), got 200");
  expectRefused("same_frames", "_odom_frame:=base_link",
                "/same_frames/base_frame: must differ from ~odom_frame");
  expectRefused("mac_above_one", "_reduction/mac_threshold:=1.5",
                "/mac_above_one/reduction/mac_threshold: must be <= 1");
}

// ~initial_speed: 0 .. ~max_speed (a parameter has no standstill noise: -0.0005 is refused as
// well); each bound named.
TEST(NodeBadParameters, InitialSpeedOutsideZeroToMaxSpeedIsNamed) {
  expectRefused("negative_initial_speed", "_initial_speed:=-1",
                "/negative_initial_speed/initial_speed: must be >= 0 m/s, got -1");
  expectRefused("fast_initial_speed", "_max_speed:=10 _initial_speed:=12.5",
                "/fast_initial_speed/initial_speed: must be at most ~max_speed (10 m/s), got 12.5");
}

// ~imu_points: each entry a published point frame, once (~points: once); every bad entry is
// named.
TEST(NodeBadParameters, BadImuPointsAreNamed) {
  // Lists cannot be given on a node's command line (roscpp reads scalars there): they go on the
  // master under the node's name first.
  struct Case {
    std::string name;
    std::vector<std::string> points, imu_points;  // points empty: ~points unset
    std::string message;
  };
  const std::vector<Case> cases = {
      {"imu_unknown",
       {},
       {"nowhere"},
       "imu_points: unknown point 'nowhere' (the description has: crew_seat, sensor_mount)"},
      {"imu_unpublished",
       {"crew_seat"},
       {"sensor_mount"},
       "imu_points: point 'sensor_mount' is not published as a frame; add it to ~points"},
      {"imu_twice",
       {},
       {"crew_seat", "crew_seat"},
       "imu_points: point 'crew_seat' is listed twice"},
      // ~points likewise (it published the frame twice in every /tf message).
      {"points_twice",
       {"sensor_mount", "crew_seat", "sensor_mount"},
       {},
       "points: point 'sensor_mount' is listed twice"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    ros::param::set("/" + c.name + "/imu_points", c.imu_points);
    if (!c.points.empty())
      ros::param::set("/" + c.name + "/points", c.points);
    const NodeRun run = runNamed(c.name, "");
    EXPECT_EQ(run.exit_status, 1) << run.output;
    EXPECT_NE(run.output.find("FATAL"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("/" + c.name + "/" + c.message), std::string::npos) << run.output;
  }
  // Not a list (a scalar on the command line).
  expectRefused("imu_scalar", "_imu_points:=sensor_mount",
                "/imu_scalar/imu_points: must be a list of strings");
}

// ~max_acceleration and ~max_deceleration: >= 0 m/s^2 and finite, a number; each named.
TEST(NodeBadParameters, BadSpeedSlewRatesAreNamed) {
  int index = 0;
  for (const std::string key : {"max_acceleration", "max_deceleration"}) {
    for (const auto& [value, message] : std::vector<std::pair<std::string, std::string>>{
             {"-1", ": must be >= 0 m/s^2, got -1"},
             {"nan", ": must be"},  // a string or NaN on the command line
             {"fast", ": must be a number, got the string 'fast'"}}) {
      SCOPED_TRACE("~" + key + " " + value);
      const std::string name = "bad_slew_" + std::to_string(index++);
      const NodeRun run = runNamed(name, "_" + key + ":=" + value);
      EXPECT_EQ(run.exit_status, 1) << run.output;
      EXPECT_NE(run.output.find("FATAL"), std::string::npos) << run.output;
      EXPECT_NE(run.output.find("/" + name + "/" + key + message), std::string::npos) << run.output;
    }
  }
}

// ~catch_up_limit below one step (1 / ~rate) skipped time at every late tick: refused, naming it.
TEST(NodeBadParameters, CatchUpLimitBelowOneStepIsNamed) {
  expectRefused("short_catch_up", "_rate:=500 _catch_up_limit:=0.001",
                "/short_catch_up/catch_up_limit: must be at least one step, 1 / ~rate = 0.002 s, "
                "got 0.001");
  // 1e300 ("never skip") overflowed the step count into skipping at every late tick.
  expectRefused("long_catch_up", "_catch_up_limit:=1e300",
                "/long_catch_up/catch_up_limit: must be at most 10 s (a tick replays it all "
                "before it returns), got 1e+300");
}

// A publishing or check rate of 1e-20 Hz overflowed ~rate / rate (llround) into "every step".
TEST(NodeBadParameters, RatesTooSlowToCountInStepsAreNamed) {
  expectRefused("slow_publish", "_publish_rate:=1e-20",
                "/slow_publish/publish_rate: must be at least 1e-06 Hz (once in 11.6 days), got "
                "1e-20");
  expectRefused("slow_contact", "_ground_contact_rate:=1e-20",
                "/slow_contact/ground_contact_rate: must be at least 1e-06 Hz (once in 11.6 days; "
                "0 turns it off), got 1e-20");
}

// A reduction the ~reduction/* settings cannot carry out on a valid description (a MAC threshold
// of 1 pairs no mode) names those settings and the file, not ~vehicle alone.
TEST(NodeBadParameters, AReductionTheSettingsCannotCarryOutNamesThem) {
  const NodeRun run = runNamed("no_pairs", "_reduction/mac_threshold:=1.0");
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_NE(run.output.find("/no_pairs/reduction/* (reducing "), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("): reduction: no global mode selected below 30 Hz (MAC threshold 1 "),
            std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("/no_pairs/vehicle ("), std::string::npos) << run.output;
}

// ~rate must let the comfort meter filter (ISO 2631-1 Wk: above 25 Hz): named as ~rate.
TEST(NodeBadParameters, RateTooLowForTheComfortFilterIsNamed) {
  const NodeRun run = runNamed("slow_rate", "_rate:=5");
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_NE(
      run.output.find("/slow_rate/rate: comfort: sample rate 5 Hz is too low for ISO 2631-1 Wk"),
      std::string::npos)
      << run.output;
  // Nor so high that no step could keep it (1e9 Hz pegged a core and ignored SIGINT).
  const NodeRun fast = runNamed("fast_rate", "_rate:=1e9");
  EXPECT_EQ(fast.exit_status, 1) << fast.output;
  EXPECT_NE(fast.output.find("/fast_rate/rate: must not exceed 100000 Hz"), std::string::npos)
      << fast.output;
}

// ~comfort_running_rms_time: the linear running r.m.s. keeps rate x time squares; a window of
// 1e8 (1e5 s at 1 kHz) would take 800 MB: refused, named as the parameter.
TEST(NodeBadParameters, ComfortRunningTimeBeyondTheWindowIsNamed) {
  expectRefused("long_rms", "_comfort_running_rms_time:=1e5",
                "/long_rms/comfort_running_rms_time: comfort: a running r.m.s. over 100000 s at "
                "1000 Hz needs 1e+08 samples, more than 1e+07");
}

// ~ground_contact_rate: >= 0 Hz, finite, at most ~rate; each named.
TEST(NodeBadParameters, BadGroundContactRateIsNamed) {
  int index = 0;
  for (const auto& [value, message] : std::vector<std::pair<std::string, std::string>>{
           {"-1", ": must be >= 0 Hz, got -1"},
           {"fast", ": must be a number"},
           {"2000", ": must not exceed ~rate (1000 Hz), got 2000"}}) {
    SCOPED_TRACE("~ground_contact_rate " + value);
    const std::string name = "bad_contact_rate_" + std::to_string(index++);
    const NodeRun run = runNamed(name, "_ground_contact_rate:=" + value);
    EXPECT_EQ(run.exit_status, 1) << run.output;
    EXPECT_NE(run.output.find("FATAL"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("/" + name + "/ground_contact_rate" + message), std::string::npos)
        << run.output;
  }
}

// A relative file path the node cannot find: roslaunch runs nodes in $ROS_HOME, so the message
// says where it looked and asks for an absolute path (it said only "file not found").
TEST(NodeBadParameters, RelativeFilesNotFoundSayWhereTheNodeLooked) {
  ros::NodeHandle private_nh("~");
  const std::string cache_dir = test::requiredParam<std::string>(private_nh, "cache_dir");
  const std::string vehicle = test::requiredParam<std::string>(private_nh, "vehicle");
  const int timeout = test::requiredParam<int>(private_nh, "bad_parameter_timeout");
  const std::string cwd = std::filesystem::current_path().string();
  for (const auto& [name, arguments, key, path] : std::vector<std::array<std::string, 4>>{
           {"relative_vehicle", "_vehicle:=no_such_dir/my_vehicle.yaml", "vehicle",
            "no_such_dir/my_vehicle.yaml"},
           {"relative_model", "_vehicle:=" + vehicle + " _reduced_model:=my_model.mat",
            "reduced_model", "my_model.mat"}}) {
    SCOPED_TRACE(arguments);
    const NodeRun run =
        runNode("__name:=" + name + " _cache_dir:=" + cache_dir + " " + arguments, timeout);
    EXPECT_EQ(run.exit_status, 1) << run.output;
    EXPECT_NE(run.output.find("/" + name + "/" + key + ": " + path +
                              ": file not found relative to the node's working directory " + cwd +
                              " (roslaunch runs nodes in $ROS_HOME): give an absolute path"),
              std::string::npos)
        << run.output;
  }
  // "~/" as a shell expands it (roslaunch passes it as written: it was looked for under a
  // directory "~" in $ROS_HOME). Quoted, so that the shell running the node leaves it alone.
  const char* home = std::getenv("HOME");
  ASSERT_NE(home, nullptr);
  const NodeRun run = runNode(
      "__name:=tilde_vehicle _cache_dir:=" + cache_dir + " '_vehicle:=~/no_such_tvd_vehicle.yaml'",
      timeout);
  EXPECT_EQ(run.exit_status, 1) << run.output;
  EXPECT_NE(run.output.find(std::string(home) + "/no_such_tvd_vehicle.yaml"), std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("relative to the node's working directory"), std::string::npos)
      << run.output;
}

// Integers must be integers (roscpp would round 2.5 to 3 and build another model); frame ids
// must be ones tf2 takes and not a wheel's or point's frame.
// A node run per case (named `name`, given `arguments`) stops at once with one FATAL line that
// holds `message`.
struct StopCase {
  std::string name, arguments, message;
};
void expectEachStopsNamed(const std::vector<StopCase>& cases) {
  for (const auto& [name, arguments, message] : cases) {
    SCOPED_TRACE(arguments);
    const NodeRun run = runNamed(name, arguments);
    EXPECT_EQ(run.exit_status, 1) << run.output;
    EXPECT_NE(run.output.find("FATAL"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(message), std::string::npos) << run.output;
  }
}

TEST(NodeBadParameters, NonIntegersAndBadFrameIdsAreNamed) {
  expectEachStopsNamed({
      {"mode_count_half", "_reduction/mode_count:=2.5",
       "/mode_count_half/reduction/mode_count: must be an integer, got the number 2.5"},
      // The command line's ranges (tvd --global-modes, --masters, --modes).
      {"global_modes_300", "_reduction/global_modes:=300",
       "/global_modes_300/reduction/global_modes: must be an integer in [1, 200], got 300 (more "
       "take minutes"},
      {"masters_1001", "_reduction/mogesec_masters:=1001",
       "/masters_1001/reduction/mogesec_masters: must be an integer in [0, 1000], got 1001"},
      {"modes_1001", "_reduction/mode_count:=1001",
       "/modes_1001/reduction/mode_count: must be an integer in [0, 1000], got 1001"},
      {"slash_prefix", "_frame_prefix:=/veh1/",
       "/slash_prefix/frame_prefix: '/veh1/' must not start with '/'"},
      {"double_slash_prefix", "_frame_prefix:=veh1//",
       "/double_slash_prefix/frame_prefix: 'veh1//' must not contain '//' (an empty name"},
      {"double_slash_base", "_base_frame:=hull//base",
       "/double_slash_base/base_frame: 'hull//base' must not contain '//'"},
      {"base_is_point", "_base_frame:=crew_seat",
       "/base_is_point/base_frame: 'crew_seat' is also the frame of a road wheel or named point"},
  });
}

// What the node accepts but would otherwise do silently: a misspelt parameter is named with the
// one it resembles, a ~publish_rate that does not divide ~rate is said to be rounded, and a ~rate
// (40 Hz) below the ground-contact check's default 50 Hz runs with it capped.
TEST(NodeBadParameters, MisspeltParametersAndRoundedRatesAreSaid) {
  ros::NodeHandle private_nh("~");
  const NodeRun run =
      runNode("__name:=said _vehicle:=" + test::requiredParam<std::string>(private_nh, "vehicle") +
                  " _cache_dir:=" + test::requiredParam<std::string>(private_nh, "cache_dir") +
                  " _rate:=40 _publish_rate:=15 _speed_timout:=1 _frame_prefix:=veh1"
                  " _tf_prefix:=veh1/ _sped_timout:=2"
                  // accepted: 0 turns the ground-contact check off; one step (1/40 s) typed
                  // to rounding
                  " _ground_contact_rate:=0 _catch_up_limit:=0.02499999",
              test::requiredParam<int>(private_nh, "bad_parameter_timeout"));
  EXPECT_EQ(run.exit_status, 124) << "the node should run until `timeout` stops it:\n"
                                  << run.output;
  EXPECT_EQ(run.output.find("FATAL"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("torsion bars"), std::string::npos) << run.output;  // bundled: no
  EXPECT_NE(
      run.output.find(
          "parameter ~speed_timout (did you mean ~speed_timeout?) is set but not a parameter"),
      std::string::npos)
      << run.output;
  // Two edits away (a letter dropped, another one) is still suggested.
  EXPECT_NE(run.output.find(
                "parameter ~sped_timout (did you mean ~speed_timeout?) is set but not a parameter"),
            std::string::npos)
      << run.output;
  // ROS 1's retired tf_prefix, what ~frame_prefix does here.
  EXPECT_NE(run.output.find("parameter ~tf_prefix (did you mean ~frame_prefix?) is set but not"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("~publish_rate 15 Hz does not divide ~rate 40 Hz: publishing every 3 "
                            "steps, at 13.3333 Hz"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("/said: /said/frame_prefix: 'veh1' has no trailing '/': the frames "
                            "read 'veh1odom'"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("while the node runs in the namespace"), std::string::npos)
      << run.output;  // at the root
}

// The node steps on whole nanoseconds: a ~rate whose period is not one (3 kHz: 333333.3 ns)
// is integrated at the rate of the step it takes, and said; the vehicle's clock ran 1e-6 fast
// against the stamps. ~publish_rate (100 Hz, every 30 steps) is not said to be rounded for it.
TEST(NodeBadParameters, ARateOfNoWholeNanosecondsIsSteppedAsTakenAndSaid) {
  ros::NodeHandle private_nh("~");
  const NodeRun run = runNode(
      "__name:=rate_ns _vehicle:=" + test::requiredParam<std::string>(private_nh, "vehicle") +
          " _cache_dir:=" + test::requiredParam<std::string>(private_nh, "cache_dir") +
          " _rate:=3000 _publish_rate:=100",
      test::requiredParam<int>(private_nh, "bad_parameter_timeout"));
  EXPECT_EQ(run.exit_status, 124) << run.output;
  EXPECT_NE(run.output.find("/rate_ns/rate 3000 Hz is not a whole number of nanoseconds a step: "
                            "stepping every 333333 ns, at 3000.003 Hz"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("does not divide"), std::string::npos) << run.output;
}

// Two vehicles pushed into namespaces without ~frame_prefix share every frame in the tf tree:
// the node says so, naming the prefix to give; with it (or at the root) nothing is said.
TEST(NodeBadParameters, ANamespaceWithoutAFramePrefixIsSaid) {
  ros::NodeHandle private_nh("~");
  const std::string common =
      " _vehicle:=" + test::requiredParam<std::string>(private_nh, "vehicle") +
      " _cache_dir:=" + test::requiredParam<std::string>(private_nh, "cache_dir");
  const int timeout = test::requiredParam<int>(private_nh, "bad_parameter_timeout");
  const NodeRun bare = runNode("__ns:=/tank1 __name:=in_ns" + common, timeout);
  EXPECT_EQ(bare.exit_status, 124) << bare.output;
  EXPECT_NE(bare.output.find("/tank1/in_ns/frame_prefix is empty while the node runs in the "
                             "namespace /tank1: its frames (odom, base_link, road_wheel_left_1, "
                             "...) are those of any other vehicle in the tf tree"),
            std::string::npos)
      << bare.output;
  EXPECT_NE(bare.output.find("give frame_prefix:=tank1/ for a tree of its own"), std::string::npos)
      << bare.output;
  const NodeRun prefixed =
      runNode("__ns:=/tank1 __name:=in_ns_prefixed _frame_prefix:=tank1/" + common, timeout);
  EXPECT_EQ(prefixed.output.find("frame_prefix is empty"), std::string::npos) << prefixed.output;
}

// A vehicle of our own without a crew_seat point starts with ~comfort_point unset: the comfort
// meter then watches the hull's CoG, and an INFO line says so (it once stopped with a FATAL line
// on the default's crew_seat). Set to a point it does not name, it still stops, naming it.
TEST(NodeBadParameters, UnsetComfortPointFallsBackToTheHullOnAVehicleWithoutACrewSeat) {
  ros::NodeHandle private_nh("~");
  const std::string own = test::requiredParam<std::string>(private_nh, "own_vehicle");
  // A cache of its own: NodeReducedModel takes the newest tracked model of ~cache_dir as the
  // bundled vehicle's.
  const std::string cache_dir =
      test::requiredParam<std::string>(private_nh, "cache_dir") + "/own_vehicle";
  const int timeout = test::requiredParam<int>(private_nh, "bad_parameter_timeout");
  const NodeRun run =
      runNode("__name:=own_vehicle _vehicle:=" + own + " _cache_dir:=" + cache_dir, timeout);
  EXPECT_EQ(run.exit_status, 124) << "the node should run until `timeout` stops it:\n"
                                  << run.output;
  EXPECT_EQ(run.output.find("FATAL"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("~comfort_point unset and " + own +
                            " names no 'crew_seat' point: ride comfort at the hull's CoG"),
            std::string::npos)
      << run.output;
  // The fixture holds the paper's chain bending on a 10 t vehicle: the chain carries the hull,
  // and the node says so as tvd statics does (vehicle/wheel_rate_estimate.h).
  EXPECT_NE(run.output.find(own + ": the hull sags 1."), std::string::npos) << run.output;
  EXPECT_NE(run.output.find(" mm under its weight, less than a fifth of the 39.5 mm of the hull "
                            "with its chain wheels"),
            std::string::npos)
      << run.output;
  const NodeRun named = runNode("__name:=own_vehicle_seat _vehicle:=" + own +
                                    " _cache_dir:=" + cache_dir + " _comfort_point:=crew_seat",
                                timeout);
  EXPECT_EQ(named.exit_status, 1) << named.output;
  EXPECT_NE(named.output.find("/own_vehicle_seat/comfort_point: unknown point 'crew_seat' (hull, "
                              "driver_seat, commander_hatch in "),
            std::string::npos)
      << named.output;
}

// Discrete arm dampers make Phi^T C Phi non-diagonal. ~method modal (the default) steps the
// coupled modes together (Simulator's ratio 0, test_simulator.cpp), so the node runs without
// the coupling WARN it gave until 2026-12-06, when each mode kept its own damping (a wheel's
// peak off by half).
TEST(NodeBadParameters, ModalMethodWithArmDampersKeepsTheCoupling) {
  ros::NodeHandle private_nh("~");
  const std::string own = test::requiredParam<std::string>(private_nh, "own_vehicle");
  const std::string cache_dir =
      test::requiredParam<std::string>(private_nh, "cache_dir") + "/arm_damped";
  std::filesystem::create_directories(cache_dir);
  const std::string damped = cache_dir + "/arm_damped.yaml";
  {
    std::ifstream in(own);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string zero = "arm_damping: {value: 0,";
    const std::string::size_type at = text.find(zero);
    ASSERT_NE(at, std::string::npos) << own << " has no zero arm_damping to replace";
    text.replace(at, zero.size(), "arm_damping: {value: 20000,");
    const std::string stations = "damped_stations:\n    value: []";
    const std::string::size_type st = text.find(stations);
    ASSERT_NE(st, std::string::npos) << own << " has no empty damped_stations to replace";
    text.replace(st, stations.size(), "damped_stations:\n    value: [1, 5]");
    std::ofstream(damped) << text;
  }
  const NodeRun run = runNode(
      "__name:=arm_damped _variant:=untracked _vehicle:=" + damped + " _cache_dir:=" + cache_dir,
      test::requiredParam<int>(private_nh, "bad_parameter_timeout"));
  EXPECT_EQ(run.exit_status, 124) << "the node should run until `timeout` stops it:\n"
                                  << run.output;
  EXPECT_NE(run.output.find("/arm_damped: modal discretisation at "), std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("the damping couples the modes"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find("keeps only the diagonal"), std::string::npos) << run.output;
}

// ~footprint_frame must be a frame of its own; ~publish_odom_tf a boolean.
TEST(NodeBadParameters, BadFootprintFrameAndOdomTfAreNamed) {
  expectEachStopsNamed({
      {"footprint_is_odom", "_footprint_frame:=odom",
       "/footprint_is_odom/footprint_frame: must differ from ~odom_frame and ~base_frame"},
      {"odom_tf_maybe", "_publish_odom_tf:=maybe",
       "/odom_tf_maybe/publish_odom_tf: must be a boolean, got the string 'maybe'"},
  });
}

// Ctrl-C while the model is being built (an empty cache: the tracked reduction takes about a
// second): the node says so on one line and exits 0. It once ended in SIGTRAP, publishing on a
// publisher created after roscpp had shut down. The signal goes to the node itself once it has
// registered with the master (roscpp's handler installed; the build runs from then on).
TEST(NodeBadParameters, InterruptedWhileBuildingTheModelExitsCleanly) {
  ros::NodeHandle private_nh("~");
  const std::string vehicle = test::requiredParam<std::string>(private_nh, "vehicle");
  char cache[] = "/tmp/tvd_interrupted_XXXXXX";
  ASSERT_NE(mkdtemp(cache), nullptr);
  NodeRun run;
  // -k: a node that ignored the signal is killed 20 s later, failing this test alone.
  std::thread node([&] {
    run = runNode("__name:=interrupted _vehicle:=" + vehicle +
                      " _variant:=tracked _cache_dir:=" + std::string(cache),
                  "-k 20 --preserve-status 60");
  });
  const bool registered = test::spinUntil(
      [] {
        std::vector<std::string> nodes;
        return ros::master::getNodes(nodes) &&
               std::find(nodes.begin(), nodes.end(), "/interrupted") != nodes.end();
      },
      30.0);
  // The node's own process (its command line starts with its path; the shell and timeout(1)
  // that started it are left alone).
  const int signalled =
      std::system("pkill -INT -f '^/[^ ]*/vehicle_dynamics_node __name:=interrupted'");
  node.join();
  std::filesystem::remove_all(cache);
  ASSERT_TRUE(registered) << run.output;
  EXPECT_EQ(signalled, 0) << "no node process to signal";
  EXPECT_EQ(run.exit_status, 0) << run.output;
  EXPECT_NE(run.output.find("/interrupted: shut down during start-up, before the model was ready"),
            std::string::npos)
      << run.output;
  EXPECT_EQ(run.output.find("FATAL"), std::string::npos) << run.output;
}

// A step slower than the period (~method exact at 100 kHz on the un-tracked model: its 254
// states take about 25-40 us per 10 us step here) cannot keep up: the "behind ROS time" warning
// says why and what to do, with the mean step time. The node reduces the model into a fresh
// cache first: its first warning came 0.7-0.9 s after the start on an idle machine, 5.5-6.5 s
// with eight busy loops and a compile beside it (review 138), so it gets 8 s (the warnings after
// the first are throttled to one in 5 s: a first one missed is not made up).
TEST(NodeBadParameters, AStepSlowerThanThePeriodIsSaid) {
  ros::NodeHandle private_nh("~");
  char cache[] = "/tmp/tvd_slow_XXXXXX";
  ASSERT_NE(mkdtemp(cache), nullptr);
  const NodeRun run = runNode(
      "__name:=slow_exact _vehicle:=" + test::requiredParam<std::string>(private_nh, "vehicle") +
          " _variant:=untracked _cache_dir:=" + std::string(cache) +
          " _method:=exact _rate:=100000",
      8);
  std::filesystem::remove_all(cache);
  EXPECT_NE(run.output.find("behind ROS time, more than ~catch_up_limit"), std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("more than the period of 10 us: lower ~rate, or use ~method modal)"),
            std::string::npos)
      << run.output;
  EXPECT_NE(run.output.find("(a step takes "), std::string::npos) << run.output;
}

// An unwritable ~cache_dir does not stop the node (the model is built), but it must not be
// reported as cached: a WARN says "not cached" and why.
TEST(NodeBadParameters, UnwritableCacheDirIsWarnedNotCached) {
  ros::NodeHandle private_nh("~");
  const std::string vehicle = test::requiredParam<std::string>(private_nh, "vehicle");
  const int timeout = test::requiredParam<int>(private_nh, "bad_parameter_timeout");
  // The node runs until the timeout (its own thread here, so that this one reads /diagnostics
  // meanwhile); the WARN goes to stderr, unbuffered.
  ros::NodeHandle nh;
  test::DiagnosticsCache diagnostics(nh);
  NodeRun run;
  std::thread node([&] {
    run = runNode("__name:=unwritable_cache _vehicle:=" + vehicle +
                      " _variant:=untracked _cache_dir:=/proc/tvd_no_cache",
                  timeout);
  });
  // What an operator's monitor shows: the model status WARN, not cached (after
  // diagnostic_updater's own "Node starting up").
  const bool reported = test::spinUntil(
      [&] {
        return diagnostics.has("unwritable_cache: model") &&
               diagnostics.message("unwritable_cache: model") != "Node starting up";
      },
      timeout - 2.0);
  node.join();
  ASSERT_TRUE(reported) << diagnostics.describe() << run.output;
  EXPECT_EQ(diagnostics.level("unwritable_cache: model"), 1) << diagnostics.describe();
  EXPECT_EQ(diagnostics.message("unwritable_cache: model").rfind("built; not cached: ", 0), 0u)
      << diagnostics.describe();
  EXPECT_EQ(diagnostics.text("unwritable_cache: model", "cached"), "False")
      << diagnostics.describe();
  // A WARN line that says it (the reduction's own WARNs, e.g. a cut eigenspace, do not count).
  std::istringstream lines(run.output);
  bool warned = false;
  for (std::string line; std::getline(lines, line);)
    warned = warned || (line.find("WARN") != std::string::npos &&
                        line.find("not cached: ") != std::string::npos);
  EXPECT_TRUE(warned) << run.output;
  EXPECT_EQ(run.output.find("built and cached"), std::string::npos) << run.output;
}

// The tracked model the fixture's node cached with the default reduction options:
// cache_dir/tracked_<description hash>.mat (other options add a second suffix). The newest such
// file: the directory outlives test runs, and files of older descriptions stay behind. Waits.
std::string defaultTrackedCacheFile(const std::string& cache_dir) {
  std::string found;
  test::spinUntil(
      [&] {
        std::error_code error;
        std::filesystem::file_time_type newest{};
        for (const auto& entry : std::filesystem::directory_iterator(cache_dir, error)) {
          const std::string name = entry.path().filename().string();
          if (name.rfind("tracked_", 0) == 0 && name.size() > 12 &&
              name.compare(name.size() - 4, 4, ".mat") == 0 &&
              name.find('_', 8) == std::string::npos &&
              (found.empty() || entry.last_write_time() > newest)) {
            found = entry.path().string();
            newest = entry.last_write_time();
          }
        }
        return !found.empty();
      },
      120.0);
  return found;
}

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writeFile(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// ~reduced_model tests: the tracked model the fixture's node cached is a file of the right kind.
class NodeReducedModel : public ::testing::Test {
 protected:
  void SetUp() override {
    ros::NodeHandle private_nh("~");
    vehicle = test::requiredParam<std::string>(private_nh, "vehicle");
    cache_dir = test::requiredParam<std::string>(private_nh, "cache_dir");
    timeout = test::requiredParam<int>(private_nh, "bad_parameter_timeout");
    file = defaultTrackedCacheFile(cache_dir);
    ASSERT_FALSE(file.empty()) << "no tracked model in " << cache_dir;
  }

  std::string vehicle, cache_dir, file;
  int timeout = 0;
};

// ~reduced_model runs a `tvd reduce --out` file instead of the cache; the cache's own file is one.
TEST_F(NodeReducedModel, GivenFileIsRunAndNamed) {
  const std::string empty_cache = cache_dir + "_unused";
  std::filesystem::remove_all(empty_cache);
  // The node keeps running (killed by the timeout, 124) and never reduces into the cache. Its
  // INFO lines go to stdout, a pipe here: line-buffered, or the kill would lose them.
  setenv("ROSCONSOLE_STDOUT_LINE_BUFFERED", "1", 1);
  // ~reduction/band_hz other than the file's: the file's model runs, and a WARN says so (tvd
  // frf|simulate refuse a reduction option with --reduced).
  const NodeRun run = runNode("__name:=given_model _vehicle:=" + vehicle +
                                  " _variant:=tracked _cache_dir:=" + empty_cache +
                                  " _reduced_model:=" + file + " _reduction/band_hz:=40.0",
                              timeout);
  EXPECT_EQ(run.exit_status, 124) << run.output;
  EXPECT_EQ(run.output.find("FATAL"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("from ~reduced_model " + file), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("band_hz 40; "), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("differ from the reduction of " + file +
                            " ('variant tracked; rule "
                            "mac; global_modes 40; band_hz 30; "),
            std::string::npos)
      << run.output;
  EXPECT_FALSE(std::filesystem::exists(empty_cache)) << "the node reduced into the cache";
}

// A given file that fails a check stops the node with one FATAL line naming the parameter and
// the file, and how to write a good one; it is never silently rebuilt.
TEST_F(NodeReducedModel, BadFileStopsTheNodeNamingIt) {
  const std::string bytes = readFile(file);
  const std::string truncated = cache_dir + "/truncated_copy.mat";
  writeFile(truncated, bytes.substr(0, bytes.size() / 2));
  // Another description: the same vehicle with a heavier hull.
  std::string description = readFile(vehicle);
  const std::string mass = "mass: {value: 30300";
  ASSERT_NE(description.find(mass), std::string::npos);
  description.replace(description.find(mass), mass.size(), "mass: {value: 31300");
  const std::string heavier = cache_dir + "/heavier_hull.yaml";
  writeFile(heavier, description);

  struct Case {
    std::string name, vehicle, variant, file, says;
  };
  const std::vector<Case> cases = {
      {"truncated_model", vehicle, "tracked", truncated, truncated + ": "},
      {"missing_model", vehicle, "tracked", cache_dir + "/none.mat", cache_dir + "/none.mat: "},
      {"other_description", heavier, "tracked", file, "reduced from another description"},
      {"other_variant", vehicle, "untracked", file,
       file + " holds the tracked variant, /other_variant/variant is untracked"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const NodeRun run =
        runNode("__name:=" + c.name + " _vehicle:=" + c.vehicle + " _variant:=" + c.variant +
                    " _cache_dir:=" + cache_dir + " _reduced_model:=" + c.file,
                timeout);
    EXPECT_EQ(run.exit_status, 1) << run.output;
    EXPECT_NE(run.output.find("FATAL"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("/" + c.name + "/reduced_model: "), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(c.says), std::string::npos) << run.output;
    if (c.name != "other_variant") {
      EXPECT_NE(run.output.find("--out FILE.mat`, or leave /" + c.name + "/reduced_model unset"),
                std::string::npos)
          << run.output;
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "node_bad_input_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
