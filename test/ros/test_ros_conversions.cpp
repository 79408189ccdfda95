// ROS-layer conversions without a master: message round trips (core -> msg -> core), the frame
// kinematics and its inverse, its rates and the accelerometer reading, bag save -> load of a track
// bag, the duration statistics, and the parameter names of a method and a hold.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>

#include <unistd.h>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/ros/conversions.h"
#include "tracked_vehicle_dynamics/ros/node_parameters.h"
#include "tracked_vehicle_dynamics/ros/online_names.h"
#include "tracked_vehicle_dynamics/ros/track_bag.h"
#include "tracked_vehicle_dynamics/terrain/iso8608.h"
#include "tracked_vehicle_dynamics/terrain/terrain_buffer.h"
#include "tracked_vehicle_dynamics/terrain/terrain_io.h"
#include "tracked_vehicle_dynamics/terrain/tracks.h"

using namespace tracked_vehicle_dynamics;
using namespace tracked_vehicle_dynamics::ros_layer;

namespace {

constexpr double kRoundTrip = 1e-12;  // pose <-> displacement, rotations of ~0.1 rad

TerrainPatch randomPatch(int lines, int samples, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> h(-0.3, 0.3);
  TerrainPatch p;
  p.start_station = -3.25;
  p.spacing = 0.02;
  p.lateral = Vector::LinSpaced(lines, -2.0, 2.0);
  p.heights.resize(lines, samples);
  for (int j = 0; j < lines; ++j)
    for (int k = 0; k < samples; ++k)
      p.heights(j, k) = h(rng);
  return p;
}

std::string temporaryPath(const std::string& name) {
  return "/tmp/tvd_test_" + std::to_string(::getpid()) + "_" + name;
}

// The message of the InputError `f` throws; a test failure when it throws none.
template <typename F>
std::string inputErrorOf(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

}  // namespace

TEST(TerrainProfileConversion, RoundTripIsExact) {
  const TerrainPatch patch = randomPatch(5, 37, 1);
  TerrainProfile msg;
  toMsg(patch, &msg);
  ASSERT_EQ(msg.samples, 37u);
  ASSERT_EQ(msg.lateral.size(), 5u);
  ASSERT_EQ(msg.heights.size(), 5u * 37u);
  // Row-major: line j, sample k at j * samples + k.
  EXPECT_EQ(msg.heights[2 * 37 + 11], patch.heights(2, 11));
  const TerrainPatch back = fromMsg(msg);
  EXPECT_EQ(back.start_station, patch.start_station);
  EXPECT_EQ(back.spacing, patch.spacing);
  EXPECT_EQ(back.lateral, patch.lateral);
  EXPECT_EQ(back.heights, patch.heights);
}

TEST(TerrainProfileConversion, MismatchedSizesAreRejectedNamingTheField) {
  TerrainProfile msg;
  toMsg(randomPatch(3, 10, 2), &msg);
  msg.heights.pop_back();
  try {
    fromMsg(msg);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("heights"), std::string::npos) << e.what();
  }
  msg.heights.push_back(0.0);
  msg.samples = 0;
  EXPECT_THROW(fromMsg(msg), InputError);
  msg.samples = 10;
  msg.lateral.clear();
  EXPECT_THROW(fromMsg(msg), InputError);
}

TEST(RoadWheelsConversion, RoundTrip) {
  std::vector<WheelState> wheels(3);
  for (int i = 0; i < 3; ++i) {
    wheels[i].name = "road_wheel_left_" + std::to_string(i + 1);
    wheels[i].displacement = 0.01 * i - 0.003;
    wheels[i].velocity = -0.2 * i;
    wheels[i].acceleration = 3.5 * i + 0.1;
  }
  RoadWheels msg;
  toMsg(wheels, 12.5, 8.25, &msg);
  double station = 0.0, speed = 0.0;
  const std::vector<WheelState> back = fromMsg(msg, &station, &speed);
  EXPECT_EQ(station, 12.5);
  EXPECT_EQ(speed, 8.25);
  ASSERT_EQ(back.size(), wheels.size());
  for (std::size_t i = 0; i < wheels.size(); ++i) {
    EXPECT_EQ(back[i].name, wheels[i].name);
    EXPECT_EQ(back[i].displacement, wheels[i].displacement);
    EXPECT_EQ(back[i].velocity, wheels[i].velocity);
    EXPECT_EQ(back[i].acceleration, wheels[i].acceleration);
  }
}

// With ~frame_prefix the wheel names are the tf frame ids (RoadWheelState.name: "wheel frame id"),
// also when the message is reused with another prefix or without one.
TEST(RoadWheelsConversion, NamesCarryTheFramePrefix) {
  std::vector<WheelState> wheels(2);
  wheels[0].name = "road_wheel_left_1";
  wheels[1].name = "road_wheel_right_1";
  RoadWheels msg;
  toMsg(wheels, 0.0, 0.0, &msg, "car1/");
  ASSERT_EQ(msg.wheels.size(), 2u);
  EXPECT_EQ(msg.wheels[0].name, "car1/road_wheel_left_1");
  EXPECT_EQ(msg.wheels[1].name, "car1/road_wheel_right_1");
  toMsg(wheels, 0.0, 0.0, &msg, "car1/");
  EXPECT_EQ(msg.wheels[0].name, "car1/road_wheel_left_1");
  toMsg(wheels, 0.0, 0.0, &msg, "car2/");
  EXPECT_EQ(msg.wheels[1].name, "car2/road_wheel_right_1");
  toMsg(wheels, 0.0, 0.0, &msg);
  EXPECT_EQ(msg.wheels[0].name, "road_wheel_left_1");
}

TEST(ComfortConversion, RoundTripWithAndWithoutAbsorbedPower) {
  ComfortReport report;
  report.point = "crew_seat";
  report.metrics.weighted_rms = 0.42;
  report.metrics.vdv = 1.7;
  report.metrics.mtvv = 0.9;
  report.metrics.mtvv_linear = 0.95;
  report.metrics.peak_weighted = 1.3;
  report.metrics.duration = 4.25;
  report.metrics.samples = 4250;
  report.running_rms = 0.33;
  report.running_rms_time = 1.0;
  report.peak_acceleration = 5.5;
  report.weighted_rms_x = 0.11;
  report.weighted_rms_y = 0.12;
  report.vibration_total_value = 0.47;
  report.weighted_rms_roll = 0.21;
  report.weighted_rms_pitch = 0.22;
  report.weighted_rms_yaw = 0.23;
  report.rotational_total_value = 0.17;
  report.seat_surface_total_value = 0.5;
  for (bool with_power : {false, true}) {
    if (with_power)
      report.metrics.absorbed_power = 2.5;
    Comfort msg;
    toMsg(report, &msg);
    EXPECT_EQ(msg.weighting, "Wk");
    EXPECT_EQ(msg.has_absorbed_power, with_power);
    const ComfortReport back = fromMsg(msg);
    EXPECT_EQ(back.point, report.point);
    EXPECT_EQ(back.metrics.weighted_rms, report.metrics.weighted_rms);
    EXPECT_EQ(back.metrics.vdv, report.metrics.vdv);
    EXPECT_EQ(back.metrics.mtvv, report.metrics.mtvv);
    EXPECT_EQ(back.metrics.mtvv_linear, report.metrics.mtvv_linear);
    EXPECT_EQ(back.metrics.peak_weighted, report.metrics.peak_weighted);
    EXPECT_EQ(back.metrics.absorbed_power, report.metrics.absorbed_power);
    EXPECT_EQ(back.metrics.duration, report.metrics.duration);
    EXPECT_EQ(back.metrics.samples, report.metrics.samples);
    EXPECT_EQ(back.running_rms, report.running_rms);
    EXPECT_EQ(back.running_rms_time, report.running_rms_time);
    EXPECT_EQ(back.peak_acceleration, report.peak_acceleration);
    EXPECT_EQ(back.weighted_rms_x, report.weighted_rms_x);
    EXPECT_EQ(back.weighted_rms_y, report.weighted_rms_y);
    EXPECT_EQ(back.vibration_total_value, report.vibration_total_value);
    EXPECT_EQ(back.weighted_rms_roll, report.weighted_rms_roll);
    EXPECT_EQ(back.weighted_rms_pitch, report.weighted_rms_pitch);
    EXPECT_EQ(back.weighted_rms_yaw, report.weighted_rms_yaw);
    EXPECT_EQ(back.rotational_total_value, report.rotational_total_value);
    EXPECT_EQ(back.seat_surface_total_value, report.seat_surface_total_value);
  }
}

// The report of a seat meter: the vertical meter's metrics, each axis and the totals.
TEST(ComfortConversion, ReportOfASeatMeterCarriesEveryAxis) {
  dynamics::SeatComfortMeter meter(1000.0);
  for (int k = 0; k < 3000; ++k) {
    const double t = k * 1e-3;
    meter.add({0.5 * std::sin(2.0 * t), 0.3 * std::sin(5.0 * t), std::sin(30.0 * t),
               0.2 * std::sin(7.0 * t), 0.4 * std::sin(9.0 * t), 0.1 * std::sin(4.0 * t)});
  }
  const ComfortReport r = comfortReport(meter, "crew_seat", 1.0, 9.0);
  EXPECT_EQ(r.point, "crew_seat");
  EXPECT_EQ(r.metrics.weighted_rms, meter.vertical().weightedRms());
  EXPECT_EQ(r.metrics.absorbed_power, meter.vertical().absorbedPower());
  EXPECT_EQ(r.running_rms, meter.vertical().runningRms());
  EXPECT_EQ(r.peak_acceleration, 9.0);
  EXPECT_EQ(r.weighted_rms_x, meter.longitudinal().weightedRms());
  EXPECT_EQ(r.weighted_rms_y, meter.lateral().weightedRms());
  EXPECT_EQ(r.weighted_rms_roll, meter.roll().weightedRms());
  EXPECT_EQ(r.weighted_rms_pitch, meter.pitch().weightedRms());
  EXPECT_EQ(r.weighted_rms_yaw, meter.yaw().weightedRms());
  EXPECT_EQ(r.vibration_total_value, meter.translationalTotalValue());
  EXPECT_EQ(r.rotational_total_value, meter.rotationalTotalValue());
  EXPECT_EQ(r.seat_surface_total_value, meter.seatSurfaceTotalValue());
  EXPECT_GT(r.rotational_total_value, 0.0);
  EXPECT_GT(r.weighted_rms_y, 0.0);
}

TEST(TransformConversion, RoundTrip) {
  RigidPose pose;
  pose.translation = Vector3(1.5, -0.25, 0.125);
  pose.rotation = rotationFromRollPitchYaw(0.1, -0.05, 0.02);
  geometry_msgs::Transform msg;
  toMsg(pose, &msg);
  const RigidPose back = fromMsg(msg);
  EXPECT_EQ(back.translation, pose.translation);
  EXPECT_TRUE(back.rotation.isApprox(pose.rotation, 1e-15));
}

TEST(VehicleFrames, HullPoseAndItsInverse) {
  const Vector3 cog(-0.1, 0.0, 1.57);
  Vector6 u;
  u << 0.002, -0.001, -0.08, 0.03, -0.12, 0.01;
  const RigidPose pose = hullPose(17.0, cog, u);
  // The CoG lands at (s, 0, 0) + p_G + u_G.
  const Vector3 cog_in_odom = pose.rotation * cog + pose.translation;
  EXPECT_NEAR((cog_in_odom - (Vector3(17.0, 0.0, 0.0) + cog + u.head<3>())).norm(), 0.0,
              kRoundTrip);
  const Vector3 rpy = rollPitchYaw(pose.rotation);
  EXPECT_NEAR((rpy - u.tail<3>()).norm(), 0.0, kRoundTrip);
  EXPECT_NEAR((hullDisplacement(17.0, cog, pose) - u).norm(), 0.0, kRoundTrip);
}

TEST(VehicleFrames, FootprintCarriesTheTravelAndBaseLinkTheRest) {
  // odom -> footprint = (s, 0, 0) unrotated; footprint -> base_link = relativeToPath(pose, s);
  // composed they give hullPose.
  Vector6 u;
  u << 0.002, -0.001, -0.08, 0.03, -0.12, 0.01;
  const Vector3 cog(-0.1, 0.0, 1.57);
  const RigidPose pose = hullPose(42.5, cog, u);
  const RigidPose above = relativeToPath(pose, 42.5);
  EXPECT_EQ(above.rotation.coeffs(), pose.rotation.coeffs());
  EXPECT_EQ(above.translation + Vector3(42.5, 0.0, 0.0), pose.translation);
  // ... and is the pose at station 0.
  EXPECT_NEAR((above.translation - hullPose(0.0, cog, u).translation).norm(), 0.0, 1e-14);
}

TEST(VehicleFrames, PitchNoseDownLowersTheFrontPoints) {
  // REP-103: positive pitch (about +y) turns +x towards -z.
  Vector6 u = Vector6::Zero();
  u(4) = 0.01;
  const Vector3 cog(0.0, 0.0, 1.0);
  EXPECT_LT(hullPointDisplacement(cog, u, Vector3(2.0, 0.0, 1.0)).z(), 0.0);
  // A point rigid with the hull stays where it is in base_link.
  const Vector3 p(2.0, 0.5, 1.5);
  const Vector3 rigid = hullPointDisplacement(cog, u, p);
  EXPECT_NEAR((relativePosition(cog, u, p, rigid) - p).norm(), 0.0, 1e-15);
}

TEST(PoseConversion, RoundTrip) {
  RigidPose pose;
  pose.translation = Vector3(-3.5, 0.75, 1.125);
  pose.rotation = rotationFromRollPitchYaw(-0.2, 0.07, 0.3);
  geometry_msgs::Pose msg;
  toMsg(pose, &msg);
  const RigidPose back = fromMsg(msg);
  EXPECT_EQ(back.translation, pose.translation);
  EXPECT_EQ(back.rotation.coeffs(), pose.rotation.coeffs());
}

// theta(t) = theta + theta' t about a state with every angle non-zero, so that the Euler-rate
// matrix differs from the identity by far more than the tolerance.
class VehicleFrameRates : public ::testing::Test {
 protected:
  VehicleFrameRates() {
    u_ << 0.01, -0.02, -0.08, 0.15, -0.25, 0.3;
    du_ << 0.3, -0.1, 0.7, 0.9, -1.3, 0.4;
    ddu_ << -2.0, 1.5, 30.0, 12.0, -25.0, 4.0;
  }
  Vector6 at(double t) const { return u_ + t * du_; }
  /// With the acceleration as well: u + t u' + t^2/2 u''.
  Vector6 accelerated(double t) const { return u_ + t * du_ + 0.5 * t * t * ddu_; }
  static constexpr double kStep = 1e-5;        // central differences [s]
  static constexpr double kDifference = 1e-8;  // O(kStep^2) and rounding / kStep
  const Vector3 cog_ = Vector3(-0.1, 0.02, 1.57);
  const double station_ = 17.0, speed_ = 8.5;
  Vector6 u_, du_, ddu_;
};

TEST_F(VehicleFrameRates, BodyRateIsTheRotationsDerivative) {
  // R^T R' = [omega_b]x for the rotation of the Euler angles theta(t).
  const auto rotation = [&](double t) {
    const Vector6 u = at(t);
    return rotationFromRollPitchYaw(u(3), u(4), u(5)).toRotationMatrix();
  };
  const Matrix3 derivative = (rotation(kStep) - rotation(-kStep)) / (2.0 * kStep);
  const Matrix3 skew = rotation(0.0).transpose() * derivative;
  const Vector3 omega(skew(2, 1), skew(0, 2), skew(1, 0));
  EXPECT_NEAR((bodyRate(u_.tail<3>(), du_.tail<3>()) - omega).norm(), 0.0, kDifference);
  // Not simply theta' at these angles.
  EXPECT_GT((bodyRate(u_.tail<3>(), du_.tail<3>()) - du_.tail<3>()).norm(), 0.1);
  // Level: the body rate is the Euler rate.
  EXPECT_EQ(bodyRate(Vector3::Zero(), du_.tail<3>()), Vector3(du_.tail<3>()));
}

TEST_F(VehicleFrameRates, BaseLinkTwistIsThePosesDerivative) {
  const auto pose = [&](double t) { return hullPose(station_ + speed_ * t, cog_, at(t)); };
  const Vector3 velocity =
      (pose(kStep).translation - pose(-kStep).translation) / (2.0 * kStep);  // odom axes
  const Vector6 twist = baseLinkTwist(speed_, cog_, u_, du_);
  const Eigen::Quaterniond r = pose(0.0).rotation;
  EXPECT_NEAR((r * Vector3(twist.head<3>()) - velocity).norm(), 0.0, kDifference);
  EXPECT_EQ(Vector3(twist.tail<3>()), bodyRate(u_.tail<3>(), du_.tail<3>()));
  // At rest: only the travel speed, along base_link's own axes.
  const Vector6 level = baseLinkTwist(speed_, cog_, Vector6::Zero(), Vector6::Zero());
  EXPECT_EQ(Vector3(level.head<3>()), Vector3(speed_, 0.0, 0.0));
  EXPECT_EQ(Vector3(level.tail<3>()), Vector3::Zero());
}

TEST_F(VehicleFrameRates, BodyAccelerationIsTheBodyRatesDerivative) {
  const auto omega = [&](double t) {
    const Vector6 u = accelerated(t);
    return bodyRate(u.tail<3>(), (du_ + t * ddu_).tail<3>());
  };
  const Vector3 derivative = (omega(kStep) - omega(-kStep)) / (2.0 * kStep);
  const Vector3 alpha = bodyAcceleration(u_.tail<3>(), du_.tail<3>(), ddu_.tail<3>());
  EXPECT_NEAR((alpha - derivative).norm(), 0.0, 1e-6);
  EXPECT_GT((alpha - ddu_.tail<3>()).norm(), 0.5);  // the Euler-rate terms count here
}

TEST_F(VehicleFrameRates, RigidPointAccelerationIsItsPositionsSecondDerivative) {
  // A point rigid with the hull sits at t + R p in odom; at constant speed its second central
  // difference is the acceleration (O(step^2) plus rounding / step^2: a larger step).
  const double step = 1e-4;
  const Vector3 point(2.4, -0.6, 2.1);
  const auto position = [&](double t) {
    const RigidPose pose = hullPose(speed_ * t, cog_, accelerated(t));
    return Vector3(pose.rotation * point + pose.translation);
  };
  const Vector3 second = (position(step) - 2.0 * position(0.0) + position(-step)) / (step * step);
  const Vector3 a = rigidPointAcceleration(cog_, u_, du_, ddu_, point);
  EXPECT_NEAR((a - second).norm(), 0.0, 1e-5 * a.norm())
      << a.transpose() << " / " << second.transpose();
  // The linear model's u_G'' + theta'' x r is off by the centripetal and Euler-rate terms.
  const Vector3 linear = ddu_.head<3>() + ddu_.tail<3>().cross(point - cog_);
  EXPECT_GT((a - linear).norm(), 0.1 * a.norm());
}

TEST(VehicleFrames, SpecificForceIsWhatAnAccelerometerReads) {
  const double g = kStandardGravity;
  const double angle = 0.2;
  const auto reading = [](double roll, double pitch, const Vector3& a) {
    return specificForce(rotationFromRollPitchYaw(roll, pitch, 0.0), a);
  };
  // Level at rest: +g0 up.
  EXPECT_NEAR((reading(0.0, 0.0, Vector3::Zero()) - Vector3(0.0, 0.0, g)).norm(), 0.0, 1e-15);
  // Nose down (positive pitch, REP-103): gravity pulls along +x, the reading is -g0 sin(pitch).
  EXPECT_NEAR(
      (reading(0.0, angle, Vector3::Zero()) - g * Vector3(-std::sin(angle), 0.0, std::cos(angle)))
          .norm(),
      0.0, 1e-14);
  // Left side up (positive roll): +g0 sin(roll) along y.
  EXPECT_NEAR(
      (reading(angle, 0.0, Vector3::Zero()) - g * Vector3(0.0, std::sin(angle), std::cos(angle)))
          .norm(),
      0.0, 1e-14);
  // Free fall reads nothing, whatever the attitude; heaving up at 2 m/s^2 level reads g0 + 2.
  EXPECT_NEAR(reading(0.3, -0.2, Vector3(0.0, 0.0, -g)).norm(), 0.0, 1e-14);
  EXPECT_NEAR(reading(0.0, 0.0, Vector3(0.0, 0.0, 2.0)).z(), g + 2.0, 1e-14);
}

TEST(TrackBag, SaveLoadRoundTripAndCoverageAhead) {
  TrackBagOptions options;
  options.track = "long_hill";
  options.speed = 10.0;
  options.clock_rate = 100.0;
  const std::string path = temporaryPath("long_hill.bag");
  const TrackBagSummary summary = writeTrackBag(path, options);
  const TrackBagContent bag = readTrackBag(path);
  std::remove(path.c_str());

  ASSERT_EQ(bag.patches.size(), summary.patches);
  ASSERT_EQ(bag.speeds.size(), summary.speed_messages);
  ASSERT_EQ(bag.clocks.size(), summary.clock_messages);
  EXPECT_NEAR(summary.duration, (terrain::kTrackLength + options.behind) / options.speed, 1e-9);
  // Speeds at k / rate for k = 0 .. floor(T rate): the run's whole length [0, T] is commanded.
  EXPECT_EQ(summary.speed_messages,
            static_cast<std::size_t>(std::floor(summary.duration * options.speed_rate)) + 1);
  ASSERT_FALSE(bag.speeds.empty());
  EXPECT_GE((bag.speeds.back().first - ros::Time(options.start_time)).toSec(),
            summary.duration - 1.0 / options.speed_rate);
  for (const auto& [time, v] : bag.speeds)
    EXPECT_EQ(v, options.speed);
  // geometry_msgs/TwistStamped by default, each stamped at the bag time it is played at: the
  // node takes it at that time, whenever it arrives.
  ASSERT_EQ(bag.speed_stamps.size(), bag.speeds.size());
  for (std::size_t i = 0; i < bag.speeds.size(); ++i)
    EXPECT_EQ(bag.speed_stamps[i], bag.speeds[i].first) << i;

  // The patches, fed to a buffer in bag order, reproduce the track on its grid, and the buffer
  // holds `lookahead` ahead of the vehicle whenever a patch arrives.
  const terrain::Terrain track = terrain::makeTrack("long_hill");
  terrain::TerrainBuffer buffer;
  const ros::Time start(options.start_time);
  for (std::size_t i = 0; i < bag.patches.size(); ++i) {
    const auto& [time, patch] = bag.patches[i];
    buffer.addPatch(patch.start_station, patch.spacing, patch.lateral, patch.heights);
    EXPECT_EQ(patch.lateral, track.lateral());
    if (i + 1 < bag.patches.size() && bag.patches[i + 1].first == time)
      continue;
    // Everything of this instant is in: the vehicle has `lookahead` ahead of it.
    const double station = (time - start).toSec() * options.speed;
    EXPECT_GE(buffer.coveredUntil(), station + options.lookahead - 1e-9) << "t = " << time;
  }
  EXPECT_LE(buffer.coveredFrom(), -options.behind + 1e-9);
  EXPECT_GE(buffer.coveredUntil(), summary.end_station + options.lookahead - 1e-9);
  for (double x = -options.behind; x < summary.end_station; x += 0.137) {
    for (double y : {-1.555, -1.245, 0.0, 1.245, 1.555}) {
      ASSERT_NEAR(buffer.height(x, y), track.height(x, y), 1e-12) << "x = " << x << ", y = " << y;
    }
  }
}

// A terrain file (here an ISO 8608 road starting at station 12 m): the bag holds it with its
// first station at 0 and its lines shifted by the centre-line position, on its own grid.
TEST(TrackBag, TerrainFileIsShiftedToTheStartAndTheCentreLine) {
  const terrain::Terrain road = terrain::makeIso8608('C', 40.0, 5.0, 0.05, 3);
  const terrain::Terrain shifted(road.stations().array() + 12.0, road.lateral(), road.heights(),
                                 "road");
  const std::string file = temporaryPath("road.csv");
  terrain::saveTerrainCsv(shifted, file);
  TrackBagOptions options;
  options.track = file;
  options.speed = 8.0;
  options.lateral_offset = 0.4;
  const TrackRun run = trackRun(options);
  // The extent alone (tvd_make_bag --peak-speed): the same run, without its patches.
  const TrackRun extent = trackRunExtent(options);
  std::remove(file.c_str());
  EXPECT_NEAR(run.end_station, 40.0 + options.behind, 1e-9);
  EXPECT_TRUE(extent.patches.empty());
  EXPECT_FALSE(run.patches.empty());
  EXPECT_EQ(extent.end_station, run.end_station);
  EXPECT_EQ(extent.duration, run.duration);
  EXPECT_EQ(extent.covered_from, run.covered_from);
  EXPECT_EQ(extent.covered_until, run.covered_until);
  terrain::TerrainBuffer buffer;
  for (const TimedPatch& timed : run.patches) {
    EXPECT_DOUBLE_EQ(timed.patch.spacing, 0.05);
    buffer.addPatch(timed.patch.start_station, timed.patch.spacing, timed.patch.lateral,
                    timed.patch.heights);
  }
  for (double x = 0.0; x < 40.0; x += 0.173)
    for (double y : {-1.5, 0.0, 1.2})
      ASSERT_NEAR(buffer.height(x, y), shifted.height(x + 12.0, y + 0.4), 1e-12) << x << ", " << y;

  // A breakpoint file, uniform across the width (one line) with samples 15 m apart: every patch
  // is one sample, sent early enough that the terrain up to `lookahead` ahead is interpolable
  // whenever one arrives (sent at `lookahead` ahead, the first contacts past station 0 once had
  // none until the vehicle reached 5 m).
  const std::string coarse = temporaryPath("coarse.csv");
  {
    std::ofstream out(coarse);
    out << "x,h\n0,0\n15,0.2\n30,0\n";
  }
  TrackBagOptions sparse;
  sparse.track = coarse;
  sparse.speed = 5.0;
  const TrackRun coarse_run = trackRun(sparse);
  std::remove(coarse.c_str());
  // The invariant binds just before each later patch arrives: what was sent before it must
  // already reach `lookahead` beyond where the reference point then is.
  terrain::TerrainBuffer coarse_buffer;
  for (std::size_t i = 0; i < coarse_run.patches.size(); ++i) {
    const TimedPatch& timed = coarse_run.patches[i];
    EXPECT_EQ(timed.patch.heights.cols(), 1);
    EXPECT_DOUBLE_EQ(timed.patch.spacing, 15.0);
    if (i > 0 && timed.time > coarse_run.patches[i - 1].time) {
      EXPECT_GE(coarse_buffer.coveredUntil(), timed.time * sparse.speed + sparse.lookahead - 1e-9)
          << "just before t = " << timed.time;
    }
    coarse_buffer.addPatch(timed.patch.start_station, timed.patch.spacing, timed.patch.lateral,
                           timed.patch.heights);
  }

  options.track = "moon_craters";
  const std::string unknown = inputErrorOf([&] { trackRun(options); });
  EXPECT_NE(unknown.find("neither a built-in track (long_hill"), std::string::npos) << unknown;
}

// --speed-message float64: the unstamped std_msgs/Float64 on /speed, the same values and times
// as the stamped default on /speed_stamped.
TEST(TrackBag, Float64SpeedsOnSpeedCarryTheStampedOnesValues) {
  TrackBagOptions options;
  options.track = "separated_waves";
  options.speed_profile = dynamics::SpeedProfile({0.0, 2.0}, {4.0, 8.0});
  const std::string stamped_path = temporaryPath("stamped.bag");
  const std::string float_path = temporaryPath("float64.bag");
  writeTrackBag(stamped_path, options);
  options.speed_message = BagSpeedMessage::Float64;
  EXPECT_EQ(speedTopic(options), "/speed");
  writeTrackBag(float_path, options);
  const TrackBagContent stamped = readTrackBag(stamped_path, "/terrain_profile", "/speed_stamped");
  const TrackBagContent unstamped = readTrackBag(float_path, "/terrain_profile", "/speed");
  const TrackBagContent misread = readTrackBag(float_path, "/terrain_profile", "/speed_stamped");
  std::remove(stamped_path.c_str());
  std::remove(float_path.c_str());
  ASSERT_FALSE(stamped.speeds.empty());
  ASSERT_EQ(unstamped.speeds, stamped.speeds);
  EXPECT_TRUE(misread.speeds.empty());
  for (std::size_t i = 0; i < unstamped.speeds.size(); ++i) {
    EXPECT_TRUE(unstamped.speed_stamps[i].isZero()) << i;
    EXPECT_EQ(stamped.speed_stamps[i], stamped.speeds[i].first) << i;
  }
}

// A speed profile (brake from 10 to 2 m/s over the first 4 s, then hold): the run lasts until
// the station, the profile's exact integral, reaches the end; the speed messages carry v(t); and
// each patch is written when the reference point is `lookahead` and one spacing before it.
TEST(TrackBag, SpeedProfileMovesTheReferencePointByItsIntegral) {
  TrackBagOptions options;
  options.track = "long_hill";
  options.speed_profile = dynamics::SpeedProfile({0.0, 4.0}, {10.0, 2.0});
  const std::string path = temporaryPath("braking.bag");
  const TrackBagSummary summary = writeTrackBag(path, options);
  const TrackBagContent bag = readTrackBag(path);
  std::remove(path.c_str());
  // 24 m in the first 4 s, then 2 m/s to the end station.
  const double end_station = terrain::kTrackLength + options.behind;
  EXPECT_NEAR(summary.duration, 4.0 + (end_station - 24.0) / 2.0, 1e-9);
  const ros::Time start(options.start_time);
  for (const auto& [time, v] : bag.speeds) {
    const double t = (time - start).toSec();
    EXPECT_NEAR(v, t < 4.0 ? 10.0 - 2.0 * t : 2.0, 1e-9) << "t = " << t;
  }
  const TrackRun run = trackRun(options);
  for (const TimedPatch& timed : run.patches) {
    const double due = timed.patch.start_station - timed.patch.spacing - options.lookahead;
    if (due <= 0.0) {
      EXPECT_EQ(timed.time, 0.0);
    } else {
      EXPECT_NEAR(options.speed_profile->station(timed.time), due, 1e-9)
          << timed.patch.start_station;
    }
  }
  // A profile that stops short of the end ends the run with it.
  options.speed_profile = dynamics::SpeedProfile({0.0, 2.0, 3.0}, {5.0, 5.0, 0.0});
  EXPECT_NEAR(trackRun(options).duration, 3.0, 1e-12);
  // A crawl that would last months is refused by name, before anything is written.
  options.speed_profile = dynamics::SpeedProfile({0.0, 1.0}, {1e-5, 1e-5});
  const std::string crawl = inputErrorOf([&] { trackRun(options); });
  EXPECT_NE(crawl.find("use a shorter terrain or a higher speed"), std::string::npos) << crawl;
}

TEST(TrackBag, InvalidOptionsNameTheField) {
  TrackBagOptions options;
  options.speed = 0.0;
  const std::string message =
      inputErrorOf([&] { writeTrackBag(temporaryPath("never.bag"), options); });
  EXPECT_NE(message.find("speed"), std::string::npos) << message;
  // Above tvd simulate's 200 km/h, at constant speed or along a profile.
  options.speed = 200.0001 / 3.6;
  const std::string fast = inputErrorOf([&] { trackRun(options); });
  EXPECT_NE(fast.find("speed"), std::string::npos) << fast;
  EXPECT_NE(fast.find("200 km/h"), std::string::npos) << fast;
  options.speed = 200.0 / 3.6;
  EXPECT_NO_THROW(trackRun(options));
  options.speed_profile = dynamics::SpeedProfile({0.0, 1.0}, {10.0, 60.0});
  const std::string profile = inputErrorOf([&] { trackRun(options); });
  EXPECT_NE(profile.find("216 km/h"), std::string::npos) << profile;
  options.speed_profile.reset();
  // A run longer than 1e4 s (replayed in real time) is refused even when its messages are few:
  // 31 m at 1 mm/s without /clock is 3.1e4 s but 1.6e6 speed messages.
  options.speed = 1e-3;
  options.clock_rate = 0.0;
  const std::string slow = inputErrorOf([&] { trackRun(options); });
  EXPECT_NE(slow.find("at most 10000 s"), std::string::npos) << slow;
  EXPECT_EQ(inputErrorOf([&] { trackRunExtent(options); }), slow);  // checked the same way
  // So slow that s / v overflows (a denormal): refused, not a run of no time.
  options.speed = 1e-320 / 3.6;
  const std::string never = inputErrorOf([&] { trackRun(options); });
  EXPECT_NE(never.find("never ends"), std::string::npos) << never;
  options.speed = 5.0;
  // A bag starting at time 0 would be refused by rosbag itself ("less than ros::TIME_MIN"):
  // named here, as the option it is.
  options.start_time = 0.0;
  const std::string at_zero = inputErrorOf([&] { trackRun(options); });
  EXPECT_NE(at_zero.find("start_time"), std::string::npos) << at_zero;
  options.start_time = 1000.0;
  options.track = "moon_craters";
  EXPECT_THROW(writeTrackBag(temporaryPath("never.bag"), options), InputError);
}

TEST(NodeParameterNames, MethodAndHoldNamesParseBackToTheirValue) {
  for (const auto method : {dynamics::DiscretizationMethod::ModalDecoupled,
                            dynamics::DiscretizationMethod::AugmentedExponential})
    EXPECT_EQ(parseMethod(methodName(method), "method"), method);
  for (const auto hold : {dynamics::InputHold::FirstOrder, dynamics::InputHold::ZeroOrder})
    EXPECT_EQ(parseHold(holdName(hold), "hold"), hold);
  EXPECT_STREQ(methodName(dynamics::DiscretizationMethod::ModalDecoupled), "modal");
  EXPECT_STREQ(holdName(dynamics::InputHold::ZeroOrder), "zero_order");
  EXPECT_THROW(parseMethod("Modal", "method"), ParameterError);
  EXPECT_THROW(parseHold("first order", "hold"), ParameterError);
}

TEST(DurationStatistics, PercentilesOfAKnownDistribution) {
  DurationStatistics stats;
  EXPECT_EQ(stats.percentile(0.99), 0.0);
  for (int i = 1; i <= 1000; ++i)
    stats.add(i * 1e-6);  // 1 .. 1000 us
  EXPECT_EQ(stats.count(), 1000u);
  EXPECT_NEAR(stats.mean(), 500.5e-6, 1e-12);
  EXPECT_NEAR(stats.percentile(0.99), 990e-6, 1.01e-6);
  EXPECT_NEAR(stats.percentile(0.5), 500e-6, 1.01e-6);
  EXPECT_DOUBLE_EQ(stats.max(), 1000e-6);
  stats.add(1.0);  // overflow bin: the exact maximum
  EXPECT_DOUBLE_EQ(stats.percentile(1.0), 1.0);
  stats.clear();
  EXPECT_EQ(stats.count(), 0u);
  // A percentile is never below the samples it counts (a bin's upper edge, capped at the
  // maximum), and falls in the bin of the sample that reaches it.
  for (int i = 0; i < 100; ++i)
    stats.add(2.5e-6);
  EXPECT_EQ(stats.percentile(0.5), 2.5e-6);
  stats.clear();
  stats.add(1.5e-6);
  stats.add(5.5e-6);
  EXPECT_LE(stats.percentile(0.5), 2e-6);
  EXPECT_GE(stats.percentile(0.5), 1.5e-6);
  // Beyond 2 ms the bins grow by 1 %: ticks of 3..12 ms (catch-up under load) with one stall of
  // 0.17 s give a p99 within 1 % of the 99th sample, not the stall (it once did).
  stats.clear();
  for (int i = 1; i <= 1000; ++i)
    stats.add(3e-3 + 9e-3 * i / 1000.0);
  stats.add(0.167);
  const double p99 = stats.percentile(0.99);
  const double sample = 3e-3 + 9e-3 * 991 / 1000.0;  // the 991st of 1001 reaches 99 %
  EXPECT_GE(p99, sample);
  EXPECT_LE(p99, sample * 1.0101);
  EXPECT_DOUBLE_EQ(stats.percentile(1.0), 0.167);
  stats.add(10.0);  // beyond the last edge: the exact maximum
  EXPECT_DOUBLE_EQ(stats.percentile(1.0), 10.0);
}
