#include "tracked_vehicle_dynamics/dynamics/frf_state_space.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "checks.h"
#include "tracked_vehicle_dynamics/dynamics/validation.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

namespace {

// Row-major: the elimination below updates rows.
using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using RowComplexMatrix = Eigen::Matrix<Complex, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Solves (j omega I - H) w = b in place of b, H upper Hessenberg, by Gaussian elimination with
// partial pivoting between rows k and k+1 (the only candidates below a Hessenberg diagonal):
// O(N^2). The rows of j omega I - H are formed as the elimination reaches them, so H is read
// once and only U is written: `cur` holds row k of the partly eliminated matrix (from column k
// on), `fresh` row k+1 of j omega I - H; the pivot row goes to U's row k and the other, less
// l times the pivot row, becomes the next `cur`. False when j omega I - H is singular to working
// precision: a pivot not above round-off of `scale` (a norm of H plus omega), or the smallest
// pivot below 10 N eps times the largest, where the error bound of the elimination,
// N eps |largest / smallest|, would pass 10 % (an undamped resonance on the grid, to within
// round-off).
struct HessenbergWork {
  RowComplexMatrix u;  // the upper triangle of U
  ComplexVector cur, fresh;
  explicit HessenbergWork(DofIndex n) : u(n, n), cur(n), fresh(n) {}
};

bool solveShiftedHessenberg(const RowMatrix& h, double omega, double scale, HessenbergWork* work,
                            ComplexVector* b) {
  const DofIndex n = h.rows();
  const Complex j_omega(0.0, omega);
  const double tiny = std::numeric_limits<double>::epsilon() * scale;
  ComplexVector& w = *b;
  ComplexVector& cur = work->cur;
  ComplexVector& fresh = work->fresh;
  cur = -h.row(0).transpose().cast<Complex>();
  cur(0) += j_omega;
  double smallest = std::numeric_limits<double>::infinity(), largest = 0.0;
  for (DofIndex k = 0; k + 1 < n; ++k) {
    const DofIndex m = n - k;
    fresh.segment(k, m) = -h.row(k + 1).segment(k, m).transpose().cast<Complex>();
    fresh(k + 1) += j_omega;
    if (std::abs(fresh(k)) > std::abs(cur(k))) {  // row k+1 is the pivot row
      cur.swap(fresh);
      std::swap(w(k), w(k + 1));
    }
    if (!(std::abs(cur(k)) > tiny))
      return false;
    smallest = std::min(smallest, std::abs(cur(k)));
    largest = std::max(largest, std::abs(cur(k)));
    work->u.row(k).segment(k, m) = cur.segment(k, m).transpose();
    const Complex l = fresh(k) / cur(k);
    fresh.segment(k + 1, m - 1) -= l * cur.segment(k + 1, m - 1);
    w(k + 1) -= l * w(k);
    cur.swap(fresh);
  }
  if (!(std::abs(cur(n - 1)) > tiny))
    return false;
  smallest = std::min(smallest, std::abs(cur(n - 1)));
  largest = std::max(largest, std::abs(cur(n - 1)));
  if (smallest < 10.0 * static_cast<double>(n) * std::numeric_limits<double>::epsilon() * largest)
    return false;
  work->u(n - 1, n - 1) = cur(n - 1);
  work->u.triangularView<Eigen::Upper>().solveInPlace(w);
  return w.allFinite();
}

}  // namespace

ComplexMatrix frfStateSpace(const SecondOrderSystem& system, const ModalSystem& modal,
                            const Vector& frequencies_hz, const InputDelay& delay,
                            OutputQuantity quantity) {
  validateSystem(system);
  if (!frequencies_hz.allFinite() || (frequencies_hz.array() < 0.0).any())
    throw InputError("frfStateSpace: frequencies must be finite and >= 0 Hz");
  const DofIndex n = system.size();
  if (modal.modeCount() != n || modal.inputCount() != system.inputCount() ||
      modal.outputCount() != system.outputCount())
    throw InputError("frfStateSpace: the modal system (" + std::to_string(modal.modeCount()) +
                     " modes, " + std::to_string(modal.inputCount()) + " inputs, " +
                     std::to_string(modal.outputCount()) + " outputs) is not the system's (" +
                     std::to_string(n) + " DOFs, " + std::to_string(system.inputCount()) +
                     " inputs, " + std::to_string(system.outputCount()) + " outputs)");
  const Vector& omega_r = modal.naturalFrequencies();
  const ModeShapes& phi = modal.shapes();
  // Sizes agree for any modal system of the same shape: its projections must be this system's
  // (not withOutput()'s other rows, nor another model's modes).
  const auto differs = [](const Matrix& a, const Matrix& b) {
    return (a - b).cwiseAbs().maxCoeff() > 1e-9 * std::max(1.0, b.cwiseAbs().maxCoeff());
  };
  // Its modes must be this system's: phi_r^T M phi_r = 1 and phi_r^T K phi_r = omega_r^2 (two
  // n^3 products, a few % of the reduction below).
  const Vector unit_mass = (phi.transpose() * system.mass * phi).diagonal();
  const Vector squares = (phi.transpose() * system.stiffness * phi).diagonal();
  const bool other_modes = n > 0 && (differs(unit_mass, Vector::Ones(n)) ||
                                     (squares - omega_r.cwiseAbs2()).cwiseAbs().maxCoeff() >
                                         1e-9 * std::max(1.0, omega_r.cwiseAbs2().maxCoeff()));
  if (other_modes ||
      (n > 0 && system.outputCount() > 0 && differs(modal.modalOutput(), system.output * phi)) ||
      (n > 0 && system.inputCount() > 0 &&
       differs(modal.modalInputStiffness(), phi.transpose() * system.input_stiffness)))
    throw InputError(
        "frfStateSpace: the modal system is not this system's (its modes, or its outputs or "
        "inputs projected on them, differ): give ModalSystem(system)");

  // A = [0 Omega; -Omega -D] with D = Phi^T C Phi (the whole of it), reduced once.
  Matrix a = Matrix::Zero(2 * n, 2 * n);
  a.topRightCorner(n, n).diagonal() = omega_r;
  a.bottomLeftCorner(n, n).diagonal() = -omega_r;
  a.bottomRightCorner(n, n) = -(phi.transpose() * system.damping * phi);
  const Eigen::HessenbergDecomposition<Matrix> hessenberg(a);
  const RowMatrix h = hessenberg.matrixH();
  const Matrix q = hessenberg.matrixQ();
  const auto q1 = q.topRows(n);
  const auto q2 = q.bottomRows(n);

  // Right-hand sides and outputs in the Hessenberg basis: b = Q_2^T Phi^T (K_u + j omega C_u) tau.
  const Matrix b_stiffness = q2.transpose() * modal.modalInputStiffness();
  const Matrix b_damping = q2.transpose() * modal.modalInputDamping();
  const Matrix velocity_output = modal.modalOutput() * q2;  // H Phi eta' = (H Phi Q_2) w
  Matrix displacement_output, rigid_output;                 // H Phi eta, elastic and rigid parts
  const bool has_rigid_modes = (omega_r.array() == 0.0).any();
  if (quantity == OutputQuantity::Displacement) {
    Vector inverse = Vector::Zero(n), rigid = Vector::Zero(n);
    for (DofIndex r = 0; r < n; ++r) {
      if (omega_r(r) > 0.0)
        inverse(r) = 1.0 / omega_r(r);  // eta_r = (omega_r eta_r) / omega_r
      else
        rigid(r) = 1.0;  // eta_r = eta_r' / (j omega)
    }
    displacement_output = modal.modalOutput() * inverse.asDiagonal() * q1;
    rigid_output = modal.modalOutput() * rigid.asDiagonal() * q2;
  }
  const double h_norm = h.cwiseAbs().rowwise().sum().maxCoeff();

  ComplexMatrix frf(frequencies_hz.size(), system.outputCount());
  HessenbergWork work(2 * n);
  ComplexVector w(2 * n);
  for (DofIndex i = 0; i < frequencies_hz.size(); ++i) {
    const double omega = kTwoPi * frequencies_hz(i);
    const ComplexVector tau = delay.at(omega, system.inputCount());
    w = b_stiffness * tau + Complex(0.0, omega) * (b_damping * tau);
    if (!solveShiftedHessenberg(h, omega, h_norm + omega, &work, &w))
      throw SolverError("frfStateSpace: j omega I - A is singular at " +
                        std::to_string(frequencies_hz(i)) +
                        " Hz (an undamped resonance, or a rigid-body mode at 0 Hz)");
    switch (quantity) {
      case OutputQuantity::Velocity:
        frf.row(i) = (velocity_output * w).transpose();
        break;
      case OutputQuantity::Acceleration:
        frf.row(i) = (Complex(0.0, omega) * (velocity_output * w)).transpose();
        break;
      case OutputQuantity::Displacement: {
        ComplexVector x = displacement_output * w;
        if (has_rigid_modes)
          x += (rigid_output * w) / Complex(0.0, omega);
        frf.row(i) = x.transpose();
        break;
      }
    }
  }
  return frf;
}

ComplexMatrix frfExact(const SecondOrderSystem& system, const ModalSystem& modal,
                       const Vector& frequencies_hz, const InputDelay& delay,
                       OutputQuantity quantity, bool* used_modal) {
  const bool diagonal = modal.maxOffDiagonalDampingRatio() <= kModalDampingCouplingTolerance;
  if (used_modal != nullptr)
    *used_modal = diagonal;
  return diagonal ? frfModal(modal, frequencies_hz, delay, quantity)
                  : frfStateSpace(system, modal, frequencies_hz, delay, quantity);
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
