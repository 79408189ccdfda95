// rostest tier 1: the node on flat terrain at rest holds static equilibrium and publishes every
// tf frame with the right parent, the same pose on odom (nav_msgs/Odometry) as on /tf, and on
// imu/<point> the specific force of gravity in the point's frame (node_static.test).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <optional>
#include <set>

#include <nav_msgs/Odometry.h>
#include <sensor_msgs/Imu.h>
#include <tf2_msgs/TFMessage.h>

#include "node_test_utils.h"
#include "tracked_vehicle_dynamics/RoadWheels.h"
#include "tracked_vehicle_dynamics/ros/conversions.h"
#include "tracked_vehicle_dynamics/ros/online_names.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

using namespace tracked_vehicle_dynamics;
using namespace tracked_vehicle_dynamics::ros_layer;

namespace {

struct TfSample {
  ros::Time stamp;
  RigidPose pose;
};

class NodeStatic : public ::testing::Test {
 protected:
  NodeStatic() : private_nh_("~"), diagnostics_(nh_) {
    // With ~frame_prefix (node_static_prefixed.test) every frame the node publishes carries it.
    prefix_ = private_nh_.param<std::string>("frame_prefix", "");
    base_ = prefix_ + "base_link";
    odom_ = prefix_ + "odom";
    // The node's ~footprint_frame and ~publish_odom_tf as the .test file sets them.
    const std::string footprint = private_nh_.param<std::string>("footprint_frame", "");
    footprint_ = footprint.empty() ? "" : prefix_ + footprint;
    publish_odom_tf_ = private_nh_.param("publish_odom_tf", true);
    tf_sub_ =
        nh_.subscribe("/tf", 1000, &NodeStatic::onTf, this, ros::TransportHints().tcpNoDelay());
    tf_static_sub_ = nh_.subscribe("/tf_static", 10, &NodeStatic::onTfStatic, this,
                                   ros::TransportHints().tcpNoDelay());
    wheels_sub_ = nh_.subscribe("road_wheels", 1000, &NodeStatic::onWheels, this,
                                ros::TransportHints().tcpNoDelay());
    comfort_sub_ = nh_.subscribe<Comfort>(
        "comfort", 10,
        [this](const Comfort::ConstPtr& msg) { comfort_frame_ = msg->header.frame_id; },
        ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
    terrain_pub_ = nh_.advertise<TerrainProfile>("terrain_profile", 10, true);
    odom_sub_ =
        nh_.subscribe("odom", 1000, &NodeStatic::onOdom, this, ros::TransportHints().tcpNoDelay());
    private_nh_.getParam("imu_points", imu_points_);
    // The node's ~variance/* as the .test file sets them (0: the default, "unknown").
    imu_acceleration_variance_ = private_nh_.param("imu_linear_acceleration_variance", 0.0);
    odom_twist_variance_ = private_nh_.param("odom_twist_variance", 0.0);
    for (const std::string& name : imu_points_) {
      imu_subs_.push_back(nh_.subscribe<sensor_msgs::Imu>(
          "imu/" + name, 1000,
          [this, name](const sensor_msgs::Imu::ConstPtr& msg) { last_imu_[name] = *msg; },
          ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay()));
    }
  }

  void onOdom(const nav_msgs::Odometry::ConstPtr& msg) {
    odom_frames_ = {msg->header.frame_id, msg->child_frame_id};
    odom_twist_covariance_ = msg->twist.covariance;
    odom_pose_covariance_ = msg->pose.covariance;
    if (collecting_) {
      odom_poses_[msg->header.stamp] = fromMsg(msg->pose.pose);
      max_odom_speed_ = std::max({max_odom_speed_, fromMsg(msg->twist.twist.linear).norm(),
                                  fromMsg(msg->twist.twist.angular).norm()});
    }
  }

  void onTfStatic(const tf2_msgs::TFMessage::ConstPtr& msg) {
    for (const auto& t : msg->transforms) {
      parents_[t.child_frame_id] = t.header.frame_id;
      static_positions_[t.child_frame_id] = fromMsg(t.transform).translation;
      static_stamps_[t.child_frame_id] = t.header.stamp;
    }
  }
  void onTf(const tf2_msgs::TFMessage::ConstPtr& msg) {
    // base_link in odom: one transform, or odom -> footprint -> base_link composed.
    std::optional<RigidPose> direct, path, above;
    for (const auto& t : msg->transforms) {
      parents_[t.child_frame_id] = t.header.frame_id;
      on_tf_.insert(t.child_frame_id);
      from_odom_ += t.header.frame_id == odom_ ? 1 : 0;
      if (t.child_frame_id == base_ && t.header.frame_id == odom_)
        direct = fromMsg(t.transform);
      if (t.child_frame_id == base_ && !footprint_.empty() && t.header.frame_id == footprint_)
        above = fromMsg(t.transform);
      if (t.child_frame_id == footprint_ && t.header.frame_id == odom_)
        path = fromMsg(t.transform);
    }
    if (!collecting_ || msg->transforms.empty())
      return;
    const ros::Time stamp = msg->transforms.front().header.stamp;
    if (direct) {
      poses_.push_back({stamp, *direct});
    } else if (above && path) {
      RigidPose pose;
      pose.rotation = path->rotation * above->rotation;
      pose.translation = path->rotation * above->translation + path->translation;
      poses_.push_back({stamp, pose});
      // At rest at station 0: odom -> footprint is the identity.
      path_offsets_.push_back(path->translation.norm() +
                              path->rotation.angularDistance(Eigen::Quaterniond::Identity()));
    } else if (above) {
      above_poses_[stamp] = *above;
    }
  }
  void onWheels(const RoadWheels::ConstPtr& msg) {
    ++wheel_messages_;
    if (collecting_) {
      for (const auto& w : msg->wheels) {
        max_wheel_displacement_ = std::max(max_wheel_displacement_, std::abs(w.displacement));
      }
      last_station_ = msg->station;
    }
  }

  ros::NodeHandle nh_, private_nh_;
  std::string prefix_, base_, odom_, footprint_;
  bool publish_odom_tf_ = true;
  std::size_t from_odom_ = 0;                   // /tf transforms whose parent is odom
  std::map<ros::Time, RigidPose> above_poses_;  // footprint -> base_link without odom's
  std::vector<double> path_offsets_;            // |odom -> footprint - (s, 0, 0)| + its rotation
  test::DiagnosticsCache diagnostics_;
  ros::Subscriber tf_sub_, tf_static_sub_, wheels_sub_, comfort_sub_, odom_sub_;
  std::vector<ros::Subscriber> imu_subs_;
  std::vector<std::string> imu_points_;
  std::map<std::string, sensor_msgs::Imu> last_imu_;
  std::pair<std::string, std::string> odom_frames_;
  std::map<ros::Time, RigidPose> odom_poses_;
  double max_odom_speed_ = 0.0;
  double imu_acceleration_variance_ = 0.0, odom_twist_variance_ = 0.0;
  boost::array<double, 36> odom_twist_covariance_{}, odom_pose_covariance_{};
  std::string comfort_frame_;
  ros::Publisher terrain_pub_;
  std::map<std::string, std::string> parents_;
  std::set<std::string> on_tf_;
  std::map<std::string, Vector3> static_positions_;
  std::map<std::string, ros::Time> static_stamps_;
  std::vector<TfSample> poses_;
  bool collecting_ = false;
  std::size_t wheel_messages_ = 0;
  double max_wheel_displacement_ = 0.0;
  double last_station_ = -1.0;
};

TEST_F(NodeStatic, FlatTerrainAtRestIsStaticEquilibriumWithAllFrames) {
  const double tolerance = test::requiredParam<double>(private_nh_, "equilibrium_tolerance");
  const double duration = test::requiredParam<double>(private_nh_, "duration");
  std::vector<std::string> expected_frames;
  ASSERT_TRUE(private_nh_.getParam("expected_frames", expected_frames));

  ASSERT_TRUE(test::spinUntil([&] { return wheel_messages_ > 0; }, 45.0))
      << "the node published nothing";
  TerrainProfile flat = test::flatProfile(-20.0, 20.0);
  flat.header.frame_id = prefix_ + "odom";  // this vehicle's path frame
  terrain_pub_.publish(flat);
  test::spinFor(0.3);  // terrain in, a few steps on it
  collecting_ = true;
  test::spinFor(duration);
  collecting_ = false;

  // Frames and parents: base_link under odom, or under the footprint (itself under odom unless
  // ~publish_odom_tf is false, when nothing on /tf hangs from odom).
  const bool base_published = !footprint_.empty() || publish_odom_tf_;
  if (base_published) {
    EXPECT_EQ(parents_[base_], footprint_.empty() ? odom_ : footprint_);
  } else {
    EXPECT_EQ(parents_.count(base_), 0u) << base_ << " published without odom's transform";
  }
  const bool footprint_published = !footprint_.empty() && publish_odom_tf_;
  if (footprint_published) {
    EXPECT_EQ(parents_[footprint_], odom_);
  }
  if (!publish_odom_tf_) {
    EXPECT_EQ(from_odom_, 0u) << "a transform from odom with ~publish_odom_tf false";
  }
  for (const std::string& name : expected_frames) {
    const std::string frame = prefix_ + name;
    ASSERT_TRUE(parents_.count(frame)) << "frame " << frame << " never published";
    EXPECT_EQ(parents_[frame], base_) << frame;
  }
  EXPECT_EQ(parents_.size(),
            expected_frames.size() + (base_published ? 1 : 0) + (footprint_published ? 1 : 0))
      << "unexpected frames";
  // Without odom's transform the poses come from the odom topic; footprint -> base_link is that
  // pose less the travel (station 0 here).
  if (!publish_odom_tf_) {
    ASSERT_TRUE(poses_.empty());
    for (const auto& [stamp, pose] : odom_poses_)
      poses_.push_back({stamp, pose});
    std::size_t compared = 0;
    for (const auto& [stamp, above] : above_poses_) {
      const auto it = odom_poses_.find(stamp);
      if (it == odom_poses_.end())
        continue;
      ++compared;
      EXPECT_EQ(above.translation, relativeToPath(it->second, 0.0).translation);
      EXPECT_NEAR(above.rotation.angularDistance(it->second.rotation), 0.0, 1e-15);
    }
    if (!footprint_.empty()) {
      EXPECT_GT(above_poses_.size(), 100u);
      EXPECT_GT(compared, 100u) << "base_footprint -> base_link and odom share too few stamps";
    }
  }
  for (double offset : path_offsets_)
    EXPECT_LE(offset, 1e-12) << "odom -> footprint must be (s, 0, 0), unrotated";
  // The named points are rigid with the hull: on /tf_static at their description position, never
  // on /tf.
  std::vector<std::string> static_frames;
  ASSERT_TRUE(private_nh_.getParam("static_frames", static_frames));
  const auto description =
      vehicle::loadVehicleDescription(test::requiredParam<std::string>(private_nh_, "vehicle"));
  for (const std::string& name : static_frames) {
    const std::string frame = prefix_ + name;
    EXPECT_EQ(on_tf_.count(frame), 0u) << frame << " is published on /tf at every sample";
    ASSERT_EQ(static_positions_.count(frame), 1u) << frame << " not on /tf_static";
    for (const auto& point : description.named_points) {
      if (point.name == name) {
        EXPECT_EQ(static_positions_[frame], point.position) << frame;
      }
    }
    // Stamped when published (start-up, before the first sample), not at the epoch.
    EXPECT_FALSE(static_stamps_[frame].isZero()) << frame << " on /tf_static stamped 0";
    if (!poses_.empty()) {
      EXPECT_LE(static_stamps_[frame], poses_.front().stamp) << frame;
    }
  }

  // Static equilibrium: constant pose, wheels at their static position, no travel.
  ASSERT_GT(poses_.size(), 100u);
  double max_move = 0.0, max_turn = 0.0;
  for (const TfSample& s : poses_) {
    max_move = std::max(max_move, (s.pose.translation - poses_.front().pose.translation).norm());
    max_turn = std::max(max_turn, s.pose.rotation.angularDistance(poses_.front().pose.rotation));
  }
  EXPECT_LE(max_move, tolerance);
  EXPECT_LE(max_turn, tolerance);
  EXPECT_LE(max_wheel_displacement_, tolerance);
  EXPECT_EQ(last_station_, 0.0);

  // The pose is the model's static equilibrium (the same cached model, loaded here).
  const test::NodeModel node = test::nodeModel(private_nh_);
  const OnlineVehicle reference(node.model, node.geometry);
  const RigidPose expected = reference.hullPose();
  EXPECT_NEAR((poses_.back().pose.translation - expected.translation).norm(), 0.0, tolerance);
  EXPECT_NEAR(poses_.back().pose.rotation.angularDistance(expected.rotation), 0.0, tolerance);
  // The hull sags under gravity.
  EXPECT_LT(expected.translation.z(), 0.0);

  // odom (nav_msgs/Odometry) carries the pose of /tf at the same stamps, and no motion at rest.
  EXPECT_EQ(odom_frames_.first, prefix_ + "odom");
  EXPECT_EQ(odom_frames_.second, base_);
  std::size_t matched = 0;
  for (const TfSample& s : poses_) {
    const auto it = odom_poses_.find(s.stamp);
    if (it == odom_poses_.end())
      continue;
    ++matched;
    EXPECT_EQ(it->second.translation, s.pose.translation);
    EXPECT_NEAR(it->second.rotation.angularDistance(s.pose.rotation), 0.0, 1e-15);
  }
  EXPECT_GT(matched, 100u) << "odom and /tf share too few stamps";
  EXPECT_LE(max_odom_speed_, tolerance);
  for (int i = 0; i < 36; ++i) {
    EXPECT_EQ(odom_twist_covariance_[i], i % 7 == 0 ? odom_twist_variance_ : 0.0) << i;
    EXPECT_EQ(odom_pose_covariance_[i], 0.0) << i;  // ~variance/odom_pose left at 0
  }
  ASSERT_FALSE(imu_points_.empty()) << "the .test file lists no imu_points to check";
  // Each IMU reads the specific force of gravity in its frame, which is parallel to base_link:
  // R^T (0, 0, g0) with R the static attitude, the hull's orientation and no rotation rate.
  const Vector3 gravity_reading = specificForce(expected.rotation, Vector3::Zero());
  EXPECT_NEAR(gravity_reading.z(), kStandardGravity, 1e-3);
  for (const std::string& name : imu_points_) {
    ASSERT_EQ(last_imu_.count(name), 1u) << "nothing on imu/" << name;
    const sensor_msgs::Imu& imu = last_imu_[name];
    EXPECT_EQ(imu.header.frame_id, prefix_ + name);
    EXPECT_NEAR((fromMsg(imu.linear_acceleration) - gravity_reading).norm(), 0.0, 1e-6) << name;
    EXPECT_NEAR(fromMsg(imu.angular_velocity).norm(), 0.0, tolerance) << name;
    EXPECT_NEAR(fromMsg(imu.orientation).angularDistance(expected.rotation), 0.0, tolerance)
        << name;
    for (int i = 0; i < 9; ++i) {
      EXPECT_EQ(imu.linear_acceleration_covariance[i],
                i % 4 == 0 ? imu_acceleration_variance_ : 0.0)
          << name << " " << i;
      EXPECT_EQ(imu.orientation_covariance[i], 0.0) << name << " " << i;
    }
  }

  // The comfort metrics are stamped in the frame of the point they are taken at.
  EXPECT_EQ(comfort_frame_, prefix_ + "crew_seat");

  // Diagnostics: every task reports; the model is described.
  ASSERT_TRUE(test::spinUntil([&] { return diagnostics_.has(": model"); }, 5.0));
  EXPECT_TRUE(diagnostics_.has(": loop"));
  EXPECT_TRUE(diagnostics_.has(": terrain"));
  EXPECT_TRUE(diagnostics_.has(": speed"));
  EXPECT_GT(diagnostics_.value(": model", "reduced DOFs"), 0.0);
  // At rest the contacts carry the vehicle, symmetric left and right, and none pressed at rest
  // pulls: the ground-contact check reports the model in range.
  ASSERT_TRUE(test::spinUntil([&] { return diagnostics_.has(": ground contact"); }, 5.0));
  EXPECT_EQ(diagnostics_.level(": ground contact"), 0) << diagnostics_.describe();
  EXPECT_GT(diagnostics_.value(": ground contact", "contacts"), 0.0);
  EXPECT_EQ(diagnostics_.value(": ground contact", "pulling now"), 0.0);
  EXPECT_EQ(diagnostics_.value(": ground contact",
                               "checks beyond the range (since the last start or reset)"),
            0.0);
  EXPECT_GT(diagnostics_.value(": ground contact", "checks (since last report)"), 0.0);
  // The rate the checks run at, every round(rate / requested) steps of the 1 kHz loop; the
  // requested one beside it only when they differ (default 50 Hz divides 1000).
  const double requested = private_nh_.param("node_ground_contact_rate", 50.0);
  const double every = std::round(1000.0 / requested);
  EXPECT_NEAR(diagnostics_.value(": ground contact", "check rate [Hz]"), 1000.0 / every, 1e-3);
  if (1000.0 / every != requested)
    EXPECT_NEAR(diagnostics_.value(": ground contact", "check rate requested [Hz]"), requested,
                1e-9);
  else
    EXPECT_TRUE(std::isnan(diagnostics_.value(": ground contact", "check rate requested [Hz]")));
  // Nothing pressed at rest pulls, so no total pull; its share of the weight is shown beside it.
  EXPECT_EQ(
      diagnostics_.value(": ground contact",
                         "largest total pull of contacts pressed at rest (since last report) [N]"),
      0.0);
  EXPECT_EQ(
      diagnostics_.value(": ground contact",
                         "largest total pull (since last report) [% of the ground force at rest]"),
      0.0);
  // The pads (soles grouped by track assembly): none pressed at rest pulls as a whole.
  EXPECT_GT(diagnostics_.value(": ground contact", "pads"), 0.0);
  EXPECT_EQ(diagnostics_.value(": ground contact", "pads pulling now"), 0.0);
  EXPECT_GT(diagnostics_.value(": ground contact",
                               "min force of a pad pressed at rest (since last report) [N]"),
            0.0);
  EXPECT_EQ(diagnostics_.value(": ground contact",
                               "checks with a pad pulling (since the last start or reset)"),
            0.0);
  const double left = diagnostics_.value(": ground contact", "ground force left now [N]");
  const double right = diagnostics_.value(": ground contact", "ground force right now [N]");
  EXPECT_GT(left, 0.0);
  EXPECT_NEAR(left, right, 1e-6 * left);
}

TEST_F(NodeStatic, APatchInAnotherFrameIsTakenAndWarnedAbout) {
  ASSERT_TRUE(test::spinUntil([&] { return diagnostics_.has(": terrain"); }, 45.0));
  EXPECT_EQ(diagnostics_.value(": terrain", "patches in another frame (total)"), 0.0)
      << diagnostics_.describe();
  // Its own odom frame with a leading '/' (tf1 style), and odom without ~frame_prefix (a source
  // that knows of no prefix): taken, not counted (the count below is exactly the one patch).
  for (const std::string& frame : {"/" + prefix_ + "odom", std::string("odom")}) {
    TerrainProfile own = test::flatProfile(-20.0, 20.0);
    own.header.frame_id = frame;
    terrain_pub_.publish(own);
    test::spinFor(0.2);
  }
  // Another vehicle's path frame (or map): the stations are taken as this vehicle's all the same.
  TerrainProfile other = test::flatProfile(-20.0, 20.0);
  other.header.frame_id = "veh2/odom";
  terrain_pub_.publish(other);
  ASSERT_TRUE(test::spinUntil(
      [&] { return diagnostics_.value(": terrain", "patches in another frame (total)") == 1.0; },
      10.0))
      << diagnostics_.describe();
  EXPECT_EQ(diagnostics_.level(": terrain"), 1) << diagnostics_.describe();
  EXPECT_EQ(diagnostics_.text(": terrain", "last patch in another frame"),
            "patch at x = -20 m in frame 'veh2/odom', not '" + prefix_ + "odom'");
  EXPECT_GE(diagnostics_.value(": terrain", "patches accepted (total)"), 3.0);
  // The WARN lasts while the latest patch is in another frame, reports with no new patch
  // included (a source sending a patch every few periods must not flicker between WARN and OK)...
  const std::size_t arrays = diagnostics_.arrays();
  ASSERT_TRUE(test::spinUntil([&] { return diagnostics_.arrays() >= arrays + 3; }, 10.0));
  EXPECT_EQ(diagnostics_.level(": terrain"), 1) << diagnostics_.describe();
  EXPECT_EQ(diagnostics_.message(": terrain"),
            "patches in another frame than " + prefix_ +
                "odom: taken as stations along this vehicle's path");
  // ... and ends with the next patch in its own frame.
  TerrainProfile own = test::flatProfile(-20.0, 20.0);
  own.header.frame_id = prefix_ + "odom";
  terrain_pub_.publish(own);
  ASSERT_TRUE(test::spinUntil(
      [&] {
        return diagnostics_.value(": terrain", "patches accepted (total)") >= 4.0 &&
               diagnostics_.level(": terrain") == 0;
      },
      10.0))
      << diagnostics_.describe();
  EXPECT_EQ(diagnostics_.value(": terrain", "patches in another frame (total)"), 1.0);
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "node_static_test");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
