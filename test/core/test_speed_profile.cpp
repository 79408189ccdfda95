// A speed varying in time and its travelled station (dynamics/speed_profile.h, speed_profile_io.h).
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>

#include "tracked_vehicle_dynamics/dynamics/speed_profile.h"
#include "tracked_vehicle_dynamics/dynamics/speed_profile_io.h"
#include "tracked_vehicle_dynamics/error.h"

namespace tvd = tracked_vehicle_dynamics;
using tvd::dynamics::SpeedProfile;

namespace {

// Cruise at 10 m/s, brake at 2 m/s^2 to 2 m/s, then at 1 m/s^2 to a stop, then stand.
SpeedProfile cruiseAndBrake() {
  return SpeedProfile({0.0, 2.0, 6.0, 8.0}, {10.0, 10.0, 2.0, 0.0});
}

std::string messageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const tvd::InputError& e) {
    return e.what();
  }
  return "(no error)";
}

class ProfileFile {
 public:
  explicit ProfileFile(const std::string& text)
      : path_((std::filesystem::temp_directory_path() /
               ("tvd_speed_profile_" + std::to_string(::getpid()) + ".csv"))
                  .string()) {
    std::ofstream(path_) << text;
  }
  ~ProfileFile() { std::filesystem::remove(path_); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace

// s(t) in closed form, segment by segment: s = s_k + v_k tau + a_k tau^2 / 2.
TEST(SpeedProfile, StationIsTheExactIntegralOfThePiecewiseLinearSpeed) {
  const SpeedProfile p = cruiseAndBrake();
  EXPECT_DOUBLE_EQ(p.station(0.0), 0.0);
  EXPECT_DOUBLE_EQ(p.station(1.0), 10.0);
  EXPECT_DOUBLE_EQ(p.station(2.0), 20.0);
  EXPECT_NEAR(p.station(4.0), 20.0 + 10.0 * 2.0 - 2.0 * 2.0 * 2.0 / 2.0, 1e-12);  // 36 m
  EXPECT_NEAR(p.station(6.0), 44.0, 1e-12);
  EXPECT_NEAR(p.station(7.0), 44.0 + 2.0 - 0.5, 1e-12);
  EXPECT_NEAR(p.station(8.0), 46.0, 1e-12);
  EXPECT_NEAR(p.station(10.0), 46.0, 1e-12);  // speed held at 0 after the last sample
  EXPECT_DOUBLE_EQ(p.speed(4.0), 6.0);
  EXPECT_DOUBLE_EQ(p.speed(7.0), 1.0);
  EXPECT_DOUBLE_EQ(p.speed(12.0), 0.0);
  EXPECT_DOUBLE_EQ(p.endTime(), 8.0);
  EXPECT_DOUBLE_EQ(p.maxSpeed(), 10.0);
  // ds/dt = v everywhere (central differences are exact for the quadratic s).
  for (double t = 0.05; t < 9.0; t += 0.1) {
    const double h = 1e-4;
    EXPECT_NEAR((p.station(t + h) - p.station(t - h)) / (2 * h), p.speed(t), 1e-6) << t;
  }
}

TEST(SpeedProfile, AccelerationIsTheExactDerivativeOfTheSpeed) {
  const SpeedProfile p = cruiseAndBrake();  // 10 m/s to 2 s, -2 m/s^2 to 6 s, -1 m/s^2 to 8 s
  EXPECT_EQ(p.acceleration(0.0), 0.0);
  EXPECT_EQ(p.acceleration(1.999), 0.0);
  EXPECT_EQ(p.acceleration(2.0), -2.0);  // right-continuous: the next segment's at a sample
  EXPECT_EQ(p.acceleration(5.0), -2.0);
  EXPECT_EQ(p.acceleration(6.0), -1.0);
  EXPECT_EQ(p.acceleration(8.0), 0.0);  // speed held after the last sample
  EXPECT_EQ(p.acceleration(20.0), 0.0);
  // dv/dt = a inside every segment.
  for (double t = 0.05; t < 9.0; t += 0.1) {
    const double h = 1e-4;
    if (std::abs(t - 2.0) < 2 * h || std::abs(t - 6.0) < 2 * h || std::abs(t - 8.0) < 2 * h)
      continue;
    EXPECT_NEAR((p.speed(t + h) - p.speed(t - h)) / (2 * h), p.acceleration(t), 1e-9) << t;
  }
}

TEST(SpeedProfile, LargestAccelerationAndWhere) {
  double at = -1.0;
  EXPECT_EQ(cruiseAndBrake().maxAbsAcceleration(&at), 2.0);  // the -2 m/s^2 braking from 2 s
  EXPECT_EQ(at, 2.0);
  EXPECT_EQ(SpeedProfile({0.0, 5.0}, {3.0, 3.0}).maxAbsAcceleration(), 0.0);
  // 30 km/h within a millisecond: 8333 m/s^2, a profile in ms read as s.
  EXPECT_NEAR(SpeedProfile({0.0, 1.0, 1.001}, {0.0, 0.0, 30.0 / 3.6}).maxAbsAcceleration(&at),
              30.0 / 3.6 / 0.001, 1e-6);
  EXPECT_EQ(at, 1.0);
}

TEST(SpeedProfile, RejectsBadSamplesByIndex) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(messageOf([] {
              SpeedProfile({0.0, 1.0}, {1.0}, "p");
            }).find("2 times but 1 speeds"),
            std::string::npos);
  EXPECT_NE(messageOf([] { SpeedProfile({0.0}, {1.0}, "p"); }).find("at least two samples"),
            std::string::npos);
  EXPECT_NE(messageOf([] {
              SpeedProfile({0.5, 1.0}, {1.0, 1.0}, "p");
            }).find("sample 0: the first time must be 0"),
            std::string::npos);
  EXPECT_NE(messageOf([] {
              SpeedProfile({0.0, 1.0, 1.0}, {1.0, 1.0, 1.0}, "p");
            }).find("sample 2: time 1 s is not after"),
            std::string::npos);
  EXPECT_NE(messageOf([] {
              SpeedProfile({0.0, 1.0}, {1.0, -2.0}, "p");
            }).find("sample 1: speed -2 m/s is negative"),
            std::string::npos);
  EXPECT_NE(messageOf([&] {
              SpeedProfile({0.0, 1.0}, {nan, 1.0}, "p");
            }).find("p: sample 0: speed is not a finite"),
            std::string::npos);
}

TEST(SpeedProfile, LoadsCsvInKilometresPerHourOrMetresPerSecond) {
  {
    const ProfileFile f("# braking\ntime_s,speed_kmh\n0,36\n\n2,36\n6,7.2\n8,0\n");
    const SpeedProfile p = tvd::dynamics::loadSpeedProfile(f.path());
    EXPECT_NEAR(p.station(6.0), 44.0, 1e-12);  // cruiseAndBrake() in km/h
    EXPECT_NEAR(p.speed(4.0), 6.0, 1e-12);
  }
  {
    const ProfileFile f("time_s,speed_m_s\n0,10\n2,10\n6,2\n8,0\n");
    EXPECT_NEAR(tvd::dynamics::loadSpeedProfile(f.path()).station(7.0), 45.5, 1e-12);
  }
  {  // As a spreadsheet saves it: a UTF-8 byte-order mark and CR-LF line ends.
    const ProfileFile f("\xEF\xBB\xBFtime_s,speed_m_s\r\n0,10\r\n2,10\r\n6,2\r\n8,0\r\n");
    EXPECT_NEAR(tvd::dynamics::loadSpeedProfile(f.path()).station(7.0), 45.5, 1e-12);
  }
}

TEST(SpeedProfile, RejectsBadFilesNamingTheRow) {
  const auto load = [](const std::string& text) {
    const ProfileFile f(text);
    return messageOf([&] { tvd::dynamics::loadSpeedProfile(f.path()); });
  };
  EXPECT_NE(
      load("time_s,speed_mph\n0,1\n1,1\n").find("row 1: expected the header time_s,speed_kmh"),
      std::string::npos);
  EXPECT_NE(load("time_s,speed_kmh\n0,1\n1,-1\n").find("row 3, column 2: speed -1 is negative"),
            std::string::npos);
  EXPECT_NE(load("time_s,speed_kmh\n0,1\n1\n").find("row 3: expected 2 columns"),
            std::string::npos);
  EXPECT_NE(load("time_s,speed_kmh\n0,1\nx,1\n").find("row 3, column 1: time 'x' is not a number"),
            std::string::npos);
  EXPECT_NE(
      load("time_s,speed_kmh\n0,1\n2,1\n1,1\n").find("row 4, column 1: time 1 s is not after"),
      std::string::npos);
  EXPECT_NE(load("time_s,speed_kmh\n0,1\n").find("at least two samples"), std::string::npos);
  EXPECT_NE(load("").find("empty"), std::string::npos);
  EXPECT_NE(messageOf([] {
              tvd::dynamics::loadSpeedProfile("/nonexistent/profile.csv");
            }).find("file not found"),
            std::string::npos);
}
