// Damping of the reduced model (paper eq. 9 reduces C like M and K). The discrete dampers of the
// model (suspension, track pads) are always projected, C_d,R = T^T C T; the model adds
// structural damping on top of them.
#pragma once

#include <string>

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

enum class DampingModel {
  /// C_R = C_d,R: the discrete dampers only.
  Discrete,
  /// C_R = C_d,R + alpha M_R + beta K_R (Rayleigh). Equal to T^T (alpha M + beta K) T, since the
  /// projection is linear; gives the ratio zeta(omega) = alpha / (2 omega) + beta omega / 2.
  Rayleigh,
  /// C_R = C_d,R + M_R Phi_R diag(2 zeta_i omega_i) Phi_R^T M_R, with (omega_i^2, Phi_R) every
  /// mode of the reduced (K_R, M_R), Phi_R^T M_R Phi_R = I. Then Phi_R^T (C_R - C_d,R) Phi_R =
  /// diag(2 zeta_i omega_i): exactly the ratio zeta_i in mode i of the reduced model (its own
  /// modes, masters included), and nothing on rigid-body modes (omega = 0).
  Modal,
};

struct DampingOptions {
  DampingModel model = DampingModel::Discrete;
  double alpha = 0.0;         ///< Rayleigh mass coefficient [1/s]
  double beta = 0.0;          ///< Rayleigh stiffness coefficient [s]
  double modal_ratio = 0.02;  ///< Modal: zeta of every mode [-] unless modal_ratios is given
  Vector modal_ratios;  ///< Modal: zeta per reduced mode, ascending frequency [-] (size m + r)
};

/// C_R for the reduced mass m_r and stiffness k_r [k x k] and the projected discrete dampers
/// c_discrete [k x k]. Throws InputError for mismatched sizes, negative or non-finite
/// coefficients, or modal_ratios of the wrong size; SolverError when M_R is not positive
/// definite (Modal).
Matrix reducedDamping(const Matrix& m_r, const Matrix& k_r, const Matrix& c_discrete,
                      const DampingOptions& options);

/// One line for reports and the .mat file, e.g. "Rayleigh alpha=0.5 1/s beta=0.001 s + discrete
/// dampers"; "+ discrete dampers" only when the model has some (`discrete_dampers`).
std::string describe(const DampingOptions& options, bool discrete_dampers);

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
