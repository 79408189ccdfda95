// rostest on simulated time with two /clock publishers (node_two_clocks.test): the test's own
// clock, running from 1 s, and a second one latched at 1000 s. Each makes the other's time jump,
// so the vehicle resets over and over; the node's loop diagnostics name the cause (WARN "/clock
// has 2 publishers ...") and count the publishers, where before they said only "jumped back"
// or "ran ahead" (review 165).
#include <gtest/gtest.h>

#include <rosgraph_msgs/Clock.h>

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

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "node_two_clocks_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
