#include "tracked_vehicle_dynamics/dynamics/discretization.h"

#include <cmath>
#include <unsupported/Eigen/MatrixFunctions>

#include "checks.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

namespace {

// Osborne/Parlett-Reinsch balancing (as in LAPACK dgebal without permutations): scales row and
// column i by powers of 2 until their off-diagonal 1-norms are within a factor 2. Returns D with
// x <- D^-1 x D applied in place.
Vector balance(Matrix& x) {
  constexpr double kRadix = 2.0;
  constexpr double kRadixSquared = kRadix * kRadix;
  constexpr int kMaxSweeps = 100;
  const DofIndex n = x.rows();
  Vector scale = Vector::Ones(n);
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    bool converged = true;
    for (DofIndex i = 0; i < n; ++i) {
      double c = x.col(i).cwiseAbs().sum() - std::abs(x(i, i));
      double r = x.row(i).cwiseAbs().sum() - std::abs(x(i, i));
      if (c == 0.0 || r == 0.0)
        continue;
      const double s = c + r;
      double f = 1.0;
      while (c < r / kRadix) {
        f *= kRadix;
        c *= kRadixSquared;
      }
      while (c >= r * kRadix) {
        f /= kRadix;
        c /= kRadixSquared;
      }
      if ((c + r) / f < 0.95 * s) {
        converged = false;
        scale(i) *= f;
        x.row(i) /= f;
        x.col(i) *= f;
      }
    }
    if (converged)
      break;
  }
  return scale;
}

}  // namespace

Matrix matrixExponential(const Matrix& x) {
  detail::requireSize("matrixExponential", "argument", x, x.rows(), x.rows());
  if (!x.allFinite())
    throw InputError("matrixExponential: argument has non-finite entries");
  if (x.rows() == 0)
    return x;
  Matrix balanced = x;
  const Vector d = balance(balanced);
  Matrix e = balanced.exp();
  // e^X = D e^{X_b} D^-1
  e = d.asDiagonal() * e * d.cwiseInverse().asDiagonal();
  return e;
}

StateSpace discretize(const StateSpace& continuous, double dt, InputHold hold) {
  validateStateSpace(continuous);
  if (!continuous.isContinuous())
    throw InputError("discretize: the system is already discrete (sample time " +
                     std::to_string(continuous.sample_time) + " s)");
  detail::requireTimeStep("discretize", dt);
  const DofIndex n = continuous.stateCount();
  const DofIndex m = continuous.inputCount();
  const bool has_offset =
      continuous.state_offset.size() != 0 && !continuous.state_offset.isZero(0.0);
  const DofIndex m_aug = m + (has_offset ? 1 : 0);  // B' = [B f0]

  const DofIndex size = hold == InputHold::ZeroOrder ? n + m_aug : n + 2 * m_aug;
  Matrix aug = Matrix::Zero(size, size);
  aug.topLeftCorner(n, n) = continuous.state_matrix * dt;
  aug.block(0, n, n, m) = continuous.input_matrix * dt;
  if (has_offset)
    aug.block(0, n + m, n, 1) = continuous.state_offset * dt;
  if (hold == InputHold::FirstOrder)
    aug.block(n, n + m_aug, m_aug, m_aug).setIdentity();
  const Matrix e = matrixExponential(aug);

  StateSpace d = continuous;
  d.sample_time = dt;
  d.hold = hold;
  d.state_matrix = e.topLeftCorner(n, n);
  const Matrix gamma = e.block(0, n, n, m);
  if (hold == InputHold::ZeroOrder) {
    d.input_matrix = gamma;
    d.next_input_matrix.resize(0, 0);
  } else {
    const Matrix gamma2 = e.block(0, n + m_aug, n, m);
    d.input_matrix = gamma - gamma2;
    d.next_input_matrix = gamma2;
  }
  if (has_offset)
    d.state_offset = e.block(0, n + m, n, 1);
  else
    d.state_offset.resize(0);
  return d;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
