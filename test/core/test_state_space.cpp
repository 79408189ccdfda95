// StateSpace, fromSecondOrder and the exact discretisation (ZOH/FOH) against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "dynamics_test_models.h"
#include "tracked_vehicle_dynamics/dynamics/discretization.h"
#include "tracked_vehicle_dynamics/dynamics/state_space.h"
#include "tracked_vehicle_dynamics/error.h"

using namespace tracked_vehicle_dynamics;
using namespace tracked_vehicle_dynamics::dynamics;

namespace {

constexpr double kExactTolerance = 1e-9;  // exact discretisation vs closed form
constexpr double kIdentityTolerance = 1e-12;

// One step of a discrete StateSpace (either hold) from z with inputs w (start), w_next (end).
Vector advance(const StateSpace& d, const Vector& z, const Vector& w, const Vector& w_next) {
  Vector z_next = d.state_matrix * z + d.input_matrix * w;
  if (d.next_input_matrix.size() != 0)
    z_next += d.next_input_matrix * w_next;
  if (d.state_offset.size() != 0)
    z_next += d.state_offset;
  return z_next;
}

Vector outputs(const StateSpace& s, const Vector& z, const Vector& w) {
  Vector y = s.output_matrix * z + s.feedthrough_matrix * w;
  if (s.output_offset.size() != 0)
    y += s.output_offset;
  return y;
}

}  // namespace

TEST(OutputLayout, RowsAndNames) {
  const OutputLayout layout({"hull uz", "wheel uz"},
                            {OutputQuantity::Acceleration, OutputQuantity::Displacement});
  EXPECT_EQ(layout.size(), 4);
  EXPECT_EQ(layout.names()[0], "hull uz/acc");
  EXPECT_EQ(layout.names()[3], "wheel uz/disp");
  EXPECT_EQ(layout.row("wheel uz", OutputQuantity::Acceleration), 1);
  EXPECT_EQ(layout.row("hull uz/disp"), 2);
  EXPECT_EQ(layout.offset(OutputQuantity::Displacement), 2);
  EXPECT_FALSE(layout.has(OutputQuantity::Velocity));
  EXPECT_THROW(layout.offset(OutputQuantity::Velocity), InputError);
  EXPECT_THROW(layout.row("turret uz/acc"), InputError);
  EXPECT_THROW(OutputLayout({"a"}, {OutputQuantity::Velocity, OutputQuantity::Velocity}),
               InputError);
}

TEST(FromSecondOrder, BlocksAndAccelerationOutput) {
  const SecondOrderSystem s = test::randomVehicle(6, 2, 3, 7, 1e7);
  const Vector f_g = Vector::LinSpaced(6, -100.0, 50.0);
  const StateSpace ss = fromSecondOrder(
      s, {OutputQuantity::Displacement, OutputQuantity::Velocity, OutputQuantity::Acceleration},
      f_g);
  ASSERT_EQ(ss.stateCount(), 12);
  ASSERT_EQ(ss.inputCount(), 4);
  ASSERT_EQ(ss.outputCount(), 9);
  EXPECT_EQ(ss.output_names[7], "dof_1 uz/acc");
  EXPECT_TRUE(ss.isContinuous());

  // A z + B w + f0 must equal [q'; q''] with M q'' = -K q - C q' + K_u u + C_u u' + f_g.
  const Vector z = Vector::Random(12);
  const Vector w = Vector::Random(4);
  const Vector q = z.head(6), v = z.tail(6), u = w.head(2), u_dot = w.tail(2);
  const Vector acc = s.mass.llt().solve(-s.stiffness * q - s.damping * v + s.input_stiffness * u +
                                        s.input_damping * u_dot + f_g);
  const Vector z_dot = ss.state_matrix * z + ss.input_matrix * w + ss.state_offset;
  EXPECT_LT((z_dot.head(6) - v).norm(), kIdentityTolerance);
  EXPECT_LT((z_dot.tail(6) - acc).norm(), kIdentityTolerance * acc.norm());
  const Vector y = outputs(ss, z, w);
  EXPECT_LT((y.segment(0, 3) - q.head(3)).norm(), kIdentityTolerance);
  EXPECT_LT((y.segment(3, 3) - v.head(3)).norm(), kIdentityTolerance);
  EXPECT_LT((y.segment(6, 3) - acc.head(3)).norm(), kIdentityTolerance * acc.norm());
}

TEST(FromSecondOrder, DimensionErrorsNameTheMatrix) {
  SecondOrderSystem s = test::quarterCar();
  s.damping = Matrix::Zero(2, 1);
  try {
    fromSecondOrder(s);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("damping C is 2x1, expected 2x2"), std::string::npos)
        << e.what();
  }
  s = test::quarterCar();
  EXPECT_THROW(fromSecondOrder(s, {OutputQuantity::Displacement}, Vector::Zero(3)), InputError);
  s.mass(1, 1) = -1.0;
  EXPECT_THROW(fromSecondOrder(s), SolverError);
}

TEST(RoadInput, CentralDifferencesAreExactForQuadratics) {
  const double dt = 0.01;
  Matrix heights(6, 2);
  for (int k = 0; k < 6; ++k) {
    const double t = k * dt;
    heights(k, 0) = t * t;
    heights(k, 1) = 3.0 - t;
  }
  const Matrix w = roadInputSeries(heights, dt);
  ASSERT_EQ(w.cols(), 4);
  for (int k = 1; k < 5; ++k) {
    EXPECT_NEAR(w(k, 2), 2.0 * k * dt, kIdentityTolerance);
    EXPECT_NEAR(w(k, 3), -1.0, kIdentityTolerance);
  }
  // The ends take one-sided differences: exact for the line, (t_1^2 - t_0^2) / dt = dt and
  // (t_5^2 - t_4^2) / dt = 9 dt for the quadratic.
  for (int k : {0, 5})
    EXPECT_NEAR(w(k, 3), -1.0, kIdentityTolerance) << k;
  EXPECT_NEAR(w(0, 2), dt, kIdentityTolerance);
  EXPECT_NEAR(w(5, 2), 9.0 * dt, kIdentityTolerance);
  EXPECT_THROW(roadInputSeries(heights, 0.0), InputError);
  EXPECT_EQ(roadInput(Vector::Ones(2), Vector::Zero(2)).size(), 4);
  EXPECT_THROW(roadInput(Vector::Ones(2), Vector::Zero(3)), InputError);
}

TEST(MatrixExponential, Identities) {
  Matrix nilpotent = Matrix::Zero(2, 2);
  nilpotent(0, 1) = 1.0;
  EXPECT_LT((matrixExponential(nilpotent) - Matrix{{1.0, 1.0}, {0.0, 1.0}}).norm(),
            kIdentityTolerance);
  const Matrix x = Matrix::Random(7, 7);
  EXPECT_LT((matrixExponential(x) * matrixExponential(-x) - Matrix::Identity(7, 7)).norm(), 1e-11);
  EXPECT_THROW(matrixExponential(Matrix::Zero(2, 3)), InputError);
}

// An undamped oscillator as stiff as the tyre (2e10 N/m on 30 kg: omega h = 26 rad at 1 ms):
// Phi = [cos wh, sin wh / w; -w sin wh, cos wh] exactly.
TEST(Discretize, StiffOscillatorTransitionMatrixIsExact) {
  const double m = 30.0, k = 2e10, h = 1e-3;
  const double omega = std::sqrt(k / m);
  const StateSpace d = discretize(fromSecondOrder(test::oneDof(m, 0.0, k, 0.0)), h);
  const double c = std::cos(omega * h), s = std::sin(omega * h);
  EXPECT_NEAR(d.state_matrix(0, 0), c, kExactTolerance);
  EXPECT_NEAR(d.state_matrix(0, 1) * omega, s, kExactTolerance);
  EXPECT_NEAR(d.state_matrix(1, 0) / omega, -s, kExactTolerance);
  EXPECT_NEAR(d.state_matrix(1, 1), c, kExactTolerance);
  // ZOH: Gamma = int e^{As} ds B with B = [0; k/m]: [1 - cos wh; w sin wh] for w = [u; u'].
  EXPECT_NEAR(d.input_matrix(0, 0), 1.0 - c, kExactTolerance);
  EXPECT_NEAR(d.input_matrix(1, 0) / omega, s, kExactTolerance);
  // Undamped: |eigenvalues of Phi| = 1 (no growth, no artificial decay).
  const Eigen::VectorXcd lambda = d.state_matrix.eigenvalues();
  for (int i = 0; i < 2; ++i)
    EXPECT_NEAR(std::abs(lambda(i)), 1.0, kExactTolerance);
}

// m x'' + c x' + k x = k U: x = U (1 - e^{-z w t} (cos w_d t + z w / w_d sin w_d t)).
TEST(Discretize, ZeroOrderHoldStepResponseIsExact) {
  const double m = 10.0, k = 4e4, zeta = 0.05, h = 1e-3, step = 0.1;
  const double omega = std::sqrt(k / m), c = 2.0 * zeta * m * omega;
  const double omega_d = omega * std::sqrt(1.0 - zeta * zeta);
  const StateSpace ss = fromSecondOrder(
      test::oneDof(m, c, k, 0.0),
      {OutputQuantity::Displacement, OutputQuantity::Velocity, OutputQuantity::Acceleration});
  const StateSpace d = discretize(ss, h, InputHold::ZeroOrder);
  EXPECT_EQ(d.next_input_matrix.size(), 0);
  const Vector w = Eigen::Vector2d(step, 0.0);
  Vector z = Vector::Zero(2);
  for (int n = 1; n <= 2000; ++n) {
    z = advance(d, z, w, w);
    const double t = n * h;
    const double decay = std::exp(-zeta * omega * t);
    const double x =
        step *
        (1.0 - decay * (std::cos(omega_d * t) + zeta * omega / omega_d * std::sin(omega_d * t)));
    const double v = step * decay * omega * omega / omega_d * std::sin(omega_d * t);
    const double a = (k * (step - x) - c * v) / m;
    const Vector y = outputs(d, z, w);
    ASSERT_NEAR(y(0), x, kExactTolerance * step) << "t = " << t;
    ASSERT_NEAR(y(1), v, kExactTolerance * step * omega) << "t = " << t;
    ASSERT_NEAR(y(2), a, kExactTolerance * step * omega * omega) << "t = " << t;
  }
}

// Ramp u = r t, u' = r through spring and damper: x = r t - (r / w_d) e^{-z w t} sin(w_d t).
// The first-order hold is exact for this piecewise-linear input; the zero-order hold is not.
TEST(Discretize, FirstOrderHoldRampResponseIsExact) {
  const double m = 10.0, k = 4e4, zeta = 0.1, h = 2e-3, rate = 0.5;
  const double omega = std::sqrt(k / m), c = 2.0 * zeta * m * omega;
  const double omega_d = omega * std::sqrt(1.0 - zeta * zeta);
  const StateSpace ss = fromSecondOrder(test::oneDof(m, c, k, c));
  const StateSpace foh = discretize(ss, h, InputHold::FirstOrder);
  const StateSpace zoh = discretize(ss, h, InputHold::ZeroOrder);
  ASSERT_EQ(foh.next_input_matrix.rows(), 2);
  Vector z_foh = Vector::Zero(2), z_zoh = Vector::Zero(2);
  double zoh_error = 0.0;
  for (int n = 0; n < 1000; ++n) {
    const Vector w = Eigen::Vector2d(rate * n * h, rate);
    const Vector w_next = Eigen::Vector2d(rate * (n + 1) * h, rate);
    z_foh = advance(foh, z_foh, w, w_next);
    z_zoh = advance(zoh, z_zoh, w, w_next);
    const double t = (n + 1) * h;
    const double x =
        rate * t - rate / omega_d * std::exp(-zeta * omega * t) * std::sin(omega_d * t);
    ASSERT_NEAR(z_foh(0), x, kExactTolerance * rate * t) << "t = " << t;
    zoh_error = std::max(zoh_error, std::abs(z_zoh(0) - x));
  }
  // ZOH lags the ramp by about half a step: r h / 2.
  EXPECT_GT(zoh_error, 0.25 * rate * h);
}

// Quarter car with a 2e10 N/m tyre on 30 kg at h = 1 ms: bounded, and at 1 Hz equal to the
// harmonic steady state x = Im(X e^{j w t}) A, X = (K - w^2 M + j w C)^-1 (K_u + j w C_u).
TEST(Discretize, StiffQuarterCarMatchesHarmonicSteadyState) {
  const SecondOrderSystem s = test::quarterCar(300.0, 30.0, 3e4, 2e3, 2e10, 50.0);
  const double h = 1e-3, frequency = 1.0, amplitude = 0.05;
  const double omega = kTwoPi * frequency;
  using Complex = std::complex<double>;
  Eigen::MatrixXcd z_dyn = s.stiffness.cast<Complex>() - omega * omega * s.mass.cast<Complex>() +
                           Complex(0.0, omega) * s.damping.cast<Complex>();
  const Eigen::VectorXcd x_harmonic = z_dyn.lu().solve(
      s.input_stiffness.cast<Complex>() + Complex(0.0, omega) * s.input_damping.cast<Complex>());

  const StateSpace ss = fromSecondOrder(s);
  for (InputHold hold : {InputHold::FirstOrder, InputHold::ZeroOrder}) {
    const StateSpace d = discretize(ss, h, hold);
    const Eigen::VectorXcd lambda = d.state_matrix.eigenvalues();
    EXPECT_LE(lambda.cwiseAbs().maxCoeff(), 1.0);  // stable: damped modes decay
    // FOH: a sine interpolated linearly errs by (w h)^2 / 8 = 4.9e-6; ZOH lags by w h / 2 = 3.1e-3.
    const double tolerance = hold == InputHold::FirstOrder ? 1e-5 : 1e-2;
    auto input = [&](double t) {
      return Vector(Eigen::Vector2d(amplitude * std::sin(omega * t),
                                    amplitude * omega * std::cos(omega * t)));
    };
    Vector z = Vector::Zero(4);
    double max_error = 0.0;
    for (int n = 0; n < 6000; ++n) {
      z = advance(d, z, input(n * h), input((n + 1) * h));
      ASSERT_LT(z.head(2).cwiseAbs().maxCoeff(), 10.0 * amplitude);
      const double t = (n + 1) * h;
      if (t < 5.0)
        continue;
      const Eigen::VectorXcd x = x_harmonic * std::exp(Complex(0.0, omega * t)) * amplitude;
      max_error = std::max(max_error, (z.head(2) - x.imag()).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(max_error, tolerance * amplitude)
        << (hold == InputHold::FirstOrder ? "first" : "zero") << "-order hold";
  }
}

// A constant generalised force is a constant input column: exact for both holds, so the static
// equilibrium K q = K_u u + f_g is a fixed point of the discrete system.
TEST(Discretize, ConstantForceKeepsStaticEquilibrium) {
  const SecondOrderSystem s = test::quarterCar();
  const Vector f_g = Eigen::Vector2d(-300.0 * 9.81, -30.0 * 9.81);
  const Vector u = Vector::Constant(1, 0.02);
  const Vector q = s.stiffness.ldlt().solve(s.input_stiffness * u + f_g);
  const StateSpace ss = fromSecondOrder(s, {OutputQuantity::Acceleration}, f_g);
  for (InputHold hold : {InputHold::ZeroOrder, InputHold::FirstOrder}) {
    const StateSpace d = discretize(ss, 1e-3, hold);
    Vector z(4);
    z << q, Vector::Zero(2);
    const Vector w = Eigen::Vector2d(u(0), 0.0);
    const Vector z_next = advance(d, z, w, w);
    EXPECT_LT((z_next - z).cwiseAbs().maxCoeff(), 1e-11 * q.cwiseAbs().maxCoeff());
    EXPECT_LT(outputs(d, z, w).cwiseAbs().maxCoeff(), 1e-5);  // acceleration ~ 0 [m/s^2]
  }
}

TEST(Discretize, RejectsBadArguments) {
  const StateSpace ss = fromSecondOrder(test::quarterCar());
  EXPECT_THROW(discretize(ss, 0.0), InputError);
  EXPECT_THROW(discretize(ss, -1e-3), InputError);
  const StateSpace d = discretize(ss, 1e-3);
  EXPECT_THROW(discretize(d, 1e-3), InputError);
  StateSpace broken = ss;
  broken.input_matrix = Matrix::Zero(3, 2);
  EXPECT_THROW(discretize(broken, 1e-3), InputError);
}
