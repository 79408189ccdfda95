// Comfort FRFs (paper eqs. 18-25): closed forms, direct vs modal, delays.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "dynamics_test_models.h"
#include "expect_input_error.h"
#include "tracked_vehicle_dynamics/dynamics/frf.h"
#include "tracked_vehicle_dynamics/dynamics/simulator.h"
#include "tracked_vehicle_dynamics/error.h"

using namespace tracked_vehicle_dynamics;
using namespace tracked_vehicle_dynamics::dynamics;

namespace {

constexpr double kClosedFormTolerance = 1e-10;
constexpr double kModalTolerance = 1e-8;  // direct vs modal, entry by entry, relative

// max over entries of |a - b| / |b|, ignoring entries of b below `floor` times its peak (zeros
// such as the acceleration at 0 Hz).
double relativeError(const ComplexMatrix& a, const ComplexMatrix& b, double floor = 1e-12) {
  const double peak = b.cwiseAbs().maxCoeff();
  double worst = 0.0;
  for (DofIndex i = 0; i < b.rows(); ++i)
    for (DofIndex j = 0; j < b.cols(); ++j)
      if (std::abs(b(i, j)) > floor * peak)
        worst = std::max(worst, std::abs(a(i, j) - b(i, j)) / std::abs(b(i, j)));
  return worst;
}

}  // namespace

// m x'' + c x' + k x = k u + c u':  x/h = (k + j w c) / (k - w^2 m + j w c).
TEST(Frf, OneDofEqualsClosedForm) {
  const double m = 40.0, c = 900.0, k = 3e5;
  const SecondOrderSystem s = test::oneDof(m, c, k, c);
  const Vector f = Vector::LinSpaced(200, 0.0, 30.0);
  for (OutputQuantity quantity :
       {OutputQuantity::Displacement, OutputQuantity::Velocity, OutputQuantity::Acceleration}) {
    const ComplexMatrix direct = frfDirect(s, f, InputDelay::synchronous(), quantity);
    const ComplexMatrix modal = frfModal(s, f, InputDelay::synchronous(), quantity);
    ASSERT_EQ(direct.rows(), 200);
    ASSERT_EQ(direct.cols(), 1);
    for (int i = 0; i < f.size(); ++i) {
      const double w = kTwoPi * f(i);
      const Complex x = Complex(k, w * c) / Complex(k - w * w * m, w * c);
      const Complex expected = quantity == OutputQuantity::Displacement ? x
                               : quantity == OutputQuantity::Velocity   ? Complex(0.0, w) * x
                                                                        : -w * w * x;
      EXPECT_LT(std::abs(direct(i, 0) - expected),
                kClosedFormTolerance * std::abs(x) * (1 + w * w));
      EXPECT_LT(std::abs(modal(i, 0) - expected), kClosedFormTolerance * std::abs(x) * (1 + w * w));
    }
  }
  // Static limit: x/h = 1 at 0 Hz.
  EXPECT_NEAR(std::abs(frfDirect(s, Vector::Zero(1), InputDelay::synchronous(),
                                 OutputQuantity::Displacement)(0, 0)),
              1.0, kClosedFormTolerance);
}

// A slow mode beside a very stiff tie (a reduced vehicle: 2e10 N/m wheel ties on light soles,
// largest omega^2 ~1e11) is a mode, not a rigid-body one: the sprung mass at 0.3 Hz has
// omega^2 / max 9e-12, which a rigid-body cut at 1e-10 of the largest zeroed (the model then
// drifted and its 0 Hz FRF was NaN). The modal FRF keeps the static limit x/h = 1.
TEST(Frf, SlowModeBesideAStiffTieIsNotRigid) {
  const double m_s = 1000.0, f_s = 0.3;
  const double k_s = m_s * std::pow(kTwoPi * f_s, 2);
  const double beta = 0.05;  // C = beta K: modal damping is then exact, as the comparison needs
  const SecondOrderSystem s = test::quarterCar(m_s, 0.05, k_s, beta * k_s, 2e10, beta * 2e10);
  const ModalSystem modal(s);
  const double ratio = std::pow(modal.naturalFrequencies()(0) / modal.naturalFrequencies()(1), 2);
  EXPECT_LT(ratio, 1e-11);
  EXPECT_NEAR(modal.naturalFrequencies()(0) / kTwoPi, f_s, 1e-6 * f_s);
  const Vector f = (Vector(3) << 0.0, 0.1, 0.3).finished();
  const ComplexMatrix direct =
      frfDirect(s, f, InputDelay::synchronous(), OutputQuantity::Displacement);
  const ComplexMatrix by_modes =
      frfModal(s, f, InputDelay::synchronous(), OutputQuantity::Displacement);
  EXPECT_TRUE(by_modes.allFinite());
  EXPECT_NEAR(std::abs(by_modes(0, 0)), 1.0, 1e-9);
  for (int i = 0; i < f.size(); ++i)
    EXPECT_LT(std::abs(by_modes(i, 0) - direct(i, 0)), 1e-6 * std::abs(direct(i, 0))) << f(i);
}

// A free body (a rigid-body mode) driven by a force k u: x/h = k / (-w^2 m) away from 0 Hz; at
// 0 Hz the modal sum's term is 0/0, refused with its cause instead of returned as NaN.
TEST(Frf, RigidBodyModeGivesTheMassLineAndRefusesZeroHertz) {
  const double m = 40.0, k = 3e5;
  SecondOrderSystem s = test::oneDof(m, 0.0, k, 0.0);
  s.stiffness(0, 0) = 0.0;  // the input still acts as the force k u
  const ModalSystem modal(s);
  EXPECT_EQ(modal.naturalFrequencies()(0), 0.0);
  const Vector f = (Vector(2) << 1.0, 7.5).finished();
  const ComplexMatrix x =
      frfModal(modal, f, InputDelay::synchronous(), OutputQuantity::Displacement);
  for (int i = 0; i < f.size(); ++i) {
    const double w = kTwoPi * f(i);
    EXPECT_NEAR(std::abs(x(i, 0) - Complex(-k / (w * w * m), 0.0)), 0.0, 1e-12 * k / (w * w * m));
  }
  expectSolverError([&] { frfModal(modal, Vector::Zero(1), InputDelay::synchronous()); },
                    {"mode 0 is a rigid-body mode", "start the grid above 0 Hz"});
}

// omega^2 below -1e-12 of the largest is an indefinite K, not a rigid-body mode's rounding
// (1e-10 of a reduced vehicle's 1.7e11 rad^2/s^2 let -17 rad^2/s^2 pass as a rigid mode).
TEST(Frf, ModalSystemRefusesANegativeOmegaSquaredBeyondRounding) {
  SecondOrderSystem s = test::quarterCar();
  s.stiffness.setZero();
  s.input_stiffness.setZero();
  s.damping.setZero();
  s.stiffness(1, 1) = 1e10;  // omega^2 = 1e10 / 30 on the unsprung mass
  const double lambda_max = 1e10 / 30.0;
  s.stiffness(0, 0) = -5e-13 * lambda_max * 300.0;  // rounding: a rigid-body mode
  EXPECT_EQ(ModalSystem(s).naturalFrequencies()(0), 0.0);
  s.stiffness(0, 0) = -5e-12 * lambda_max * 300.0;
  expectSolverError([&] { ModalSystem{s}; }, {"stiffness K is indefinite"});
}

// Modal damping ratios: finite and >= 0, so an undamped mode (zeta = 0) is accepted as given.
TEST(Frf, ModalSystemTakesZeroDampingRatios) {
  const SecondOrderSystem s = test::quarterCar();
  const ModalSystem modal(s, Vector::Zero(s.size()));
  EXPECT_EQ(modal.dampingRatios(), Vector::Zero(s.size()));
  expectInputError([&] { ModalSystem(s, Vector::Constant(s.size(), -0.01)); },
                   {"damping ratios must be finite and >= 0"});
}

// phi^T C phi >= 0 for every mode of a positive semi-definite C: a C that adds energy is refused.
TEST(Frf, ModalSystemRefusesDampingThatIsNotPositiveSemiDefinite) {
  SecondOrderSystem s = test::quarterCar();
  s.damping = -0.01 * s.stiffness;
  expectInputError([&] { ModalSystem{s}; }, {"damping C is not positive semi-definite"});
}

// The coupling of modal damping c = Phi^T C Phi is max |c_rs| / sqrt(|c_rr c_ss|):
// [[1, 0.5], [0.5, 4]] gives 0.5 / sqrt(1 * 4) = 0.25.
TEST(Frf, OffDiagonalDampingRatioIsNormalisedByBothDiagonals) {
  Matrix c(2, 2);
  c << 1.0, 0.5, 0.5, 4.0;
  EXPECT_EQ(maxOffDiagonalRatio(c), 0.25);
  c(1, 1) = 0.0;  // a coupled mode without damping of its own
  EXPECT_TRUE(std::isinf(maxOffDiagonalRatio(c)));
}

// Rayleigh damping: the modal superposition of eq. 20 equals the direct solution of eq. 18.
TEST(Frf, DirectEqualsModalForRayleighDamping) {
  const SecondOrderSystem s = test::randomVehicle(24, 6, 8, 17);
  const Vector f = Vector::LinSpaced(301, 0.0, 60.0);
  const ModalSystem modal(s);
  EXPECT_LT(modal.maxOffDiagonalDampingRatio(), 1e-8);
  // Phi^T M Phi = I and Phi^T K Phi = diag(omega^2).
  const Matrix& phi = modal.shapes();
  EXPECT_LT((phi.transpose() * s.mass * phi - Matrix::Identity(24, 24)).norm(), 1e-10);
  const Matrix modal_k = phi.transpose() * s.stiffness * phi;
  EXPECT_LT((modal_k - Matrix(modal.naturalFrequencies().cwiseAbs2().asDiagonal())).norm(),
            1e-10 * modal_k.norm());
  for (const InputDelay& delay :
       {InputDelay::synchronous(), InputDelay::travelling(s.input_stations, 8.3)}) {
    for (OutputQuantity quantity : {OutputQuantity::Displacement, OutputQuantity::Acceleration}) {
      const ComplexMatrix direct = frfDirect(s, f, delay, quantity);
      const ComplexMatrix by_modes = frfModal(modal, f, delay, quantity);
      EXPECT_LT(relativeError(by_modes, direct), kModalTolerance);
    }
  }
}

TEST(Frf, SparseDirectEqualsDenseDirect) {
  const SecondOrderSystem s = test::randomVehicle(30, 5, 4, 23);
  const Vector f = Vector::LinSpaced(50, 0.0, 40.0);
  const InputDelay delay = InputDelay::travelling(s.input_stations, 5.0);
  const ComplexMatrix dense = frfDirect(s, f, delay);
  const ComplexMatrix sparse = frfDirect(toSparse(s), f, delay);
  EXPECT_LT(relativeError(sparse, dense), 1e-9);
}

// Every input at the same station: no delay, the travelled FRF is the synchronous one.
TEST(Frf, SameStationDelayEqualsSynchronous) {
  SecondOrderSystem s = test::randomVehicle(12, 4, 3, 31);
  s.input_stations = Vector::Constant(4, 1.7);
  const Vector f = Vector::LinSpaced(80, 0.5, 40.0);
  const ComplexMatrix travelled = frfModal(s, f, InputDelay::travelling(s.input_stations, 3.0));
  const ComplexMatrix synchronous = frfModal(s, f, InputDelay::synchronous());
  EXPECT_LT((travelled - synchronous).cwiseAbs().maxCoeff(), 0.0 + 1e-15 * synchronous.norm());
}

// Linearity in tau: FRF(tau) = sum_q tau_q FRF_q (FRF_q: input q alone), hence the wheelbase
// filter can never exceed the sum of the individual contributions: |FRF(tau)| <= sum |FRF_q|.
TEST(Frf, DelayedFrfIsBoundedByItsContributions) {
  const SecondOrderSystem s = test::randomVehicle(16, 4, 5, 41);
  const Vector f = Vector::LinSpaced(120, 0.2, 50.0);
  const double speed = 6.0;
  const ModalSystem modal(s);
  const ComplexMatrix delayed = frfModal(modal, f, InputDelay::travelling(s.input_stations, speed));
  ComplexMatrix sum = ComplexMatrix::Zero(f.size(), 5);
  Matrix bound = Matrix::Zero(f.size(), 5);
  for (int q = 0; q < 4; ++q) {
    SecondOrderSystem single = s;
    single.input_stiffness = s.input_stiffness.col(q);
    single.input_damping = s.input_damping.col(q);
    single.input_stations = s.input_stations.segment(q, 1);
    const ComplexMatrix contribution = frfModal(single, f, InputDelay::synchronous());
    const double lag = s.input_stations.maxCoeff() - s.input_stations(q);
    for (int i = 0; i < f.size(); ++i)
      sum.row(i) += std::polar(1.0, -kTwoPi * f(i) * lag / speed) * contribution.row(i);
    bound += magnitude(contribution);
  }
  EXPECT_LT((delayed - sum).cwiseAbs().maxCoeff(), 1e-10 * delayed.cwiseAbs().maxCoeff());
  EXPECT_TRUE((magnitude(delayed).array() <= bound.array() * (1.0 + 1e-12)).all());
  EXPECT_TRUE((magnitude(frfModal(modal, f, InputDelay::synchronous())).array() <=
               bound.array() * (1.0 + 1e-12))
                  .all());
}

// Sign convention of eqs. 23-24: the front-most input has no delay, the others lag.
TEST(InputDelay, FrontInputIsHitFirst) {
  const InputDelay delay = InputDelay::travelling(Eigen::Vector3d(2.0, 0.5, -1.0), 10.0);
  EXPECT_NEAR(delay.lags()(0), 0.0, 0.0);
  EXPECT_NEAR(delay.lags()(1), 1.5, 1e-15);
  EXPECT_NEAR(delay.lags()(2), 3.0, 1e-15);
  const double omega = 7.0;
  const ComplexVector tau = delay.at(omega, 3);
  EXPECT_NEAR(std::abs(tau(0) - Complex(1.0, 0.0)), 0.0, 1e-15);
  EXPECT_NEAR(std::arg(tau(1)), -omega * 0.15, 1e-14);
  EXPECT_NEAR(std::arg(tau(2)), -omega * 0.3, 1e-14);
  EXPECT_THROW(delay.at(omega, 2), InputError);
  EXPECT_THROW(InputDelay::travelling(Eigen::Vector3d::Zero(), 0.0), InputError);
  EXPECT_TRUE(InputDelay::synchronous().isSynchronous());
  EXPECT_EQ(InputDelay::synchronous().at(omega, 4), ComplexVector::Ones(4));
}

// The FRF predicts the steady-state amplitude of a time simulation over a sine road of
// wavelength lambda at speed v (omega = 2 pi v / lambda, eq. 17), each input seeing the road
// at its own station: a check of the delay convention in the time domain.
TEST(Frf, PredictsSteadyStateOfTimeSimulation) {
  const SecondOrderSystem s = test::randomVehicle(10, 3, 3, 51, 2e8, 2.0, 1e-4);
  const double speed = 5.0, wavelength = 2.5, height = 0.02, dt = 1e-3;
  const double omega = kTwoPi * speed / wavelength;
  const Vector f = Vector::Constant(1, omega / kTwoPi);
  const InputDelay delay = InputDelay::travelling(s.input_stations, speed);
  ComplexMatrix frf(1, 6);
  frf << frfDirect(s, f, delay, OutputQuantity::Displacement),
      frfDirect(s, f, delay, OutputQuantity::Acceleration);
  SimulatorOptions o;
  o.time_step = dt;
  o.hold = InputHold::FirstOrder;
  o.quantities = {OutputQuantity::Displacement, OutputQuantity::Acceleration};
  Simulator sim(s, o);
  // Rayleigh alpha = 2 decays every transient as e^{-t}: after 12 s it is below 1e-5.
  const int samples = 12001;
  Matrix w(samples, 6);
  for (int k = 0; k < samples; ++k)
    for (int q = 0; q < 3; ++q) {
      const double phase = omega * (k * dt + s.input_stations(q) / speed);
      w(k, q) = height * std::sin(phase);
      w(k, 3 + q) = height * omega * std::cos(phase);
    }
  const Matrix y = sim.simulate(w);
  // u_q = h Im(e^{j omega (t + x_front / v)} tau_q): the response is Im(FRF h e^{j omega (t +
  // x_front / v)}).
  const double front = s.input_stations.maxCoeff();
  for (int j = 0; j < 6; ++j) {
    const double peak = height * std::abs(frf(0, j));
    // The linear interpolation of the sine errs by (omega h)^2 / 8 = 2e-5 in displacement; its
    // kinks at every sample also shake the tyre modes, which shows in the accelerations.
    const double tolerance = j < 3 ? 1e-4 : 1e-3;
    for (int k = samples - 2000; k < samples; ++k) {
      const double t = k * dt;
      const double expected =
          (frf(0, j) * height * std::polar(1.0, omega * (t + front / speed))).imag();
      ASSERT_NEAR(y(k, j), expected, tolerance * peak) << "output " << j << ", t = " << t;
    }
  }
}

TEST(Frf, ErrorsAndHelpers) {
  const double omega = kTwoPi * 1.0;
  const SecondOrderSystem undamped = test::oneDof(1.0, 0.0, omega * omega, 0.0);
  EXPECT_THROW(frfDirect(undamped, Vector::Constant(1, 1.0), InputDelay::synchronous()),
               SolverError);
  EXPECT_THROW(frfDirect(undamped, Vector::Constant(1, -1.0), InputDelay::synchronous()),
               InputError);
  EXPECT_THROW(frfModal(undamped, Vector::Constant(1, 2.0),
                        InputDelay::travelling(Eigen::Vector2d(0.0, 1.0), 1.0)),
               InputError);
  ComplexMatrix z(1, 2);
  z << Complex(3.0, 4.0), Complex(0.0, -2.0);
  EXPECT_NEAR(magnitude(z)(0, 0), 5.0, 1e-15);
  EXPECT_NEAR(phase(z)(0, 1), -M_PI / 2.0, 1e-15);
}
