// rostest on simulated time with two /clock publishers (node_two_clocks.test): the test's own
// clock, running from 1 s, and a second one latched at 1000 s. Each makes the other's time jump,
// so the vehicle resets over and over; the node's loop diagnostics name the cause (WARN "/clock
// has 2 publishers ...") and count the publishers, where before they said only "jumped back"
// or "ran ahead" (review 165).
#include <gtest/gtest.h>

#include <rosgraph_msgs/Clock.h>
#include <rosgraph_msgs/Log.h>

#include <atomic>
#include <string>

#include "node_test_utils.h"

using namespace tracked_vehicle_dynamics::ros_layer;

namespace {

TEST(NodeTwoClocks, TheLoopDiagnosticsNameBothClockPublishers) {
  ros::NodeHandle nh;
  test::DiagnosticsCache diagnostics(nh);
  const ros::Publisher clock = nh.advertise<rosgraph_msgs::Clock>("/clock", 10);
  ros::Time t(1.0);
  // The node loads (or reduces) its model meanwhile; the clock runs until it reports.
  ASSERT_TRUE(test::tickClockUntil(
      clock, &t,
      [&] {
        return diagnostics.message(": loop").find("/clock has 2 publishers") != std::string::npos;
      },
      60.0))
      << diagnostics.describe();
  EXPECT_EQ(diagnostics.level(": loop"), diagnostic_msgs::DiagnosticStatus::WARN);
  EXPECT_NE(diagnostics.message(": loop").find("one time source per master"), std::string::npos)
      << diagnostics.describe();
  EXPECT_EQ(diagnostics.value(": loop", "/clock publishers"), 2.0) << diagnostics.describe();
}

// Two clocks running apart jump ROS time back at every other message; each jump back resets the
// vehicle. The log says so once a second of wall time, not at every jump (rosconsole's own
// throttle reads ROS time, which each jump re-opened: 401 lines in 12 s, review 166).
TEST(NodeTwoClocks, ResetsOfTwoClocksAreLoggedOnceASecond) {
  ros::NodeHandle nh;
  test::DiagnosticsCache diagnostics(nh);
  std::atomic<int> reset_lines{0};
  const ros::Subscriber log = nh.subscribe<rosgraph_msgs::Log>(
      "/rosout", 1000, [&](const rosgraph_msgs::Log::ConstPtr& msg) {
        if (msg->msg.find("ROS time jumped back") != std::string::npos)
          ++reset_lines;
      });
  const ros::Publisher clock = nh.advertise<rosgraph_msgs::Clock>("/clock", 100);
  test::spinFor(1.0);  // connected
  const double before = diagnostics.value(": loop", "time jumps back (total)");
  // 3 s of wall time: 100 s on and 50 s back, 100 times a second.
  const ros::WallTime end = ros::WallTime::now() + ros::WallDuration(3.0);
  for (int i = 0; ros::WallTime::now() < end; ++i) {
    test::publishClock(clock, ros::Time(100.0 + 1e-3 * i));
    ros::WallDuration(0.005).sleep();
    test::publishClock(clock, ros::Time(50.0 + 1e-3 * i));
    ros::WallDuration(0.005).sleep();
    ros::spinOnce();
  }
  // The last report (~diagnostic_period on wall time while ROS time jumps) and the log lines.
  test::spinFor(2.0);
  const double jumps = diagnostics.value(": loop", "time jumps back (total)") - before;
  EXPECT_GT(jumps, 30.0) << diagnostics.describe();
  EXPECT_GE(reset_lines.load(), 1);
  EXPECT_LE(reset_lines.load(), 5) << jumps << " jumps back";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "node_two_clocks_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
