// Modal form of a second-order system (paper eq. 20), used by the modal-decoupled simulator and
// the modal FRF. With K phi_r = omega_r^2 M phi_r, Phi^T M Phi = I and q = Phi eta:
//
//   eta_r'' + d_r eta_r' + omega_r^2 eta_r = phi_r^T (K_u u + C_u u' + f_g)
//   d_r = 2 zeta_r omega_r
//
// Exact when Phi^T C Phi is diagonal (proportional/Rayleigh damping, C = a M + b K). Otherwise the
// modal damping approximation d_r = phi_r^T C phi_r (zeta_r = phi_r^T C phi_r / (2 omega_r))
// drops the off-diagonal coupling; maxOffDiagonalDampingRatio() tells how much was dropped.
// All n modes are kept (no truncation), so sum_r phi_r phi_r^T = M^-1 exactly.
#pragma once

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/dynamics/second_order_system.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// Above this maxOffDiagonalDampingRatio() the damping couples the modes beyond round-off
/// (discrete dampers, e.g. suspension.arm_damping): the modal damping approximation is then an
/// approximation, and the tools say so or solve without it.
constexpr double kModalDampingCouplingTolerance = 1e-6;

/// max over r != s of |c_rs| / sqrt(c_rr c_ss) of a damping matrix in mass-normalised modal
/// coordinates (infinite where an off-diagonal term meets a zero diagonal): what the modal
/// damping approximation drops, 0 when c is diagonal.
double maxOffDiagonalRatio(const Matrix& modal_damping);

/// What the modal damping approximation drops, for a user: "" when coupling is within the
/// tolerance. `what`: the run or result it concerns (e.g. "--method modal (the default)");
/// `instead`: what gives the exact answer.
std::string modalDampingCouplingWarning(double coupling, const std::string& what,
                                        const std::string& instead);

class ModalSystem {
 public:
  /// Solves the dense generalised eigenproblem K phi = omega^2 M phi (O(n^3)).
  /// damping_ratios: zeta_r per mode [-], ascending-frequency order; empty = derived from C.
  /// Throws InputError for inconsistent sizes, a wrong number of or negative damping ratios, or
  /// M/K not symmetric, or (damping derived from C) C not positive semi-definite; SolverError
  /// when M is not positive definite, K has a clearly negative eigenvalue, or the eigensolver
  /// fails.
  explicit ModalSystem(const SecondOrderSystem& system, const Vector& damping_ratios = Vector());

  /// The same decomposition with other outputs y = H q: H [n_outputs x n], one name per row
  /// (empty: "output i"). What it costs is H Phi, not the eigen-solve: a second stepper on the
  /// same system with other outputs (ground_contact_forces.h) reuses the first one's modes.
  /// Throws InputError when H has not n columns or the names do not match its rows.
  ModalSystem withOutput(const Matrix& output, std::vector<std::string> names) const;

  DofIndex modeCount() const { return frequencies_.size(); }
  DofIndex inputCount() const { return modal_input_stiffness_.cols(); }
  DofIndex outputCount() const { return modal_output_.rows(); }

  /// omega_r [rad/s], ascending; rigid-body modes (|omega^2| <= 1e-12 max |omega^2|) are exactly 0;
  /// below -1e-12 max |omega^2| K is indefinite (SolverError). A system held to ground (K
  /// positive definite, no near-mechanism) has none: its modes below 1e-6 max |omega^2| are
  /// refined by inverse subspace iteration to their own relative accuracy, however stiff its ties
  /// (a pad on a 1e15 N/m road beside 0.7 Hz chain modes).
  const Vector& naturalFrequencies() const { return frequencies_; }
  /// d_r = 2 zeta_r omega_r [1/s]: the modal damping coefficient (defined for rigid modes too).
  const Vector& dampingCoefficients() const { return damping_coefficients_; }
  /// zeta_r = d_r / (2 omega_r) [-]; 0 for a rigid-body mode.
  Vector dampingRatios() const;
  /// Phi [n x n], mass-normalised: Phi^T M Phi = I, Phi^T K Phi = diag(omega^2).
  const ModeShapes& shapes() const { return shapes_; }
  /// Phi^T K_u [n_modes x n_inputs] [N/m per unit modal mass].
  const Matrix& modalInputStiffness() const { return modal_input_stiffness_; }
  /// Phi^T C_u [n_modes x n_inputs].
  const Matrix& modalInputDamping() const { return modal_input_damping_; }
  /// H Phi [n_outputs x n_modes].
  const Matrix& modalOutput() const { return modal_output_; }
  /// Phi^T M [n_modes x n]: modal coordinates of a physical vector, eta = Phi^T M q.
  const Matrix& massProjection() const { return mass_projection_; }
  /// max over r != s of |c_rs| / sqrt(c_rr c_ss) with c = Phi^T C Phi: 0 for proportional
  /// damping; the size of the coupling neglected by the modal damping approximation.
  double maxOffDiagonalDampingRatio() const { return max_off_diagonal_damping_ratio_; }
  /// One name per row of H (from the system, or "output i").
  const std::vector<std::string>& outputNames() const { return output_names_; }
  /// Input stations [m] copied from the system (may be empty).
  const Vector& inputStations() const { return input_stations_; }

 private:
  Vector frequencies_;
  Vector damping_coefficients_;
  ModeShapes shapes_;
  Matrix modal_input_stiffness_;
  Matrix modal_input_damping_;
  Matrix modal_output_;
  Matrix mass_projection_;
  double max_off_diagonal_damping_ratio_ = 0.0;
  std::vector<std::string> output_names_;
  Vector input_stations_;
};

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
