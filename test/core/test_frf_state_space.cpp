// The exact FRF of a system whose damping couples its modes, by one Hessenberg reduction
// (frf_state_space.h): it must equal the dense LU of eq. 18 (frfDirect) to round-off, where
// eq. 20's modal damping does not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "dynamics_test_models.h"
#include "tracked_vehicle_dynamics/dynamics/frf_state_space.h"
#include "tracked_vehicle_dynamics/error.h"

using namespace tracked_vehicle_dynamics;
using namespace tracked_vehicle_dynamics::dynamics;

namespace {

// max |a - b| over the peak of |b|: round-off of the two solutions relative to the response.
double errorOverPeak(const ComplexMatrix& a, const ComplexMatrix& b) {
  return (a - b).cwiseAbs().maxCoeff() / b.cwiseAbs().maxCoeff();
}

// The same output by output: max over columns of max |a - b| / max |b| in that column (a small
// output is not judged against a large one's peak).
double errorPerOutput(const ComplexMatrix& a, const ComplexMatrix& b) {
  double worst = 0.0;
  for (Eigen::Index c = 0; c < b.cols(); ++c)
    worst = std::max(worst,
                     (a.col(c) - b.col(c)).cwiseAbs().maxCoeff() / b.col(c).cwiseAbs().maxCoeff());
  return worst;
}

// A discrete damper c between DOFs i and j (a rotary arm damper in the vehicle): C stops being
// a combination of M and K.
void addDamper(SecondOrderSystem* s, int i, int j, double c) {
  s->damping(i, i) += c;
  s->damping(j, j) += c;
  s->damping(i, j) -= c;
  s->damping(j, i) -= c;
}

}  // namespace

// A random vehicle-like model on 2e10 N/m tyres with three discrete dampers: coupled modes.
TEST(FrfStateSpace, EqualsTheDirectSolutionWhenDampersCoupleTheModes) {
  SecondOrderSystem s = test::randomVehicle(40, 6, 8, 71);
  addDamper(&s, 3, 20, 4e4);
  addDamper(&s, 11, 30, 2e4);
  addDamper(&s, 0, 39, 1e4);
  const ModalSystem modal(s);
  ASSERT_GT(modal.maxOffDiagonalDampingRatio(), 0.1);
  const Vector f = Vector::LinSpaced(401, 0.0, 60.0);
  for (const InputDelay& delay :
       {InputDelay::synchronous(), InputDelay::travelling(s.input_stations, 8.3)}) {
    for (OutputQuantity quantity :
         {OutputQuantity::Displacement, OutputQuantity::Velocity, OutputQuantity::Acceleration}) {
      const ComplexMatrix direct = frfDirect(s, f, delay, quantity);
      const ComplexMatrix fast = frfStateSpace(s, modal, f, delay, quantity);
      ASSERT_EQ(fast.rows(), direct.rows());
      ASSERT_EQ(fast.cols(), direct.cols());
      EXPECT_LT(errorOverPeak(fast, direct), 1e-9) << static_cast<int>(quantity);
      EXPECT_LT(errorPerOutput(fast, direct), 1e-8) << static_cast<int>(quantity);
      // What the exactness buys: eq. 20 (diagonal of Phi^T C Phi) is visibly off here.
      EXPECT_GT(errorOverPeak(frfModal(modal, f, delay, quantity), direct), 1e-3);
    }
  }
}

// frfExact takes the state space where dampers couple the modes and eq. 20 where they do not
// (Rayleigh damping), and says which.
TEST(FrfStateSpace, FrfExactChoosesTheRouteByTheCoupling) {
  const Vector f = Vector::LinSpaced(121, 0.0, 60.0);
  const InputDelay delay = InputDelay::synchronous();
  SecondOrderSystem coupled = test::randomVehicle(30, 4, 6, 5);
  addDamper(&coupled, 2, 17, 3e4);
  const ModalSystem coupled_modes(coupled);
  bool used_modal = true;
  const ComplexMatrix exact =
      frfExact(coupled, coupled_modes, f, delay, OutputQuantity::Acceleration, &used_modal);
  EXPECT_FALSE(used_modal);
  const ComplexMatrix direct = frfDirect(coupled, f, delay, OutputQuantity::Acceleration);
  EXPECT_LT(errorOverPeak(exact, direct), 1e-9);
  EXPECT_GT(errorOverPeak(frfModal(coupled_modes, f, delay), direct), 1e-3);

  const SecondOrderSystem rayleigh = test::randomVehicle(30, 4, 6, 5);
  const ModalSystem rayleigh_modes(rayleigh);
  ASSERT_LE(rayleigh_modes.maxOffDiagonalDampingRatio(), kModalDampingCouplingTolerance);
  const ComplexMatrix modal_route =
      frfExact(rayleigh, rayleigh_modes, f, delay, OutputQuantity::Acceleration, &used_modal);
  EXPECT_TRUE(used_modal);
  EXPECT_EQ(modal_route, frfModal(rayleigh_modes, f, delay));
  EXPECT_LT(errorOverPeak(modal_route, frfDirect(rayleigh, f, delay)), 1e-9);
}

// The quarter car with a suspension damper and an undamped 2e10 N/m tyre (non-proportional):
// the static limit x/h = 1 at 0 Hz for both masses, and the direct solution at every frequency.
TEST(FrfStateSpace, QuarterCarOnAStiffTyreKeepsTheStaticLimit) {
  const SecondOrderSystem s = test::quarterCar(300.0, 30.0, 3e4, 2e3, 2e10, 0.0);
  const ModalSystem modal(s);
  ASSERT_GT(modal.maxOffDiagonalDampingRatio(), 1e-3);
  const Vector f = Vector::LinSpaced(301, 0.0, 30.0);
  const ComplexMatrix x =
      frfStateSpace(s, modal, f, InputDelay::synchronous(), OutputQuantity::Displacement);
  EXPECT_NEAR(std::abs(x(0, 0) - 1.0), 0.0, 1e-9);
  EXPECT_NEAR(std::abs(x(0, 1) - 1.0), 0.0, 1e-9);
  EXPECT_LT(
      errorOverPeak(x, frfDirect(s, f, InputDelay::synchronous(), OutputQuantity::Displacement)),
      1e-9);
}

// Two masses joined by a spring and a damper, driven by a force on the first (an input that
// is a force, not a road): a rigid-body mode (omega = 0). Above 0 Hz its displacement comes
// from eta' / (j omega); at 0 Hz j omega I - A is singular and that is said.
TEST(FrfStateSpace, RigidBodyModeAboveZeroHertzAndSingularAtIt) {
  SecondOrderSystem s;
  const double m1 = 10.0, m2 = 30.0, k = 4e4, c = 60.0;
  s.mass = Eigen::Vector2d(m1, m2).asDiagonal();
  s.stiffness = k * Eigen::Matrix2d{{1, -1}, {-1, 1}};
  s.damping = c * Eigen::Matrix2d{{1, -1}, {-1, 1}};
  s.damping(1, 1) += 5.0;  // a damper to ground on mass 2 only: not proportional
  s.input_stiffness = (Matrix(2, 1) << 1.0, 0.0).finished();
  s.input_damping = Matrix::Zero(2, 1);
  s.output = Matrix::Identity(2, 2);
  s.output_names = {"m1", "m2"};
  s.input_stations = Vector::Zero(1);
  const ModalSystem modal(s);
  ASSERT_EQ(modal.naturalFrequencies()(0), 0.0);
  const Vector f = Vector::LinSpaced(100, 0.05, 20.0);
  for (OutputQuantity quantity :
       {OutputQuantity::Displacement, OutputQuantity::Velocity, OutputQuantity::Acceleration})
    EXPECT_LT(errorOverPeak(frfStateSpace(s, modal, f, InputDelay::synchronous(), quantity),
                            frfDirect(s, f, InputDelay::synchronous(), quantity)),
              1e-9);
  s.damping(1, 1) -= 5.0;  // free-free: the rigid mode has no damping, singular at 0 Hz
  EXPECT_THROW(frfStateSpace(s, ModalSystem(s), Vector::Zero(1), InputDelay::synchronous()),
               SolverError);
}

TEST(FrfStateSpace, Errors) {
  const double omega = kTwoPi * 1.0;
  const SecondOrderSystem undamped = test::oneDof(1.0, 0.0, omega * omega, 0.0);
  const ModalSystem modal(undamped);
  try {
    frfStateSpace(undamped, modal, Vector::Constant(1, 1.0), InputDelay::synchronous());
    ADD_FAILURE() << "an undamped resonance on the grid is singular";
  } catch (const SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("1.000000 Hz"), std::string::npos) << e.what();
  }
  // 1e-15 off the resonance: the elimination's error bound N eps / (2e-15) passes 10 %, so
  // singular to working precision, not a response of 1e15 of unknown accuracy.
  EXPECT_THROW(
      frfStateSpace(undamped, modal, Vector::Constant(1, 1.0 + 1e-15), InputDelay::synchronous()),
      SolverError);
  EXPECT_THROW(frfStateSpace(undamped, modal, Vector::Constant(1, -1.0), InputDelay::synchronous()),
               InputError);
  const SecondOrderSystem other = test::quarterCar();
  EXPECT_THROW(frfStateSpace(other, modal, Vector::Constant(1, 2.0), InputDelay::synchronous()),
               InputError);
  // Same sizes, other outputs (withOutput) or another model's modes: refused, not a wrong FRF.
  const ModalSystem car(other);
  EXPECT_THROW(frfStateSpace(other, car.withOutput(Matrix::Identity(2, 2) * 2.0, {"a", "b"}),
                             Vector::Constant(1, 2.0), InputDelay::synchronous()),
               InputError);
  const SecondOrderSystem softer = test::quarterCar(300.0, 30.0, 2e4);
  EXPECT_THROW(frfStateSpace(other, ModalSystem(softer), Vector::Constant(1, 2.0),
                             InputDelay::synchronous()),
               InputError);
}
