// Static track tension (track_assembly.static_tension) as a pre-stress of the chain loops: it
// stiffens what turns a tensioned member (the free top run becomes a taut string), leaves the
// vehicle's rigid-body motions free, and is read, checked and hashed like any other key.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "expect_input_error.h"
#include "tracked_vehicle_dynamics/fem/free_motion.h"
#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/vehicle/chain_path.h"
#include "tracked_vehicle_dynamics/vehicle/track_tension.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

#ifndef TVD_SOURCE_DIR
#define TVD_SOURCE_DIR "."
#endif

namespace tvd = tracked_vehicle_dynamics;
namespace veh = tracked_vehicle_dynamics::vehicle;
using tvd::Matrix;
using tvd::SparseMatrix;

namespace {

constexpr double kTension = 20e3;  // [N], a typical static track tension of a 50 t vehicle

tvd::fem::System assembled(const veh::VehicleDescription& d, veh::Variant variant,
                           bool body_preloads = true) {
  veh::VehicleModel vm = veh::buildVehicleModel(d, variant);
  if (!body_preloads)
    vm.model.body_preloads.clear();
  return tvd::fem::assemble(vm.model);
}

veh::VehicleDescription tensioned(double tension) {
  veh::VehicleDescription d;
  d.track_assembly.static_tension = tension;
  return d;
}

/// K(T) - K(0): the geometric stiffness, on the same DOFs (a pre-load adds no DOF).
SparseMatrix geometricPart(const veh::VehicleDescription& d, bool body_preloads = true) {
  const tvd::fem::System loaded = assembled(d, veh::Variant::Tracked, body_preloads);
  const tvd::fem::System bare = assembled(veh::VehicleDescription{}, veh::Variant::Tracked);
  EXPECT_EQ(loaded.size(), bare.size());
  return SparseMatrix(loaded.stiffness - bare.stiffness);
}

TEST(TrackTension, TheTensionedLoopsLeaveTheVehicleFreeToTurnAsAWhole) {
  const tvd::fem::System bare = assembled(veh::VehicleDescription{}, veh::Variant::Tracked);
  const Matrix rigid = tvd::fem::rigidBodyModes(bare);
  // Turning a tensioned loop of length L about an axis in its plane takes T L per radian^2
  // (every member's N L): both chains, 92 x 0.1615 m each, about y.
  const double loop_turn = 2.0 * kTension * 14.858;
  const Matrix alone = rigid.transpose() * (geometricPart(tensioned(kTension), false) * rigid);
  EXPECT_NEAR(alone(4, 4), loop_turn, 0.01 * loop_turn);
  // The wheels hold the loops' pull and hang on the hull, whose compression takes it back.
  // What is left is the round-off of K(T) - K(0) with K's 2e10 N/m contact springs (1e-9).
  const Matrix held = rigid.transpose() * (geometricPart(tensioned(kTension)) * rigid);
  EXPECT_LT(held.cwiseAbs().maxCoeff(), 1e-7 * loop_turn) << held;
}

TEST(TrackTension, TheGeometricStiffnessIsLinearInTheTension) {
  SparseMatrix one = geometricPart(tensioned(kTension));
  SparseMatrix three = geometricPart(tensioned(3.0 * kTension));
  const double scale = one.coeffs().cwiseAbs().maxCoeff();
  EXPECT_GT(scale, 0.0);
  // Exact up to the round-off of K(T) - K(0) beside K's 2e10 N/m contact springs (1e-9).
  SparseMatrix nonlinear = three - 3.0 * one;
  EXPECT_LT(nonlinear.coeffs().cwiseAbs().maxCoeff(), 1e-7 * scale);
}

/// The two lowest modes are the free top runs' first vertical modes (left and right). Tension
/// adds the taut string's omega^2 = (pi / L)^2 T / mu, span L and mass mu per metre, to the
/// beam loop's own: f_T^2 - f_0^2 = T / (4 mu L^2).
TEST(TrackTension, TheFreeTopRunsFirstModeRisesAsATautString) {
  const veh::VehicleDescription bare;
  const veh::ChainPath path(bare, veh::solveIdlerX(bare));
  const auto top = path.interval(veh::ChainSegment::TopRun);
  const double span = top.second - top.first;
  const double mu = bare.track_assembly.mass / bare.track_assembly.pitch;
  tvd::fem::ModalRequest request;
  request.count = 2;
  auto lowest = [&](const veh::VehicleDescription& d) {
    const tvd::fem::System s = assembled(d, veh::Variant::Tracked);
    return tvd::fem::solveModes(s.stiffness, s.mass, request).frequencies_hz;
  };
  const tvd::Vector f0 = lowest(bare);
  for (double tension : {kTension, 3.0 * kTension}) {
    const tvd::Vector f = lowest(tensioned(tension));
    const double string = tension / (4.0 * mu * span * span);
    for (int side = 0; side < 2; ++side) {
      const double rise = f(side) * f(side) - f0(side) * f0(side);
      // The span's ends are not pins: the chain stays bonded a little way onto the sprocket
      // and idler (measured: 12 % and 8 % above the pinned string at 20 and 60 kN).
      EXPECT_GT(rise / string, 1.0) << tension;
      EXPECT_LT(rise / string, 1.2) << tension;
    }
  }
}

TEST(TrackTension, ATensionBeyondHalfTheWeightIsQuestioned) {
  auto questioned = [](double tension) {
    for (const std::string& w : veh::descriptionWarnings(tensioned(tension)))
      if (w.find("track_assembly.static_tension") != std::string::npos &&
          w.find("more than half the vehicle's weight") != std::string::npos)
        return true;
    return false;
  };
  EXPECT_FALSE(questioned(60e3));  // the paper vehicle weighs 546 kN
  EXPECT_TRUE(questioned(20e6));   // 20 kN typed in mN
  // The limit itself: half the weight of every mass the tracked model carries (hull, wheels,
  // both chains, sprockets and idlers).
  const veh::VehicleModel vm =
      veh::buildVehicleModel(veh::VehicleDescription{}, veh::Variant::Tracked);
  const double weight = tvd::kStandardGravity * vm.model.totalMass();
  EXPECT_FALSE(questioned(0.499 * weight)) << weight;
  EXPECT_TRUE(questioned(0.501 * weight)) << weight;
}

TEST(TrackTension, TheUntrackedVehicleHasNoLoopToTension) {
  const tvd::fem::System loaded = assembled(tensioned(kTension), veh::Variant::Untracked);
  const tvd::fem::System bare = assembled(veh::VehicleDescription{}, veh::Variant::Untracked);
  EXPECT_EQ(Matrix(loaded.stiffness), Matrix(bare.stiffness));
}

std::string paperVehicleText() {
  std::ifstream in(std::string(TVD_SOURCE_DIR) + "/config/vehicles/paper_vehicle.yaml");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The paper vehicle's file with `line` added to its track_assembly section.
std::string withTrackLine(const std::string& line) {
  std::string text = paperVehicleText();
  const std::string anchor = "track_assembly:\n";
  const auto at = text.find(anchor);
  EXPECT_NE(at, std::string::npos);
  text.insert(at + anchor.size(), "  " + line + "\n");
  return text;
}

TEST(TrackTension, TheKeyIsOptionalCheckedAndHashedOnlyWhenGiven) {
  const veh::VehicleDescription given = veh::parseVehicleDescription(
      withTrackLine("static_tension: {value: 20000, unit: N, source: \"tensioner setting\"}"),
      "tensioned.yaml");
  ASSERT_TRUE(given.track_assembly.static_tension.has_value());
  EXPECT_DOUBLE_EQ(*given.track_assembly.static_tension, 20e3);
  EXPECT_EQ(given.sources.at("track_assembly.static_tension"), "tensioner setting");
  // Absent, the description hashes as before the key existed (cached models stay valid); given,
  // even as 0, it is part of the hash.
  EXPECT_EQ(veh::descriptionHash(veh::parseVehicleDescription(paperVehicleText(), "paper.yaml")),
            veh::descriptionHash(veh::VehicleDescription{}));
  EXPECT_NE(veh::descriptionHash(given), veh::descriptionHash(veh::VehicleDescription{}));
  // Given as 0 it is read, hashed (it was given) and said to leave the chain a free-length loop;
  // the model is the untensioned one.
  const veh::VehicleDescription slack = veh::parseVehicleDescription(
      withTrackLine("static_tension: {value: 0, unit: N, source: \"slack chain\"}"), "slack.yaml");
  ASSERT_TRUE(slack.track_assembly.static_tension.has_value());
  EXPECT_EQ(*slack.track_assembly.static_tension, 0.0);
  EXPECT_NE(veh::descriptionHash(slack), veh::descriptionHash(veh::VehicleDescription{}));
  EXPECT_EQ(veh::trackTensionText(slack, veh::Variant::Tracked),
            "track tension 0 N: the chain is a free-length beam loop");
  EXPECT_EQ(Matrix(assembled(slack, veh::Variant::Tracked).stiffness),
            Matrix(assembled(veh::VehicleDescription{}, veh::Variant::Tracked).stiffness));
  tvd::expectInputError(
      [] {
        veh::parseVehicleDescription(
            withTrackLine("static_tension: {value: -5000, unit: N, source: \"x\"}"), "pushed.yaml");
      },
      {"pushed.yaml", "track_assembly.static_tension"});
  tvd::expectInputError(
      [] {
        veh::parseVehicleDescription(
            withTrackLine("static_tension: {value: 20, unit: kN, source: \"x\"}"), "unit.yaml");
      },
      {"unit.yaml", "static_tension", "not the expected 'N'"});
}

}  // namespace
