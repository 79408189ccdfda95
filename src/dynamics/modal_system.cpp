#include "tracked_vehicle_dynamics/dynamics/modal_system.h"

#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <string>

#include "checks.h"
#include "tracked_vehicle_dynamics/dynamics/validation.h"
#include "tracked_vehicle_dynamics/fem/low_mode_refinement.h"

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
void requireSymmetric(const Matrix& x, const std::string& what) {
  const double norm = x.norm();
  if (norm > 0.0 && (x - x.transpose()).norm() > kSymmetryTolerance * norm)
    throw InputError("ModalSystem: " + what + " is not symmetric (relative asymmetry " +
                     brief((x - x.transpose()).norm() / norm) + ")");
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
  const bool held = fem::refineLowModes(stiffness, mass, &lambda, &shapes_);
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
