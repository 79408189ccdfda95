#include "tracked_vehicle_dynamics/dynamics/modal_system.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

#include "checks.h"
#include "tracked_vehicle_dynamics/dynamics/validation.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

namespace {

// Relative asymmetry tolerated in M and K (rounding of a reduction), ||X - X^T|| / ||X||.
constexpr double kSymmetryTolerance = 1e-8;
// Eigenvalues with |omega^2| below this fraction of the largest are rigid-body modes (set to 0):
// the dense solver's rounding, a few n eps lambda_max; below minus it, K is indefinite. Not
// more: a reduced vehicle's lambda_max is ~1.3e11 rad^2/s^2 (the 2e10 N/m wheel ties on light
// soles), so 1e-10 of it took any real chain mode below ~0.6 Hz for a rigid one (a lighter
// vehicle's top run has them at 0.51 Hz), with no stiffness left to hold it, and passed an
// unstable omega^2 of -17 rad^2/s^2 as a rigid mode (review 134).
constexpr double kRigidBodyTolerance = 1e-12;
// |phi^T C phi| below this fraction of the largest is rounding (beta K on a rigid-body mode):
// taken as >= 0; more negative, C is not positive semi-definite.
constexpr double kDampingRoundoff = 1e-10;
// Modes below this fraction of lambda_max are refined by inverse subspace iteration when K is
// positive definite: the dense solver gives them to an absolute n eps lambda_max, a relative
// error of 1e-8 and more below it (400 coordinates).
constexpr double kRefineBelow = 1e-6;
// K_ii / (Cholesky pivot)^2 above this: a near-mechanism (a free body's rigid motion survives
// the factorisation as a pivot of rounding size), not a structure held to ground; the modes
// are then left as the dense solver gives them. Nastran's MAXRATIO warns at 1e7.
constexpr double kMaxPivotRatio = 1e10;

void requireSymmetric(const Matrix& x, const std::string& what) {
  const double norm = x.norm();
  if (norm > 0.0 && (x - x.transpose()).norm() > kSymmetryTolerance * norm)
    throw InputError("ModalSystem: " + what + " is not symmetric (relative asymmetry " +
                     brief((x - x.transpose()).norm() / norm) + ")");
}

/// The dense solver (Cholesky of M, then a symmetric tridiagonal QR) has an absolute eigenvalue
/// error of a few n eps lambda_max. A vehicle on stiff ties spans more decades than that
/// resolves: ground springs of 9e14 N/m under pads of a few hundred grams give lambda_max ~ 1e15
/// rad^2/s^2, and its 0.7 Hz chain modes (omega^2 = 18) came out within a few rad^2/s^2, below
/// 1e-12 lambda_max, so they were taken for rigid-body modes and the hull drifted off on flat road
/// (review 157). When K is positive definite (held to ground), inverse subspace iteration gives
/// the low modes to their own relative accuracy: with K = L L^T, accurate on such graded matrices
/// (the stiff ties sit on the diagonal), X' = K^-1 M X and the Rayleigh-Ritz pair
///   K_p = X'^T (M X) (= X'^T K X' with no product by K, whose cancellation is the error),
///   M_p = X'^T M X'.
/// Returns whether the modes below kRefineBelow lambda_max were refined (then none is rigid).
bool refineLowModes(const Matrix& stiffness, const Matrix& mass, double lambda_max, Vector* lambda,
                    Matrix* shapes) {
  const DofIndex n = lambda->size();
  DofIndex p = 0;
  while (p < n && (*lambda)(p) <= kRefineBelow * lambda_max)
    ++p;
  if (p == 0 || p == n)
    return false;
  const Eigen::LLT<Matrix> k_factor(stiffness);
  if (k_factor.info() != Eigen::Success)
    return false;
  const Vector pivots = k_factor.matrixLLT().diagonal().cwiseAbs2();
  for (DofIndex i = 0; i < n; ++i)
    if (!(pivots(i) * kMaxPivotRatio >= stiffness(i, i)))
      return false;
  // One step: the solver's low subspace is accurate (its error is eps lambda_max over the gap
  // to the high modes, itself of the order of lambda_max); only the modes within it are not,
  // and the Rayleigh-Ritz step on K^-1 M X sorts them out.
  const Matrix y = mass * shapes->leftCols(p);
  const Matrix x1 = k_factor.solve(y);
  const Matrix m_x1 = mass * x1;
  Matrix k_p = x1.transpose() * y;
  Matrix m_p = x1.transpose() * m_x1;
  k_p = 0.5 * (k_p + k_p.transpose()).eval();
  m_p = 0.5 * (m_p + m_p.transpose()).eval();
  const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> ritz(
      k_p, m_p, Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
  if (ritz.info() != Eigen::Success)
    return false;
  const Matrix x = x1 * ritz.eigenvectors();  // M-normalised: Z^T M_p Z = I
  // The solver's high modes were M-orthogonal to its low ones; to the refined ones only to
  // ~1e-11, which a state projected on the modes and back (eta = Phi^T M q, q = Phi eta) would
  // lose. Make them M-orthogonal again, h -= X c with c = X^T M h, and unit again,
  // h^T M h = 1 - |c|^2: the change is of that order, the high modes' Rayleigh quotients move by
  // its square.
  Matrix high = shapes->rightCols(n - p);
  const Matrix c = (m_x1 * ritz.eigenvectors()).transpose() * high;
  high -= x * c;
  for (DofIndex j = 0; j < n - p; ++j)
    high.col(j) /= std::sqrt(1.0 - c.col(j).squaredNorm());
  lambda->head(p) = ritz.eigenvalues();
  shapes->leftCols(p) = x;
  shapes->rightCols(n - p) = high;
  return true;
}

}  // namespace

ModalSystem::ModalSystem(const SecondOrderSystem& system, const Vector& damping_ratios) {
  validateSystem(system);
  const DofIndex n = system.size();
  if (damping_ratios.size() != 0) {
    detail::requireLength("ModalSystem", "damping ratios", damping_ratios, n);
    if (!(damping_ratios.array() >= 0.0).all() || !damping_ratios.allFinite())
      throw InputError("ModalSystem: damping ratios must be finite and >= 0");
  }
  requireSymmetric(system.mass, "mass M");
  requireSymmetric(system.stiffness, "stiffness K");
  const Matrix mass = 0.5 * (system.mass + system.mass.transpose());
  const Matrix stiffness = 0.5 * (system.stiffness + system.stiffness.transpose());
  if (Eigen::LLT<Matrix>(mass).info() != Eigen::Success)
    throw SolverError("ModalSystem: mass matrix M (" + detail::sizeText(n, n) +
                      ") is not positive definite");

  // K phi = lambda M phi, eigenvectors M-normalised, eigenvalues ascending.
  const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> solver(
      stiffness, mass, Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
  if (solver.info() != Eigen::Success)
    throw SolverError("ModalSystem: the dense generalised eigensolver did not converge");
  Vector lambda = solver.eigenvalues();
  shapes_ = solver.eigenvectors();
  const double lambda_max = std::max(lambda.cwiseAbs().maxCoeff(), 0.0);
  // Held to ground (K positive definite): no rigid-body mode, and the low ones refined.
  const bool held = refineLowModes(stiffness, mass, lambda_max, &lambda, &shapes_);
  for (DofIndex r = 0; r < n; ++r) {
    if (held && lambda(r) > 0.0)
      continue;
    if (std::abs(lambda(r)) <= kRigidBodyTolerance * lambda_max) {
      lambda(r) = 0.0;
    } else if (lambda(r) < 0.0) {
      throw SolverError("ModalSystem: stiffness K is indefinite: mode " + std::to_string(r) +
                        " has omega^2 = " + brief(lambda(r)) + " rad^2/s^2");
    }
  }
  frequencies_ = lambda.cwiseSqrt();

  // c = Phi^T C Phi; its diagonal gives the modal damping d_r = 2 zeta_r omega_r.
  const Matrix modal_damping = shapes_.transpose() * system.damping * shapes_;
  max_off_diagonal_damping_ratio_ = maxOffDiagonalRatio(modal_damping);
  if (damping_ratios.size() != 0) {
    damping_coefficients_ = 2.0 * damping_ratios.cwiseProduct(frequencies_);
  } else {
    damping_coefficients_ = modal_damping.diagonal();
    // phi^T C phi >= 0 for a positive semi-definite C, up to rounding (e.g. beta K on a
    // rigid-body mode).
    const double d_max = damping_coefficients_.cwiseAbs().maxCoeff();
    for (DofIndex r = 0; r < n; ++r) {
      double& d = damping_coefficients_(r);
      if (std::abs(d) <= kDampingRoundoff * d_max)
        d = std::max(d, 0.0);
      if (d < 0.0)
        throw InputError("ModalSystem: damping C is not positive semi-definite: mode " +
                         std::to_string(r) + " has phi^T C phi = " + brief(d) + " 1/s");
    }
  }

  modal_input_stiffness_ = shapes_.transpose() * system.input_stiffness;
  modal_input_damping_ = shapes_.transpose() * system.input_damping;
  modal_output_ = system.output * shapes_;
  mass_projection_ = shapes_.transpose() * mass;
  output_names_ = system.output_names;
  if (output_names_.empty())
    for (DofIndex i = 0; i < system.outputCount(); ++i)
      output_names_.push_back("output " + std::to_string(i));
  input_stations_ = system.input_stations;
}

ModalSystem ModalSystem::withOutput(const Matrix& output, std::vector<std::string> names) const {
  if (output.cols() != modeCount())
    throw InputError("ModalSystem::withOutput: H is " +
                     detail::sizeText(output.rows(), output.cols()) + ", expected " +
                     std::to_string(modeCount()) + " columns");
  if (!names.empty() && static_cast<DofIndex>(names.size()) != output.rows())
    throw InputError("ModalSystem::withOutput: " + std::to_string(names.size()) + " names for " +
                     std::to_string(output.rows()) + " outputs");
  ModalSystem out = *this;
  out.modal_output_ = output * shapes_;
  out.output_names_ = std::move(names);
  if (out.output_names_.empty())
    for (DofIndex i = 0; i < output.rows(); ++i)
      out.output_names_.push_back("output " + std::to_string(i));
  return out;
}

Vector ModalSystem::dampingRatios() const {
  Vector zeta = Vector::Zero(modeCount());
  for (DofIndex r = 0; r < modeCount(); ++r)
    if (frequencies_(r) > 0.0)
      zeta(r) = damping_coefficients_(r) / (2.0 * frequencies_(r));
  return zeta;
}

double maxOffDiagonalRatio(const Matrix& modal_damping) {
  double worst = 0.0;
  for (DofIndex s = 0; s < modal_damping.cols(); ++s)
    for (DofIndex r = 0; r < modal_damping.rows(); ++r) {
      if (r == s || modal_damping(r, s) == 0.0)
        continue;
      const double diagonal = std::sqrt(std::abs(modal_damping(r, r) * modal_damping(s, s)));
      const double ratio = diagonal > 0.0 ? std::abs(modal_damping(r, s)) / diagonal
                                          : std::numeric_limits<double>::infinity();
      worst = std::max(worst, ratio);
    }
  return worst;
}

std::string modalDampingCouplingWarning(double coupling, const std::string& what,
                                        const std::string& instead) {
  if (!(coupling > kModalDampingCouplingTolerance))
    return "";
  std::ostringstream m;
  m << std::setprecision(3)
    << "the damping couples the modes (Phi^T C Phi off its diagonal by up to " << coupling
    << " of the diagonal terms: discrete dampers such as suspension.arm_damping): " << what
    << " keeps only the diagonal (modal damping), which can move peaks by tens of per cent "
       "(README, tvd frf); "
    << instead;
  return m.str();
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
