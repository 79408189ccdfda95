// Road inputs sampled from a terrain as the vehicle advances (dynamics/road_excitation.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <set>
#include <string>

#include "tracked_vehicle_dynamics/dynamics/road_excitation.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/terrain/terrain.h"
#include "tracked_vehicle_dynamics/terrain/terrain_lines.h"
#include "tracked_vehicle_dynamics/terrain/tracks.h"

namespace tvd = tracked_vehicle_dynamics;

namespace {
// h(x, y) = a x + b y on a grid: bilinear interpolation reproduces it exactly.
tvd::terrain::Terrain plane(double a, double b) {
  tvd::Vector x = tvd::Vector::LinSpaced(301, 0.0, 30.0);
  tvd::Vector y = tvd::Vector::LinSpaced(11, -2.5, 2.5);
  tvd::Matrix h(y.size(), x.size());
  for (int i = 0; i < y.size(); ++i)
    for (int j = 0; j < x.size(); ++j)
      h(i, j) = a * x(j) + b * y(i);
  return tvd::terrain::Terrain(x, y, h, "plane");
}
}  // namespace

TEST(RoadExcitation, SamplesEachInputAtItsOwnPosition) {
  const double a = 0.02, b = -0.01, speed = 8.0, station = 10.0, offset = 0.5;
  tvd::Vector xq(3), yq(3);
  xq << 2.0, 0.0, -2.0;
  yq << 1.4, -1.4, 0.3;
  const tvd::dynamics::RoadExcitation road(xq, yq, offset);
  tvd::Vector w;
  road.sample(plane(a, b), station, speed, w);
  ASSERT_EQ(w.size(), 6);
  for (int q = 0; q < 3; ++q) {
    EXPECT_NEAR(w(q), a * (station + xq(q)) + b * (yq(q) + offset), 1e-12) << q;
    EXPECT_NEAR(w(3 + q), speed * a, 1e-12) << q;  // u' = v dh/dx
  }
}

TEST(RoadExcitation, RejectsInconsistentInputs) {
  EXPECT_THROW(tvd::dynamics::RoadExcitation(tvd::Vector::Zero(3), tvd::Vector::Zero(2)),
               tvd::InputError);
  tvd::Vector bad = tvd::Vector::Zero(2);
  bad(1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(tvd::dynamics::RoadExcitation(bad, tvd::Vector::Zero(2)), tvd::InputError);
}

// A constant-speed series: row j is w at station s0 + v (first + j) dt, on the plane's closed
// form u = a x + b y, u' = v a.
TEST(RoadExcitation, SeriesFollowsTheStation) {
  const double a = 0.02, b = -0.01, speed = 8.0, s0 = 1.0, dt = 0.01;
  tvd::Vector xq(2), yq(2);
  xq << 1.5, -1.5;
  yq << 1.0, -1.0;
  const tvd::dynamics::RoadExcitation road(xq, yq);
  const tvd::Matrix w = road.sampleSeries(plane(a, b), s0, speed, dt, 7, 50);
  ASSERT_EQ(w.rows(), 50);
  ASSERT_EQ(w.cols(), 4);
  for (int j = 0; j < 50; ++j)
    for (int q = 0; q < 2; ++q) {
      EXPECT_NEAR(w(j, q), a * (s0 + speed * (7 + j) * dt + xq(q)) + b * yq(q), 1e-12) << j;
      EXPECT_NEAR(w(j, 2 + q), speed * a, 1e-12) << j;
    }
}

// A varying-speed series: row j is sample() at its own station and speed, so the rate column
// u' = v dh/dx follows the speed; at equal speeds it is the constant-speed series.
TEST(RoadExcitation, VaryingSpeedSeriesSamplesEachRowAtItsStationAndSpeed) {
  const double a = 0.02, b = -0.01;
  tvd::Vector xq(2), yq(2);
  xq << 1.5, -1.5;
  yq << 1.0, -1.0;
  const tvd::dynamics::RoadExcitation road(xq, yq);
  tvd::Vector stations(4), speeds(4);
  stations << 3.0, 3.3, 3.4, 3.42;
  speeds << 12.0, 6.0, 2.0, 0.0;
  const tvd::Matrix w = road.sampleSeries(plane(a, b), stations, speeds);
  ASSERT_EQ(w.rows(), 4);
  for (int j = 0; j < 4; ++j)
    for (int q = 0; q < 2; ++q) {
      EXPECT_NEAR(w(j, q), a * (stations(j) + xq(q)) + b * yq(q), 1e-12) << j;
      EXPECT_NEAR(w(j, 2 + q), speeds(j) * a, 1e-12) << j;
    }
  const double s0 = 3.0, speed = 8.0, dt = 0.01;
  tvd::Vector even(30);
  for (int j = 0; j < 30; ++j)
    even(j) = s0 + speed * (5 + j) * dt;
  // (Not bit for bit: the compiler may contract s0 + v k dt into an FMA in one place only.)
  EXPECT_LT((road.sampleSeries(plane(a, b), even, tvd::Vector::Constant(30, speed)) -
             road.sampleSeries(plane(a, b), s0, speed, dt, 5, 30))
                .cwiseAbs()
                .maxCoeff(),
            1e-15);
  EXPECT_THROW(road.sampleSeries(plane(a, b), stations, tvd::Vector::Zero(3)), tvd::InputError);
}

// Through TerrainLines (one combined height-and-slope lookup per input) the inputs equal those
// sampled from the terrain itself, and every row of a series equals sample() at its station.
TEST(RoadExcitation, TerrainLinesGiveTheTerrainsInputs) {
  const tvd::terrain::Terrain track = tvd::terrain::makeTrack("oop_waves");
  tvd::Vector xq(4), yq(4);
  xq << 2.4, 0.3, -0.9, -2.4;
  yq << 1.3, -1.3, 0.7, 0.0;
  const tvd::dynamics::RoadExcitation road(xq, yq, 1.0);
  const tvd::terrain::TerrainLines lines(track, road.inputY());
  const double speed = 30.0 / 3.6, dt = 1e-3, s0 = track.startStation();
  const tvd::Matrix series = road.sampleSeries(lines, s0, speed, dt, 0, 4000);
  tvd::Vector from_lines, from_terrain;
  for (long j = 0; j < series.rows(); j += 7) {
    const double station = s0 + speed * static_cast<double>(j) * dt;
    road.sample(lines, station, speed, from_lines);
    road.sample(track, station, speed, from_terrain);
    EXPECT_EQ((series.row(j).transpose() - from_lines).cwiseAbs().maxCoeff(), 0.0) << j;
    EXPECT_LT((from_lines - from_terrain).head(4).cwiseAbs().maxCoeff(), 1e-12) << j;
    EXPECT_LT((from_lines - from_terrain).tail(4).cwiseAbs().maxCoeff(), 1e-9 * speed) << j;
  }
  EXPECT_GT(series.leftCols(4).cwiseAbs().maxCoeff(), 0.1);  // the waves are under the inputs
}

// The held series (sampled only where the profile changes, contacts on identical profiles
// sharing a channel) is the dense series bit for bit: on the three test tracks, with a lateral
// offset, from a later first sample, and with an input off the lines (sampled every step).
TEST(RoadExcitation, HeldSeriesIsTheDenseSeriesBitForBit) {
  // Four contacts per station (left/right x inner/outer), five stations, as on a vehicle.
  const double stations[5] = {2.34, 1.56, 0.0, -1.56, -2.34};
  const double rows[4] = {1.6, 1.2, -1.2, -1.6};
  tvd::Vector xq(20), yq(20);
  for (int s = 0; s < 5; ++s)
    for (int r = 0; r < 4; ++r) {
      xq(4 * s + r) = stations[s];
      yq(4 * s + r) = rows[r];
    }
  for (const char* name : {"long_hill", "separated_waves", "oop_waves"}) {
    const tvd::terrain::Terrain track = tvd::terrain::makeTrack(name);
    for (const double offset : {0.0, 1.0}) {
      const tvd::dynamics::RoadExcitation road(xq, yq, offset);
      const tvd::terrain::TerrainLines lines(track, road.inputY());
      for (const double kmh : {5.0, 50.0}) {
        const double speed = kmh / 3.6, dt = 1e-3, s0 = track.startStation();
        const long count = static_cast<long>(std::ceil((track.endStation() - s0) / speed / dt)) + 1;
        for (const long first : {0L, 1234L}) {
          const tvd::Matrix dense = road.sampleSeries(lines, s0, speed, dt, first, count - first);
          const tvd::dynamics::HeldInputSeries held =
              road.sampleHeldSeries(lines, s0, speed, dt, first, count - first);
          ASSERT_NO_THROW(held.validate());
          const tvd::Matrix back = held.dense();
          ASSERT_EQ(back.rows(), dense.rows());
          EXPECT_EQ(std::memcmp(back.data(), dense.data(), sizeof(double) * dense.size()), 0)
              << name << " offset " << offset << " at " << kmh << " km/h from " << first
              << ": worst " << (back - dense).cwiseAbs().maxCoeff();
          // One channel pair per station and distinct profile: on a laterally uniform track
          // (the hill, the separated waves) the four pad rows are one profile.
          std::set<int> profiles;
          for (int r = 0; r < 4; ++r)
            profiles.insert(lines.profileOf(rows[r] + offset));
          if (std::string(name) != "oop_waves") {
            EXPECT_EQ(profiles.size(), 1u) << name;
          } else {
            EXPECT_GE(profiles.size(), 2u) << name;
          }
          EXPECT_EQ(held.channels.size(), 10 * profiles.size()) << name;
          // Most samples are flat terrain: the events are a small part of the series.
          std::size_t events = 0;
          for (const auto& ch : held.channels)
            events += ch.steps.size() * ch.columns.size();
          if (std::string(name) == "long_hill") {
            EXPECT_LT(events, static_cast<std::size_t>(dense.size() / 4)) << kmh;
          }
        }
      }
    }
  }
  // An input off the lines (not a profile of TerrainLines) is sampled at every step.
  const tvd::terrain::Terrain track = tvd::terrain::makeTrack("long_hill");
  const tvd::dynamics::RoadExcitation road(xq, yq);
  const tvd::Vector other_y = (tvd::Vector(1) << 0.3).finished();
  const tvd::terrain::TerrainLines lines(track, other_y);
  const tvd::Matrix dense = road.sampleSeries(lines, track.startStation(), 2.0, 1e-3, 0, 3000);
  const tvd::Matrix back =
      road.sampleHeldSeries(lines, track.startStation(), 2.0, 1e-3, 0, 3000).dense();
  EXPECT_EQ(std::memcmp(back.data(), dense.data(), sizeof(double) * dense.size()), 0);
}

TEST(RoadExcitation, HeldSeriesRejectsInconsistentChannels) {
  tvd::dynamics::HeldInputSeries s;
  s.samples = 10;
  s.initial = tvd::Vector::Zero(3);
  s.channels.push_back({{0, 1}, {2, 5}, {0.1, 0.2}});
  EXPECT_NO_THROW(s.validate());
  auto expectError = [](const tvd::dynamics::HeldInputSeries& bad, const std::string& part) {
    try {
      bad.validate();
      ADD_FAILURE() << "accepted; expected an error naming '" << part << "'";
    } catch (const tvd::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
    }
  };
  auto bad = s;
  bad.channels[0].steps = {5, 2};
  expectError(bad, "event 1 at step 2");
  bad = s;
  bad.channels[0].steps = {0, 5};
  expectError(bad, "event 0 at step 0");
  bad = s;
  bad.channels.push_back({{1}, {}, {}});
  expectError(bad, "column 1 is already in channel 0");
  bad = s;
  bad.channels[0].columns = {0, 3};
  expectError(bad, "column 3 outside");
  bad = s;
  bad.channels[0].values[1] = std::nan("");
  expectError(bad, "value of event 1");
  bad = s;
  bad.initial(1) = 0.5;
  expectError(bad, "one channel is one signal");
  bad = s;
  bad.channels[0].values.pop_back();
  expectError(bad, "2 steps but 1 values");
  // dense() and row() agree with the hold rule.
  const tvd::Matrix w = s.dense();
  EXPECT_EQ(w(1, 0), 0.0);
  EXPECT_EQ(w(2, 1), 0.1);
  EXPECT_EQ(w(4, 0), 0.1);
  EXPECT_EQ(w(9, 1), 0.2);
  EXPECT_EQ(w(9, 2), 0.0);
  for (long k = 0; k < 10; ++k)
    EXPECT_EQ((s.row(k) - w.row(k).transpose()).norm(), 0.0);
}
