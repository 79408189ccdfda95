// Statics with unilateral springs (fem/unilateral_static.h) against a hand-solved lift-off, and the
// vehicle at rest with pads, road wheels, sprockets, idlers and return rollers that cannot pull
// (vehicle/contact_statics.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <utility>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/static_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/fem/unilateral_static.h"
#include "tracked_vehicle_dynamics/vehicle/contact_statics.h"
#include "tracked_vehicle_dynamics/vehicle/static_summary.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"

#ifndef TVD_SOURCE_DIR
#define TVD_SOURCE_DIR "."
#endif

namespace tvd = tracked_vehicle_dynamics;
namespace fem = tracked_vehicle_dynamics::fem;
namespace veh = tracked_vehicle_dynamics::vehicle;

namespace {

constexpr double kGravity = 9.80665;  // [m/s^2], fem::Model's default gravity
constexpr double kK = 1e6;            // [N/m] each support
constexpr double kMass = 1000.0;      // [kg]

/// A rigid bar along x on n (odd) equal vertical supports at x = 0, 1, ..., n - 1 (nodes 1 .. n;
/// the middle node carries the bar), its weight `eccentricity` ahead of the middle. The middle
/// support also holds x, y, roll and yaw, which the vertical supports do not, with stiffness that
/// is not unilateral.
fem::Model barOnSupports(int n, double eccentricity) {
  const int middle = (n + 1) / 2;
  fem::Model m;
  fem::RigidJoint bar;
  bar.master = middle;
  for (int i = 0; i < n; ++i) {
    m.addNode(i + 1, tvd::Vector3(i, 0, 0));
    if (i + 1 != middle)
      bar.slaves.push_back(i + 1);
    fem::Spring s;
    s.n1 = i + 1;
    s.stiffness(2) = kK;
    if (i + 1 == middle)
      s.stiffness << kK, kK, kK, kK, 0.0, kK;
    s.name = "support_" + std::to_string(i);
    m.springs.push_back(s);
  }
  m.rigid_joints.push_back(bar);
  fem::Mass w;
  w.node = middle;
  w.mass = kMass;
  w.offset = tvd::Vector3(eccentricity, 0, 0);
  w.inertia = tvd::Matrix3::Identity();
  m.masses.push_back(w);
  return m;
}

/// Every support of barOnSupports(n, ...) unilateral, pushing up.
std::vector<fem::UnilateralSpring> supports(std::size_t n = 3) {
  std::vector<fem::UnilateralSpring> all;
  for (std::size_t i = 0; i < n; ++i)
    all.push_back({i, 2, 1.0});
  return all;
}

double verticalDisplacement(const fem::System& system, const fem::StaticResult& r, tvd::NodeId n) {
  return fem::physicalDisplacement(system, r.displacement, n, 2);
}

veh::VehicleDescription paperDescription() {
  return veh::loadVehicleDescription(std::string(TVD_SOURCE_DIR) +
                                     "/config/vehicles/paper_vehicle.yaml");
}

/// The paper vehicle, tracked, with three return rollers per side under its top run (it has
/// none: a free return run).
veh::VehicleModel trackedWithReturnRollers() {
  veh::VehicleDescription rollers = paperDescription();
  rollers.return_rollers.x = {-1.17, 0.39, 1.95};  // between the road wheels
  rollers.return_rollers.mass = 80.0;
  return veh::buildVehicleModel(rollers, veh::Variant::Tracked);
}

/// The paper vehicle, tracked, as it is and with return rollers.
std::vector<veh::VehicleModel> trackedVehicles() {
  return {veh::buildVehicleModel(paperDescription(), veh::Variant::Tracked),
          trackedWithReturnRollers()};
}

/// The centre node of the sprocket, idler or roller a chain wheel contact belongs to.
tvd::NodeId wheelCentre(const veh::VehicleLayout& layout, const veh::ChainWheelContact& c) {
  const auto side = static_cast<std::size_t>(c.side);
  switch (c.wheel) {
    case veh::ChainWheel::Sprocket:
      return layout.sprockets.at(side);
    case veh::ChainWheel::Idler:
      return layout.idlers.at(side);
    case veh::ChainWheel::ReturnRoller: {
      const std::size_t per_side = layout.return_rollers.size() / 2;
      return layout.return_rollers.at(side * per_side + static_cast<std::size_t>(c.roller));
    }
  }
  return 0;
}

}  // namespace

TEST(UnilateralStatic, BarLiftsOffItsUnloadedSupport) {
  // Weight F at x = 1.8. Bonded, the three equal supports take F/3 + 0.4 F (x_i - 1): the one at
  // x = 0 pulls, -F/15. Unilateral it lets go; the other two share F as a bar on two supports,
  // 0.2 F and 0.8 F, and the free end rises by 0.4 F / k (the bar's slope times 1 m).
  const double f = kMass * kGravity;
  const fem::Model model = barOnSupports(3, 0.8);
  const fem::System bonded = fem::assemble(model);
  const fem::StaticResult b = fem::solveStatic(bonded, bonded.gravity_load);
  EXPECT_NEAR(-kK * verticalDisplacement(bonded, b, 1), -f / 15.0, 1e-9 * f);

  const fem::UnilateralStaticResult r = fem::solveUnilateralStatic(model, supports());
  ASSERT_EQ(r.released, (std::vector<bool>{true, false, false}));
  EXPECT_EQ(r.iterations, 2);
  EXPECT_DOUBLE_EQ(r.normal_force[0], 0.0);
  EXPECT_NEAR(r.normal_force[1], 0.2 * f, 1e-9 * f);
  EXPECT_NEAR(r.normal_force[2], 0.8 * f, 1e-9 * f);
  EXPECT_NEAR(verticalDisplacement(r.system, r.statics, 1), 0.4 * f / kK, 1e-9 * f / kK);
  // The released support lost its normal stiffness only; the model given is untouched.
  EXPECT_EQ(r.model.springs[0].stiffness(2), 0.0);
  EXPECT_EQ(model.springs[0].stiffness(2), kK);
  EXPECT_EQ(r.model.springs[1].stiffness(0), kK);
}

TEST(UnilateralStatic, BrakingMovesTheLoadForwardAndLiftsTheRearSupport) {
  // The weight at height h = 1 m over the middle support (x = 1). A steady forward acceleration a
  // adds the travel inertia -m a along x at that height; the moment balance about the middle
  // support gives sum (x_i - 1) F_i = -m a h (braking, a < 0: load to the front, +x). Bonded on
  // three supports: F_i = m g / 3 - m a h (x_i - 1) / 2, and the rear one pulls once
  // -a > 2 g / (3 h). At a = -8 m/s^2 it lets go, and the bar on two supports gives
  // F_2 = -m a h = 8000 N, F_1 = m g - 8000 N; the middle support holds F_x = m a.
  const double f = kMass * kGravity;
  fem::Model model = barOnSupports(3, 0.0);
  model.masses[0].offset = tvd::Vector3(0.0, 0.0, 1.0);
  for (const double a : {-2.0, 2.0}) {
    const fem::UnilateralStaticResult r =
        fem::solveUnilateralStatic(model, supports(), 100, fem::ActiveSetUpdate::AllViolated, a);
    ASSERT_EQ(r.released, (std::vector<bool>{false, false, false})) << a;
    for (int i = 0; i < 3; ++i)
      EXPECT_NEAR(r.normal_force[static_cast<std::size_t>(i)], f / 3.0 - kMass * a * (i - 1) / 2.0,
                  1e-9 * f)
          << "a = " << a << ", support " << i;
    // The longitudinal reaction: the middle support's x spring, -k u_x = m a.
    EXPECT_NEAR(-kK * fem::physicalDisplacement(r.system, r.statics.displacement, 2, 0), kMass * a,
                1e-9 * f);
  }
  const fem::UnilateralStaticResult r =
      fem::solveUnilateralStatic(model, supports(), 100, fem::ActiveSetUpdate::AllViolated, -8.0);
  ASSERT_EQ(r.released, (std::vector<bool>{true, false, false}));
  EXPECT_NEAR(r.normal_force[1], f - 8000.0, 1e-9 * f);
  EXPECT_NEAR(r.normal_force[2], 8000.0, 1e-9 * f);
  // Zero acceleration is the gravity case itself.
  const fem::UnilateralStaticResult rest = fem::solveUnilateralStatic(model, supports());
  const fem::UnilateralStaticResult zero =
      fem::solveUnilateralStatic(model, supports(), 100, fem::ActiveSetUpdate::AllViolated, 0.0);
  EXPECT_EQ(rest.statics.displacement, zero.statics.displacement);
}

TEST(UnilateralStatic, NormalFollowsTheSpringFrameAndTheSign) {
  // The same supports with their frames turned 180 deg about x (local z = global -z): with sign
  // -1 they still push the bar up, and the lift-off is the one above; with sign +1 they would
  // pull it down, all in tension under gravity, and the released bar floats.
  const double f = kMass * kGravity;
  fem::Model model = barOnSupports(3, 0.8);
  for (fem::Spring& s : model.springs)
    s.frame = tvd::Vector3(1.0, -1.0, -1.0).asDiagonal();
  std::vector<fem::UnilateralSpring> down = supports();
  for (fem::UnilateralSpring& c : down)
    c.sign = -1.0;
  const fem::UnilateralStaticResult r = fem::solveUnilateralStatic(model, down);
  ASSERT_EQ(r.released, (std::vector<bool>{true, false, false}));
  EXPECT_NEAR(r.normal_force[1], 0.2 * f, 1e-9 * f);
  EXPECT_NEAR(r.normal_force[2], 0.8 * f, 1e-9 * f);
  EXPECT_NEAR(verticalDisplacement(r.system, r.statics, 1), 0.4 * f / kK, 1e-9 * f / kK);
  EXPECT_THROW(fem::solveUnilateralStatic(model, supports()), tvd::SolverError);
}

TEST(UnilateralStatic, TooFewSolvesIsASolverError) {
  // The lift-off above takes 2 solves (bonded, then with the first support released).
  const fem::Model model = barOnSupports(3, 0.8);
  try {
    fem::solveUnilateralStatic(model, supports(), 1);
    FAIL() << "no error";
  } catch (const tvd::SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("did not settle after 1 solves"), std::string::npos)
        << e.what();
  }
  EXPECT_EQ(fem::solveUnilateralStatic(model, supports(), 2).iterations, 2);
}

TEST(UnilateralStatic, BothUpdateRulesFindTheOneSolution) {
  // Equal supports under a rigid bar carry F/n + F e (x_i - xm) / sum (x_j - xm)^2 over the
  // active ones (mean xm, weight e ahead of it). Only {4, 5, 6} carries F at x = 5.4 in
  // compression: F (2/15, 1/3, 8/15); the bar then rises 1/15 F/k at x = 3 (no overlap there).
  // Releasing every violated support at once and the worst one at a time (the fallback) must
  // both arrive there: the problem has one solution.
  const double f = kMass * kGravity;
  const fem::Model model = barOnSupports(7, 2.4);  // weight at x = 5.4
  const std::vector<fem::UnilateralSpring> all = supports(7);
  for (const fem::ActiveSetUpdate update :
       {fem::ActiveSetUpdate::AllViolated, fem::ActiveSetUpdate::WorstOnly}) {
    const fem::UnilateralStaticResult r = fem::solveUnilateralStatic(model, all, 100, update);
    EXPECT_EQ(r.released, (std::vector<bool>{true, true, true, true, false, false, false}));
    const double expected[7] = {0, 0, 0, 0, 2.0 / 15.0, 1.0 / 3.0, 8.0 / 15.0};
    for (int i = 0; i < 7; ++i)
      EXPECT_NEAR(r.normal_force[i], expected[i] * f, 1e-9 * f) << i;
    EXPECT_NEAR(verticalDisplacement(r.system, r.statics, 4), f / (15.0 * kK), 1e-9 * f / kK);
  }
  // Released all at once: {0, 1}, then {2}, then {3}: four solves; one at a time, five.
  EXPECT_EQ(fem::solveUnilateralStatic(model, all).iterations, 4);
  EXPECT_EQ(fem::solveUnilateralStatic(model, all, 100, fem::ActiveSetUpdate::WorstOnly).iterations,
            5);
}

TEST(UnilateralStatic, NoTensionMeansTheBondedSolution) {
  // Weight within the middle third: every support pushes, nothing is released.
  const fem::Model model = barOnSupports(3, 0.3);
  const fem::UnilateralStaticResult r = fem::solveUnilateralStatic(model, supports());
  EXPECT_EQ(std::count(r.released.begin(), r.released.end(), true), 0);
  EXPECT_EQ(r.iterations, 1);
  const fem::System bonded = fem::assemble(model);
  const fem::StaticResult b = fem::solveStatic(bonded, bonded.gravity_load);
  EXPECT_NEAR((r.statics.displacement - b.displacement).norm(), 0.0, 1e-12 * b.displacement.norm());
}

TEST(UnilateralStatic, BadSpringsAndATotalLiftOffAreNamed) {
  const fem::Model model = barOnSupports(3, 0.0);
  EXPECT_THROW(fem::solveUnilateralStatic(model, {{7, 2, 1.0}}), tvd::InputError);
  EXPECT_THROW(fem::solveUnilateralStatic(model, {{0, 3, 1.0}}), tvd::InputError);
  EXPECT_THROW(fem::solveUnilateralStatic(model, {{0, 2, 0.0}}), tvd::InputError);
  EXPECT_THROW(fem::solveUnilateralStatic(model, {{0, 0, 1.0}}), tvd::InputError);  // no kx
  // Gravity upwards: every support would pull; released, the bar floats.
  fem::Model up = model;
  up.gravity = tvd::Vector3(0, 0, kGravity);
  try {
    fem::solveUnilateralStatic(up, supports());
    FAIL() << "no error";
  } catch (const tvd::SolverError& e) {
    // It names the springs it released and the free motion they leave. (Releasing all three at
    // once leaves the bar free; from the bonded set, one at a time, two released already leave
    // it a mechanism on the third.)
    const std::string what = e.what();
    EXPECT_NE(what.find("with the 2 unilateral springs in tension released (support_"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("mechanism"), std::string::npos) << what;
    EXPECT_NE(what.find("singular"), std::string::npos) << what;
  }
}

TEST(ContactStatics, TrackedVehicleRestsOnPadsAndWheelsThatPush) {
  const veh::VehicleDescription d = paperDescription();
  const veh::VehicleModel vehicle = veh::buildVehicleModel(d, veh::Variant::Tracked);
  const veh::ContactStatics c = veh::computeContactStatics(vehicle);
  const veh::StaticSummary& s = c.summary;
  EXPECT_LT(s.balanceError(), 1e-6);
  // Complementarity: no ground reaction pulls, a lifted sole carries nothing and has not sunk
  // below the road; no wheel pulls on its link, a lifted one carries nothing.
  const tvd::Vector u = c.system.dofs.transformation() *
                        fem::solveStatic(c.system, c.system.gravity_load).displacement;
  const double tolerance = 1e-6 * s.weight;
  int lifted = 0;
  for (std::size_t i = 0; i < s.pad_loads.size(); ++i) {
    EXPECT_GE(s.pad_loads[i], -tolerance) << i;
    if (!c.pad_lifted[i])
      continue;
    ++lifted;
    EXPECT_EQ(s.pad_loads[i], 0.0) << i;
    EXPECT_GE(u(c.system.dofs.physical(vehicle.layout.road_inputs[i].node, 2)), -1e-12) << i;
  }
  for (std::size_t i = 0; i < s.wheel_loads.size(); ++i) {
    EXPECT_GE(s.wheel_loads[i], -tolerance) << vehicle.layout.wheels[i].name;
    if (c.wheel_lifted[i]) {
      EXPECT_EQ(s.wheel_loads[i], 0.0) << vehicle.layout.wheels[i].name;
    }
  }
  // The bonded model pulls on the road between the wheels, at its rearmost wheels and at the
  // sprocket's lowest links (towards the rear incline): here the soles between the wheels and
  // those sprocket links let go, the rest stays down. With the chain free to leave the sprocket
  // the rearmost wheels no longer pull on it (with the sprocket bonded, they lifted).
  EXPECT_GT(lifted, 0);
  EXPECT_LT(lifted, static_cast<int>(s.pad_loads.size()) / 2);
  EXPECT_FALSE(c.wheel_lifted[6] || c.wheel_lifted[13]);  // road_wheel_left_7, road_wheel_right_7
  EXPECT_GT(s.wheel_loads[6], 0.0);
  const veh::ChainWheelRelease sprocket =
      veh::chainWheelRelease(vehicle.layout, c.chain_wheel_released, 0, veh::ChainWheel::Sprocket);
  EXPECT_GT(sprocket.released, 0);
  EXPECT_LT(sprocket.released, sprocket.contacts);
}

TEST(ContactStatics, UntrackedVehicleIsAlreadyInCompression) {
  const veh::VehicleDescription d = paperDescription();
  const veh::VehicleModel vehicle = veh::buildVehicleModel(d, veh::Variant::Untracked);
  const veh::ContactStatics c = veh::computeContactStatics(vehicle);
  EXPECT_EQ(c.iterations, 1);
  EXPECT_EQ(std::count(c.pad_lifted.begin(), c.pad_lifted.end(), true), 0);
  // No chain, no sprocket, idler or roller contacts.
  EXPECT_TRUE(vehicle.layout.chain_wheel_contacts.empty());
  EXPECT_TRUE(c.chain_wheel_released.empty());
  EXPECT_TRUE(c.summary.chain_wheel_loads.empty());
  const veh::StaticSummary bonded =
      veh::computeStaticSummary(vehicle, fem::assemble(vehicle.model));
  EXPECT_NEAR(c.summary.hull_sag, bonded.hull_sag, 1e-12);
  for (std::size_t i = 0; i < bonded.wheel_loads.size(); ++i)
    EXPECT_NEAR(c.summary.wheel_loads[i], bonded.wheel_loads[i], 1e-9 * bonded.weight);
}

TEST(ContactStatics, UntrackedPadsLeftOnOneColumnOfSolesAreNamed) {
  // Hard braking (or accelerating) leaves every un-tracked pad on its front (rear) column of
  // soles, and together they let the hull move, each pad rocking about its column (the
  // wheel-link contact carries no moment). No equilibrium with contacts that cannot pull; the
  // message names the pads and the column instead of the free motion's node numbers. Just below
  // the limit some pads keep two columns.
  const veh::VehicleModel vehicle =
      veh::buildVehicleModel(paperDescription(), veh::Variant::Untracked);
  for (const auto& [a, column] : {std::pair<double, std::string>{-9.0, "front"}, {9.0, "rear"}}) {
    SCOPED_TRACE(a);
    try {
      veh::computeContactStatics(vehicle, a);
      ADD_FAILURE() << "solved, but every pad stands on one column of soles";
    } catch (const tvd::SolverError& e) {
      EXPECT_NE(std::string(e.what()).find(
                    "no static equilibrium with contacts that cannot pull: every pad on the road "
                    "has lifted but for one column of soles (14 track assemblies: track_left_0 "
                    "at x = 2.34 m (" +
                    column + " column), "),
                std::string::npos)
          << e.what();
    }
  }
  const veh::ContactStatics c = veh::computeContactStatics(vehicle, -7.0);
  EXPECT_EQ(std::count(c.pad_lifted.begin(), c.pad_lifted.end(), true), 52);
}

TEST(ContactStatics, AChangeThatLeavesAPartFreeIsRetakenOneContactAtATime) {
  // Centre of gravity 2.3 m aft: changing every violated contact at once lifts two pads entirely
  // with their wheels' patches (free bodies) for a solve. From the last solved set one contact
  // at a time finds the solution: the same set as the worst-only rule from the start, no
  // pressed contact pulling, reactions equal to the weight.
  veh::VehicleDescription aft = paperDescription();
  aft.hull.cog_x = -2.3;
  const veh::VehicleModel vehicle = veh::buildVehicleModel(aft, veh::Variant::Untracked);
  const veh::ContactStatics c = veh::computeContactStatics(vehicle);
  const fem::UnilateralStaticResult worst = fem::solveUnilateralStatic(
      vehicle.model, veh::unilateralContacts(vehicle), 400, fem::ActiveSetUpdate::WorstOnly);
  const std::size_t pads = vehicle.layout.road_inputs.size();
  ASSERT_EQ(c.pad_lifted.size(), pads);
  EXPECT_GT(std::count(c.pad_lifted.begin(), c.pad_lifted.end(), true), 0);
  for (std::size_t i = 0; i < pads; ++i)
    EXPECT_EQ(c.pad_lifted[i], worst.released[i]) << "road input " << i;
  for (std::size_t i = 0; i < worst.normal_force.size(); ++i)
    EXPECT_GE(worst.normal_force[i], 0.0);
  EXPECT_NEAR(c.summary.ground_reaction, c.summary.weight, 1e-6 * c.summary.weight);
}

TEST(ContactStatics, BrakingIsHeldByTheRoadAndLoadsTheFrontWheels) {
  // 0.3 g braking of the tracked vehicle: the road holds it back with m a along x and still
  // carries its weight; the nose goes down (+ry, REP-103) and the front wheels take load from
  // the rear ones. Linear in a while the contacts stay bonded (the un-tracked vehicle).
  const double a = -0.3 * kGravity;
  const veh::VehicleDescription d = paperDescription();
  const veh::VehicleModel tracked = veh::buildVehicleModel(d, veh::Variant::Tracked);
  const veh::ContactStatics rest = veh::computeContactStatics(tracked);
  const veh::ContactStatics brake = veh::computeContactStatics(tracked, a);
  const double m = tracked.model.totalMass();
  EXPECT_NEAR(brake.summary.ground_reaction_x, m * a, 1e-6 * m * kGravity);
  EXPECT_NEAR(rest.summary.ground_reaction_x, 0.0, 1e-6 * m * kGravity);
  EXPECT_NEAR(brake.summary.ground_reaction, brake.summary.weight, 1e-6 * brake.summary.weight);
  EXPECT_GT(brake.summary.hull_pitch, rest.summary.hull_pitch);
  EXPECT_GT(brake.summary.wheel_loads.front(), rest.summary.wheel_loads.front());  // left 1
  EXPECT_LT(brake.summary.wheel_loads[6], rest.summary.wheel_loads[6]);            // left 7

  const veh::VehicleModel untracked = veh::buildVehicleModel(d, veh::Variant::Untracked);
  const fem::System system = fem::assemble(untracked.model);
  const veh::StaticSummary s0 = veh::computeStaticSummary(untracked, system);
  const veh::StaticSummary s1 = veh::computeStaticSummary(untracked, system, a);
  const veh::StaticSummary s2 = veh::computeStaticSummary(untracked, system, 2.0 * a);
  EXPECT_NEAR(s2.hull_pitch - s0.hull_pitch, 2.0 * (s1.hull_pitch - s0.hull_pitch),
              1e-9 * std::abs(s1.hull_pitch - s0.hull_pitch));
  EXPECT_NEAR(s1.ground_reaction_x, untracked.model.totalMass() * a,
              1e-6 * untracked.model.totalMass() * kGravity);
  // Unilateral and bonded agree while no pad sole lifts: at 0.05 g (at 0.3 g the rear soles of
  // the rear pads, tipped forward by the shear, let go).
  const veh::StaticSummary gentle = veh::computeStaticSummary(untracked, system, a / 6.0);
  const veh::ContactStatics c1 = veh::computeContactStatics(untracked, a / 6.0);
  EXPECT_EQ(std::count(c1.pad_lifted.begin(), c1.pad_lifted.end(), true), 0);
  EXPECT_NEAR(c1.summary.hull_pitch, gentle.hull_pitch, 1e-9 * std::abs(gentle.hull_pitch));
}

TEST(ContactStatics, LinksPushTheirSprocketsIdlersAndRollersOrLeaveThem) {
  // Complementarity of the chain wheel contacts, with the normal checked against the geometry:
  // the contact frame's z must point from the contact point on the link to the wheel's centre,
  // the direction in which the link pushes the wheel. A bonded contact carries
  // N = k z . (u_link - u_wheel) >= 0; a released one carries nothing and its link has not moved
  // into the wheel, z . (u_link - u_wheel) <= 0. With the sign of unilateralContacts flipped the
  // solver would keep the pulling contacts and release the pushing ones, and both checks fail;
  // so would the rollers', which carry the top run in compression.
  for (const veh::VehicleModel& vehicle : trackedVehicles()) {
    const veh::VehicleLayout& layout = vehicle.layout;
    SCOPED_TRACE(std::to_string(layout.return_rollers.size()) + " return rollers");
    const veh::ContactStatics c = veh::computeContactStatics(vehicle);
    const veh::StaticSummary& s = c.summary;
    EXPECT_LT(s.balanceError(), 1e-6);
    // The chain's vertical balance (StaticSummary::chain_wheel_vertical): what holds it up, the
    // ground and the sprockets, idlers and rollers, equals what presses it down, the road wheels
    // and its own weight. A wrong sign or a missed contact would be off by that force, which is
    // not small (it is why the wheel loads do not sum to the weight).
    const double wheels = std::accumulate(s.wheel_loads.begin(), s.wheel_loads.end(), 0.0);
    const double chain_weight = layout.mass.track_assemblies * vehicle.model.gravity.norm();
    EXPECT_NEAR(s.ground_reaction + s.chain_wheel_vertical, wheels + chain_weight, 1e-6 * s.weight);
    EXPECT_GT(std::abs(s.chain_wheel_vertical), 0.01 * s.weight);
    ASSERT_FALSE(layout.chain_wheel_contacts.empty());
    ASSERT_EQ(c.chain_wheel_released.size(), layout.chain_wheel_contacts.size());
    ASSERT_EQ(s.chain_wheel_loads.size(), layout.chain_wheel_contacts.size());
    const tvd::Vector u = c.system.dofs.transformation() *
                          fem::solveStatic(c.system, c.system.gravity_load).displacement;
    const auto index = vehicle.model.nodeIndex();
    const auto position = [&](tvd::NodeId id) {
      return vehicle.model.nodes[index.at(id)].position;
    };
    const auto displacement = [&](tvd::NodeId id) -> tvd::Vector3 {
      return u.segment<3>(c.system.dofs.physical(id, 0));
    };
    const double tolerance = 1e-6 * s.weight;
    int rollers = 0, released = 0;
    for (std::size_t i = 0; i < layout.chain_wheel_contacts.size(); ++i) {
      const veh::ChainWheelContact& w = layout.chain_wheel_contacts[i];
      const fem::Spring& spring = vehicle.model.springs[w.spring];
      const std::string& name = spring.name;
      const tvd::Vector3 to_centre =
          (position(wheelCentre(layout, w)) - position(spring.n1)).normalized();
      const tvd::Vector3 n = spring.frame.col(2);
      ASSERT_GT(n.dot(to_centre), 0.5) << name;
      const double approach = n.dot(displacement(spring.n2) - displacement(spring.n1));
      const double k = vehicle.model.springs[w.spring].stiffness(2);
      if (c.chain_wheel_released[i]) {
        ++released;
        EXPECT_EQ(s.chain_wheel_loads[i], 0.0) << name;
        EXPECT_LE(k * approach, tolerance) << name << ": released but overlapping";
      } else {
        EXPECT_GE(k * approach, -tolerance) << name << ": bonded but pulling";
        EXPECT_NEAR(s.chain_wheel_loads[i], k * approach, 1e-9 * s.weight) << name;
      }
      if (w.wheel == veh::ChainWheel::ReturnRoller) {
        // The top run rests on the rollers: in compression, bonded.
        ++rollers;
        EXPECT_FALSE(c.chain_wheel_released[i]) << name;
        EXPECT_GT(s.chain_wheel_loads[i], 0.0) << name;
      }
    }
    EXPECT_EQ(rollers, static_cast<int>(layout.return_rollers.size()));
    // The bonded model pulls on some of them (the lowest sprocket links): the case is not void.
    EXPECT_GT(released, 0);
  }
}

TEST(ContactStatics, ReleasedSetsMirrorLeftAndRight) {
  // The vehicle is symmetric about x-z: each side releases the same contacts (the chain wheel
  // contacts and road wheels are listed in the same sequence per side).
  const veh::VehicleModel vehicle = trackedWithReturnRollers();
  const veh::VehicleLayout& layout = vehicle.layout;
  const veh::ContactStatics c = veh::computeContactStatics(vehicle);
  const std::size_t contacts = layout.chain_wheel_contacts.size() / 2;
  ASSERT_EQ(2 * contacts, layout.chain_wheel_contacts.size());
  for (std::size_t i = 0; i < contacts; ++i) {
    const veh::ChainWheelContact& left = layout.chain_wheel_contacts[i];
    const veh::ChainWheelContact& right = layout.chain_wheel_contacts[contacts + i];
    ASSERT_EQ(left.side, 0);
    ASSERT_EQ(right.side, 1);
    ASSERT_EQ(left.wheel, right.wheel) << i;
    EXPECT_EQ(c.chain_wheel_released[i], c.chain_wheel_released[contacts + i])
        << vehicle.model.springs[left.spring].name;
    EXPECT_NEAR(c.summary.chain_wheel_loads[i], c.summary.chain_wheel_loads[contacts + i],
                1e-6 * c.summary.weight);
  }
  for (const veh::ChainWheel wheel :
       {veh::ChainWheel::Sprocket, veh::ChainWheel::Idler, veh::ChainWheel::ReturnRoller}) {
    const veh::ChainWheelRelease l =
        veh::chainWheelRelease(layout, c.chain_wheel_released, 0, wheel);
    const veh::ChainWheelRelease r =
        veh::chainWheelRelease(layout, c.chain_wheel_released, 1, wheel);
    EXPECT_GT(l.contacts, 0) << veh::chainWheelName(wheel);
    EXPECT_EQ(l.contacts, r.contacts) << veh::chainWheelName(wheel);
    EXPECT_EQ(l.released, r.released) << veh::chainWheelName(wheel);
  }
  const std::size_t wheels = layout.wheels.size() / 2;
  for (std::size_t i = 0; i < wheels; ++i)
    EXPECT_EQ(c.wheel_lifted[i], c.wheel_lifted[wheels + i]) << layout.wheels[i].name;
  int lifted[2] = {0, 0};
  for (std::size_t i = 0; i < layout.road_inputs.size(); ++i)
    lifted[layout.road_inputs[i].side] += c.pad_lifted[i] ? 1 : 0;
  EXPECT_EQ(lifted[0], lifted[1]);
  EXPECT_THROW(veh::chainWheelRelease(layout, {true}, 0, veh::ChainWheel::Idler),
               std::invalid_argument);
}

TEST(ContactStatics, ChainHangsInItsPinsWithEveryChainWheelLetGo) {
  // A released sprocket, idler or roller contact leaves no mechanism: the chain is a continuous
  // beam pin to pin, on the road wheels and the ground. Even with the normal of every one of
  // them released the stiffness matrix stays regular and the ground carries the weight.
  veh::VehicleModel vehicle = trackedWithReturnRollers();
  for (const veh::ChainWheelContact& w : vehicle.layout.chain_wheel_contacts)
    vehicle.model.springs[w.spring].stiffness(2) = 0.0;
  const fem::System system = fem::assemble(vehicle.model);
  veh::StaticSummary s;
  ASSERT_NO_THROW(s = veh::computeStaticSummary(vehicle, system));
  EXPECT_LT(s.balanceError(), 1e-6);
  for (double load : s.chain_wheel_loads)
    EXPECT_EQ(load, 0.0);
}
