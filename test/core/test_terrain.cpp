// Terrain: grid interpolation, the paper's tracks and the half-round obstacle (closed forms),
// ISO 8608 roads (PSD identities), file round trips and every bad-input message, and the online
// TerrainBuffer.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "expect_input_error.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/terrain/interpolation_loss.h"
#include "tracked_vehicle_dynamics/terrain/iso8608.h"
#include "tracked_vehicle_dynamics/terrain/moving_average.h"
#include "tracked_vehicle_dynamics/terrain/terrain.h"
#include "tracked_vehicle_dynamics/terrain/terrain_buffer.h"
#include "tracked_vehicle_dynamics/terrain/terrain_io.h"
#include "tracked_vehicle_dynamics/terrain/terrain_lines.h"
#include "tracked_vehicle_dynamics/terrain/terrain_plausibility.h"
#include "tracked_vehicle_dynamics/terrain/tracks.h"

#ifndef TVD_SOURCE_DIR
#define TVD_SOURCE_DIR "."
#endif

namespace tracked_vehicle_dynamics {
namespace terrain {
namespace {

// Exact arithmetic up to rounding of sums of a few thousand terms.
constexpr double kRoundoff = 1e-12;
// Smoothing the piecewise-linear interpolant of a sinusoid sampled every dx instead of the
// sinusoid itself errs by about A (2π dx / λ)^2 / 12: below 7e-5 m for the tracks' waves.
constexpr double kSamplingTolerance = 1e-4;

double sinc(double window, double wavelength) {
  const double a = kPi * window / wavelength;
  return std::sin(a) / a;
}

/// Stations where h(x) - level changes sign, by linear interpolation between stations.
std::vector<double> crossings(const Terrain& t, double y, double level, double from, double to) {
  std::vector<double> out;
  const Vector& x = t.stations();
  const Vector h = t.profile(y);
  for (Eigen::Index i = 1; i < x.size(); ++i) {
    if (x(i - 1) < from || x(i) > to)
      continue;
    const double a = h(i - 1) - level;
    const double b = h(i) - level;
    if ((a < 0.0) != (b < 0.0))
      out.push_back(x(i - 1) + (x(i) - x(i - 1)) * a / (a - b));
  }
  return out;
}

/// Expects `call` to throw InputError whose message contains every one of `parts`.
/// A scratch directory removed at the end of the test.
class TempDir {
 public:
  TempDir() {
    path_ = std::filesystem::temp_directory_path() /
            ("tvd_terrain_test_" + std::to_string(::getpid()) + "_" +
             ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  std::string file(const std::string& name, const std::string& content = "") const {
    const std::string path = (path_ / name).string();
    if (!content.empty())
      std::ofstream(path) << content;
    return path;
  }

 private:
  std::filesystem::path path_;
};

// ---------------------------------------------------------------------------------------------
// Terrain grid

// Written values read back bit for bit, in their shortest text: a user opening the file sees
// 0.05 and 0, not 0.050000000000000003 and -0.
TEST(TerrainFiles, WrittenNumbersAreShortAndExact) {
  TempDir dir;
  Vector x(4);
  x << 0.0, 0.05, 0.1, 0.1 + 0.05;  // the last is 0.15000000000000002
  Vector y(2);
  y << -0.5, 0.5;
  Matrix h(2, 4);
  h << -0.0, 0.05, 1e-3, 0.1 + 0.2, 0.0, -0.25, 2.0 / 3.0, 7.0;
  const Terrain t(x, y, h, "numbers");
  for (const std::string name : {"t.csv", "t.yaml"}) {
    const std::string path = dir.file(name);
    if (name == "t.csv")
      saveTerrainCsv(t, path);
    else
      saveTerrainYaml(t, path);
    std::ifstream in(path);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text.find("-0,"), std::string::npos) << text;
    EXPECT_EQ(text.find("0.050000000000000003"), std::string::npos) << text;
    EXPECT_NE(text.find("0.05"), std::string::npos) << text;
    EXPECT_NE(text.find("0.15000000000000002"), std::string::npos) << text;
    const Terrain back = loadTerrain(path);
    EXPECT_EQ(back.stations(), t.stations()) << name;
    EXPECT_EQ(back.lateral(), t.lateral()) << name;
    EXPECT_EQ(back.heights(), t.heights()) << name;
  }
}

TEST(TerrainFiles, ASemicolonSeparatedFileIsToldSo) {
  TempDir dir;
  const std::string path = dir.file("semi.csv", "x;-1;1\n0;0;0\n1;0.1;0.1\n");
  expectInputError([&] { loadTerrain(path); },
                   {"semi.csv", "row 1", "separated by commas; this line has ';' or tabs"});
}

// The paper's tracks are ground; a 10 m bump over 5 m, or heights in mm, are not.
TEST(TerrainPlausibility, PaperTracksPassAndAScaleMistakeIsNamed) {
  for (const std::string track : {"long_hill", "separated_waves", "oop_waves"}) {
    const Terrain t = loadTrack(track);
    EXPECT_LT(steepestSlope(t).slope, kSteepestPlausibleSlope) << track;
    EXPECT_TRUE(terrainWarnings(track, t).empty()) << track;
  }
  // oop_waves: 2 pi A / lambda = pi 0.6 / 1.2, less the 0.2 m average's sinc (0.955): 1.5.
  EXPECT_NEAR(steepestSlope(loadTrack("oop_waves")).slope, 1.5, 0.05);
  Vector x = Vector::LinSpaced(101, 0.0, 10.0);
  Vector y(2);
  y << -2.0, 2.0;
  Matrix h = Matrix::Zero(2, 101);
  for (int i = 0; i < 101; ++i)
    h(1, i) = 10.0 * std::sin(M_PI * std::clamp(x(i) - 2.5, 0.0, 5.0) / 5.0);  // 10 m over 5 m
  const Terrain bump(x, y, h, "bump");
  const SteepestSlope s = steepestSlope(bump);
  EXPECT_NEAR(s.slope, 10.0 * M_PI / 5.0, 0.05);  // peak dh/dx at the flanks
  EXPECT_EQ(s.lateral, 2.0);
  const std::vector<std::string> w = terrainWarnings("bump.csv", bump);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("bump.csv: slopes up to 6.2", 0), 0u) << w[0];
  EXPECT_NE(w[0].find("heights in mm read as m?"), std::string::npos) << w[0];
}

TEST(TerrainPlausibility, StationsInMillimetresAreNamedByTheirSpacing) {
  // The long hill written in mm and read as m: 1000 times as long, sampled every 10 m, and
  // (heights in mm too) no steeper. The median spacing names it; a flat run-in of two samples
  // 50 m apart before a 0.01 m grid does not.
  Terrain hill = loadTrack("long_hill");
  const Terrain in_mm(hill.stations() * 1000.0, hill.lateral(), hill.heights() * 1000.0, "hill_mm");
  EXPECT_NEAR(medianSpacing(in_mm.stations()), 10.0, 1e-6);
  const std::vector<std::string> w = terrainWarnings("hill_mm.csv", in_mm);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("hill_mm.csv: sampled every 10 m (median spacing)", 0), 0u) << w[0];
  EXPECT_NE(w[0].find("stations in mm read as m?"), std::string::npos) << w[0];

  Vector x(hill.stations().size() + 1);
  x << hill.startStation() - 50.0, hill.stations();
  Matrix h(hill.heights().rows(), x.size());
  h << hill.heights().col(0), hill.heights();
  EXPECT_TRUE(terrainWarnings("run_in.csv", Terrain(x, hill.lateral(), h)).empty());
  EXPECT_EQ(medianSpacing(Vector::Constant(1, 3.0)), 0.0);
}

TEST(TerrainPlausibility, BreakpointProfilesAreNotSampledProfiles) {
  // A step given by its corners (spacings 2, 0.2, 1.8, 0.2, 1.8 m) and a flat run given by its
  // ends are piecewise-linear roads described exactly: no spacing warning. The same step sampled
  // every 1.8 m is a sampled profile, and coarse.
  Vector x(6);
  x << 0.0, 2.0, 2.2, 4.0, 4.2, 6.0;
  Matrix h(1, 6);
  h << 0.0, 0.0, 0.05, 0.05, 0.0, 0.0;
  const Terrain corners(x, Vector::Zero(1), h);
  EXPECT_NEAR(medianSpacing(x), 1.8, 1e-12);
  EXPECT_FALSE(isSampledProfile(corners));
  EXPECT_TRUE(terrainWarnings("step.csv", corners).empty());
  const Terrain flat(Eigen::Vector2d(0.0, 15.0), Vector::Zero(1), Matrix::Zero(1, 2));
  EXPECT_FALSE(isSampledProfile(flat));
  EXPECT_TRUE(terrainWarnings("flat.csv", flat).empty());
  // The same corners in mm read as m: 6 km of road, its median spacing 1800 m.
  const Terrain in_mm(x * 1000.0, Vector::Zero(1), h);
  const std::vector<std::string> mm = terrainWarnings("step_mm.csv", in_mm);
  ASSERT_EQ(mm.size(), 1u);
  EXPECT_EQ(mm[0].rfind("step_mm.csv: sampled every 1800 m (median spacing)", 0), 0u) << mm[0];
  // A survey every 2 m with +-5 % jitter is a sampled profile.
  Vector survey(21);
  Matrix bumps(1, 21);
  for (int i = 0; i < 21; ++i) {
    survey(i) = 2.0 * i + (i % 2 == 0 ? 0.1 : -0.1) * (i > 0 && i < 20);
    bumps(0, i) = 0.05 * std::sin(0.7 * i);
  }
  const Terrain surveyed(survey, Vector::Zero(1), bumps);
  EXPECT_TRUE(isSampledProfile(surveyed));
  EXPECT_EQ(terrainWarnings("survey.csv", surveyed).size(), 1u);
  const Vector sampled_x = Vector::LinSpaced(6, 0.0, 9.0);
  const Terrain sampled(sampled_x, Vector::Zero(1), h);
  EXPECT_TRUE(isSampledProfile(sampled));
  const std::vector<std::string> w = terrainWarnings("coarse.csv", sampled);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("coarse.csv: sampled every 1.8 m (median spacing)", 0), 0u) << w[0];
}

TEST(TerrainPlausibility, AnOnlinePatchIsCheckedAgainstTheGroundBeforeIt) {
  Vector y(2);
  y << -2.0, 2.0;
  const auto patch = [&](double height, int n = 11) { return Matrix::Constant(2, n, height); };
  TerrainBuffer buffer;
  // No terrain since the start: the contacts stand on z = 0.
  EXPECT_TRUE(patchWarnings(0.0, 0.1, y, patch(0.5), buffer, true).empty());
  std::vector<std::string> w = patchWarnings(0.0, 0.1, y, patch(102.5), buffer, true);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("starts 102.5 m above the flat ground the vehicle stands on", 0), 0u)
      << w[0];
  EXPECT_NE(w[0].find("not altitudes?"), std::string::npos) << w[0];
  // Holding unknown heights (terrain dropped, not a restart): no reference, nothing said.
  EXPECT_TRUE(patchWarnings(0.0, 0.1, y, patch(102.5), buffer, false).empty());

  // Altitudes throughout: the first patch steps, the next ones continue it.
  buffer.addPatch(0.0, 0.1, y, patch(102.5));
  EXPECT_TRUE(patchWarnings(1.1, 0.1, y, patch(102.7), buffer, false).empty());  // bridged gap
  EXPECT_TRUE(patchWarnings(0.5, 0.1, y, patch(103.0), buffer, false).empty());  // overlap
  // After a gap the contacts hold the last heights: the step is from there.
  Matrix down = patch(100.0);
  down.row(1).setConstant(99.0);
  PatchStep judged;
  w = patchWarnings(20.0, 0.1, y, down, buffer, false, &judged);
  ASSERT_EQ(w.size(), 1u);
  // The step it judged is handed out, as patchStep() gives it.
  const PatchStep step = patchStep(20.0, y, down, buffer, false);
  EXPECT_TRUE(judged.known && judged.implausible());
  EXPECT_EQ(judged.step, step.step);
  EXPECT_EQ(judged.reference, step.reference);
  EXPECT_EQ(judged.lateral, step.lateral);
  EXPECT_EQ(w[0].rfind("starts 3.5 m below the terrain before it (102.5 m at y = 2 m)", 0), 0u)
      << w[0];
  // A patch starting before all the terrain has nothing before it.
  EXPECT_TRUE(patchWarnings(-5.0, 0.1, y, patch(0.0), buffer, false).empty());

  // Slope and spacing, as for a file.
  Matrix wave = patch(0.0, 5);
  wave(0, 2) = 1.0;  // 1 m over 0.1 m
  w = patchWarnings(-5.0, 0.1, y, wave, TerrainBuffer(), true);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("slopes up to 10 m/m", 0), 0u) << w[0];
  w = patchWarnings(-5.0, 10.0, y, patch(0.0), TerrainBuffer(), true);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("sampled every 10 m", 0), 0u) << w[0];
}

TEST(TerrainPlausibility, PatchStepIsTheLargestLineStepFromTheGroundBefore) {
  Vector y(2);
  y << -2.0, 2.0;
  TerrainBuffer buffer;
  Matrix first = Matrix::Constant(2, 11, 0.2);
  first(1, 0) = -1.3;  // the left line starts 1.3 m below the flat ground
  terrain::PatchStep s = terrain::patchStep(0.0, y, first, buffer, true);
  EXPECT_TRUE(s.known);
  EXPECT_DOUBLE_EQ(s.step, -1.3);
  EXPECT_DOUBLE_EQ(s.reference, 0.0);
  EXPECT_DOUBLE_EQ(s.lateral, 2.0);
  EXPECT_TRUE(s.implausible());
  // Nothing to step from: unknown, never implausible.
  s = terrain::patchStep(0.0, y, first, buffer, false);
  EXPECT_FALSE(s.known);
  EXPECT_FALSE(s.implausible());
  // From the terrain before it, line by line: 0.9 m up on the right, within kLargestPlausibleStep.
  buffer.addPatch(0.0, 0.1, y, Matrix::Constant(2, 11, 0.1));
  Matrix next = Matrix::Constant(2, 5, 0.1);
  next(0, 0) = 1.0;
  s = terrain::patchStep(1.0, y, next, buffer, false);
  EXPECT_TRUE(s.known);
  EXPECT_NEAR(s.step, 0.9, 1e-12);
  EXPECT_DOUBLE_EQ(s.lateral, -2.0);
  EXPECT_FALSE(s.implausible());
  // Wrong shapes are no step (addPatch refuses them).
  EXPECT_FALSE(terrain::patchStep(1.0, y, Matrix::Constant(3, 5, 9.0), buffer, true).known);
}

TEST(Terrain, BilinearIsExactForBilinearSurfaces) {
  // h = a + b x + c y + d x y is reproduced exactly by bilinear interpolation.
  const auto surface = [](double x, double y) { return 0.1 + 0.2 * x - 0.3 * y + 0.05 * x * y; };
  Vector x(4), y(3);
  x << 0.0, 0.5, 1.5, 4.0;  // non-uniform
  y << -1.0, 0.0, 2.0;
  Matrix h(3, 4);
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 4; ++i)
      h(j, i) = surface(x(i), y(j));
  }
  const Terrain t(x, y, h);
  EXPECT_FALSE(t.isUniform());
  for (double xi = 0.0; xi <= 4.0; xi += 0.137) {
    for (double yi = -1.0; yi <= 2.0; yi += 0.31) {
      EXPECT_NEAR(t.height(xi, yi), surface(xi, yi), kRoundoff);
      // Within a cell the x-slope of the bilinear surface is b + d y.
      if (xi < 4.0) {
        EXPECT_NEAR(t.slope(xi, yi), 0.2 + 0.05 * yi, kRoundoff);
      }
    }
  }
}

TEST(Terrain, HoldsEdgesInXAndClampsInY) {
  Vector x(3), y(2);
  x << 0.0, 1.0, 2.0;
  y << -1.0, 1.0;
  Matrix h(2, 3);
  h << 1.0, 2.0, 3.0,  //
      5.0, 6.0, 7.0;
  const Terrain t(x, y, h, "edges");
  EXPECT_TRUE(t.isUniform());
  EXPECT_DOUBLE_EQ(t.spacing(), 1.0);
  EXPECT_DOUBLE_EQ(t.height(-10.0, -1.0), 1.0);
  EXPECT_DOUBLE_EQ(t.height(10.0, 1.0), 7.0);
  EXPECT_DOUBLE_EQ(t.height(1.0, -5.0), 2.0);
  EXPECT_DOUBLE_EQ(t.height(1.0, 5.0), 6.0);
  EXPECT_DOUBLE_EQ(t.height(0.5, 0.0), 3.5);
  EXPECT_DOUBLE_EQ(t.slope(-1.0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(t.slope(2.5, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(t.slope(0.5, 0.0), 1.0);
  EXPECT_TRUE(std::isnan(t.height(std::nan(""), 0.0)));
  EXPECT_DOUBLE_EQ(t.height(std::numeric_limits<double>::infinity(), 0.0), 5.0);
}

// Flat runs: where consecutive samples are equal on every line, the height is the sample's,
// exactly (not (1 - w) h + w h, which rounds), and flatRunEnd() says how far that holds.
TEST(Terrain, FlatRunsAreExactAndKnowTheirEnd) {
  Vector x = Vector::LinSpaced(9, 0.0, 0.08);
  Vector y(2);
  y << -1.0, 1.0;
  Matrix h(2, 9);
  h << 0.1, 0.4, 0.4, 0.4, 0.4, 0.3, 0.3, 0.7, 0.7,  //
      0.2, 0.4, 0.4, 0.4, 0.4, 0.3, 0.5, 0.7, 0.7;
  const Terrain t(x, y, h, "runs");
  EXPECT_EQ(t.flatRunEnd(0), x(0));
  EXPECT_EQ(t.flatRunEnd(1), x(4));
  EXPECT_EQ(t.flatRunEnd(3), x(4));
  EXPECT_EQ(t.flatRunEnd(5), x(5));  // line 1 changes 5 -> 6
  EXPECT_EQ(t.flatRunEnd(7), x(8));
  EXPECT_EQ(t.flatRunEnd(8), x(8));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> along(x(1), x(4));
  for (int k = 0; k < 1000; ++k) {
    const double s = along(rng);
    for (const double lateral : {-1.0, -0.37, 0.0, 0.81, 1.0}) {
      // Both lines are 0.4 over samples 1..4: the height is 0.4 exactly at every y.
      ASSERT_EQ(t.height(s, lateral), 0.4) << s << " at y = " << lateral;
    }
  }
}

TEST(Terrain, EqualLinesBlendToTheirValueExactly) {
  // (1 - w) h + w h rounds off h for some (h, w): the blend between equal lateral lines must
  // not, or a laterally uniform track gives each pad row its own profile bit pattern and
  // TerrainLines stops sharing channels between them.
  const Vector x = Vector::LinSpaced(200, 0.0, 1.99);
  Vector y(3);
  y << -2.0, 0.5, 2.0;
  Matrix h(3, 200);
  for (Eigen::Index i = 0; i < 200; ++i) {
    h(0, i) = h(1, i) = 0.1 + 0.37 * std::sin(0.7 * static_cast<double>(i));
    h(2, i) = i % 2 == 0 ? h(1, i) : -h(1, i);  // line 2 agrees with line 1 on every other sample
  }
  const Terrain t(x, y, h, "equal lines");
  int rounded = 0;  // how often the naive blend would have missed: the test must be able to fail
  for (int k = 1; k < 400; ++k) {
    const double lateral = -2.0 + 2.5 * k / 400.0;  // strictly between lines 0 and 1
    const double w = (lateral + 2.0) / 2.5;
    const Vector p = t.profile(lateral);
    ASSERT_EQ(std::memcmp(p.data(), h.row(0).eval().data(), sizeof(double) * 200), 0) << lateral;
    for (Eigen::Index i = 0; i < 199; ++i) {
      if ((1.0 - w) * h(0, i) + w * h(1, i) != h(0, i))
        ++rounded;
      ASSERT_EQ(t.height(x(i), lateral), h(0, i)) << lateral << " " << i;
      ASSERT_EQ(t.slope(x(i) + 0.001, lateral), (h(0, i + 1) - h(0, i)) / (x(i + 1) - x(i)))
          << lateral << " " << i;
    }
  }
  EXPECT_GT(rounded, 0);
  // Between lines 1 and 2, the even samples agree and blend exactly; the odd ones interpolate.
  const Vector p = t.profile(1.0);
  for (Eigen::Index i = 0; i < 200; i += 2)
    ASSERT_EQ(p(i), h(1, i)) << i;
  EXPECT_NEAR(p(1), (2.0 / 3.0) * h(1, 1) + (1.0 / 3.0) * h(2, 1), 1e-15);
}

TEST(Terrain, SingleLateralLineIsUniformAcrossWidth) {
  Vector x(2), y(1);
  x << 0.0, 1.0;
  y << 0.0;
  Matrix h(1, 2);
  h << 0.0, 1.0;
  const Terrain t(x, y, h);
  EXPECT_DOUBLE_EQ(t.height(0.25, -3.0), 0.25);
  EXPECT_DOUBLE_EQ(t.height(0.25, 3.0), 0.25);
}

TEST(Terrain, RejectsBadGrids) {
  Vector x(3), y(2);
  x << 0.0, 1.0, 1.0;
  y << -1.0, 1.0;
  expectInputError([&] { Terrain(x, y, Matrix::Zero(2, 3), "dup"); },
                   {"terrain 'dup'", "station 2", "strictly increasing"});
  x << 0.0, 1.0, 2.0;
  Matrix h = Matrix::Zero(2, 3);
  h(1, 2) = std::nan("");
  expectInputError([&] { Terrain(x, y, h, "nan"); }, {"lateral line 1", "station 2", "finite"});
  h(1, 2) = 1e300;  // e.g. millimetres read as metres many times over: no road is that high
  expectInputError([&] { Terrain(x, y, h, "high"); }, {"station 2", "is 1e+300 m", "+-10000 m"});
  h(1, 2) = -9000.0;  // the shore of the Dead Sea is at -430 m, Everest at 8849 m: both accepted
  EXPECT_EQ(Terrain(x, y, h, "deep").height(2.0, 1.0), -9000.0);
  expectInputError([&] { Terrain(x, y, Matrix::Zero(3, 3), "size"); },
                   {"heights are 3 x 3", "expected 2 lateral lines x 3 stations"});
  expectInputError([&] { Terrain(Vector(), y, Matrix::Zero(2, 0), "empty"); }, {"no stations"});
  // Positions near the double range overflowed the track's length (x_end - x_start) to inf.
  x << -1e308, 0.0, 1e308;
  expectInputError([&] { Terrain(x, y, Matrix::Zero(2, 3), "far"); },
                   {"terrain 'far'", "station 0 is -1e+308 m", "beyond +-1e+08 m"});
  x << 0.0, 1.0, 2.0;
  y << -2e8, 1.0;
  expectInputError([&] { Terrain(x, y, Matrix::Zero(2, 3), "wide"); },
                   {"lateral line 0 is -2e+08 m", "beyond +-1e+08 m"});
  // The bound itself, and a UTM northing as a station datum, are accepted.
  y << -1.0, 1e8;
  x << 5.3e6, 5.3e6 + 1.0, 5.3e6 + 2.0;
  EXPECT_EQ(Terrain(x, y, Matrix::Zero(2, 3), "utm").height(5.3e6 + 1.0, 0.0), 0.0);
}

// ---------------------------------------------------------------------------------------------
// Moving average

TEST(MovingAverage, KeepsLinesAndScalesSinusoidsBySinc) {
  const double dx = 0.01;
  const double window = 0.2;
  const int n = 2001;
  Vector line(n), wave(n);
  const double wavelength = 1.0;
  for (int i = 0; i < n; ++i) {
    line(i) = 0.3 - 0.7 * i * dx;
    wave(i) = std::sin(2.0 * kPi * i * dx / wavelength);
  }
  const Vector smooth_line = movingAverage(line, dx, window);
  const Vector smooth_wave = movingAverage(wave, dx, window);
  const double interpolation_error = std::pow(2.0 * kPi * dx / wavelength, 2) / 12.0;
  for (int i = 10; i < n - 10; ++i) {  // away from the held edges
    EXPECT_NEAR(smooth_line(i), line(i), kRoundoff);
    EXPECT_NEAR(smooth_wave(i), sinc(window, wavelength) * wave(i), 1.1 * interpolation_error);
  }
  EXPECT_EQ(movingAverage(wave, dx, 0.0), wave);
  expectInputError([&] { movingAverage(wave, 0.0, window); }, {"spacing 0 m"});
  expectInputError([&] { movingAverage(wave, dx, -1.0); }, {"window -1 m"});
}

// A window that is not a whole number of samples (0.15 m at 0.02 m: 3.75 either side) takes the
// partial end cells by interpolation: the result is the mean of the piecewise-linear profile over
// the window, here against a fine midpoint rule. (The default 0.2 m at 0.01 m ends on samples,
// and a straight line's two end errors cancel: neither sees a wrong weight at the ends.)
TEST(MovingAverage, AFractionalWindowIsTheMeanOfTheInterpolatedProfile) {
  const double dx = 0.02, window = 0.15;
  const int n = 200;
  Vector wave(n);
  for (int i = 0; i < n; ++i)
    wave(i) = std::sin(2.0 * kPi * i * dx / 0.3);
  const Vector smooth = movingAverage(wave, dx, window);
  const auto profile = [&](double x) {
    const double t = x / dx;
    const int k = static_cast<int>(std::floor(t));
    return (1.0 - (t - k)) * wave(k) + (t - k) * wave(k + 1);
  };
  double worst = 0.0;
  for (int i = 10; i < n - 10; ++i) {
    const int parts = 20000;
    double sum = 0.0;
    for (int j = 0; j < parts; ++j)
      sum += profile(i * dx - 0.5 * window + (j + 0.5) * window / parts);
    worst = std::max(worst, std::abs(smooth(i) - sum / parts));
  }
  EXPECT_LT(worst, 1e-6);
}

// ---------------------------------------------------------------------------------------------
// The paper's tracks (§4.2.1)

TEST(Tracks, FactoryKnowsThePaperTracks) {
  const std::vector<std::string> names = trackNames();
  ASSERT_EQ(names.size(), 3u);
  for (const std::string& name : names) {
    const Terrain t = makeTrack(name);
    EXPECT_EQ(t.name(), name);
    EXPECT_EQ(t.stations().size(), 3001);
    EXPECT_DOUBLE_EQ(t.startStation(), 0.0);
    EXPECT_NEAR(t.endStation(), kTrackLength, kRoundoff);
    EXPECT_NEAR(t.spacing(), kTrackSpacing, kRoundoff);
    EXPECT_NEAR(t.lateral().maxCoeff() - t.lateral().minCoeff(), kTrackWidth, kRoundoff);
    // Flat entry and exit.
    EXPECT_DOUBLE_EQ(t.height(0.0, 0.0), 0.0);
    EXPECT_DOUBLE_EQ(t.height(kTrackLength, 0.0), 0.0);
  }
  expectInputError([] { makeTrack("moon"); },
                   {"unknown track 'moon'", "long_hill", "oop_waves", "half_round:H"});
  // Listings add the parameterised obstacle as a form, not as a name.
  std::vector<std::string> forms = names;
  forms.push_back("half_round:H");
  EXPECT_EQ(trackForms(), forms);
  EXPECT_FALSE(isBuiltInTrack("half_round:H"));
  TrackOptions bad;
  bad.spacing = 0.0;
  expectInputError([&] { makeTrack("long_hill", bad); }, {"TrackOptions::spacing"});
  EXPECT_DOUBLE_EQ(defaultLateralOffset("oop_waves"), kOopWavesLateralOffset);
  EXPECT_DOUBLE_EQ(defaultLateralOffset("long_hill"), 0.0);
}

TEST(Tracks, LongHillClosedForms) {
  const Terrain t = makeTrack("long_hill");
  const double w = kTrackSmoothingWindow;
  const double s = kLongHillHeight / kLongHillRamp;  // ramp slope
  // Plateau: exactly the hill height at least W/2 away from the ramp corners, any y.
  const double top_end = kLongHillStart + kLongHillRamp + kLongHillTop;  // 21 m
  for (double x = kLongHillStart + kLongHillRamp + w / 2; x <= top_end - w / 2 + 1e-9; x += 0.05) {
    for (double y : {-2.5, 0.0, 1.3})
      EXPECT_NEAR(t.height(x, y), kLongHillHeight, kRoundoff);
  }
  // Ramp midpoints and the linear stretch of the ramps.
  EXPECT_NEAR(t.height(10.5, 0.0), 0.5 * kLongHillHeight, kRoundoff);
  EXPECT_NEAR(t.height(21.5, 0.0), 0.5 * kLongHillHeight, kRoundoff);
  EXPECT_NEAR(t.height(10.3, 0.0), s * 0.3, kRoundoff);
  EXPECT_NEAR(t.slope(10.5, 0.0), s, kRoundoff);
  EXPECT_NEAR(t.slope(21.5, 0.0), -s, kRoundoff);
  EXPECT_NEAR(t.slope(16.0, 0.0), 0.0, kRoundoff);
  // The top is 10 m long (the paper's "10 m long"), the ramps beside it: 12 m foot to foot.
  EXPECT_DOUBLE_EQ(kLongHillLength, 12.0);
  EXPECT_NEAR(t.height(11.1, 0.0), kLongHillHeight, kRoundoff);
  EXPECT_NEAR(t.height(20.9, 0.0), kLongHillHeight, kRoundoff);
  // Smoothed corners: h = s (x - x_c + W/2)^2 / (2 W) near the foot, s W / 8 at the corner.
  EXPECT_NEAR(t.height(10.0, 0.0), s * w / 8.0, kRoundoff);
  EXPECT_NEAR(t.height(11.0, 0.0), kLongHillHeight - s * w / 8.0, kRoundoff);
  EXPECT_NEAR(t.height(21.0, 0.0), kLongHillHeight - s * w / 8.0, kRoundoff);
  EXPECT_NEAR(t.height(22.0, 0.0), s * w / 8.0, kRoundoff);
  for (double x : {9.93, 9.95, 10.04, 10.07}) {
    const double d = x - (kLongHillStart - w / 2);
    EXPECT_NEAR(t.height(x, 0.0), s * d * d / (2.0 * w), kRoundoff) << "x = " << x;
  }
  // Flat run-in and run-out up to W/2 from the feet.
  EXPECT_DOUBLE_EQ(t.height(9.9, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(t.height(22.1, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(t.height(-3.0, 0.0), 0.0);
}

// The paper's §4.2.1 dimensions, as literals measured on the built tracks (the other track tests
// read tracks.h's constants, which a typo there would carry into both sides): 30 m x 5 m sampled
// every 0.01 m; a 0.4 m hill with a 10 m top and 1 m ramps; 10 waves of 1.8 m, 0.15 m deep; 10
// out-of-phase waves of 1.2 m, 0.6 m deep. The 0.2 m moving average scales a sinusoid of
// wavelength L by sin(pi W / L) / (pi W / L) and leaves the hill's linear stretches alone.
TEST(Tracks, DimensionsAreThePapers) {
  const double w = 0.2;
  const auto smoothing = [&](double wavelength) {
    const double a = kPi * w / wavelength;
    return std::sin(a) / a;
  };
  for (const char* name : {"long_hill", "separated_waves", "oop_waves"}) {
    const Terrain t = makeTrack(name);
    EXPECT_NEAR(t.length(), 30.0, 1e-12) << name;
    EXPECT_NEAR(t.stations()(1) - t.stations()(0), 0.01, 1e-12) << name;
    EXPECT_NEAR(t.lateral()(t.lateral().size() - 1) - t.lateral()(0), 5.0, 1e-12) << name;
  }
  // Long hill: the half-height crossings lie a ramp's midpoint in from each foot, i.e. top +
  // one ramp = 11 m apart; the top stays at 0.4 m over 10 m less the window.
  const Terrain hill = makeTrack("long_hill");
  const std::vector<double> half = crossings(hill, 0.0, 0.2, 0.0, 30.0);
  ASSERT_EQ(half.size(), 2u);
  EXPECT_NEAR(half[1] - half[0], 11.0, 1e-6);
  double top = 0.0, on_top = 0.0;
  for (double x = 0.0; x <= 30.0; x += 0.001) {
    const double h = hill.height(x, 0.0);
    top = std::max(top, h);
    on_top += (std::abs(h - 0.4) < 1e-9) ? 0.001 : 0.0;
  }
  EXPECT_NEAR(top, 0.4, 1e-12);
  EXPECT_NEAR(on_top, 10.0 - w, 0.003);
  // Separated waves: 10 troughs 1.8 m apart, 0.15 m deep before smoothing.
  const Terrain waves = makeTrack("separated_waves");
  // h = -(D/2)(1 - cos): its mean level -D/2 crosses where cos = 0, twice a period.
  const std::vector<double> mid = crossings(waves, 0.0, -0.075, 0.0, 30.0);
  ASSERT_EQ(mid.size(), 20u);  // two per period
  EXPECT_NEAR((mid[19] - mid[1]) / 9.0, 1.8, 1e-6);
  double lowest = 0.0;
  for (double x = 0.0; x <= 30.0; x += 0.001)
    lowest = std::min(lowest, waves.height(x, 0.0));
  // -(D/2)(1 + sinc), less the linear interpolation's h'' dx^2 / 8 = 1.1e-5 m at the trough.
  EXPECT_NEAR(-2.0 * lowest / (1.0 + smoothing(1.8)), 0.15, 2e-5);
  // Out-of-phase waves: 1.2 m, 0.6 m peak-to-trough at the edges, left against right.
  TrackOptions centred;  // the track's own frame: its edges at y = +-2.5 m
  centred.lateral_offset = 0.0;
  const Terrain oop = makeTrack("oop_waves", centred);
  double high = 0.0, low = 0.0;
  for (double x = 0.0; x <= 30.0; x += 0.001) {
    high = std::max(high, oop.height(x, 2.5));
    low = std::min(low, oop.height(x, 2.5));
    EXPECT_NEAR(oop.height(x, -2.5), -oop.height(x, 2.5), 1e-12);
  }
  // Less the interpolation's h'' dx^2 / 8 = 1.0e-4 m at the crest and at the trough.
  EXPECT_NEAR((high - low) / smoothing(1.2), 0.6, 3e-4);
  const std::vector<double> zeros = crossings(oop, 2.5, 0.0, 1.0, 29.0);
  ASSERT_GE(zeros.size(), 19u);
  EXPECT_NEAR((zeros[zeros.size() - 2] - zeros[1]) / ((zeros.size() - 3) / 2.0), 1.2, 1e-6);
  EXPECT_DOUBLE_EQ(defaultLateralOffset("oop_waves"), 1.0);  // "a lateral offset of 1 m"
}

TEST(Tracks, SeparatedWavesWavelengthAndDepth) {
  const Terrain t = makeTrack("separated_waves");
  const double d = kSeparatedWavesDepth;
  const double lambda = kSeparatedWavesWavelength;
  const double gain = sinc(kTrackSmoothingWindow, lambda);
  const double end = kSeparatedWavesStart + kSeparatedWavesPeriods * lambda;
  // Hollows below the ground: never above it.
  EXPECT_LE(t.heights().maxCoeff(), kRoundoff);
  // Mid-level crossings every half wavelength: 2 per period.
  const std::vector<double> x = crossings(t, 0.0, -d / 2, kSeparatedWavesStart + 0.5, end - 0.5);
  ASSERT_EQ(x.size(), 2u * kSeparatedWavesPeriods - 2);
  for (std::size_t i = 1; i < x.size(); ++i)
    EXPECT_NEAR(x[i] - x[i - 1], lambda / 2, 1e-3);
  // Depth: peak-to-trough D sinc(W/λ) between interior crests (x0 + kλ) and troughs.
  for (int k = 1; k < kSeparatedWavesPeriods; ++k) {
    const double crest = kSeparatedWavesStart + k * lambda;
    EXPECT_NEAR(t.height(crest, 0.0), -0.5 * d * (1.0 - gain), kSamplingTolerance);
    EXPECT_NEAR(t.height(crest + lambda / 2, 0.0), -0.5 * d * (1.0 + gain), kSamplingTolerance);
  }
  // Uniform across the width.
  EXPECT_EQ(t.profile(-2.5), t.profile(2.5));
}

TEST(Tracks, OopWavesOppositePhaseAndInnerOuterDiffer) {
  TrackOptions centred;
  centred.lateral_offset = 0.0;
  const Terrain t = makeTrack("oop_waves", centred);
  const double lambda = kOopWavesWavelength;
  const double gain = sinc(kTrackSmoothingWindow, lambda);
  for (double x = 0.0; x <= kTrackLength; x += 0.173) {
    for (double y : {0.5, 1.1, 1.7, 2.5}) {
      EXPECT_NEAR(t.height(x, y), -t.height(x, -y), kRoundoff) << "x = " << x << ", y = " << y;
    }
  }
  // At a crest of the left side (quarter wavelength), the outer pad row is higher than the inner
  // one, in the ratio of their lateral positions (amplitude linear in y).
  const double crest = kOopWavesStart + 2.25 * lambda;
  const double inner = t.height(crest, 1.1);
  const double outer = t.height(crest, 1.7);
  EXPECT_GT(inner, 0.05);
  EXPECT_GT(outer - inner, 0.05);
  EXPECT_NEAR(outer / inner, 1.7 / 1.1, 1e-9);
  EXPECT_NEAR(t.height(crest, 2.5), 0.5 * kOopWavesDepth * gain, kSamplingTolerance);
  EXPECT_NEAR(t.height(crest, -2.5), -0.5 * kOopWavesDepth * gain, kSamplingTolerance);
  // Zero crossings every half wavelength.
  const double end = kOopWavesStart + kOopWavesPeriods * lambda;
  const std::vector<double> x = crossings(t, 2.5, 0.0, kOopWavesStart + 0.3, end - 0.3);
  ASSERT_GE(x.size(), 2u * kOopWavesPeriods - 2);
  for (std::size_t i = 1; i < x.size(); ++i)
    EXPECT_NEAR(x[i] - x[i - 1], lambda / 2, 1e-3);
}

TEST(Tracks, OopWavesDefaultOffsetShiftsThePathFrame) {
  TrackOptions centred;
  centred.lateral_offset = 0.0;
  const Terrain on_track = makeTrack("oop_waves", centred);
  const Terrain driven = makeTrack("oop_waves");  // 1 m offset towards +y
  const Vector shifted = on_track.lateral().array() - kOopWavesLateralOffset;
  EXPECT_TRUE(driven.lateral().isApprox(shifted));
  for (double x = 9.0; x <= 21.0; x += 0.37) {
    for (double y : {-1.4, -1.1, 1.1, 1.4}) {
      EXPECT_NEAR(driven.height(x, y), on_track.height(x, y + kOopWavesLateralOffset), kRoundoff);
    }
  }
  // With the offset the two sides no longer cancel: the vehicle also heaves.
  const double crest = kOopWavesStart + 2.25 * kOopWavesWavelength;
  EXPECT_GT(driven.height(crest, 1.4) + driven.height(crest, -1.4), 0.1);
}

// ---------------------------------------------------------------------------------------------
// The half-round obstacle, half_round:H (NRMM)

/// Closed-form crest of the smoothed half-round: the mean of sqrt(H² - u²) over |u| <= W/2, the
/// circular segment's area [a sqrt(H² - a²) + H² asin(a/H)] / W, a = W/2 (the whole half-disc,
/// πH²/2 / W, when W/2 >= H).
double smoothedCrest(double height, double window) {
  const double a = std::min(0.5 * window, height);
  // sqrt((H - a)(H + a)), not sqrt(H² - a²): exactly 0 at a = H even when the compiler fuses
  // H² - a² into a multiply-add (x86-64-v3), which leaves a rounding residue under the root.
  return (a * std::sqrt((height - a) * (height + a)) + height * height * std::asin(a / height)) /
         window;
}

/// What point sampling every dx loses of ∫ sqrt(H² - u²) du at its two feet, where the slope is
/// vertical: the trapezoidal rule on a square-root end point errs by |ζ(-1/2)| sqrt(2H) dx^1.5
/// (Navot's extension of Euler-Maclaurin, ζ(-1/2) = -0.2078862...), an end point on a station.
double footSamplingError(double height, double dx) {
  return 2.0 * 0.2078862250 * std::sqrt(2.0 * height) * std::pow(dx, 1.5);
}

/// ∫ h dx of one line of a track (zero at both ends): the trapezoidal rule, exact for the
/// piecewise-linear interpolant Terrain uses.
double area(const Terrain& t, Eigen::Index line) {
  return t.heights().row(line).sum() * t.spacing();
}

TEST(Tracks, HalfRoundUnsmoothedIsTheSemicircle) {
  const double height = 0.2;
  TrackOptions exact;
  exact.smoothing_window = 0.0;
  const Terrain t = makeTrack("half_round:0.2", exact);
  EXPECT_EQ(t.name(), "half_round:0.2");
  EXPECT_EQ(t.stations().size(), 3001);
  EXPECT_NEAR(t.endStation(), kTrackLength, kRoundoff);
  EXPECT_NEAR(t.lateral().maxCoeff() - t.lateral().minCoeff(), kTrackWidth, kRoundoff);
  EXPECT_DOUBLE_EQ(t.lateral().minCoeff(), -kTrackWidth / 2);  // centred: no default offset
  // Every station: the semicircle on the obstacle, exactly 0 off it.
  const Vector& x = t.stations();
  int on_obstacle = 0;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const double d = x(i) - kHalfRoundCentre;
    if (std::abs(d) < height - 1e-9) {
      ++on_obstacle;
      EXPECT_NEAR(t.heights()(0, i), std::sqrt(height * height - d * d), kRoundoff) << x(i);
    } else if (std::abs(d) > height + 1e-9) {
      EXPECT_EQ(t.heights()(0, i), 0.0) << "x = " << x(i);
    } else {
      EXPECT_NEAR(t.heights()(0, i), 0.0, 1e-7) << "foot at x = " << x(i);  // sqrt of round-off
    }
  }
  EXPECT_EQ(on_obstacle, 39);  // 2 H / dx - 1 stations strictly between the feet
  // The crest is H exactly, at xc, on every line; between stations the chord of the arc.
  for (Eigen::Index j = 0; j < t.lateral().size(); ++j) {
    EXPECT_EQ(t.height(kHalfRoundCentre, t.lateral()(j)), height);
    EXPECT_EQ(t.profile(t.lateral()(j)), t.profile(0.0)) << "line " << j;  // uniform
  }
  EXPECT_NEAR(t.height(kHalfRoundCentre + 0.12, 1.0), std::sqrt(0.04 - 0.0144), kRoundoff);
  EXPECT_EQ(t.heights().maxCoeff(), height);
  EXPECT_EQ(t.heights().minCoeff(), 0.0);
}

TEST(Tracks, HalfRoundSmoothedKeepsTheAreaAndLowersTheCrest) {
  const double w = kTrackSmoothingWindow;
  const double dx = kTrackSpacing;
  for (const double height : {0.1, 0.15, 0.3}) {
    SCOPED_TRACE("H = " + std::to_string(height));
    const std::string name = halfRoundName(height);
    TrackOptions exact;
    exact.smoothing_window = 0.0;
    const Terrain raw = makeTrack(name, exact);
    const Terrain t = makeTrack(name);
    // The moving average conserves ∫h dx exactly (the profile is 0 at both ends); the sampled
    // semicircle has the half-disc's area πH²/2 less the feet's sampling error.
    EXPECT_NEAR(area(t, 0), area(raw, 0), kRoundoff);
    EXPECT_NEAR(area(t, 0), 0.5 * kPi * height * height, 1.1 * footSamplingError(height, dx));
    // Crest: the moving average of the semicircle at xc, of the sampled arc's chords. With the
    // feet inside the window (H <= W/2) their sampling error divided by W; otherwise the chords'
    // mean sag, dx² |h''| / 12, at most at the window's edge: h'' = -H² / (H² - u²)^1.5.
    const double a = 0.5 * w;
    const double tolerance = height <= a + 1e-12 ? 1.1 * footSamplingError(height, dx) / w
                                                 : dx * dx / 12.0 * height * height /
                                                       std::pow(height * height - a * a, 1.5);
    const double crest = smoothedCrest(height, w);
    EXPECT_NEAR(t.height(kHalfRoundCentre, 0.0), crest, tolerance);
    EXPECT_LT(crest, height - 5.0 * tolerance);  // lower than H, measurably
    EXPECT_EQ(t.heights().maxCoeff(), t.height(kHalfRoundCentre, 0.0));
    // Flat run-in and run-out, exactly 0, from W/2 (one station more for round-off) beyond the
    // feet; uniform across the width.
    for (Eigen::Index i = 0; i < t.stations().size(); ++i) {
      if (std::abs(t.stations()(i) - kHalfRoundCentre) >= height + a + dx) {
        ASSERT_EQ(t.heights()(0, i), 0.0) << "x = " << t.stations()(i);
      }
    }
    EXPECT_EQ(t.heights().minCoeff(), 0.0);
    EXPECT_EQ(t.profile(-kTrackWidth / 2), t.profile(kTrackWidth / 2));
  }
  // The crest ratios quoted in tracks.h.
  EXPECT_NEAR(smoothedCrest(0.1, w) / 0.1, kPi / 4, 1e-12);
  EXPECT_NEAR(smoothedCrest(0.15, w) / 0.15, 0.920, 5e-4);
  EXPECT_NEAR(smoothedCrest(0.2, w) / 0.2, 0.957, 5e-4);
  EXPECT_NEAR(smoothedCrest(0.3, w) / 0.3, 0.981, 5e-4);
}

TEST(Tracks, HalfRoundSpecsAreReadAndBadOnesNamed) {
  EXPECT_TRUE(isBuiltInTrack("half_round:0.2"));
  EXPECT_TRUE(isBuiltInTrack("half_round:1"));  // the bound itself
  EXPECT_EQ(halfRoundHeight("half_round:0.25"), 0.25);
  EXPECT_EQ(halfRoundHeight("half_round:2e-1"), 0.2);
  EXPECT_EQ(halfRoundHeight("long_hill"), std::nullopt);
  EXPECT_EQ(halfRoundHeight("half_round.csv"), std::nullopt);  // a file, not a spec
  EXPECT_EQ(halfRoundName(0.1), "half_round:0.1");
  EXPECT_EQ(halfRoundHeight(halfRoundName(0.123456789012345)), 0.123456789012345);
  EXPECT_EQ(makeTrack("half_round:2e-1").name(), "half_round:0.2");  // one name per height
  EXPECT_EQ(defaultLateralOffset("half_round:0.2"), 0.0);
  EXPECT_NO_THROW(checkTrackName("half_round:0.3"));
  // loadTrack reads a spec as the built-in track, the same terrain.
  const Terrain built = makeTrack("half_round:0.15");
  const Terrain loaded = loadTrack("half_round:0.15");
  EXPECT_EQ(loaded.heights(), built.heights());
  EXPECT_EQ(loaded.lateral(), built.lateral());

  struct Bad {
    std::string spec;
    std::string fault;
  };
  const std::vector<Bad> bad = {
      {"half_round", "the obstacle height is missing"},
      {"half_round:", "the obstacle height is missing"},
      {"half_round:abc", "'abc' is not a number"},
      {"half_round:0.2x", "'0.2x' is not a number"},
      {"half_round:0.2 m", "'0.2 m' is not a number"},
      {"half_round: 0.2", "' 0.2' is not a number"},
      {"half_round:0", "must be in (0, 1] m, got 0"},
      {"half_round:-0.1", "must be in (0, 1] m, got -0.1"},
      {"half_round:nan", "must be in (0, 1] m, got nan"},
      {"half_round:inf", "must be in (0, 1] m, got inf"},
      {"half_round:20", "got 20 (more than any vehicle's ground clearance"},
  };
  for (const Bad& b : bad) {
    SCOPED_TRACE(b.spec);
    EXPECT_FALSE(isBuiltInTrack(b.spec));
    const std::vector<std::string> parts = {"track '" + b.spec + "': ", b.fault};
    expectInputError([&] { makeTrack(b.spec); }, parts);
    expectInputError([&] { checkTrackName(b.spec); }, parts);
    expectInputError([&] { defaultLateralOffset(b.spec); }, parts);
    // Not "neither a built-in track nor a terrain file": the spec's own fault.
    expectInputError([&] { loadTrack(b.spec); }, parts);
  }
  expectInputError([] { makeHalfRound(-0.2); }, {"track 'half_round:-0.2'", "got -0.2"});
  expectInputError([] { loadTrack("moon"); }, {"neither a built-in track", "half_round:H"});
  TrackOptions bad_options;
  bad_options.smoothing_window = -1.0;
  expectInputError([&] { makeTrack("half_round:0.2", bad_options); },
                   {"track 'half_round:0.2'", "TrackOptions::smoothing_window"});
}

// ---------------------------------------------------------------------------------------------
// ISO 8608

TEST(Iso8608, ClassReferencePsd) {
  EXPECT_DOUBLE_EQ(iso8608ReferencePsd('A'), 16e-6);
  EXPECT_DOUBLE_EQ(iso8608ReferencePsd('C'), 256e-6);
  EXPECT_DOUBLE_EQ(iso8608ReferencePsd('h'), 16e-6 * std::pow(4.0, 7));
  EXPECT_DOUBLE_EQ(iso8608Psd('B', 0.2), 64e-6 / 4.0);
  expectInputError([] { iso8608ReferencePsd('I'); }, {"class 'I' is not one of A..H"});
  expectInputError([] { makeIso8608('Z', 100.0, 5.0, 0.05, 1); }, {"class 'Z'"});
  expectInputError([] { makeIso8608('C', 100.0, 5.0, 0.25, 1); }, {"Nyquist"});
  expectInputError([] { makeIso8608('C', -1.0, 5.0, 0.05, 1); }, {"length -1 m"});
  // A length typed in millimetres (2000 km) is refused at once, not left to exhaust the memory.
  expectInputError(
      [] { makeIso8608('C', 2e6, 5.0, 0.05, 1); },
      {"length 2e+06 m", "40000001 stations; at most 2e+07", "generate a shorter road"});
}

TEST(Iso8608, VarianceIsThePsdIntegralInClosedForm) {
  // ∫ G0 (n/n0)^-2 dn over [a, b] = G0 n0^2 (1/a - 1/b); class C, the ISO band 0.011 .. 2.83:
  // 256e-6 * 0.01 * (1/0.011 - 1/2.83) = 2.31823e-4 m^2.
  const double c_band = 256e-6 * 0.01 * (1.0 / 0.011 - 1.0 / 2.83);
  EXPECT_NEAR(iso8608Variance('C', 0.011, 2.83) / c_band, 1.0, kRoundoff);
  EXPECT_NEAR(c_band, 2.31823e-4, 1e-9);
  // w = 4: G0 n0^4 (a^-3 - b^-3) / 3.
  EXPECT_NEAR(iso8608Variance('B', 0.05, 1.0, 4.0) / (64e-6 * 1e-4 * (8000.0 - 1.0) / 3.0), 1.0,
              kRoundoff);
  // w = 1, a branch of its own (the power law's antiderivative is a logarithm there):
  // G0 n0 ln(b / a), and continuous with its neighbours.
  const double log_band = 16e-6 * 0.1 * std::log(10.0);
  EXPECT_NEAR(iso8608Variance('A', 0.1, 1.0, 1.0) / log_band, 1.0, kRoundoff);
  EXPECT_NEAR(iso8608Variance('A', 0.1, 1.0, 1.0 + 1e-7) / log_band, 1.0, 1e-6);
  EXPECT_NEAR(iso8608Variance('A', 0.1, 1.0, 1.0 - 1e-7) / log_band, 1.0, 1e-6);
}

TEST(Iso8608, SampledVarianceIsTheBandsVariance) {
  const double length = 200.0;
  const double spacing = 0.05;
  Iso8608Options options;  // ISO band 0.011 .. 2.83 cycles/m, no taper
  const Terrain road = makeIso8608('C', length, 5.0, spacing, 42, options);
  const Vector h = road.profile(0.0);
  // One period: samples 0 .. N-2 (the last station repeats the first). The harmonics are whole
  // periods of it and below Nyquist, so they are orthogonal on the samples and the variance is
  // Σ a_k^2 / 2 exactly, whatever the random phases: the bins [(k ∓ 1/2) / L] clipped to the
  // band tile it (1/(2L) = 0.0025 lies below 0.011), so Σ a_k^2 / 2 = ∫ G over the band.
  const Vector period = h.head(h.size() - 1);
  const double mean = period.mean();
  const double variance = (period.array() - mean).square().mean();
  const double expected = 256e-6 * 0.01 * (1.0 / 0.011 - 1.0 / 2.83);
  EXPECT_NEAR(variance / expected, 1.0, 1e-9);
  EXPECT_NEAR(mean, 0.0, 1e-12);
}

TEST(Iso8608, PeriodogramFollowsClassPsd) {
  const double length = 200.0;
  const double spacing = 0.05;
  const Terrain road = makeIso8608('D', length, 5.0, spacing, 7);
  const Vector h = road.profile(0.0);
  const Eigen::Index m = h.size() - 1;  // samples in one period
  // Harmonic k carries the PSD integrated over its bin [(k - 1/2), (k + 1/2)] / L, so its
  // periodogram a_k^2 L / 2 is the bin's mean of G = G0 n0^2 n^-2, that is G(k/L) / (1 - 1/(4k^2)),
  // whatever its random phase (class D: G0 = 1024e-6 m^3, n0 = 0.1 cycles/m).
  for (int k = 10; k <= 500; k += 7) {
    std::complex<double> x(0.0, 0.0);
    for (Eigen::Index i = 0; i < m; ++i)
      x += h(i) * std::polar(1.0, -2.0 * kPi * k * i / m);
    const double amplitude = 2.0 * std::abs(x) / static_cast<double>(m);
    const double psd = amplitude * amplitude / 2.0 * length;  // a_k^2 / (2 Δn)
    const double n = k / length;
    const double bin_mean = 1024e-6 * std::pow(n / 0.1, -2.0) / (1.0 - 1.0 / (4.0 * k * k));
    EXPECT_NEAR(psd / bin_mean, 1.0, 1e-8) << "harmonic " << k;
  }
}

TEST(Iso8608, SeedsAreDeterministicAndClassesScale) {
  const Terrain a = makeIso8608('B', 100.0, 5.0, 0.05, 123);
  const Terrain b = makeIso8608('B', 100.0, 5.0, 0.05, 123);
  const Terrain c = makeIso8608('B', 100.0, 5.0, 0.05, 124);
  EXPECT_EQ(a.heights(), b.heights());
  EXPECT_GT((a.heights() - c.heights()).cwiseAbs().maxCoeff(), 1e-3);
  // One class up is 4x the PSD: the same seed gives twice the heights.
  const Terrain up = makeIso8608('C', 100.0, 5.0, 0.05, 123);
  EXPECT_TRUE(up.heights().isApprox(2.0 * a.heights(), 1e-12));
  // Fully correlated by default: both sides see the same profile.
  EXPECT_EQ(a.profile(-2.5), a.profile(2.5));
}

// The taper is the raised cosine w(d) = (1 - cos(pi d / L)) / 2 of the distance d to the nearer
// end, and 1 beyond L: the same road with and without it differ by exactly that factor.
TEST(Iso8608, TaperIsARaisedCosineOfTheDistanceToTheEnd) {
  Iso8608Options tapered;
  tapered.taper_length = 5.0;
  const Terrain plain = makeIso8608('C', 100.0, 3.0, 0.05, 7);
  const Terrain road = makeIso8608('C', 100.0, 3.0, 0.05, 7, tapered);
  double worst = 0.0;
  for (Eigen::Index i = 0; i < plain.stations().size(); ++i) {
    const double d = std::min(plain.stations()(i), 100.0 - plain.stations()(i));
    const double w = d < 5.0 ? 0.5 * (1.0 - std::cos(kPi * d / 5.0)) : 1.0;
    worst = std::max(worst, std::abs(road.heights()(0, i) - w * plain.heights()(0, i)));
  }
  EXPECT_LT(worst, 1e-12);
}

// Each harmonic's phase is uniform on [0, 2 pi): the road is zero-mean over seeds. With the
// harmonics on the DFT's grid (k / length) and no taper, the DFT of one road gives each phase
// back, so their signs split about evenly (a phase drawn on [0, pi) would leave none negative).
TEST(Iso8608, HarmonicPhasesCoverTheWholeCircle) {
  const double length = 100.0, dx = 0.05;
  const Terrain road = makeIso8608('C', length, 3.0, dx, 3);
  const int samples = static_cast<int>(std::lround(length / dx));
  int negative = 0, harmonics = 0;
  for (int k = 2; k <= 280; ++k) {  // inside the default band, 0.011 .. 2.83 cycles/m
    std::complex<double> x = 0.0;
    for (int i = 0; i < samples; ++i)
      x += road.heights()(0, i) * std::polar(1.0, -2.0 * kPi * k * i / samples);
    ++harmonics;
    negative += std::arg(x) < 0.0 ? 1 : 0;
  }
  const double share = static_cast<double>(negative) / harmonics;
  EXPECT_GT(share, 0.3);
  EXPECT_LT(share, 0.7);
}

TEST(Iso8608, IndependentSidesAndTaper) {
  Iso8608Options options;
  options.correlation = LateralCorrelation::IndependentSides;
  options.taper_length = 5.0;
  const Terrain road = makeIso8608('E', 100.0, 4.0, 0.05, 9, options);
  ASSERT_EQ(road.lateral().size(), 4);
  const Vector right = road.profile(-1.5);
  const Vector left = road.profile(1.5);
  EXPECT_GT((left - right).cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_NEAR(right(0), 0.0, kRoundoff);
  EXPECT_NEAR(left(left.size() - 1), 0.0, kRoundoff);
}

// ---------------------------------------------------------------------------------------------
// Files

TEST(TerrainIo, CsvRoundTripIsExact) {
  const TempDir dir;
  const Terrain hill = makeTrack("long_hill");
  const std::string path = dir.file("long_hill.csv");
  hill.saveCsv(path);
  const Terrain loaded = loadTerrain(path);
  EXPECT_EQ(loaded.name(), "long_hill");
  EXPECT_EQ(loaded.stations(), hill.stations());
  EXPECT_EQ(loaded.lateral(), hill.lateral());
  EXPECT_EQ(loaded.heights(), hill.heights());
}

TEST(TerrainIo, YamlRoundTripIsExact) {
  const TempDir dir;
  const Terrain road = makeIso8608('C', 20.0, 3.0, 0.05, 5);
  const std::string path = dir.file("road.yaml");
  road.saveYaml(path);
  const Terrain loaded = loadTerrain(path);
  EXPECT_EQ(loaded.name(), road.name());
  EXPECT_EQ(loaded.stations(), road.stations());
  EXPECT_EQ(loaded.lateral(), road.lateral());
  EXPECT_EQ(loaded.heights(), road.heights());
}

TEST(TerrainIo, TwoColumnCsvIsUniformAcrossWidth) {
  const TempDir dir;
  for (const std::string& content :
       {std::string("x,h\n0,0\n1,0.5\n"), std::string("0,0\n1,0.5\n")}) {
    const Terrain t = loadTerrainCsv(dir.file("profile.csv", content));
    EXPECT_EQ(t.lateral().size(), 1);
    EXPECT_DOUBLE_EQ(t.height(0.5, -2.0), 0.25);
    EXPECT_DOUBLE_EQ(t.height(0.5, 2.0), 0.25);
  }
}

TEST(TerrainIo, ShippedExamplesLoad) {
  const std::string dir = std::string(TVD_SOURCE_DIR) + "/config/tracks/";
  const Terrain bump = loadTerrain(dir + "bump.yaml");
  EXPECT_EQ(bump.name(), "bump");
  EXPECT_NEAR(bump.height(1.5, 0.0), 0.1, 1e-9);
  const Terrain twist = loadTerrain(dir + "twist.csv");
  EXPECT_EQ(twist.lateral().size(), 3);
  EXPECT_NEAR(twist.height(1.5, 1.5), -twist.height(1.5, -1.5), kRoundoff);
  EXPECT_GT(twist.height(1.5, 1.5), 0.0);
  const Terrain step = loadTerrain(dir + "step_profile.csv");
  EXPECT_DOUBLE_EQ(step.height(3.0, 1.0), 0.05);
  // Ground that looks like ground (the README runs them): no warning.
  for (const char* file : {"bump.yaml", "twist.csv", "step_profile.csv", "flat_15m.csv"})
    EXPECT_TRUE(terrainWarnings(file, loadTerrain(dir + file)).empty()) << file;
}

TEST(TerrainIo, CsvLineEndingsOfEveryKindReadAlike) {
  // LF, CR LF and a lone CR (classic Mac OS): the same terrain, and the same row numbers in a
  // message. Read as one line, a CR-only file was a single comment ("empty").
  const TempDir dir;
  const std::string lines[] = {"# twist", "x,-1,1", "0,0,0", "1,0.1,-0.1", "2,0,0"};
  Matrix first;
  for (const std::string end : {"\n", "\r\n", "\r"}) {
    std::string text;
    for (const std::string& line : lines)
      text += line + end;
    const Terrain t = loadTerrainCsv(dir.file("ends.csv", text));
    ASSERT_EQ(t.stations().size(), 3);
    EXPECT_DOUBLE_EQ(t.height(1.0, 1.0), -0.1);
    if (first.size() > 0) {
      EXPECT_EQ(t.heights(), first);
    }
    first = t.heights();
    std::string bad = text;
    bad.replace(bad.find("0.1"), 3, "abc");
    expectInputError([&] { loadTerrainCsv(dir.file("bad_ends.csv", bad)); },
                     {"row 4, column 2", "'abc' is not a number"});
  }
}

TEST(TerrainIo, BadCsvNamesFileAndRow) {
  const TempDir dir;
  struct Case {
    std::string content;
    std::vector<std::string> parts;
  };
  const std::vector<Case> cases = {
      {"x,-1,1\n0,0,0\n1,nan,0\n", {"row 3, column 2", "height 'nan' is not a finite number"}},
      {"x,-1,1\n0,0,0\ninf,0,0\n", {"row 3, column 1", "station 'inf' is not a finite number"}},
      {"x,-1,1\n0,0,0\n1,0,1e30\n", {"row 3, column 3", "height 1e+30 m is beyond +-10000 m"}},
      {"x,-1,1\n0,0,0\n1e300,0,0\n", {"row 3, column 1", "station 1e+300 m is beyond +-1e+08 m"}},
      {"x,-1,1\n-1e300,0,0\n1,0,0\n", {"row 2, column 1", "station -1e+300 m is beyond +-1e+08 m"}},
      {std::string("x,-1,1\n0,0,0\n1,0\0,0\n", 21),
       {"row 3, column 2", "height '0\\x00' is not a number"}},
      {"x,-1,1\n0,0,0\n1,0,0\n1,0,0\n", {"row 4", "duplicate station x = 1 m (also on row 3)"}},
      {"x,-1,1\n0,0,0\n2,0,0\n1,0,0\n", {"row 4", "stations must be strictly increasing"}},
      {"x,-1,1\n0,0,0\n1e-300,0.1,0\n2,0.1,0\n",
       {"row 3",
        "station x = 1e-300 m is 1e-300 m from the previous station; at least 1e-06 m "
        "apart"}},
      {"x,-1,-0.9999999999\n0,0,0\n1,0,0\n",
       {"lateral line 1 (-0.9999999999 m) is 1e-10 m from lateral line 0; at least 1e-06 m apart"}},
      // A cell is shown up to 60 characters (a 500,000-digit one made a 500 kB line).
      {"x,-1,1\n0,0,0\n1," + std::string(500000, '3') + ",0\n",
       {"row 3, column 2", "height '" + std::string(60, '3') +
                               "... (500000 characters)' is out of "
                               "range"}},
      {"x,-1,1\n0,0,0\n1,0\n", {"row 3", "expected 3 columns (x and 2 heights), got 2"}},
      {"x,-1,1\n0,0,0\n1,abc,0\n", {"row 3, column 2", "height 'abc' is not a number"}},
      // Beyond a double's range either way: out of range, as the YAML reader says it.
      {"x,-1,1\n0,0,0\n1,1e400,0\n", {"row 3, column 2", "height '1e400' is out of range"}},
      {"x,-1,1\n0,0,0\n1,0,-1e-400\n", {"row 3, column 3", "height '-1e-400' is out of range"}},
      {"# only a comment\n\n", {"empty (no header or data rows)"}},
      {"x,-1,1\n", {"no data rows (only a header)"}},
      {"0,0,0\n1,0,0\n", {"row 1", "need a header row"}},
      {"x,1,-1\n0,0,0\n", {"row 1, column 3", "lateral positions must be strictly increasing"}},
      {"x,left,right\n0,0,0\n", {"row 1, column 2", "lateral position 'left' is not a number"}},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string path = dir.file("bad" + std::to_string(i) + ".csv", cases[i].content);
    std::vector<std::string> parts = cases[i].parts;
    parts.push_back(path);
    SCOPED_TRACE(cases[i].content);
    expectInputError([&] { loadTerrainCsv(path); }, parts);
  }
  // Stations exactly 1 um apart load, in either format, though their differences round either
  // side of 1e-6 (3e-6 - 2e-6 = 9.999999999999999e-7), far out too (1e8 m: 1.5e-8 m a bit).
  EXPECT_EQ(loadTerrainCsv(dir.file("micron.csv", "x,h\n0,0\n1e-6,0\n2e-6,0\n3e-6,0\n"))
                .stations()
                .size(),
            4);
  EXPECT_EQ(loadTerrain(dir.file("micron.yaml",
                                 "spacing: 1e-6\nstart: 99999999\nheights: [0, 0, "
                                 "0, 0, 0, 0, 0, 0, 0, 0]\n"))
                .stations()
                .size(),
            10);
  // A subnormal is a double all the same (what a save of a tiny value writes).
  EXPECT_EQ(
      loadTerrainCsv(dir.file("subnormal.csv", "x,-1,1\n0,0,0\n1,1e-320,0\n")).heights()(0, 1),
      1e-320);
  // The bound itself is a station like any other.
  EXPECT_EQ(loadTerrainCsv(dir.file("bound.csv", "x,-1,1\n0,0,0\n1e8,0,0\n")).endStation(), 1e8);
  expectInputError([&] { loadTerrain(dir.file("missing.csv")); },
                   {"missing.csv", "file not found"});
  expectInputError([&] { loadTerrain(dir.file("terrain.txt", "0,0\n")); },
                   {"terrain.txt", "unknown terrain file type '.txt'"});
}

TEST(TerrainIo, BadYamlNamesFileAndKey) {
  const TempDir dir;
  struct Case {
    std::string content;
    std::vector<std::string> parts;
  };
  const std::vector<Case> cases = {
      {"spacing: 0.1\ny: [-1, 1]\nheights:\n  - [0, 0, 0]\n  - [0, 0, .nan]\n",
       {"heights[1][2]", "not a finite number"}},
      {"spacing: 0.1\ny: [-1, 1]\nheights:\n  - [0, 0, 0]\n  - [0, 0]\n",
       {"heights[1]", "expected 3 heights"}},
      {"x: [0, 1, 1]\nheights: [0, 0, 0]\n", {"x[2]", "duplicate station 1 m"}},
      {"x: [0, 2, 1]\nheights: [0, 0, 0]\n", {"x[2]", "stations must be strictly increasing"}},
      {"x: [0, 1]\nheights: [0, 0, 0]\n", {"x", "got 2 entries"}},
      {"spacing: 0.1\nx: [0, 1, 2]\nheights: [0, 0, 0]\n", {"exactly one of 'spacing'"}},
      {"spacing: -0.1\nheights: [0, 0, 0]\n", {"spacing", "must be at least 1e-06 m"}},
      // Stations closer than 1 um: a subnormal spacing made the slope infinite, and the run
      // failed late naming no file.
      {"spacing: 1e-300\nheights: [0, 0, 0]\n",
       {"spacing: spacing 1e-300 m must be at least 1e-06 m"}},
      {"x: [0, 1e-9, 2]\nheights: [0, 0.1, 0.1]\n",
       {"x[1]", "station 1e-09 m is 1e-09 m from the previous one; at least 1e-06 m apart"}},
      {"spacing: 0.1\n", {"heights", "required key is missing"}},
      {"spacing: 0.1\nheights: [0, 0]\nwidth: 3\n", {"width", "unknown key"}},
      // Another of the package's files is named for what it is (its first key was "unknown").
      {"name: beam\nnodes:\n  - {id: 1, x: [0, 0, 0]}\n",
       {"not a terrain file", "this is an FE model file"}},
      {"hull:\n  mass: {value: 30300, unit: kg, source: x}\n",
       {"not a terrain file", "this is a vehicle description"}},
      {"spacing: 0.1\ny: [1, -1]\nheights: [[0], [0]]\n",
       {"y[1]", "lateral positions must be strictly increasing"}},
      {"spacing: 0.1\nheights: []\n", {"heights", "at least one height"}},
      {"spacing: 0.1\ny: [-1, 1]\nheights: [[0, 0.1, 0.2], [0, 5e4, 0]]\n",
       {"heights[1][1]", "height 50000 m is beyond +-10000 m", "(line 3)"}},
      {"spacing: 0.1\nheights: [0, 0.1, -2e4]\n", {"heights[2]", "-20000 m is beyond"}},
      {"spacing: 0.1\nstart: 1e300\nheights: [0, 0.1, 0]\n",
       {"start: start 1e+300 m and spacing 0.1 m give station 1 = 1e+300 m", "(line 2)"}},
  };
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const std::string path = dir.file("bad" + std::to_string(i) + ".yaml", cases[i].content);
    std::vector<std::string> parts = cases[i].parts;
    parts.push_back(path);
    SCOPED_TRACE(cases[i].content);
    expectInputError([&] { loadTerrainYaml(path); }, parts);
  }
}

// ---------------------------------------------------------------------------------------------
// TerrainBuffer

/// A patch of h = 0.1 x + 0.05 y, linear so that interpolation and bridging are exact.
void addPlane(TerrainBuffer* buffer, double start, double spacing, int samples) {
  Vector y(3);
  y << -1.0, 0.0, 1.0;
  Matrix h(3, samples);
  for (int j = 0; j < 3; ++j) {
    for (int k = 0; k < samples; ++k)
      h(j, k) = 0.1 * (start + k * spacing) + 0.05 * y(j);
  }
  buffer->addPatch(start, spacing, y, h);
}

TEST(TerrainBuffer, ContiguousPatchesActAsOneGrid) {
  TerrainBuffer buffer;
  EXPECT_TRUE(buffer.empty());
  EXPECT_EQ(buffer.coveredUntil(), -std::numeric_limits<double>::infinity());
  expectInputError([&] { buffer.height(0.0, 0.0); }, {"not covered", "no terrain received"});
  addPlane(&buffer, 0.0, 0.1, 10);  // 0 .. 0.9
  addPlane(&buffer, 1.0, 0.1, 10);  // 1.0 .. 1.9: the 0.9 .. 1.0 gap is bridged
  EXPECT_EQ(buffer.patchCount(), 2u);
  EXPECT_DOUBLE_EQ(buffer.coveredFrom(), 0.0);
  EXPECT_NEAR(buffer.coveredUntil(), 1.9, kRoundoff);
  for (double x = 0.0; x <= 1.9; x += 0.023) {
    for (double y : {-1.0, -0.3, 0.8}) {
      ASSERT_TRUE(buffer.covers(x)) << x;
      EXPECT_NEAR(buffer.height(x, y), 0.1 * x + 0.05 * y, kRoundoff) << "x = " << x;
    }
  }
  EXPECT_FALSE(buffer.covers(2.5));
  expectInputError([&] { buffer.height(2.5, 0.0); },
                   {"x = 2.5 m is not covered", "contiguous until 1.9 m"});
  // A hole: coverage stays contiguous up to 1.9 m.
  addPlane(&buffer, 5.0, 0.1, 10);
  EXPECT_NEAR(buffer.coveredUntil(), 1.9, kRoundoff);
  EXPECT_FALSE(buffer.covers(3.0));
  EXPECT_TRUE(buffer.covers(5.5));
}

// Patches ending (or starting) at the same station with different spacings: whether the gap
// after (before) them is bridged is judged the same way by the contiguous coverage and by the
// height lookup, so every station up to coveredUntil() has a height (review 132: a fine patch
// ending with a coarse one made the coverage bridge a gap the lookup refused, and every step of
// the online vehicle threw there).
TEST(TerrainBuffer, CoverageAndLookupAgreeOnPatchesEndingOrStartingTogether) {
  const auto expectHeightsUpToCoverage = [](const TerrainBuffer& buffer, double until) {
    EXPECT_NEAR(buffer.coveredUntil(), until, kRoundoff);
    for (double x = buffer.coveredFrom(); x <= buffer.coveredUntil(); x += 0.01) {
      ASSERT_TRUE(buffer.covers(x)) << "x = " << x;
      EXPECT_NEAR(buffer.height(x, 0.0), 0.1 * x, 1e-9) << "x = " << x;
    }
  };
  {
    SCOPED_TRACE("equal ends");
    TerrainBuffer buffer;
    addPlane(&buffer, 0.0, 1.0, 11);   // 0 .. 10, coarse
    addPlane(&buffer, 9.0, 0.1, 11);   // 9 .. 10, fine and newer: the heights near 10 m
    addPlane(&buffer, 11.2, 0.1, 11);  // after a 1.2 m gap: within 1.5 of the coarse spacing
    expectHeightsUpToCoverage(buffer, 12.2);
  }
  {
    SCOPED_TRACE("equal ends, the coarse patch starting later");
    TerrainBuffer buffer;
    addPlane(&buffer, 0.0, 0.125, 81);  // 0 .. 10, fine (binary fractions: the ends are equal)
    addPlane(&buffer, 9.0, 1.0, 2);     // 9 .. 10, coarse and newer, ending with it
    addPlane(&buffer, 11.2, 0.1, 11);   // after a 1.2 m gap: within 1.5 of the coarse spacing
    expectHeightsUpToCoverage(buffer, 12.2);
  }
  {
    SCOPED_TRACE("equal starts");
    TerrainBuffer buffer;
    addPlane(&buffer, 0.0, 0.1, 11);  // 0 .. 1.0
    addPlane(&buffer, 1.2, 1.0, 11);  // 1.2 .. 11.2, coarse: bridges the 0.2 m gap
    addPlane(&buffer, 1.2, 0.05, 5);  // 1.2 .. 1.4, fine and newer: the heights after the gap
    expectHeightsUpToCoverage(buffer, 11.2);
  }
  {
    SCOPED_TRACE("a gap neither side bridges");
    TerrainBuffer buffer;
    addPlane(&buffer, 0.0, 0.1, 11);  // 0 .. 1.0
    addPlane(&buffer, 1.2, 0.1, 11);  // a 0.2 m gap > 1.5 x 0.1 m
    expectHeightsUpToCoverage(buffer, 1.0);
    EXPECT_FALSE(buffer.covers(1.1));
  }
}

TEST(TerrainBuffer, NewerPatchWinsAndFreesCoveredOnes) {
  TerrainBuffer buffer;
  addPlane(&buffer, 0.0, 0.1, 20);  // 0 .. 1.9
  Vector y(1);
  y << 0.0;
  buffer.addPatch(0.5, 0.1, y, Matrix::Constant(1, 4, 7.0));  // 0.5 .. 0.8
  EXPECT_DOUBLE_EQ(buffer.height(0.6, 0.3), 7.0);
  EXPECT_NEAR(buffer.height(0.3, 0.0), 0.03, kRoundoff);
  EXPECT_NEAR(buffer.height(1.2, 0.0), 0.12, kRoundoff);
  EXPECT_EQ(buffer.patchCount(), 2u);
  // A patch over everything frees both.
  addPlane(&buffer, 0.0, 0.05, 41);  // 0 .. 2.0
  EXPECT_EQ(buffer.patchCount(), 1u);
  EXPECT_NEAR(buffer.height(0.6, 0.0), 0.06, kRoundoff);
}

TEST(TerrainBuffer, DropBehindFreesOldDataAndKeepsTheRest) {
  TerrainBuffer buffer;
  for (int p = 0; p < 5; ++p)
    addPlane(&buffer, p * 1.0, 0.1, 10);  // 0 .. 4.9
  EXPECT_NEAR(buffer.coveredUntil(), 4.9, kRoundoff);
  buffer.dropBehind(2.35);
  EXPECT_EQ(buffer.patchCount(), 3u);
  // The patch from 2 m is kept whole while less than half of it lies behind (a cut copies the
  // rest); at 2.55 m half does, and it is cut at its last sample before, 2.5 m.
  EXPECT_NEAR(buffer.coveredFrom(), 2.0, kRoundoff);
  EXPECT_FALSE(buffer.covers(1.0));
  buffer.dropBehind(2.55);
  EXPECT_EQ(buffer.patchCount(), 3u);
  EXPECT_NEAR(buffer.coveredFrom(), 2.5, kRoundoff);
  for (double x = 2.55; x <= 4.9; x += 0.05)
    EXPECT_NEAR(buffer.height(x, 0.0), 0.1 * x, kRoundoff);
  // Dropping just past a patch end keeps the bridge into the next patch.
  buffer.dropBehind(2.95);
  EXPECT_NEAR(buffer.height(2.95, 0.0), 0.295, kRoundoff);
  buffer.clear();
  EXPECT_TRUE(buffer.empty());
}

// gridFor(): the grid it returns answers exactly as height() everywhere in the interval it
// gives (newer patches overlapping an older one cut the interval), and nothing outside patches.
TEST(TerrainBuffer, GridForGivesTheAnsweringGridAndWhereItAnswers) {
  TerrainBuffer buffer;
  addPlane(&buffer, 0.0, 0.1, 30);  // 0 .. 2.9
  Vector y(1);
  y << 0.0;
  buffer.addPatch(1.0, 0.1, y, Matrix::Constant(1, 5, 7.0));  // newer, 1.0 .. 1.4, inside
  addPlane(&buffer, 3.0, 0.1, 10);                            // 3.0 .. 3.9 (bridged gap)
  const std::uint64_t revision = buffer.revision();
  double from = 0.0, until = 0.0;
  const Terrain* grid = buffer.gridFor(0.5, &from, &until);
  ASSERT_NE(grid, nullptr);
  EXPECT_EQ(from, 0.0);
  EXPECT_GT(until, 0.9);
  EXPECT_LT(until, 1.0);  // the newer patch takes over at 1.0
  EXPECT_EQ(buffer.gridFor(2.0, &from, &until), grid);
  EXPECT_GT(from, 1.4);
  EXPECT_LT(from, 1.5);
  EXPECT_NEAR(until, 2.9, kRoundoff);
  ASSERT_NE(buffer.gridFor(1.2, &from, &until), nullptr);
  EXPECT_DOUBLE_EQ(buffer.gridFor(1.2, &from, &until)->height(1.2, 0.0), 7.0);
  EXPECT_EQ(buffer.gridFor(2.95, &from, &until), nullptr);  // bridged gap: ask height()
  EXPECT_EQ(buffer.gridFor(5.0, &from, &until), nullptr);   // not covered
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> station(-0.5, 4.5);
  for (int k = 0; k < 500; ++k) {
    const double x = station(rng);
    const Terrain* g = buffer.gridFor(x, &from, &until);
    if (g == nullptr)
      continue;
    ASSERT_LE(from, x);
    ASSERT_GE(until, x);
    for (double t : {0.0, 0.37, 1.0}) {
      const double xt = from + t * (until - from);
      for (double yt : {-0.7, 0.0, 0.4}) {
        const Terrain::LateralCell cell = g->lateralCellOf(yt);
        EXPECT_EQ(g->height(xt, cell), buffer.height(xt, yt)) << "x " << x << " at " << xt;
      }
    }
  }
  EXPECT_EQ(buffer.revision(), revision);  // queries change nothing
  buffer.dropBehind(0.2);
  EXPECT_NE(buffer.revision(), revision);
}

// One long patch under a vehicle that keeps receiving short ones ahead: each arrival's
// dropBehind() used to copy the rest of the long patch (3 ms a time for 10 km). It is cut only
// when half of it lies behind, so over 10,000 arrivals it is cut a handful of times, each cut at
// least halving it, and every height ahead is kept.
TEST(TerrainBuffer, ALongPatchIsCutByHalvesNotAtEveryArrival) {
  TerrainBuffer buffer;
  addPlane(&buffer, 0.0, 0.1, 10001);  // 0 .. 1000 m
  double from = buffer.coveredFrom();
  int cuts = 0;
  for (int k = 1; k <= 1000; ++k) {
    const double station = k * 1.0;
    addPlane(&buffer, 1000.0 + station, 0.1, 11);  // a metre ahead, every metre
    buffer.dropBehind(station - 0.5);
    if (buffer.coveredFrom() != from) {
      ++cuts;
      // Cut at the last sample at or before the station, after half of what was there.
      EXPECT_LE(buffer.coveredFrom(), station - 0.5 + kRoundoff);
      EXPECT_GE(buffer.coveredFrom() - from, 0.5 * (1000.0 - from) - 0.1);
      from = buffer.coveredFrom();
    }
    EXPECT_NEAR(buffer.height(station, 0.0), 0.1 * station, 1e-9);
  }
  EXPECT_GE(cuts, 8);  // 0 -> 500 -> 750 -> ... -> 999
  EXPECT_LE(cuts, 12);
}

// The memory limit: storedBytes() counts every stored grid as patchBytes() does, through adds,
// replacements, cuts and drops; a patch that would take it beyond the limit is refused, naming
// the sizes, and nothing changes; one replacing stored patches counts what it frees.
TEST(TerrainBuffer, MemoryLimitRefusesAPatchBeyondItAndCountsWhatIsFreed) {
  EXPECT_EQ(TerrainBuffer::patchBytes(1, 20), 8u * (20 * 2 + 1));
  EXPECT_EQ(TerrainBuffer::patchBytes(9, 1000), 8u * (1000 * 10 + 9));
  // Saturates instead of wrapping.
  EXPECT_EQ(TerrainBuffer::patchBytes(1u << 20, std::size_t{1} << 60),
            std::numeric_limits<std::size_t>::max());
  TerrainBuffer buffer;
  EXPECT_EQ(buffer.storedBytes(), 0u);
  const std::size_t plane = TerrainBuffer::patchBytes(3, 10);  // addPlane: three lines
  for (int p = 0; p < 3; ++p)
    addPlane(&buffer, p * 1.0, 0.1, 10);  // 0 .. 2.9
  EXPECT_EQ(buffer.storedBytes(), 3 * plane);
  EXPECT_NEAR(buffer.furthestEnd(), 2.9, kRoundoff);
  buffer.setMemoryLimit(4 * plane);
  addPlane(&buffer, 3.0, 0.1, 10);  // exactly the limit: taken
  EXPECT_EQ(buffer.storedBytes(), 4 * plane);
  const std::uint64_t revision = buffer.revision();
  try {
    addPlane(&buffer, 100.0, 0.1, 10);
    FAIL() << "a patch beyond the limit was taken";
  } catch (const InputError& e) {
    const std::string text = e.what();
    for (const char* part : {"patch at station 100 m", "stored (stations 0 .. 3.9 m)",
                             "exceed the terrain buffer's limit", "far ahead of the vehicle"})
      EXPECT_NE(text.find(part), std::string::npos) << part << " in: " << text;
  }
  EXPECT_EQ(buffer.revision(), revision);  // nothing changed
  EXPECT_EQ(buffer.patchCount(), 4u);
  EXPECT_FALSE(buffer.covers(100.5));
  // A patch over the first two frees them: 4 - 2 + 1 patches' worth, within the limit.
  addPlane(&buffer, 0.0, 0.1, 20);  // 0 .. 1.9
  EXPECT_EQ(buffer.patchCount(), 3u);
  EXPECT_EQ(buffer.storedBytes(), 2 * plane + TerrainBuffer::patchBytes(3, 20));
  // Cuts count what they keep: the 20-sample patch cut at 1.0 m keeps 10 samples.
  buffer.dropBehind(1.05);
  EXPECT_EQ(buffer.storedBytes(), 3 * plane);
  // Drops free (the patch from 2 m, cut to its last sample on the way): now the far patch fits.
  buffer.dropBehind(3.05);
  EXPECT_EQ(buffer.storedBytes(), plane + TerrainBuffer::patchBytes(3, 1));
  buffer.dropBehind(3.2);
  EXPECT_EQ(buffer.patchCount(), 1u);
  EXPECT_EQ(buffer.storedBytes(), plane);
  addPlane(&buffer, 100.0, 0.1, 10);
  EXPECT_EQ(buffer.storedBytes(), 2 * plane);
  EXPECT_NEAR(buffer.furthestEnd(), 100.9, kRoundoff);
  // A patch larger than the limit alone says so without a stored part.
  buffer.clear();
  EXPECT_EQ(buffer.storedBytes(), 0u);
  EXPECT_EQ(buffer.furthestEnd(), -std::numeric_limits<double>::infinity());
  expectInputError([&] { addPlane(&buffer, 0.0, 0.1, 100); },
                   {"patch at station 0 m: 3.2 kB exceeds the terrain buffer's limit of 1.4 kB"});
  EXPECT_TRUE(buffer.empty());
}

TEST(TerrainBuffer, RejectsBadPatches) {
  TerrainBuffer buffer;
  Vector y(2);
  y << -1.0, 1.0;
  Matrix h = Matrix::Zero(2, 5);
  expectInputError([&] { buffer.addPatch(3.0, 0.0, y, h); },
                   {"patch at station 3 m", "spacing 0 m must be positive"});
  expectInputError([&] { buffer.addPatch(3.0, 0.1, y, Matrix::Zero(3, 5)); },
                   {"3 lines", "2 lateral positions"});
  h(1, 4) = std::nan("");
  expectInputError([&] { buffer.addPatch(3.0, 0.1, y, h); }, {"line 1, sample 4 is not finite"});
  // Finite but beyond +-10 km (a height in millimetres read as metres, or a sentinel such as
  // -3.4e38 for "no data"): refused through the grid's own check, naming the sample.
  h(1, 4) = -3.4e38;
  expectInputError([&] { buffer.addPatch(3.0, 0.1, y, h); },
                   {"patch at x = 3 m", "lateral line 1", "station 4 (x = 3.4 m)", "+-10000 m"});
  h(1, 4) = 0.0;
  Vector reversed(2);
  reversed << 1.0, -1.0;
  expectInputError([&] { buffer.addPatch(3.0, 0.1, reversed, Matrix::Zero(2, 5)); },
                   {"lateral position 1", "not greater"});
  expectInputError([&] { buffer.addPatch(std::nan(""), 0.1, y, Matrix::Zero(2, 5)); },
                   {"start station is not finite"});
  // Spacings that pass as positive and finite but break the grid: named as the spacing.
  expectInputError([&] { buffer.addPatch(3.0, 1e308, y, Matrix::Zero(2, 5)); },
                   {"spacing 1e+308 m over 5 samples", "not finite and distinct"});
  expectInputError([&] { buffer.addPatch(1e6, 1e-300, y, Matrix::Zero(2, 5)); },
                   {"spacing 1e-300 m", "too large or too small for the start station"});
  EXPECT_TRUE(buffer.empty());
}

// The precomputed lines give Terrain::height()/slope() at their lateral positions (uniform and
// non-uniform grids, inside and outside the stations, between lateral lines), and fall back to
// the terrain for any other y; heightAndSlope() gives both at once.
TEST(TerrainLines, EqualTerrainSampling) {
  const Terrain oop = makeTrack("oop_waves");
  Vector stations(6), lateral(3);
  stations << 0.0, 0.3, 0.35, 1.0, 2.5, 2.6;
  lateral << -1.0, 0.2, 1.5;
  Matrix heights(3, 6);
  heights << 0.0, 0.1, -0.2, 0.3, 0.0, 0.5,  //
      0.2, 0.0, 0.1, -0.1, 0.4, 0.0,         //
      -0.3, 0.2, 0.0, 0.1, 0.1, 0.2;
  const Terrain uneven(stations, lateral, heights, "uneven");
  std::mt19937 rng(7);
  for (const Terrain* t : {&oop, &uneven}) {
    Vector ys(5);
    ys << t->lateral()(0) - 0.3, 0.37, -0.61, t->lateral()(t->lateral().size() - 1), 0.37;
    const TerrainLines lines(*t, ys);
    EXPECT_EQ(lines.lineCount(), 4u);  // 0.37 appears twice
    std::uniform_real_distribution<double> x(t->startStation() - 1.0, t->endStation() + 1.0);
    for (int k = 0; k < 2000; ++k) {
      const double xk = k < 10 ? t->stations()(k % t->stations().size()) : x(rng);
      for (double y : {0.37, -0.61, ys(0), 0.9 /* not a line: falls back */}) {
        const double scale = 1.0 + std::abs(t->height(xk, y));
        EXPECT_NEAR(lines.height(xk, y), t->height(xk, y), 1e-12 * scale)
            << t->name() << " x " << xk;
        EXPECT_NEAR(lines.slope(xk, y), t->slope(xk, y), 1e-9 * (1.0 + std::abs(t->slope(xk, y))))
            << t->name() << " x " << xk;
        // The combined lookup is the same arithmetic as the two separate ones.
        double h = 0.0, dhdx = 0.0;
        lines.heightAndSlope(xk, y, h, dhdx);
        EXPECT_EQ(h, lines.height(xk, y)) << t->name() << " x " << xk;
        EXPECT_EQ(dhdx, lines.slope(xk, y)) << t->name() << " x " << xk;
      }
    }
  }
}

TEST(Terrain, SlopeAtAStationIsThatOfTheCellAhead) {
  // On the stations the profile has a kink; slope() returns the slope of the cell that starts
  // there (x_i <= x < x_i+1, the cell whose height interpolation applies ahead of the station),
  // as the non-uniform lookup and TerrainLines do. On a uniform grid the cell index comes from
  // (x - x_0) / dx, which rounds just below i at some stations; the grid decides, not rounding.
  const int n = 400;
  Vector x(n);
  Matrix h(1, n);
  for (int i = 0; i < n; ++i) {
    x(i) = 0.1 * i;
    h(0, i) = 1e-3 * i * i;  // every cell has its own slope, (2 i + 1) 1e-3 / dx
  }
  const Terrain t(x, Vector::Zero(1), h);
  for (int i = 0; i + 1 < n; ++i)
    ASSERT_EQ(t.slope(x(i), 0.0), (h(0, i + 1) - h(0, i)) / (x(i + 1) - x(i))) << "x " << x(i);
}

// Linear interpolation between stations dx apart passes sinc(pi n dx)^2 of a harmonic's
// amplitude, sinc^4 of its power: checked on an interpolated sampled cosine by projecting it
// back onto the harmonic (the aliases lie at other frequencies), and the inverse.
TEST(InterpolationLoss, SincToTheFourthOfThePowerAndItsInverse) {
  for (const auto& [n, dx] : {std::pair{2.83, 0.17}, std::pair{2.83, 0.05}, std::pair{1.0, 0.3}}) {
    const long samples = 40000;
    const int fine = 16;  // interpolated points per interval
    double c = 0.0, s = 0.0, w = 0.0;
    for (long k = 0; k + 1 < samples; ++k) {
      const double h0 = std::cos(kTwoPi * n * dx * static_cast<double>(k));
      const double h1 = std::cos(kTwoPi * n * dx * static_cast<double>(k + 1));
      for (int j = 0; j < fine; ++j) {
        const double f = (j + 0.5) / fine;
        const double x = dx * (static_cast<double>(k) + f);
        const double h = (1.0 - f) * h0 + f * h1;
        c += h * std::cos(kTwoPi * n * x);
        s += h * std::sin(kTwoPi * n * x);
        w += 1.0;
      }
    }
    const double amplitude = 2.0 * std::hypot(c, s) / w;
    EXPECT_NEAR(amplitude * amplitude, interpolatedPowerShare(n, dx), 2e-3) << n << " " << dx;
  }
  EXPECT_DOUBLE_EQ(interpolatedPowerShare(2.83, 0.0), 1.0);
  EXPECT_NEAR(interpolatedPowerShare(2.0, 0.5), 0.0, 1e-30);  // a whole period per interval
  // 19 % at 0.17 m and 88 % at the default 0.05 m (the terrain command's notes).
  EXPECT_NEAR(interpolatedPowerShare(2.83, 0.17), 0.19, 0.005);
  EXPECT_NEAR(interpolatedPowerShare(2.83, 0.05), 0.876, 0.0005);
  for (const double share : {0.1, 0.5, 0.8, 0.99}) {
    const double dx = spacingKeepingPowerShare(2.83, share);
    EXPECT_NEAR(interpolatedPowerShare(2.83, dx), share, 1e-12) << share;
    EXPECT_LT(2.83 * dx, 1.0);  // the main lobe
  }
  EXPECT_NEAR(spacingKeepingPowerShare(2.83, 0.8), 0.0647, 5e-5);
  EXPECT_NEAR(spacingKeepingPowerShare(1.0, 0.8) / spacingKeepingPowerShare(4.0, 0.8), 4.0, 1e-12);
  expectInputError([] { spacingKeepingPowerShare(2.83, 1.0); }, {"share 1", "between 0 and 1"});
  expectInputError([] { spacingKeepingPowerShare(0.0, 0.8); }, {"frequency 0", "positive"});
}

}  // namespace
}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
