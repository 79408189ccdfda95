// Static equilibrium on a road: K q0 = f_g + K_u u0 (StaticEquilibriumSolver), on the reduced
// paper vehicle of both variants. A uniform road height h under every input lifts the vehicle
// rigidly by h (K r_h = K_u h 1 for the rigid vertical translation r_h, gravity unchanged); a
// height under the left inputs only rolls it to the right side down (positive rx, REP-103), and
// by the vehicle's left/right symmetry lifts its CoG by h / 2.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <memory>
#include <string>

#include "tracked_vehicle_dynamics/dynamics/static_equilibrium.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tvd = tracked_vehicle_dynamics;
using tvd::Matrix;
using tvd::Vector;
using tvd::dynamics::StaticEquilibriumSolver;

namespace {

const std::string kVehicle = std::string(TVD_SOURCE_DIR) + "/config/vehicles/paper_vehicle.yaml";
constexpr double kHeight = 0.3;  // [m] road height under the inputs
// Rigid translation: rounding of the solve relative to the height (K spans tyre stiffnesses of
// 1e9 N/m and suspension ones of 1e5 N/m).
constexpr double kRigidTolerance = 1e-9;
// The CoG's lift by a one-sided height: the description is symmetric up to rounding.
constexpr double kSymmetryTolerance = 1e-9;

const tvd::reduction::ReducedModel& model(tvd::vehicle::Variant variant) {
  static std::map<tvd::vehicle::Variant, std::unique_ptr<tvd::reduction::ReducedModel>> cache;
  auto& slot = cache[variant];
  if (!slot) {
    slot = std::make_unique<tvd::reduction::ReducedModel>(
        tvd::reduction::reduceVehicle(tvd::vehicle::loadVehicleDescription(kVehicle), variant, {}));
  }
  return *slot;
}

Eigen::Index row(const std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  EXPECT_NE(it, names.end()) << name;
  return static_cast<Eigen::Index>(it - names.begin());
}

bool startsWith(const std::string& s, const std::string& prefix) {
  return s.compare(0, prefix.size(), prefix) == 0;
}

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() &&
         s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

class StaticEquilibriumOnRoad : public ::testing::TestWithParam<tvd::vehicle::Variant> {
 protected:
  /// Displacement outputs y = H q0 at equilibrium on road heights u.
  Vector outputs(const StaticEquilibriumSolver& solver, const Vector& u) const {
    const auto& sys = model(GetParam()).system;
    return sys.output * solver.solve(u).head(sys.size());
  }
};

TEST_P(StaticEquilibriumOnRoad, EqualsTheOneShotSolveAndHasZeroVelocity) {
  const auto& m = model(GetParam());
  const StaticEquilibriumSolver solver(m.system, m.gravity_load);
  const Vector u = Vector::LinSpaced(m.system.inputCount(), -0.1, 0.2);
  const Vector z = solver.solve(u);
  const tvd::DofIndex n = m.system.size();
  ASSERT_EQ(z.size(), 2 * n);
  EXPECT_TRUE(z.tail(n).isZero(0.0));
  const Vector load = m.gravity_load + m.system.input_stiffness * u;
  EXPECT_LT((m.system.stiffness * z.head(n) - load).norm(), 1e-9 * load.norm());
  EXPECT_TRUE(z == tvd::dynamics::staticEquilibrium(m.system, u, m.gravity_load));
  EXPECT_THROW(solver.solve(Vector::Zero(m.system.inputCount() + 1)), tvd::InputError);
}

TEST_P(StaticEquilibriumOnRoad, UniformRoadHeightLiftsTheVehicleRigidly) {
  const auto& m = model(GetParam());
  const auto& names = m.system.output_names;
  const StaticEquilibriumSolver solver(m.system, m.gravity_load);
  const Eigen::Index inputs = m.system.inputCount();
  const Vector flat = outputs(solver, Vector::Zero(inputs));
  const Vector lifted = outputs(solver, Vector::Constant(inputs, kHeight));
  const Vector shift = lifted - flat;
  int vertical = 0, wheels = 0;
  for (Eigen::Index k = 0; k < shift.size(); ++k) {
    const std::string& name = names[static_cast<std::size_t>(k)];
    // Every vertical translation rises by h; horizontal translations and rotations stay.
    const double expected = endsWith(name, " uz") ? kHeight : 0.0;
    EXPECT_NEAR(shift(k), expected, kRigidTolerance * kHeight) << name;
    vertical += endsWith(name, " uz");
    wheels += startsWith(name, "road_wheel_") && endsWith(name, " uz");
  }
  EXPECT_GE(wheels, 14);        // 7 road wheels per side on the paper vehicle
  EXPECT_GT(vertical, wheels);  // hull and named points too
  // The flat equilibrium is not trivially zero: the hull sags under gravity.
  EXPECT_LT(flat(row(names, "hull uz")), -1e-3);
}

TEST_P(StaticEquilibriumOnRoad, LeftSideHeightRollsTheHullRightSideDown) {
  const auto& m = model(GetParam());
  const auto& names = m.system.output_names;
  const StaticEquilibriumSolver solver(m.system, m.gravity_load);
  const Eigen::Index inputs = m.system.inputCount();
  Vector left = Vector::Zero(inputs);
  int left_inputs = 0, right_inputs = 0;
  for (Eigen::Index q = 0; q < inputs; ++q) {
    if (m.system.input_lateral(q) > 0.0) {  // y left
      left(q) = kHeight;
      ++left_inputs;
    } else {
      right_inputs += m.system.input_lateral(q) < 0.0;
    }
  }
  ASSERT_GT(left_inputs, 0);
  ASSERT_EQ(left_inputs, right_inputs);
  const Vector shift = outputs(solver, left) - outputs(solver, Vector::Zero(inputs));
  // REP-103: rx about x forward; the left side (+y) up is a positive roll.
  const double roll = shift(row(names, "hull rx"));
  EXPECT_GT(roll, 1e-3 * kHeight);  // [rad] for a track of a few metres: about h / 3
  EXPECT_LT(roll, kHeight);         // at most h over 1 m
  // Symmetric half h/2 on both sides (a rigid lift) plus an antisymmetric half that does not
  // move the CoG vertically.
  EXPECT_NEAR(shift(row(names, "hull uz")), 0.5 * kHeight, kSymmetryTolerance);
  for (int k = 1; k <= 7; ++k) {
    const double up_left = shift(row(names, "road_wheel_left_" + std::to_string(k) + " uz"));
    const double up_right = shift(row(names, "road_wheel_right_" + std::to_string(k) + " uz"));
    EXPECT_GT(up_left, up_right) << "wheel " << k;
    EXPECT_NEAR(up_left + up_right, kHeight, kSymmetryTolerance) << "wheel " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(BothVariants, StaticEquilibriumOnRoad,
                         ::testing::Values(tvd::vehicle::Variant::Untracked,
                                           tvd::vehicle::Variant::Tracked),
                         [](const auto& info) {
                           return std::string(tvd::vehicle::variantName(info.param));
                         });

}  // namespace
