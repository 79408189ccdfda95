// The hand estimate of the hull on its torsion bars (vehicle/wheel_rate_estimate.h), the
// warnings that compare the model with it, and suspension.guide_stiffness, which lets a rolling
// road wheel (low contact_shear_stiffness) keep its lateral guidance.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "expect_input_error.h"
#include "file_bytes.h"
#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/vehicle/mode_classification.h"
#include "tracked_vehicle_dynamics/vehicle/static_summary.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"
#include "tracked_vehicle_dynamics/vehicle/wheel_rate_estimate.h"

#ifndef TVD_SOURCE_DIR
#define TVD_SOURCE_DIR "."
#endif

namespace tvd = tracked_vehicle_dynamics;
namespace veh = tracked_vehicle_dynamics::vehicle;
using tracked_vehicle_dynamics::expectInputError;

namespace {

const std::string kPaperFile = std::string(TVD_SOURCE_DIR) + "/config/vehicles/paper_vehicle.yaml";
const std::string kLightFile = std::string(TVD_SOURCE_DIR) + "/test/data/light_5_axle.yaml";

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The paper's description with `line` added after the suspension's contact_shear_stiffness entry.
std::string withSuspensionLine(const std::string& line) {
  std::string text = tvd::readBytes(kPaperFile);
  const std::size_t key = text.find("  contact_shear_stiffness:");
  const std::size_t next = text.find("  guide_contact_height:", key);
  EXPECT_NE(key, std::string::npos);
  EXPECT_NE(next, std::string::npos);
  text.insert(next, line + "\n");
  return text;
}

struct Solved {
  veh::VehicleModel vehicle;
  tvd::fem::System system;
  tvd::fem::ModalBasis basis;
  std::vector<veh::ModeClass> classes;
};

Solved solve(const veh::VehicleDescription& d, veh::Variant variant, int count) {
  Solved s;
  s.vehicle = veh::buildVehicleModel(d, variant);
  s.system = tvd::fem::assemble(s.vehicle.model);
  tvd::fem::ModalRequest request;
  request.count = count;
  s.basis = tvd::fem::solveModes(s.system.stiffness, s.system.mass, request);
  s.classes = veh::classifyModes(s.vehicle, s.system, s.basis);
  return s;
}

// The frequency of the lowest mode whose main hull motion is `motion` (NaN if none).
double lowest(const Solved& s, veh::HullMotion motion) {
  for (std::size_t i = 0; i < s.classes.size(); ++i)
    if (s.classes[i].kind == veh::ModeKind::Hull && s.classes[i].hull_motions.front() == motion)
      return s.basis.frequencies_hz(static_cast<Eigen::Index>(i));
  return std::nan("");
}

veh::ModeClass hullMode(std::vector<veh::HullMotion> motions) {
  veh::ModeClass c;
  c.kind = veh::ModeKind::Hull;
  c.hull_motions = std::move(motions);
  return c;
}

}  // namespace

// k_r = k_t / (a cos beta)^2 in series with k_z; sag m g / (n k_s), bounce sqrt(n k_s / m) / 2 pi.
TEST(WheelRateEstimate, ClosedFormOnThePaperVehicle) {
  const veh::VehicleDescription d;
  const veh::WheelRateEstimate u = veh::wheelRateEstimate(d, veh::Variant::Untracked);
  const double lever = 0.58 * std::cos(9.0 * tvd::kPi / 180.0);
  const double kr = 5.2e5 / (lever * lever);
  EXPECT_NEAR(u.wheel_rate / kr, 1.0, 1e-12);
  EXPECT_NEAR(u.wheel_rate, 1.5846e6, 100.0);  // the doc's 1.58e6 N/m
  const double ks = 1.0 / (1.0 / kr + 1.0 / 1.895e7);
  EXPECT_NEAR(u.series_rate / ks, 1.0, 1e-12);
  EXPECT_EQ(u.wheels, 14);
  EXPECT_EQ(u.sprung_mass, 30300.0);
  EXPECT_NEAR(u.sag / (30300.0 * tvd::kStandardGravity / (14.0 * ks)), 1.0, 1e-12);
  EXPECT_NEAR(u.bounce_hz / (std::sqrt(14.0 * ks / 30300.0) / (2.0 * tvd::kPi)), 1.0, 1e-12);
  EXPECT_NEAR(u.bounce_hz, 4.14, 0.005);  // doc/vehicle_model.md
  // Tracked: the sprockets and idlers are rigid with the hull and ride on the same springs.
  const veh::WheelRateEstimate t = veh::wheelRateEstimate(d, veh::Variant::Tracked);
  EXPECT_EQ(t.sprung_mass, 30300.0 + 2.0 * (d.sprocket.mass + d.idler.mass));
  EXPECT_NEAR(t.sag / u.sag, t.sprung_mass / u.sprung_mass, 1e-12);
  EXPECT_NEAR(t.bounce_hz / u.bounce_hz, std::sqrt(u.sprung_mass / t.sprung_mass), 1e-12);
}

// The cosine in the lever a cos(beta) matters: on the light fixture with rolling wheels (nothing
// but the torsion bars and pads holding the hull up) the un-tracked model's sag follows the
// estimate at arm angles from 0 to 45 degrees, where dropping the cosine would be 2x off.
TEST(WheelRateEstimate, TheUntrackedSagFollowsTheArmAngle) {
  veh::VehicleDescription d = veh::loadVehicleDescription(kLightFile);
  d.suspension.contact_shear_stiffness = 1e4;
  d.suspension.guide_stiffness = 2e10;
  for (const double degrees : {0.0, 20.0, 45.0}) {
    d.suspension.arm_angle = degrees * tvd::kPi / 180.0;
    const veh::VehicleModel model = veh::buildVehicleModel(d, veh::Variant::Untracked);
    const tvd::fem::System system = tvd::fem::assemble(model.model);
    const veh::StaticSummary s = veh::computeStaticSummary(model, system);
    const veh::WheelRateEstimate e = veh::wheelRateEstimate(d, veh::Variant::Untracked);
    EXPECT_NEAR(-s.hull_sag / e.sag, 1.0, 0.03) << degrees << " deg: " << s.hull_sag;
  }
}

// The un-tracked model under a load through the CoG turns every arm alike: its sag is the
// estimate's (the wheels' tie drags no patch against another), within the CoG's small offset.
TEST(WheelRateEstimate, TheUntrackedSagIsTheEstimatesAndThePaperVehicleIsNotWarnedAbout) {
  const veh::VehicleDescription d;
  for (const veh::Variant v : {veh::Variant::Untracked, veh::Variant::Tracked}) {
    const veh::VehicleModel model = veh::buildVehicleModel(d, v);
    const tvd::fem::System system = tvd::fem::assemble(model.model);
    const veh::StaticSummary s = veh::computeStaticSummary(model, system);
    const veh::WheelRateEstimate e = veh::wheelRateEstimate(d, v);
    if (v == veh::Variant::Untracked)
      EXPECT_NEAR(-s.hull_sag / e.sag, 1.0, 0.07) << s.hull_sag;  // 15.3 mm against 14.5
    else
      EXPECT_GT(-s.hull_sag / e.sag, veh::kMinSagShare);  // 4.5 mm against 16.2: 0.28
    EXPECT_EQ(veh::sagShareWarning(s.hull_sag, d, v), "");
  }
}

// The light fixture holds the paper's chain bending and locked wheels on a 10 t vehicle: the
// chain carries its hull (1.2 mm of sag against 39.5 mm), and the locked wheels stiffen its
// un-tracked bounce 2.7 times. Both are said, naming the keys to fit.
TEST(WheelRateEstimate, ACopiedChainAndLockedWheelsOnALightVehicleAreNamed) {
  const veh::VehicleDescription d = veh::loadVehicleDescription(kLightFile);
  const Solved tracked = solve(d, veh::Variant::Tracked, 20);
  const veh::StaticSummary s = veh::computeStaticSummary(tracked.vehicle, tracked.system);
  const std::string sag = veh::sagShareWarning(s.hull_sag, d, veh::Variant::Tracked);
  for (const char* part : {"the hull sags 1.", "less than a fifth of the 39.5 mm",
                           "track_assembly.link_member_bending_inertia 1.1e-08 m^4",
                           "suspension.contact_shear_stiffness 2e+10 N/m", "\"Tuning\""})
    EXPECT_TRUE(contains(sag, part)) << part << "\n" << sag;
  const std::string bounce =
      veh::bounceWarning(d, veh::Variant::Tracked, tracked.classes, tracked.basis.frequencies_hz);
  EXPECT_TRUE(contains(bounce, "the hull's bounce (mode ")) << bounce;
  EXPECT_TRUE(contains(bounce, "beyond 2.5 times")) << bounce;

  const Solved untracked = solve(d, veh::Variant::Untracked, 12);
  const double f = lowest(untracked, veh::HullMotion::Bounce);
  const veh::WheelRateEstimate e = veh::wheelRateEstimate(d, veh::Variant::Untracked);
  EXPECT_GT(f / e.bounce_hz, 2.5) << f;  // 7.0 Hz against 2.6
  const std::string u = veh::bounceWarning(d, veh::Variant::Untracked, untracked.classes,
                                           untracked.basis.frequencies_hz);
  for (const char* part : {"times the 2.60 Hz of the hull (9500 kg) on its 10 road wheels'",
                           "beyond 1.5 times (the paper's vehicle: 1.2)",
                           "suspension.contact_shear_stiffness 2e+10 N/m",
                           "\"The un-tracked bounce against a hand estimate\""})
    EXPECT_TRUE(contains(u, part)) << part << "\n" << u;
  EXPECT_FALSE(contains(u, "link_member_bending_inertia")) << u;  // no chain un-tracked
}

// The limits, exactly: at and just below them nothing is said; just beyond, the warning.
TEST(WheelRateEstimate, WarningsStartJustBeyondTheirLimits) {
  const veh::VehicleDescription d;
  for (const veh::Variant v : {veh::Variant::Untracked, veh::Variant::Tracked}) {
    const veh::WheelRateEstimate e = veh::wheelRateEstimate(d, v);
    const double limit =
        v == veh::Variant::Tracked ? veh::kMaxTrackedBounceRatio : veh::kMaxUntrackedBounceRatio;
    veh::ModeClass chain;  // a track mode first: the bounce mode is the second
    const std::vector<veh::ModeClass> classes = {chain, hullMode({veh::HullMotion::Bounce})};
    tvd::Vector f(2);
    f << 0.5, limit * e.bounce_hz;
    EXPECT_EQ(veh::bounceWarning(d, v, classes, f), "");
    f(1) = 1.01 * limit * e.bounce_hz;
    EXPECT_TRUE(contains(veh::bounceWarning(d, v, classes, f), "(mode 2, "));
    // A pitch mode that bounces too is not the bounce mode; without one nothing is judged.
    // An off-centre CoG makes the bounce pitch+bounce: that is no verdict of "above them all".
    EXPECT_EQ(veh::bounceWarning(
                  d, v, {chain, hullMode({veh::HullMotion::Pitch, veh::HullMotion::Bounce})}, f),
              "");
    const std::vector<veh::ModeClass> no_bounce = {chain, hullMode({veh::HullMotion::Pitch})};
    f(1) = limit * e.bounce_hz;  // the modes reach the limit, not beyond: nothing to say
    EXPECT_EQ(veh::bounceWarning(d, v, no_bounce, f), "");
    // Beyond it with no mode that bounces at all: the bounce lies higher still.
    f(1) = 1.01 * limit * e.bounce_hz;
    const std::string above = veh::bounceWarning(d, v, no_bounce, f);
    EXPECT_TRUE(contains(above, "no hull bounce mode among the 2 lowest modes (up to ")) << above;
    EXPECT_TRUE(contains(above, "--count")) << above;
    EXPECT_EQ(veh::bounceWarning(d, v, {}, tvd::Vector()), "");

    veh::StaticSummary s;
    s.hull_sag = -veh::kMinSagShare * e.sag;
    EXPECT_EQ(veh::sagShareWarning(s.hull_sag, d, v), "");
    s.hull_sag *= 0.99;
    EXPECT_TRUE(contains(veh::sagShareWarning(s.hull_sag, d, v), "less than a fifth"));
    // A hull that rises under its own weight (a bonded chain bent upwards can lift it).
    s.hull_sag = 1.5e-3;
    const std::string rises = veh::sagShareWarning(s.hull_sag, d, v);
    EXPECT_TRUE(contains(rises, "the hull rises 1.50 mm under its own weight, where the "))
        << rises;
    EXPECT_TRUE(contains(rises, " would sag: ")) << rises;
  }
}

// suspension.guide_stiffness: optional; given, it is the lateral stiffness of the guide horns and
// of the chain wheels' hold across the links, while contact_shear_stiffness keeps the patches'
// along the chain. A description without it means what it meant and hashes as before.
TEST(GuideStiffness, IsOptionalReadWithItsUnitAndKeepsOldHashes) {
  const veh::VehicleDescription plain = veh::loadVehicleDescription(kPaperFile);
  EXPECT_FALSE(plain.suspension.guide_stiffness.has_value());
  EXPECT_EQ(veh::guideStiffness(plain.suspension), plain.suspension.contact_shear_stiffness);
  EXPECT_EQ(veh::descriptionHash(plain), veh::descriptionHash(veh::VehicleDescription{}));

  const veh::VehicleDescription given = veh::parseVehicleDescription(
      withSuspensionLine("  guide_stiffness: {value: 3e9, unit: N/m, source: \"test\"}"),
      "given.yaml");
  ASSERT_TRUE(given.suspension.guide_stiffness.has_value());
  EXPECT_EQ(*given.suspension.guide_stiffness, 3e9);
  EXPECT_EQ(veh::guideStiffness(given.suspension), 3e9);
  EXPECT_NE(veh::descriptionHash(given), veh::descriptionHash(plain));
  EXPECT_EQ(given.sources.at("suspension.guide_stiffness"), "test");

  expectInputError(
      [&] {
        veh::parseVehicleDescription(
            withSuspensionLine("  guide_stiffness: {value: -1, unit: N/m, source: \"test\"}"),
            "negative.yaml");
      },
      {"negative.yaml", "suspension.guide_stiffness", "must be positive, got -1"});
  // 0 would leave the hull free sideways: a singular stiffness that named no key.
  expectInputError(
      [&] {
        veh::parseVehicleDescription(
            withSuspensionLine("  guide_stiffness: {value: 0, unit: N/m, source: \"test\"}"),
            "zero.yaml");
      },
      {"zero.yaml", "suspension.guide_stiffness", "must be positive, got 0"});
  expectInputError(
      [&] {
        veh::parseVehicleDescription(
            withSuspensionLine("  guide_stiffness: {value: 1, unit: kN/m, source: \"test\"}"),
            "unit.yaml");
      },
      {"unit.yaml", "suspension.guide_stiffness.unit", "not the expected 'N/m'"});
  veh::VehicleDescription coded;
  coded.suspension.guide_stiffness = std::nan("");
  expectInputError([&] { veh::validateDescription(coded, "coded"); },
                   {"suspension.guide_stiffness", "out of range or not finite"});
}

TEST(GuideStiffness, SetsTheLateralSpringsAndKeepsARollingWheelGuided) {
  veh::VehicleDescription d = veh::loadVehicleDescription(kLightFile);
  d.suspension.contact_shear_stiffness = 1e4;  // rolling wheels
  d.suspension.guide_stiffness = 2e10;
  for (const veh::Variant v : {veh::Variant::Untracked, veh::Variant::Tracked}) {
    const veh::VehicleModel model = veh::buildVehicleModel(d, v);
    int guides = 0, patches = 0, chain_wheels = 0;
    for (const tvd::fem::Spring& s : model.model.springs) {
      if (contains(s.name, "/guide")) {
        ++guides;
        EXPECT_EQ(s.stiffness(0), 0.0) << s.name;
        EXPECT_EQ(s.stiffness(1), 2e10) << s.name;
      } else if (contains(s.name, "/contact")) {
        ++patches;
        EXPECT_EQ(s.stiffness(0), 1e4) << s.name;
        EXPECT_EQ(s.stiffness(1), 0.0) << s.name;
      } else if (s.name.rfind("sprocket_", 0) == 0 || s.name.rfind("idler_", 0) == 0) {
        ++chain_wheels;
        EXPECT_EQ(s.stiffness(1), 2e10) << s.name;
      }
    }
    EXPECT_EQ(guides, 10);
    EXPECT_EQ(patches, 10);
    EXPECT_EQ(chain_wheels > 0, v == veh::Variant::Tracked);
  }
  // Rolling, the un-tracked hull bounces on its torsion bars (the estimate less the wheels'
  // own motion), and the guide horns still hold it sideways: its lateral mode stays several
  // times what it is when the guides are as soft as the patches.
  const Solved guided = solve(d, veh::Variant::Untracked, 12);
  const double bounce = lowest(guided, veh::HullMotion::Bounce);
  EXPECT_NEAR(bounce / veh::wheelRateEstimate(d, veh::Variant::Untracked).bounce_hz, 1.0, 0.1)
      << bounce;
  EXPECT_EQ(
      veh::bounceWarning(d, veh::Variant::Untracked, guided.classes, guided.basis.frequencies_hz),
      "");
  d.suspension.guide_stiffness.reset();  // the guides as soft as the patches
  const Solved loose = solve(d, veh::Variant::Untracked, 12);
  const double lateral_guided = lowest(guided, veh::HullMotion::Lateral);
  const double lateral_loose = lowest(loose, veh::HullMotion::Lateral);
  EXPECT_GT(lateral_guided, 3.0 * lateral_loose) << lateral_guided << " " << lateral_loose;
  EXPECT_NEAR(lowest(loose, veh::HullMotion::Bounce), bounce, 1e-6 * bounce);
}

// What the warnings print, to the digit, and which modes and keys they judge (from a mutation
// run: each of these once passed with the code wrong). The paper vehicle's estimate: k_r =
// 1.58456e6 N/m, k_s = 1.46228e6 N/m, 14 wheels, 30300 kg, sag 14.5 mm, bounce 4.14 Hz.
TEST(WheelRateEstimate, TheWarningsSayTheEstimateAndJudgeTheRightMode) {
  veh::VehicleDescription d;
  const veh::Variant un = veh::Variant::Untracked, tr = veh::Variant::Tracked;
  const veh::WheelRateEstimate e = veh::wheelRateEstimate(d, un);
  const double b = e.bounce_hz;
  // The estimate as printed: the series rate beside the wheel rate.
  const std::string tiny = veh::sagShareWarning(-0.15 * e.sag, d, un);
  for (const char* part :
       {"the hull sags 2.18 mm under its weight, less than a fifth of the 14.5 mm of the hull "
        "(30300 kg) on its 14 road wheels' torsion bars and pads alone (wheel rate "
        "k_t / (a cos beta)^2 = 1.58456e+06 N/m, in series with "
        "track_assembly.compression_stiffness: 1.46228e+06 N/m per wheel)"})
    EXPECT_TRUE(contains(tiny, part)) << tiny;
  // A hull that does not move sags 0.00 mm, whatever the sign of its zero.
  for (const double zero : {0.0, -0.0}) {
    const std::string none = veh::sagShareWarning(zero, d, tr);
    EXPECT_TRUE(contains(none,
                         "the hull sags 0.00 mm under its weight, less than a fifth of the "
                         "16.2 mm"))
        << none;
  }
  // The bounce ratio with two decimals.
  veh::ModeClass chain;
  tvd::Vector f(2);
  f << 0.5, 2.0 * b;
  const std::string twice =
      veh::bounceWarning(d, un, {chain, hullMode({veh::HullMotion::Bounce})}, f);
  EXPECT_TRUE(contains(twice,
                       "the hull's bounce (mode 2, 8.27 Hz) is 2.00 times the 4.14 Hz of "
                       "the hull (30300 kg)"))
      << twice;
  // Only the lowest bounce-led hull mode is judged: a second one far above is no verdict.
  f << b, 3.0 * b;
  EXPECT_EQ(veh::bounceWarning(d, un,
                               {hullMode({veh::HullMotion::Bounce}),
                                hullMode({veh::HullMotion::Bounce, veh::HullMotion::Pitch})},
                               f),
            "");
  // A wheel mode that carries the hull's bounce along is not the hull's bounce.
  veh::ModeClass wheel;
  wheel.kind = veh::ModeKind::WheelBounce;
  wheel.hull_motions = {veh::HullMotion::Bounce};
  f << 3.0 * b, b;
  EXPECT_EQ(veh::bounceWarning(d, un, {wheel, hullMode({veh::HullMotion::Bounce})}, f), "");
  // No bounce mode at all, the modes three times beyond: the factor as printed.
  f << 0.5, 3.0 * b;
  const std::string above =
      veh::bounceWarning(d, un, {chain, hullMode({veh::HullMotion::Pitch})}, f);
  EXPECT_TRUE(contains(above,
                       "no hull bounce mode among the 2 lowest modes (up to 12.41 Hz, 3.0 "
                       "times the 4.14 Hz"))
      << above;
  // The key that locks the wheels is contact_shear_stiffness, not guide_stiffness.
  veh::VehicleDescription light = veh::loadVehicleDescription(kLightFile);
  light.suspension.contact_shear_stiffness = 1e4;
  light.suspension.guide_stiffness = 2e10;
  const std::string named = veh::sagShareWarning(-0.001, light, tr);
  EXPECT_TRUE(contains(named, "suspension.contact_shear_stiffness 10000 N/m")) << named;
  // Return rollers ride on the hull too (each side's), tracked only.
  d.return_rollers.x = {0.5, -1.0};
  d.return_rollers.mass = 60.0;
  EXPECT_EQ(veh::wheelRateEstimate(d, tr).sprung_mass,
            30300.0 + 2.0 * (d.sprocket.mass + d.idler.mass + 2.0 * 60.0));
  EXPECT_EQ(veh::wheelRateEstimate(d, un).sprung_mass, 30300.0);
}

// guide_stiffness, given in code, is checked by validateDescription() like a read one; left
// unset it is not in the canonical text (so the hash of every earlier description stands); and
// it is also the return rollers' hold across the links.
TEST(GuideStiffness, CheckedInCodeAbsentFromOldHashesAndHoldsTheRollers) {
  veh::VehicleDescription coded;
  for (const double bad : {0.0, 1e16}) {
    coded.suspension.guide_stiffness = bad;
    expectInputError([&] { veh::validateDescription(coded, "coded"); },
                     {"suspension.guide_stiffness", "out of range or not finite"});
  }
  const veh::VehicleDescription paper = veh::loadVehicleDescription(kPaperFile);
  EXPECT_FALSE(contains(veh::canonicalDescription(paper), "guide_stiffness"));

  veh::VehicleDescription d = paper;
  d.return_rollers.x = {0.4, -1.2};
  d.return_rollers.mass = 50.0;
  d.suspension.contact_shear_stiffness = 1e4;
  d.suspension.guide_stiffness = 3e9;
  const veh::VehicleModel model = veh::buildVehicleModel(d, veh::Variant::Tracked);
  int rollers = 0;
  for (const tvd::fem::Spring& s : model.model.springs)
    if (s.name.rfind("return_roller_", 0) == 0) {
      ++rollers;
      EXPECT_EQ(s.stiffness(1), 3e9) << s.name;
    }
  EXPECT_EQ(rollers, 4);
}

// The attitude of a rigid hull on equal wheel rates: phi = m g x_G / (k_s sum x_i^2), x_G the
// sprung mass's CoG (tracked: with the chain wheels, the idler where the chain closes).
TEST(WheelRateEstimate, AttitudeClosedFormOnThePaperVehicle) {
  const veh::VehicleDescription d;
  const veh::WheelRateEstimate u = veh::wheelRateEstimate(d, veh::Variant::Untracked);
  // Seven axles 0.78 m apart about the middle, both sides: 2 l^2 (9 + 4 + 1 + 0 + 1 + 4 + 9).
  const double second_moment = 2.0 * 0.78 * 0.78 * 28.0;
  EXPECT_NEAR(u.end_station, 3.0 * 0.78, 1e-12);
  EXPECT_NEAR(u.cog_x, d.hull.cog_x, 1e-15);
  EXPECT_NEAR(
      u.pitch / (u.sprung_mass * tvd::kStandardGravity * 0.12 / (u.series_rate * second_moment)),
      1.0, 1e-12);
  const veh::WheelRateEstimate t = veh::wheelRateEstimate(d, veh::Variant::Tracked);
  const veh::VehicleModel tracked = veh::buildVehicleModel(d, veh::Variant::Tracked);
  const double idler_x =
      tracked.model.nodes[tracked.model.nodeIndex().at(tracked.layout.idlers[0])].position.x();
  EXPECT_NEAR(
      t.cog_x * t.sprung_mass,
      30300.0 * 0.12 + 2.0 * (d.sprocket.mass * d.sprocket.centre_x + d.idler.mass * idler_x),
      1e-6 * t.sprung_mass);
  EXPECT_NEAR(
      t.pitch / (t.sprung_mass * tvd::kStandardGravity * t.cog_x / (t.series_rate * second_moment)),
      1.0, 1e-12);
  // The FE model agrees, sign included, once nothing but the torsion bars and pads holds the
  // hull (the wheels rolling on their links: 1e4 N/m fore and aft instead of locked): the
  // un-tracked model pitches 0.0411 deg nose down at rest, the estimate 0.0410.
  veh::VehicleDescription rolling = d;
  rolling.suspension.contact_shear_stiffness = 1e4;
  const veh::VehicleModel model = veh::buildVehicleModel(rolling, veh::Variant::Untracked);
  const tvd::fem::System system = tvd::fem::assemble(model.model);
  const double pitch = veh::computeStaticSummary(model, system).hull_pitch;
  const veh::WheelRateEstimate r = veh::wheelRateEstimate(rolling, veh::Variant::Untracked);
  EXPECT_GT(pitch, 0.0);
  EXPECT_NEAR(pitch / r.pitch, 1.0, 0.01);
}

// Tracked, the return rollers ride with the hull as the sprocket and idler do: the sprung mass's
// CoG is the mass-weighted mean x of every body on the torsion bars, both sides' rollers
// included. One roller a side ahead of the wheelbase's middle moves it forward.
TEST(WheelRateEstimate, TheTrackedCogHoldsTheReturnRollers) {
  veh::VehicleDescription d;
  d.return_rollers.x = {1.2};
  d.return_rollers.mass = 60.0;
  const veh::WheelRateEstimate t = veh::wheelRateEstimate(d, veh::Variant::Tracked);
  const veh::VehicleModel tracked = veh::buildVehicleModel(d, veh::Variant::Tracked);
  const double idler_x =
      tracked.model.nodes[tracked.model.nodeIndex().at(tracked.layout.idlers[0])].position.x();
  const double rollers = 2.0 * 60.0;  // one a side
  EXPECT_EQ(t.sprung_mass, 30300.0 + 2.0 * (d.sprocket.mass + d.idler.mass) + rollers);
  EXPECT_NEAR(t.cog_x * t.sprung_mass,
              30300.0 * 0.12 +
                  2.0 * (d.sprocket.mass * d.sprocket.centre_x + d.idler.mass * idler_x) +
                  rollers * 1.2,
              1e-6 * t.sprung_mass);
}

// A light front-drive carrier, its chain bending a hundredth of the paper's (1e-10 m^4): even
// so its bonded tracked model (what
// modes, frf and simulate linearise about) sits nose up, where its torsion bars would hold it
// nose down (the CoG ahead of the wheelbase's middle): said. Its un-tracked model and the
// paper's vehicle, which sit as the estimate does, are not.
TEST(WheelRateEstimate, AHullNotSittingOnItsTorsionBarsIsSaid) {
  const veh::VehicleDescription carrier = veh::loadVehicleDescription(
      std::string(TVD_SOURCE_DIR) + "/test/data/front_drive_carrier.yaml");
  const auto pitchOf = [](const veh::VehicleDescription& d, veh::Variant variant) {
    const veh::VehicleModel m = veh::buildVehicleModel(d, variant);
    const tvd::fem::System system = tvd::fem::assemble(m.model);
    return veh::computeStaticSummary(m, system).hull_pitch;
  };
  const double tracked = pitchOf(carrier, veh::Variant::Tracked);
  const veh::WheelRateEstimate e = veh::wheelRateEstimate(carrier, veh::Variant::Tracked);
  EXPECT_LT(tracked, 0.0);  // nose up
  EXPECT_GT(e.pitch, 0.0);  // nose down
  const std::string w = veh::attitudeWarning(tracked, carrier, veh::Variant::Tracked);
  for (const char* part :
       {"the hull sits 0.7",
        " deg nose up at rest, where the hull with its "
        "chain wheels (8700 kg) on its 10 road wheels'",
        " deg nose down (its CoG 0.11", "more than a quarter of its 78.8 mm sag",
        "track_assembly.link_member_bending_inertia", "compare tvd statics --contact bilateral"})
    EXPECT_TRUE(contains(w, part)) << part << "\n" << w;
  EXPECT_EQ(veh::attitudeWarning(pitchOf(carrier, veh::Variant::Untracked), carrier,
                                 veh::Variant::Untracked),
            "");
  const veh::VehicleDescription paper = veh::loadVehicleDescription(kPaperFile);
  for (veh::Variant v : {veh::Variant::Untracked, veh::Variant::Tracked})
    EXPECT_EQ(veh::attitudeWarning(pitchOf(paper, v), paper, v), "");
  // The limit itself: a quarter of the sag at the end axles, and just beyond it.
  const double limit = veh::kMaxPitchShare * e.sag / e.end_station;
  EXPECT_EQ(veh::attitudeWarning(e.pitch + 0.999 * limit, carrier, veh::Variant::Tracked), "");
  EXPECT_NE(veh::attitudeWarning(e.pitch - 1.001 * limit, carrier, veh::Variant::Tracked), "");
}
