// Road inputs sampled from a terrain as the vehicle advances (dynamics/road_excitation.h).
#include <gtest/gtest.h>

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
    for (int j = 0; j < x.size(); ++j) h(i, j) = a * x(j) + b * y(i);
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
