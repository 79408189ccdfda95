// rostest tier 2: bad input keeps the node alive, publishing finite values, with a diagnostics
// entry for each kind; the loop holds its rate (node_bad_input.test, real time).
#include <gtest/gtest.h>

#include <limits>

#include <geometry_msgs/AccelStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <std_msgs/Float64.h>
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
    tf_sub_ = nh_.subscribe("/tf", 10000, &NodeBadInput::onTf, this);
    wheels_sub_ = nh_.subscribe("road_wheels", 10000, &NodeBadInput::onWheels, this);
    accel_sub_ = nh_.subscribe("hull/accel", 10000, &NodeBadInput::onAccel, this);
    twist_sub_ = nh_.subscribe("hull/twist", 10000, &NodeBadInput::onTwist, this);
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
  const int bad_patches = 5;

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

  ASSERT_TRUE(test::spinUntil(
      [&] {
        return diagnostics_.value(": terrain", "patches rejected (total)") >= bad_patches &&
               diagnostics_.value(": speed", "speeds rejected (total)") >= bad_speeds &&
               diagnostics_.value(": terrain", "steps with uncovered contacts (total)") > 0;
      },
      5.0))
      << diagnostics_.describe();
  EXPECT_EQ(diagnostics_.value(": terrain", "patches rejected (total)"), bad_patches);
  EXPECT_EQ(diagnostics_.value(": speed", "speeds rejected (total)"), bad_speeds);
  EXPECT_EQ(diagnostics_.level(": terrain"),
            static_cast<int>(diagnostic_msgs::DiagnosticStatus::WARN));
  EXPECT_EQ(diagnostics_.value(": loop", "non-finite resets (total)"), 0.0);
  std::printf("%s", diagnostics_.describe().c_str());
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "node_bad_input_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
