// Simulator (augmented-exponential and modal-decoupled engines), static equilibrium and the
// Newmark reference integrator.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "dynamics_test_models.h"
#include "expect_input_error.h"
#include "tracked_vehicle_dynamics/dynamics/discretization.h"
#include "tracked_vehicle_dynamics/dynamics/modal_system.h"
#include "tracked_vehicle_dynamics/dynamics/newmark.h"
#include "tracked_vehicle_dynamics/dynamics/simulator.h"
#include "tracked_vehicle_dynamics/dynamics/static_equilibrium.h"
#include "tracked_vehicle_dynamics/error.h"

using namespace tracked_vehicle_dynamics;
using namespace tracked_vehicle_dynamics::dynamics;

#include "count_allocations.h"

namespace {

constexpr double kMethodAgreement = 1e-8;   // modal vs augmented exponential, of the peak
constexpr double kNewmarkAgreement = 5e-3;  // Newmark (h/50) vs exact simulator, of the peak
// Rounding of Phi z + Gamma w + f_d, amplified by 1 / (1 - |lambda|) of the slowest mode over
// 200 steps: ~1e-10 of the state (a wrong offset or gain gives 1e-3 and more).
constexpr double kEquilibriumTolerance = 3e-10;

const std::vector<OutputQuantity> kAllQuantities = {
    OutputQuantity::Displacement, OutputQuantity::Velocity, OutputQuantity::Acceleration};

// Road inputs W = [U, U'] [n_samples x 2 n_inputs] of a vehicle at speed v over a
// raised-cosine bump of height a and length l starting at x0; input q at station x_q sees the
// road at x = v t + x_q, so the front input meets the bump first.
Matrix bumpInputs(const Vector& stations, int samples, double dt, double speed, double height,
                  double length, double x0) {
  const DofIndex n_u = stations.size();
  Matrix w = Matrix::Zero(samples, 2 * n_u);
  for (int k = 0; k < samples; ++k)
    for (DofIndex q = 0; q < n_u; ++q) {
      const double s = (speed * k * dt + stations(q) - x0) / length;
      if (s <= 0.0 || s >= 1.0)
        continue;
      w(k, q) = 0.5 * height * (1.0 - std::cos(kTwoPi * s));
      w(k, n_u + q) = 0.5 * height * kTwoPi / length * speed * std::sin(kTwoPi * s);
    }
  return w;
}

// max |a - b| over each column block of `block` rows, relative to the peak of that block in b.
double relativeBlockError(const Matrix& a, const Matrix& b, DofIndex block) {
  double worst = 0.0;
  for (DofIndex c0 = 0; c0 < b.cols(); c0 += block) {
    const double peak = b.middleCols(c0, block).cwiseAbs().maxCoeff();
    const double error = (a - b).middleCols(c0, block).cwiseAbs().maxCoeff();
    worst = std::max(worst, error / peak);
  }
  return worst;
}

SimulatorOptions options(DiscretizationMethod method, InputHold hold, double dt = 1e-3) {
  SimulatorOptions o;
  o.time_step = dt;
  o.hold = hold;
  o.method = method;
  o.quantities = kAllQuantities;
  return o;
}

/// options() with the generalized force f_g (gravity) applied.
SimulatorOptions options(DiscretizationMethod method, InputHold hold, const Vector& f_g) {
  SimulatorOptions o = options(method, hold);
  o.generalized_force = f_g;
  return o;
}

/// The gravity load of the 14-DOF test vehicles (every DOF's mass) and their bump road: 1.5 s at
/// 1 ms, 8 m/s over a 0.1 m bump.
Vector gravityLoad(const SecondOrderSystem& s) {
  return -kStandardGravity * s.mass * Vector::Ones(s.size());
}
Matrix bumpRoad(const SecondOrderSystem& s) {
  return bumpInputs(s.input_stations, 1500, 1e-3, 8.0, 0.1, 1.5, 3.0);
}

}  // namespace

// The outputs of the same input series through the dense augmented-exponential engine, and the
// modal engine batched (simulate) and stepped, all from z0 (empty: static equilibrium at zero
// road input), with their final states and the modal engine's off-diagonal damping ratio.
struct EngineRuns {
  Matrix dense, batch, stepped;
  Vector dense_state, batch_state;
  double off_diagonal = 0.0;
  std::vector<std::string> dense_names, batch_names;
};
EngineRuns runEngines(const SecondOrderSystem& s, const Vector& f_g, const Matrix& w,
                      InputHold hold = InputHold::FirstOrder, const Vector& z0_given = Vector()) {
  const SimulatorOptions dense_options =
      options(DiscretizationMethod::AugmentedExponential, hold, f_g);
  const SimulatorOptions modal_options = options(DiscretizationMethod::ModalDecoupled, hold, f_g);
  Simulator dense(s, dense_options), batch(s, modal_options), stepped(s, modal_options);
  const Vector z0 =
      z0_given.size() > 0 ? z0_given : staticEquilibrium(s, Vector::Zero(s.inputCount()), f_g);
  for (Simulator* sim : {&dense, &batch, &stepped})
    sim->reset(z0, w.row(0).transpose());
  EngineRuns runs;
  runs.dense = dense.simulate(w);
  runs.batch = batch.simulate(w);
  runs.stepped.resize(w.rows(), runs.batch.cols());
  runs.stepped.row(0) = stepped.outputs().transpose();
  for (DofIndex k = 1; k < w.rows(); ++k) {
    stepped.step(w.row(k).transpose());
    runs.stepped.row(k) = stepped.outputs().transpose();
  }
  runs.dense_state = dense.state();
  runs.batch_state = batch.state();
  runs.off_diagonal = batch.maxOffDiagonalDampingRatio();
  runs.dense_names = dense.outputNames();
  runs.batch_names = batch.outputNames();
  return runs;
}

// Rayleigh damping C = alpha M + beta K (and C_u = beta K_u) is diagonalised by the modes, so
// the modal-decoupled discretisation is exact as well: both engines agree to rounding, here on
// a model with 2e10 N/m tyres, gravity and all three output quantities.
TEST(Simulator, ModalEqualsAugmentedExponentialForRayleighDamping) {
  const SecondOrderSystem s = test::randomVehicle(14, 4, 6, 11);
  const Vector f_g = gravityLoad(s);
  const Matrix w = bumpRoad(s);
  const Vector z0 = staticEquilibrium(s, w.row(0).head(4).transpose(), f_g);
  for (InputHold hold : {InputHold::ZeroOrder, InputHold::FirstOrder}) {
    const EngineRuns runs = runEngines(s, f_g, w, hold, z0);
    EXPECT_LT(runs.off_diagonal, 1e-8);
    EXPECT_LT(relativeBlockError(runs.batch, runs.dense, 6), kMethodAgreement);
    EXPECT_LT((runs.batch_state - runs.dense_state).norm(),
              kMethodAgreement * runs.dense_state.norm());
    EXPECT_EQ(runs.dense_names, runs.batch_names);
    EXPECT_EQ(runs.batch_names[13], "dof_1 uz/acc");
  }
}

// The blocked modal simulate() and the dense one must equal step-by-step stepping.
TEST(Simulator, SimulateEqualsStepping) {
  const SecondOrderSystem s = test::randomVehicle(10, 3, 4, 5);
  const Matrix w = bumpInputs(s.input_stations, 700, 1e-3, 12.0, 0.05, 1.0, 2.5);
  for (DiscretizationMethod method :
       {DiscretizationMethod::ModalDecoupled, DiscretizationMethod::AugmentedExponential})
    for (InputHold hold : {InputHold::ZeroOrder, InputHold::FirstOrder}) {
      Simulator batch(s, options(method, hold));
      Simulator stepped(s, options(method, hold));
      const Matrix y = batch.simulate(w);
      ASSERT_EQ(y.rows(), 700);
      ASSERT_EQ(y.cols(), 12);
      Matrix y_stepped(700, 12);
      y_stepped.row(0) = stepped.outputs().transpose();
      for (int k = 1; k < 700; ++k) {
        stepped.step(w.row(k).transpose());
        y_stepped.row(k) = stepped.outputs().transpose();
      }
      EXPECT_LT(relativeBlockError(y, y_stepped, 4), 1e-12);
      EXPECT_EQ(batch.stepCount(), 699);
      EXPECT_NEAR(batch.time(), 0.699, 1e-12);
      EXPECT_LT((batch.state() - stepped.state()).norm(), 1e-12 * stepped.state().norm());
    }
}

// A Simulator built from a discrete StateSpace runs the same recursion as one built from the
// second-order system; step(w_begin, w_end) first replaces the current input.
TEST(Simulator, FromDiscreteStateSpaceAndTwoSidedStep) {
  const SecondOrderSystem s = test::randomVehicle(7, 2, 3, 13);
  const SimulatorOptions o =
      options(DiscretizationMethod::AugmentedExponential, InputHold::FirstOrder);
  Simulator from_system(s, o);
  Simulator from_state_space(
      discretize(fromSecondOrder(s, kAllQuantities), 1e-3, InputHold::FirstOrder));
  const Matrix w = bumpInputs(s.input_stations, 300, 1e-3, 9.0, 0.05, 1.0, 2.2);
  EXPECT_LT(relativeBlockError(from_state_space.simulate(w), from_system.simulate(w), 3), 1e-14);
  EXPECT_EQ(from_state_space.hold(), InputHold::FirstOrder);
  EXPECT_EQ(from_state_space.timeStep(), 1e-3);

  Simulator a(s, o), b(s, o);
  const Vector w0 = Vector::Random(4), w1 = Vector::Random(4);
  a.step(w0, w1);
  b.reset(Vector::Zero(14), w0);
  b.step(w1);
  EXPECT_LT((a.state() - b.state()).norm(), 1e-15 * b.state().norm());
  EXPECT_EQ(a.outputs(), b.outputs());
}

// A free (ungrounded) chain under gravity falls as a rigid body, q = -g t^2 / 2: exercises the
// omega = 0 modes and an input without any modal force.
TEST(Simulator, RigidBodyFreeFallIsExact) {
  SecondOrderSystem s = test::chain(3, 15.0, 1e6, 0.0, 0.0, 0.0);
  const Vector f_g = -kStandardGravity * s.mass * Vector::Ones(3);
  for (DiscretizationMethod method :
       {DiscretizationMethod::AugmentedExponential, DiscretizationMethod::ModalDecoupled})
    for (InputHold hold : {InputHold::ZeroOrder, InputHold::FirstOrder}) {
      SimulatorOptions o = options(method, hold, 2e-3);
      o.generalized_force = f_g;
      Simulator sim(s, o);
      const Matrix y = sim.simulate(Matrix::Zero(501, 2));
      for (int k = 0; k <= 500; k += 50) {
        const double t = k * 2e-3;
        for (int i = 0; i < 3; ++i) {
          EXPECT_NEAR(y(k, i), -0.5 * kStandardGravity * t * t, 1e-9) << "t = " << t;
          EXPECT_NEAR(y(k, 3 + i), -kStandardGravity * t, 1e-9) << "t = " << t;
          EXPECT_NEAR(y(k, 6 + i), -kStandardGravity, 1e-7) << "t = " << t;
        }
      }
    }
}

// Heavy masses on soft springs over light pads held by ground ties of 1e15 N/m (the vehicle's
// pads on a very stiff road): lambda_max ~ 5e15 rad^2/s^2 while the masses' modes lie at 10-50.
// The dense solver alone gave those to an absolute few n eps lambda_max, below 1e-12 lambda_max,
// and took them for rigid-body modes (0 Hz): the modal simulator let the masses drift off and the
// modal FRF refused "mode 0 is a rigid-body mode" (review 157). Closed form in the limit of rigid
// ties (the ties' compliance shifts them by k_s / k_g = 1e-11): a fixed-fixed chain of masses m,
// neighbours and both ends joined by k_c, each mass on k_s,
//   lambda_j = (k_s + 4 k_c sin^2(j pi / (2 (N + 1)))) / m.
TEST(Simulator, StiffGroundTiesKeepTheLowModes) {
  const int count = 10;
  const double m = 1000.0, m_pad = 0.2, k_s = 1e4, k_c = 2e4, k_g = 1e15;
  const int n = 2 * count;  // mass i at 2 i, its pad at 2 i + 1
  SecondOrderSystem s;
  s.mass = Matrix::Zero(n, n);
  s.stiffness = Matrix::Zero(n, n);
  s.input_stiffness = Matrix::Zero(n, count);
  const auto spring = [&](int a, int b, double k) {
    s.stiffness(a, a) += k;
    if (b >= 0) {
      s.stiffness(b, b) += k;
      s.stiffness(a, b) -= k;
      s.stiffness(b, a) -= k;
    }
  };
  for (int i = 0; i < count; ++i) {
    s.mass(2 * i, 2 * i) = m;
    s.mass(2 * i + 1, 2 * i + 1) = m_pad;
    spring(2 * i, 2 * i + 1, k_s);
    spring(2 * i + 1, -1, k_g);
    s.input_stiffness(2 * i + 1, i) = k_g;
    spring(2 * i, i + 1 < count ? 2 * i + 2 : -1, k_c);
  }
  spring(0, -1, k_c);
  s.damping = Matrix::Zero(n, n);
  s.input_damping = Matrix::Zero(n, count);
  s.output = Matrix::Identity(n, n);
  s.input_stations = Vector::Zero(count);
  const ModalSystem modal(s);
  const Vector& omega = modal.naturalFrequencies();
  for (int j = 1; j <= count; ++j) {
    const double sine = std::sin(j * M_PI / (2.0 * (count + 1)));
    const double expected = (k_s + 4.0 * k_c * sine * sine) / m;
    EXPECT_NEAR(omega(j - 1) * omega(j - 1) / expected, 1.0, 1e-9) << "mode " << j;
  }
  for (int r = 1; r < n; ++r)
    EXPECT_LE(omega(r - 1), omega(r)) << "mode " << r;
  // Still a modal basis: Phi^T M Phi = I and Phi^T K Phi = diag(omega^2), the refined low block
  // against the solver's high one included (K's terms to its own size, ~1e16).
  const Matrix& phi = modal.shapes();
  const Matrix identity = phi.transpose() * s.mass * phi;
  EXPECT_LT((identity - Matrix::Identity(n, n)).cwiseAbs().maxCoeff(), 1e-9);
  const Matrix low = phi.leftCols(count).transpose() * s.stiffness * phi.leftCols(count);
  const Vector low_squared = omega.head(count).cwiseAbs2();
  EXPECT_LT((low - Matrix(low_squared.asDiagonal())).cwiseAbs().maxCoeff() / low_squared.maxCoeff(),
            1e-6);
  // At rest on level ground and pushed by gravity the masses sink k-statically and stay: the
  // modal engine equals the augmented exponential (which never needed the modes).
  const Vector f_g = -kStandardGravity * s.mass * Vector::Ones(n);
  Matrix runs[2];
  int which = 0;
  for (DiscretizationMethod method :
       {DiscretizationMethod::AugmentedExponential, DiscretizationMethod::ModalDecoupled}) {
    Simulator sim(s, options(method, InputHold::FirstOrder, f_g));
    runs[which++] = sim.simulate(Matrix::Zero(2001, 2 * count));
  }
  const double sag = runs[0].col(0).cwiseAbs().maxCoeff();
  ASSERT_GT(sag, 0.1 * kStandardGravity * m / (k_s + 2.0 * k_c));
  EXPECT_LT((runs[1].leftCols(n) - runs[0].leftCols(n)).cwiseAbs().maxCoeff(), 1e-6 * sag);
}

// K q0 = K_u u0 + f_g exactly, and the simulation started there stays there (both engines).
TEST(Simulator, StaticEquilibriumIsAFixedPoint) {
  const SecondOrderSystem s = test::randomVehicle(9, 3, 3, 3);
  const Vector f_g = -kStandardGravity * s.mass * Vector::Ones(9);
  const Vector u0 = (Vector(3) << 0.01, -0.02, 0.03).finished();
  const Vector z0 = staticEquilibrium(s, u0, f_g);
  const Vector load = s.input_stiffness * u0 + f_g;
  EXPECT_LT((s.stiffness * z0.head(9) - load).norm(), 1e-12 * (s.input_stiffness * u0).norm());
  EXPECT_TRUE(z0.tail(9).isZero(0.0));

  Vector w0 = Vector::Zero(6);
  w0.head(3) = u0;
  for (DiscretizationMethod method :
       {DiscretizationMethod::AugmentedExponential, DiscretizationMethod::ModalDecoupled})
    for (InputHold hold : {InputHold::ZeroOrder, InputHold::FirstOrder}) {
      SimulatorOptions o = options(method, hold);
      o.generalized_force = f_g;
      Simulator sim(s, o);
      sim.reset(z0, w0);
      for (int k = 0; k < 200; ++k)
        sim.step(w0);
      EXPECT_LT((sim.state() - z0).cwiseAbs().maxCoeff(),
                kEquilibriumTolerance * z0.cwiseAbs().maxCoeff());
      EXPECT_LT(sim.outputs().tail(3).cwiseAbs().maxCoeff(), 1e-5);  // accelerations [m/s^2]
    }
  // A free rigid-body motion has no static equilibrium.
  SecondOrderSystem free = test::chain(3, 10.0, 1e4, 0.0, 0.0, 0.0);
  EXPECT_THROW(staticEquilibrium(free, Vector::Zero(1)), SolverError);
  EXPECT_THROW(staticEquilibrium(s, Vector::Zero(2)), InputError);
}

// 10-DOF chain over a bump: the exact FOH simulation at 1 ms and Newmark average acceleration at
// h/50 fed with the same piecewise-linear input agree within 0.5 % of the peak.
TEST(Simulator, MatchesNewmarkOnChain) {
  const SecondOrderSystem s = test::chain(10, 20.0, 2e5, 150.0, 4e5, 400.0);
  const double dt = 1e-3;
  const int samples = 1200, substeps = 50;
  const Matrix w = bumpInputs(s.input_stations, samples, dt, 10.0, 0.08, 1.2, 1.0);
  Simulator simulator(
      s, options(DiscretizationMethod::AugmentedExponential, InputHold::FirstOrder, dt));
  const Matrix y = simulator.simulate(w);

  NewmarkIntegrator newmark(toSparse(s), dt / substeps, kAllQuantities);
  EXPECT_EQ(newmark.outputNames(), simulator.outputNames());
  Matrix y_newmark(samples, y.cols());
  y_newmark.row(0) = newmark.outputs().transpose();
  for (int k = 1; k < samples; ++k) {
    for (int j = 1; j <= substeps; ++j) {
      const double f = static_cast<double>(j) / substeps;
      newmark.step(((1.0 - f) * w.row(k - 1) + f * w.row(k)).transpose());
    }
    y_newmark.row(k) = newmark.outputs().transpose();
  }
  EXPECT_NEAR(newmark.time(), (samples - 1) * dt, 1e-9);
  EXPECT_LT(relativeBlockError(y_newmark, y, 10), kNewmarkAgreement);
}

// Newmark average acceleration conserves the energy of an undamped oscillator (no numerical
// damping) and is stable far beyond the explicit limit (omega h = 26).
TEST(Newmark, UnconditionallyStableWithoutNumericalDamping) {
  const SecondOrderSystem s = test::oneDof(30.0, 0.0, 2e10, 0.0);
  NewmarkIntegrator newmark(toSparse(s), 1e-3);
  const double k = 2e10, m = 30.0;
  newmark.reset(Vector::Constant(1, 1e-3), Vector::Zero(1), Vector::Zero(2));
  const double energy0 = 0.5 * k * 1e-6;
  // The rule is the trapezoid (a Cayley transform) of q'' = -omega^2 q: in (omega q, v) an exact
  // rotation by theta, tan(theta / 2) = omega h / 2 (here 3.0 rad a step, where the true motion
  // turns by 25.8): q_n = q_0 cos(n theta), v_n = -omega q_0 sin(n theta). An integrator that
  // did not move would keep the energy too; it would not turn.
  const double omega = std::sqrt(k / m), theta = 2.0 * std::atan(0.5 * omega * 1e-3);
  for (int i = 0; i < 1000; ++i) {
    newmark.step(Vector::Zero(2));
    const double q = newmark.displacement()(0), v = newmark.velocity()(0);
    ASSERT_NEAR(0.5 * k * q * q + 0.5 * m * v * v, energy0, 1e-9 * energy0);
    const double turned = theta * (i + 1);
    ASSERT_NEAR(q, 1e-3 * std::cos(turned), 1e-9 * 1e-3) << "step " << i + 1;
    ASSERT_NEAR(v, -omega * 1e-3 * std::sin(turned), 1e-9 * omega * 1e-3) << "step " << i + 1;
  }
  EXPECT_THROW(newmark.step(Vector::Zero(3)), InputError);
  EXPECT_THROW(NewmarkIntegrator(toSparse(s), 0.0), InputError);
}

// Average acceleration on a damped oscillator, at a coarse step: the rule's energy balance is
// exact, E_{n+1} - E_n = -h c vbar^2 with vbar = (v_n + v_{n+1}) / 2 (the trapezoid's power of
// the damper), for any h. A stray h C a term in the right-hand side breaks it at O(h^2).
TEST(Newmark, AverageAccelerationDissipatesExactlyTheDampersWork) {
  const double m = 2.0, c = 3.0, k = 800.0, h = 0.02;  // omega h = 0.4
  NewmarkIntegrator newmark(toSparse(test::oneDof(m, c, k, 0.0)), h);
  newmark.reset(Vector::Constant(1, 0.1), Vector::Zero(1), Vector::Zero(2));
  const double scale = 0.5 * k * 0.1 * 0.1;  // the initial energy
  double worst = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double q0 = newmark.displacement()(0), v0 = newmark.velocity()(0);
    newmark.step(Vector::Zero(2));
    const double q1 = newmark.displacement()(0), v1 = newmark.velocity()(0);
    const double e0 = 0.5 * m * v0 * v0 + 0.5 * k * q0 * q0;
    const double e1 = 0.5 * m * v1 * v1 + 0.5 * k * q1 * q1;
    const double v_bar = 0.5 * (v0 + v1);
    worst = std::max(worst, std::abs(e1 - e0 + h * c * v_bar * v_bar) / scale);
  }
  EXPECT_LT(worst, 1e-12);
  // And the state itself: the trapezoid of x' = A x, x = (q, v), A = [0 1; -k/m -c/m], is
  // x_{n+1} = (I - h A / 2)^-1 (I + h A / 2) x_n, iterated here on 2 x 2 matrices.
  Eigen::Matrix2d a;
  a << 0.0, 1.0, -k / m, -c / m;
  const Eigen::Matrix2d step = (Eigen::Matrix2d::Identity() - 0.5 * h * a).inverse() *
                               (Eigen::Matrix2d::Identity() + 0.5 * h * a);
  Eigen::Vector2d x(0.1, 0.0);
  for (int i = 0; i < 200; ++i)
    x = step * x;
  EXPECT_NEAR(newmark.displacement()(0), x(0), 1e-12);
  EXPECT_NEAR(newmark.velocity()(0), x(1), 1e-11);
  EXPECT_GT(std::abs(x(0)) + std::abs(x(1)) / std::sqrt(k / m), 1e-4);  // not yet at rest
}

// A single discrete damper at the chain's end is not proportional: the modal engine reports the
// neglected coupling, and both engines still agree roughly (lightly damped).
// A discrete damper couples the modes: the modal engine steps the coupled dynamic modes
// together and equals the augmented exponential to rounding (both holds, blocked and stepped,
// gravity and all three quantities), reporting nothing dropped; given damping ratios instead,
// each mode keeps its own (the modal damping approximation) and the coupling is reported. With
// a quasi-static cut between the body and tyre modes the damper's coupling across the cut is
// what drops: far apart in frequency, little.
TEST(Simulator, CoupledDampingIsSteppedWhole) {
  SecondOrderSystem s = test::randomVehicle(14, 4, 6, 11);
  // Dampers between DOFs 2-9 and 5-12: C no longer alpha M + beta K.
  for (const auto& [i, j, c] : {std::tuple<int, int, double>{2, 9, 3e3}, {5, 12, 1.5e3}}) {
    s.damping(i, i) += c;
    s.damping(j, j) += c;
    s.damping(i, j) -= c;
    s.damping(j, i) -= c;
  }
  ASSERT_GT(ModalSystem(s).maxOffDiagonalDampingRatio(), 0.1);
  const Vector f_g = gravityLoad(s);
  const Matrix w = bumpRoad(s);
  const Vector z0 = staticEquilibrium(s, w.row(0).head(4).transpose(), f_g);
  for (InputHold hold : {InputHold::ZeroOrder, InputHold::FirstOrder}) {
    const SimulatorOptions modal_options = options(DiscretizationMethod::ModalDecoupled, hold, f_g);
    const EngineRuns runs = runEngines(s, f_g, w, hold, z0);
    const Matrix& y_dense = runs.dense;
    EXPECT_EQ(runs.off_diagonal, 0.0);
    EXPECT_LT(relativeBlockError(runs.batch, y_dense, 6), kMethodAgreement);
    EXPECT_LT((runs.batch_state - runs.dense_state).norm(),
              kMethodAgreement * runs.dense_state.norm());
    EXPECT_LT(relativeBlockError(runs.stepped, runs.batch, 6), 1e-10);

    // Each mode on its own damping ratio (the approximation): reported, and off.
    SimulatorOptions ratios_options = modal_options;
    ratios_options.modal_damping_ratios = ModalSystem(s).dampingRatios();
    Simulator diagonal(s, ratios_options);
    EXPECT_GT(diagonal.maxOffDiagonalDampingRatio(), 0.1);
    diagonal.reset(z0, w.row(0).transpose());
    EXPECT_GT(relativeBlockError(diagonal.simulate(w), y_dense, 6), 1e-3);

    // The 4 tyre modes quasi-static (cut in the log middle of the gap below them, as in
    // QuasiStaticTruncationKeepsStaticsAndDisplacements), the body modes coupled: the dampers'
    // coupling across the cut is kept (their force from the tyre modes' rates, and the tyre
    // modes' static response to theirs), so the displacement changes err by what the same cut
    // costs without dampers (zero-order hold 8.4e-3, first-order 4.6e-5), not 4 % (both
    // dropped).
    const Vector hz = ModalSystem(s).naturalFrequencies() / kTwoPi;
    ASSERT_GT(hz(10) / hz(9), 5.0);
    SimulatorOptions cut_options = modal_options;
    cut_options.max_mode_frequency_hz = std::sqrt(hz(9) * hz(10));
    Simulator cut(s, cut_options);
    ASSERT_EQ(cut.quasiStaticModeCount(), 4);
    EXPECT_EQ(cut.maxOffDiagonalDampingRatio(), 0.0);
    cut.reset(z0, w.row(0).transpose());
    const Matrix y_cut = cut.simulate(w);
    const auto cutError = [&](const Matrix& y_cut_run, const Matrix& y_exact) {
      return relativeBlockError(y_cut_run.leftCols(6).rowwise() - y_cut_run.row(0).leftCols(6),
                                y_exact.leftCols(6).rowwise() - y_exact.row(0).leftCols(6), 6);
    };
    const SecondOrderSystem undamped = test::randomVehicle(14, 4, 6, 11);
    Simulator undamped_cut(undamped, cut_options),
        undamped_dense(undamped, options(DiscretizationMethod::AugmentedExponential, hold, f_g));
    const Vector u0 = staticEquilibrium(undamped, w.row(0).head(4).transpose(), f_g);
    undamped_cut.reset(u0, w.row(0).transpose());
    undamped_dense.reset(u0, w.row(0).transpose());
    const double own = cutError(undamped_cut.simulate(w), undamped_dense.simulate(w));
    const double error = cutError(y_cut, y_dense);
    std::cout << "cut: " << error << " with dampers, " << own << " without\n";
    EXPECT_LT(error, 1.5 * own + 1e-5);
    // The cut state is the dense one's to that error as well (state() adds the same terms).
    EXPECT_LT((cut.state() - runs.dense_state).head(14).cwiseAbs().maxCoeff(),
              0.05 * runs.dense_state.head(14).cwiseAbs().maxCoeff());
    // Stepped, the displacement outputs are H q of the state at every step: the dampers' term
    // -H Phi_t Omega_t^-2 D_tn eta'_n is in the outputs as in state() (review 145: dropped from
    // the outputs alone, 4.9e-8 of a 0.06 m peak, within the cut's own error above).
    Simulator stepped_cut(s, cut_options);
    stepped_cut.reset(z0, w.row(0).transpose());
    const Eigen::Index n_y = s.output.rows();
    double identity = 0.0, peak = 0.0;
    for (Eigen::Index k = 1; k < w.rows(); ++k) {
      stepped_cut.step(w.row(k).transpose());
      const Vector q = stepped_cut.state().head(14);
      identity = std::max(identity,
                          (stepped_cut.outputs().head(n_y) - s.output * q).cwiseAbs().maxCoeff());
      peak = std::max(peak, stepped_cut.outputs().head(n_y).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(identity, 1e-12 * peak);
  }
}

TEST(Simulator, ResetAndStateRoundTrip) {
  const SecondOrderSystem s = test::randomVehicle(8, 2, 3, 21);
  Simulator modal(s, options(DiscretizationMethod::ModalDecoupled, InputHold::ZeroOrder));
  const Vector z0 = Vector::Random(16);
  const Vector w0 = Vector::Random(4);
  modal.reset(z0, w0);
  EXPECT_LT((modal.state() - z0).norm(), 1e-12 * z0.norm());
  EXPECT_EQ(modal.input(), w0);
  EXPECT_EQ(modal.time(), 0.0);
  modal.reset();
  EXPECT_TRUE(modal.state().isZero(0.0));
  EXPECT_EQ(modal.stateCount(), 16);
  EXPECT_EQ(modal.inputCount(), 4);
  EXPECT_EQ(modal.outputCount(), 9);
}

TEST(Simulator, RejectsBadArguments) {
  const SecondOrderSystem s = test::quarterCar();
  Simulator sim(s, options(DiscretizationMethod::AugmentedExponential, InputHold::ZeroOrder));
  EXPECT_THROW(sim.step(Vector::Zero(3)), InputError);
  EXPECT_THROW(sim.reset(Vector::Zero(3)), InputError);
  EXPECT_THROW(sim.simulate(Matrix::Zero(4, 3)), InputError);
  SimulatorOptions bad = options(DiscretizationMethod::AugmentedExponential, InputHold::ZeroOrder);
  bad.time_step = 0.0;
  EXPECT_THROW(Simulator(s, bad), InputError);
  bad = options(DiscretizationMethod::ModalDecoupled, InputHold::ZeroOrder);
  bad.modal_damping_ratios = Vector::Constant(3, 0.02);
  EXPECT_THROW(Simulator(s, bad), InputError);
  bad.modal_damping_ratios.resize(0);
  bad.generalized_force = Vector::Zero(5);
  EXPECT_THROW(Simulator(s, bad), InputError);
  EXPECT_THROW(Simulator(fromSecondOrder(s)), InputError);  // continuous
}

// A NaN or infinite input stepped in stayed in the state for good and every later output was
// NaN, silently. Refused before anything changes, naming the entry; both engines.
TEST(Simulator, NonFiniteInputsAreRefusedAndChangeNothing) {
  const SecondOrderSystem s = test::randomVehicle(8, 2, 3, 21);
  for (DiscretizationMethod method :
       {DiscretizationMethod::AugmentedExponential, DiscretizationMethod::ModalDecoupled}) {
    Simulator sim(s, options(method, InputHold::FirstOrder));
    const Vector w = Vector::Constant(4, 0.01);
    sim.step(w);
    const Vector state = sim.state(), outputs = sim.outputs();
    Vector bad = w;
    bad(2) = std::numeric_limits<double>::quiet_NaN();
    expectInputError([&] { sim.step(bad); }, {"Simulator::step", "input w entry 2 is nan"});
    expectInputError([&] { sim.step(w, bad); }, {"input w_end entry 2"});
    bad(2) = -std::numeric_limits<double>::infinity();
    expectInputError([&] { sim.step(bad, w); }, {"input w_begin entry 2 is -inf"});
    expectInputError([&] { sim.reset(state, bad); }, {"Simulator::reset", "input w0 entry 2"});
    Vector bad_state = state;
    bad_state(5) = std::numeric_limits<double>::infinity();
    expectInputError([&] { sim.reset(bad_state); }, {"state z0 entry 5 is inf"});
    Matrix series = Matrix::Constant(6, 4, 0.01);
    series(4, 1) = std::numeric_limits<double>::quiet_NaN();
    expectInputError([&] { sim.simulate(series); }, {"input series row 4 entry 1 is nan"});
    EXPECT_EQ(sim.state(), state) << methodName(method);
    EXPECT_EQ(sim.outputs(), outputs) << methodName(method);
    EXPECT_EQ(sim.input(), w) << methodName(method);
    EXPECT_EQ(sim.stepCount(), 1) << methodName(method);
  }
}

// A moved-from simulator has no engine: its calls throw std::logic_error saying so (outputs()
// and step() dereferenced the null engine and crashed). Assigned another simulator, it runs.
TEST(Simulator, AMovedFromSimulatorRefusesCallsUntilAssigned) {
  const SecondOrderSystem s = test::quarterCar();
  for (DiscretizationMethod method :
       {DiscretizationMethod::AugmentedExponential, DiscretizationMethod::ModalDecoupled}) {
    Simulator sim(s, options(method, InputHold::ZeroOrder));
    const Simulator taker = std::move(sim);
    const Vector w = Vector::Zero(taker.inputCount());
    const auto expectMovedFrom = [](auto call) {
      try {
        call();
        ADD_FAILURE() << "no std::logic_error from a moved-from Simulator";
      } catch (const std::logic_error& e) {
        EXPECT_NE(std::string(e.what()).find("Simulator: used after being moved from"),
                  std::string::npos)
            << e.what();
      }
    };
    expectMovedFrom([&] { sim.outputs(); });
    expectMovedFrom([&] { sim.step(w); });
    expectMovedFrom([&] { sim.step(w, w); });
    expectMovedFrom([&] { sim.reset(); });
    expectMovedFrom([&] { sim.state(); });
    expectMovedFrom([&] { sim.time(); });
    expectMovedFrom([&] { sim.simulate(Matrix::Zero(3, w.size())); });
    expectMovedFrom([&] { sim.dynamicModeCount(); });
    sim = Simulator(s, options(method, InputHold::ZeroOrder));
    sim.step(w);
    EXPECT_EQ(sim.stepCount(), 1);
    EXPECT_EQ(sim.outputs().size(), taker.outputCount());
  }
}

// Given modal damping ratios replace C in the modal engine: equal to the augmented exponential
// with the damping matrix that has exactly these ratios, C = M Phi diag(2 zeta omega) Phi^T M.
TEST(Simulator, GivenModalDampingRatios) {
  SecondOrderSystem s = test::randomVehicle(6, 2, 3, 4, 2e10, 0.0, 0.0);
  const Vector zeta = Vector::LinSpaced(6, 0.01, 0.2);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> modes(s.stiffness, s.mass);
  const Matrix mass_phi = s.mass * modes.eigenvectors();
  const Vector d = 2.0 * zeta.cwiseProduct(modes.eigenvalues().cwiseSqrt());
  SimulatorOptions o = options(DiscretizationMethod::ModalDecoupled, InputHold::FirstOrder);
  o.modal_damping_ratios = zeta;
  Simulator modal(s, o);
  s.damping = mass_phi * d.asDiagonal() * mass_phi.transpose();
  Simulator dense(s, options(DiscretizationMethod::AugmentedExponential, InputHold::FirstOrder));
  const Matrix w = bumpInputs(s.input_stations, 800, 1e-3, 10.0, 0.05, 1.0, 2.5);
  EXPECT_LT(relativeBlockError(modal.simulate(w), dense.simulate(w), 3), kMethodAgreement);
  // The ratios read back (reports print them): zeta_r = d_r / (2 omega_r).
  EXPECT_LT(
      (ModalSystem(test::randomVehicle(6, 2, 3, 4, 2e10, 0.0, 0.0), zeta).dampingRatios() - zeta)
          .cwiseAbs()
          .maxCoeff(),
      1e-12);
}

#if TVD_COUNTS_ALLOCATIONS  // glibc, no sanitizer: see count_allocations.h
TEST(Simulator, StepDoesNotAllocate) {
  // With and without input damping C_u (the modal engine drops zero input columns).
  // And with a damper between DOFs 1 and 7, whose coupled dynamic modes are stepped together.
  SecondOrderSystem damped = test::randomVehicle(12, 3, 4, 9);
  damped.damping(1, 1) += 2e3;
  damped.damping(7, 7) += 2e3;
  damped.damping(1, 7) -= 2e3;
  damped.damping(7, 1) -= 2e3;
  for (const SecondOrderSystem& s : {test::randomVehicle(12, 3, 4, 9),
                                     test::randomVehicle(12, 3, 4, 9, 2e10, 0.5, 0.0), damped}) {
    const Vector w = Vector::Random(6);
    for (DiscretizationMethod method :
         {DiscretizationMethod::AugmentedExponential, DiscretizationMethod::ModalDecoupled})
      for (InputHold hold : {InputHold::ZeroOrder, InputHold::FirstOrder}) {
        Simulator sim(s, options(method, hold));
        sim.step(w);  // warm-up outside the counted region
        g_allocations = 0;
        g_count_allocations = true;
        for (int k = 0; k < 100; ++k)
          sim.step(w);
        sim.step(w, w);
        g_count_allocations = false;
        EXPECT_EQ(g_allocations, 0);
      }
  }
}
#endif

// Modal truncation with quasi-static modes (mode-acceleration method): on a model whose tyre
// modes (2e10 N/m) sit far above the body modes, cutting between the two groups changes the
// displacements over a bump by < 0.2 % of the peak, keeps the static equilibrium exact, and
// the blocked simulate() still equals stepping. A cut-off above every mode changes nothing.
TEST(Simulator, QuasiStaticTruncationKeepsStaticsAndDisplacements) {
  const int n = 12, inputs = 4, outputs = 6;
  const SecondOrderSystem s = test::randomVehicle(n, inputs, outputs, 11);
  const ModalSystem modal(s);
  const Vector hz = modal.naturalFrequencies() / kTwoPi;
  // The `inputs` tyre modes are the highest; cut in the (log) middle of the gap below them.
  const double soft = hz(n - inputs - 1), stiff = hz(n - inputs);
  ASSERT_GT(stiff / soft, 5.0) << "the test model must separate body and tyre modes";
  const double cut = std::sqrt(soft * stiff);
  const Vector f_g = -kStandardGravity * s.mass * Vector::Ones(n);
  const Matrix w = bumpInputs(s.input_stations, 900, 1e-3, 8.0, 0.05, 1.0, 2.0);

  SimulatorOptions exact_options =
      options(DiscretizationMethod::ModalDecoupled, InputHold::FirstOrder);
  exact_options.generalized_force = f_g;
  SimulatorOptions cut_options = exact_options;
  cut_options.max_mode_frequency_hz = cut;
  Simulator exact(s, exact_options), truncated(s, cut_options), stepped(s, cut_options);
  EXPECT_EQ(truncated.dynamicModeCount(), n - inputs);
  EXPECT_EQ(truncated.quasiStaticModeCount(), inputs);
  EXPECT_EQ(exact.dynamicModeCount(), n);

  const Vector z0 = staticEquilibrium(s, Vector::Zero(inputs), f_g);
  exact.reset(z0, w.row(0).transpose());
  truncated.reset(z0, w.row(0).transpose());
  stepped.reset(z0, w.row(0).transpose());
  // Statics: the truncated state at rest is the static equilibrium, to rounding, and so are its
  // outputs, H z0: the cut modes' share of the sag comes in through their static response to
  // gravity (the displacement changes compared below would cancel a constant offset).
  EXPECT_LT((truncated.state() - z0).cwiseAbs().maxCoeff(), 1e-12 * z0.cwiseAbs().maxCoeff());
  const Vector at_rest = s.output * z0.head(n);
  EXPECT_LT((truncated.outputs().head(outputs) - at_rest).norm(), 1e-10 * at_rest.norm());

  const Matrix y_exact = exact.simulate(w);
  const Matrix y_cut = truncated.simulate(w);
  const Matrix displacement_change =
      y_cut.leftCols(outputs).rowwise() - y_cut.row(0).leftCols(outputs);
  const Matrix displacement_exact =
      y_exact.leftCols(outputs).rowwise() - y_exact.row(0).leftCols(outputs);
  EXPECT_LT(relativeBlockError(displacement_change, displacement_exact, outputs), 2e-3);
  // Velocities: the quasi-static part follows K_u u'.
  EXPECT_LT(relativeBlockError(y_cut.middleCols(outputs, outputs),
                               y_exact.middleCols(outputs, outputs), outputs),
            2e-2);

  Matrix y_stepped(w.rows(), y_cut.cols());
  y_stepped.row(0) = stepped.outputs().transpose();
  for (DofIndex k = 1; k < w.rows(); ++k) {
    stepped.step(w.row(k).transpose());
    y_stepped.row(k) = stepped.outputs().transpose();
  }
  EXPECT_LT(relativeBlockError(y_cut, y_stepped, outputs), 1e-12);
  EXPECT_LT((truncated.state() - stepped.state()).norm(), 1e-12 * stepped.state().norm());

  SimulatorOptions all_options = exact_options;
  all_options.max_mode_frequency_hz = 2.0 * hz(n - 1);
  Simulator all(s, all_options);
  all.reset(z0, w.row(0).transpose());
  EXPECT_EQ(all.quasiStaticModeCount(), 0);
  EXPECT_LT(relativeBlockError(all.simulate(w), y_exact, outputs), 1e-13);

  SimulatorOptions bad = exact_options;
  bad.max_mode_frequency_hz = -1.0;
  EXPECT_THROW(Simulator(s, bad), InputError);
  bad = options(DiscretizationMethod::AugmentedExponential, InputHold::FirstOrder);
  bad.max_mode_frequency_hz = 100.0;
  EXPECT_THROW(Simulator(s, bad), InputError);
}

// coordinates(): the watched rows of q and q', as state() gives them, from both engines, with and
// without quasi-static modes and input damping C_u, at rest and while a bump passes, without
// allocating (modal engine); a row outside q is refused by name.
TEST(Simulator, WatchedCoordinatesAreTheStatesRows) {
  const int n = 12, inputs = 4;
  for (const SecondOrderSystem& s : {test::randomVehicle(n, inputs, 6, 11),
                                     test::randomVehicle(n, inputs, 6, 11, 2e10, 0.5, 0.0)}) {
    const ModalSystem modal(s);
    const double cut = std::sqrt(modal.naturalFrequencies()(n - inputs - 1) *
                                 modal.naturalFrequencies()(n - inputs)) /
                       kTwoPi;
    const Vector f_g = -kStandardGravity * s.mass * Vector::Ones(n);
    const Matrix w = bumpInputs(s.input_stations, 300, 1e-3, 8.0, 0.05, 1.0, 0.5);
    const std::vector<DofIndex> rows = {7, 0, 11, 3, 3};  // any order, repeats allowed
    for (double max_hz : {0.0, cut}) {
      for (DiscretizationMethod method :
           {DiscretizationMethod::AugmentedExponential, DiscretizationMethod::ModalDecoupled}) {
        if (max_hz > 0 && method == DiscretizationMethod::AugmentedExponential)
          continue;
        SimulatorOptions o = options(method, InputHold::FirstOrder);
        o.generalized_force = f_g;
        o.max_mode_frequency_hz = max_hz;
        Simulator sim(s, o);
        Vector z;
        sim.coordinates(&z);
        EXPECT_EQ(z.size(), 0);  // none chosen
        sim.watchCoordinates(rows);
        sim.reset(staticEquilibrium(s, Vector::Zero(inputs), f_g), w.row(0).transpose());
        for (DofIndex k = 1; k < w.rows(); ++k) {
          sim.step(w.row(k).transpose());
          if (k % 50 != 1)
            continue;
          sim.coordinates(&z);
          const Vector full = sim.state();
          ASSERT_EQ(z.size(), 10);
          for (std::size_t i = 0; i < rows.size(); ++i) {
            EXPECT_NEAR(z(static_cast<DofIndex>(i)), full(rows[i]), 1e-12 * full.head(n).norm());
            EXPECT_NEAR(z(5 + static_cast<DofIndex>(i)), full(n + rows[i]),
                        1e-12 * full.tail(n).norm() + 1e-15);
          }
        }
#if TVD_COUNTS_ALLOCATIONS  // the modal engine's check runs in the node's loop: no allocation
        g_allocations = 0;
        g_count_allocations = true;
        sim.coordinates(&z);
        g_count_allocations = false;
        if (method == DiscretizationMethod::ModalDecoupled) {
          EXPECT_EQ(g_allocations, 0);
        }
#endif
      }
    }
    Simulator sim(s, options(DiscretizationMethod::ModalDecoupled, InputHold::FirstOrder));
    try {
      sim.watchCoordinates({2, 12});
      FAIL() << "expected InputError";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("coordinate 12 (entry 1) is outside the 12"),
                std::string::npos)
          << e.what();
    }
  }
}

// Blocks where some of the inputs change at every sample and the others hold (non-zero) values:
// simulate() multiplies only the changing columns and adds the others' constant part.
TEST(Simulator, BlocksWithSomeInputsChangingAreExact) {
  const int n = 40, inputs = 40, outputs = 6;
  const SecondOrderSystem s = test::randomVehicle(n, inputs, outputs, 5);
  const Vector f_g = -kStandardGravity * s.mass * Vector::Ones(n);
  const int samples = 1800;
  Matrix w(samples, 2 * inputs);
  for (int q = 0; q < 2 * inputs; ++q)
    w.col(q).setConstant(1e-3 * (1 + q % 7));  // held values
  for (int k = 0; k < samples; ++k) {
    // A quarter of the heights change, a different quarter after sample 700 and 1300.
    const int first = k < 700 ? 0 : k < 1300 ? 20 : 10;
    for (int q = first; q < first + 10; ++q)
      w(k, q) = 0.02 * std::sin(0.013 * k * (q + 1));
  }
  const EngineRuns runs = runEngines(s, f_g, w);
  const Matrix &y_dense = runs.dense, &y_batch = runs.batch, &y_stepped = runs.stepped;
  EXPECT_LT(relativeBlockError(y_batch, y_dense, outputs), kMethodAgreement);
  EXPECT_LT(relativeBlockError(y_stepped, y_dense, outputs), kMethodAgreement);
  EXPECT_LT(relativeBlockError(y_batch, y_stepped, outputs), 1e-9);
}

// Road inputs change only where the terrain under them is not flat, and the modal engine then
// updates its input terms G w by increments (simulator.cpp). On 40 inputs crossing a short bump
// one after the other (at most two of 80 input columns change per step, over more steps than
// the re-anchoring interval) the result must still be the exact one: equal to the dense
// augmented-exponential engine, stepped and blocked, and — with quasi-static modes, whose
// output terms are in G too — equal by linearity to runs whose inputs change densely:
//   y(W) = y(W + D) - y(D) + y(0)   for any input series D (y affine in W).
TEST(Simulator, SparseInputChangesAreExact) {
  const int n = 40, inputs = 40, outputs = 6;
  const SecondOrderSystem s = test::randomVehicle(n, inputs, outputs, 3);
  const Vector f_g = -kStandardGravity * s.mass * Vector::Ones(n);
  const Matrix w = bumpInputs(s.input_stations, 2500, 1e-3, 8.0, 0.05, 0.3, 3.0);
  // Sparse indeed: never more than one input (height and rate) on the bump at a time.
  for (DofIndex k = 1; k < w.rows(); ++k)
    ASSERT_LE(((w.row(k) - w.row(k - 1)).array() != 0.0).count(), 4);

  const EngineRuns runs = runEngines(s, f_g, w);
  const Matrix &y_dense = runs.dense, &y_batch = runs.batch, &y_stepped = runs.stepped;
  EXPECT_LT(relativeBlockError(y_batch, y_dense, outputs), kMethodAgreement);
  EXPECT_LT(relativeBlockError(y_stepped, y_dense, outputs), kMethodAgreement);

  // Quasi-static modes above the 20th: compare with dense input changes by linearity.
  const ModalSystem modal(s);
  SimulatorOptions cut_options =
      options(DiscretizationMethod::ModalDecoupled, InputHold::FirstOrder);
  cut_options.generalized_force = f_g;
  const Vector z0 = staticEquilibrium(s, Vector::Zero(inputs), f_g);
  cut_options.max_mode_frequency_hz = modal.naturalFrequencies()(20) / kTwoPi;
  const Matrix dither = 1e-3 * Matrix::Random(w.rows(), w.cols());
  auto run = [&](const Matrix& series, bool step_by_step) {
    Simulator sim(s, cut_options);
    EXPECT_GT(sim.quasiStaticModeCount(), 0);
    sim.reset(z0, series.row(0).transpose());
    if (!step_by_step)
      return Matrix(sim.simulate(series));
    Matrix y(series.rows(), sim.outputCount());
    y.row(0) = sim.outputs().transpose();
    for (DofIndex k = 1; k < series.rows(); ++k) {
      sim.step(series.row(k).transpose());
      y.row(k) = sim.outputs().transpose();
    }
    return y;
  };
  const Matrix zero = Matrix::Zero(w.rows(), w.cols());
  for (bool step_by_step : {false, true}) {
    const Matrix y_sparse = run(w, step_by_step);
    const Matrix y_linear =
        run(w + dither, step_by_step) - run(dither, step_by_step) + run(zero, step_by_step);
    // Displacements and velocities (the rows the quasi-static terms enter).
    EXPECT_LT(
        relativeBlockError(y_sparse.leftCols(2 * outputs), y_linear.leftCols(2 * outputs), outputs),
        1e-9)
        << (step_by_step ? "stepped" : "blocked");
  }
}

// A series stored by its changes (held_input_series.h) gives the outputs of its dense form: with
// channels shared by several columns, events at every sample (the dense block product) and a
// few per block (column increments), columns in no channel held at non-zero values, every mode
// dynamic or most of them quasi-static, and through the dense engine's fallback.
TEST(Simulator, HeldSeriesEqualsItsDenseSeries) {
  const int n = 40, inputs = 40, outputs = 6;
  const SecondOrderSystem s = test::randomVehicle(n, inputs, outputs, 7);
  const Vector f_g = -kStandardGravity * s.mass * Vector::Ones(n);
  HeldInputSeries held;
  held.samples = 2100;
  held.initial = Vector::Zero(2 * inputs);
  for (int j = 60; j < 80; ++j)
    held.initial(j) = 1e-3 * (j % 5);  // in no channel: held
  // Channel c carries columns c, c + 10, c + 20 (heights) or 40 + c, 50 + c (rates).
  for (int c = 0; c < 10; ++c) {
    HeldInputSeries::Channel h, r;
    h.columns = {c, c + 10, c + 20};
    r.columns = {40 + c, 50 + c};
    for (long k = 1; k < held.samples; ++k) {
      const bool dense_window = k > 300 + 50 * c && k < 900 + 50 * c;  // every sample
      const bool sparse_event = k % (97 + c) == 0;                     // now and then
      if (dense_window || sparse_event) {
        h.steps.push_back(k);
        h.values.push_back(0.03 * std::sin(0.011 * k * (c + 1)));
        r.steps.push_back(k);
        r.values.push_back(0.3 * std::cos(0.011 * k * (c + 1)));
      }
    }
    held.channels.push_back(h);
    held.channels.push_back(r);
  }
  const Matrix w = held.dense();
  const Vector z0 = staticEquilibrium(s, w.row(0).head(inputs).transpose(), f_g);
  const ModalSystem modal(s);
  for (const double cut_hz : {0.0, modal.naturalFrequencies()(15) / kTwoPi}) {
    for (const DiscretizationMethod method :
         {DiscretizationMethod::ModalDecoupled, DiscretizationMethod::AugmentedExponential}) {
      if (method == DiscretizationMethod::AugmentedExponential && cut_hz > 0)
        continue;
      SimulatorOptions o = options(method, InputHold::FirstOrder);
      o.generalized_force = f_g;
      o.max_mode_frequency_hz = cut_hz;
      o.quantities = {OutputQuantity::Displacement, OutputQuantity::Velocity,
                      OutputQuantity::Acceleration};
      Simulator a(s, o), b(s, o);
      a.reset(z0, w.row(0).transpose());
      b.reset(z0, w.row(0).transpose());
      const Matrix y_held = a.simulate(held);
      const Matrix y_dense = b.simulate(w);
      EXPECT_LT(relativeBlockError(y_held, y_dense, outputs), 1e-12) << "cut " << cut_hz;
      EXPECT_LT((a.state() - b.state()).norm(), 1e-12 * b.state().norm());
      EXPECT_EQ((a.input() - b.input()).norm(), 0.0);
      EXPECT_EQ(a.stepCount(), b.stepCount());
    }
  }
  // A series of the wrong width, or an invalid one, is refused by name.
  Simulator sim(s, options(DiscretizationMethod::ModalDecoupled, InputHold::FirstOrder));
  HeldInputSeries narrow = held;
  narrow.initial = Vector::Zero(3);
  EXPECT_THROW(sim.simulate(narrow), InputError);
  HeldInputSeries unordered = held;
  std::swap(unordered.channels[0].steps[0], unordered.channels[0].steps[1]);
  EXPECT_THROW(sim.simulate(unordered), InputError);
}

TEST(Simulator, MethodAndHoldNamesRoundTrip) {
  // One name per variant, each parsed back to it; any other spelling is none (the callers name
  // the option in their refusal).
  for (const auto method : {dynamics::DiscretizationMethod::AugmentedExponential,
                            dynamics::DiscretizationMethod::ModalDecoupled})
    EXPECT_EQ(dynamics::methodFromName(dynamics::methodName(method)), method);
  EXPECT_STREQ(dynamics::methodName(dynamics::DiscretizationMethod::ModalDecoupled), "modal");
  EXPECT_STREQ(dynamics::methodName(dynamics::DiscretizationMethod::AugmentedExponential), "exact");
  for (const auto hold : {dynamics::InputHold::ZeroOrder, dynamics::InputHold::FirstOrder})
    EXPECT_EQ(dynamics::holdFromName(dynamics::holdName(hold)), hold);
  EXPECT_STREQ(dynamics::holdName(dynamics::InputHold::FirstOrder), "first_order");
  for (const char* bad : {"", "Modal", "exact ", "first order", "zero_order\n"}) {
    EXPECT_FALSE(dynamics::methodFromName(bad).has_value()) << bad;
    EXPECT_FALSE(dynamics::holdFromName(bad).has_value()) << bad;
  }
}
