#include "tracked_vehicle_dynamics/dynamics/discrete_modes.h"

#include <algorithm>
#include <unsupported/Eigen/MatrixFunctions>

#include "checks.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

DiscreteModes discretizeModes(const Vector& frequencies, const Vector& damping_coefficients,
                              double dt, InputHold hold) {
  const std::string where = "discretizeModes";
  detail::requireTimeStep(where, dt);
  detail::requireLength(where, "damping coefficients", damping_coefficients, frequencies.size());
  if (!frequencies.allFinite() || (frequencies.array() < 0.0).any())
    throw InputError(where + ": natural frequencies must be finite and >= 0");
  if (!damping_coefficients.allFinite() || (damping_coefficients.array() < 0.0).any())
    throw InputError(where + ": damping coefficients must be finite and >= 0");

  const DofIndex n = frequencies.size();
  DiscreteModes modes;
  modes.sample_time = dt;
  modes.hold = hold;
  for (Vector* v : {&modes.a11, &modes.a12, &modes.a21, &modes.a22, &modes.g0_disp, &modes.g0_vel,
                    &modes.g1_disp, &modes.g1_vel})
    v->setZero(n);

  for (DofIndex r = 0; r < n; ++r) {
    const double omega = frequencies(r);
    const double d = damping_coefficients(r);
    // Balanced coordinates xi = [eta; eta'/s] and scaled input p_hat = p / s^2:
    //   xi' = [0 s; -omega^2/s -d] xi + [0; s] p_hat
    const double s = std::max(omega, 1.0 / dt);
    Eigen::Matrix4d aug = Eigen::Matrix4d::Zero();
    aug(0, 1) = s * dt;
    aug(1, 0) = -omega * omega / s * dt;
    aug(1, 1) = -d * dt;
    aug(1, 2) = s * dt;
    if (hold == InputHold::FirstOrder)
      aug(2, 3) = 1.0;
    const Eigen::Matrix4d e = aug.exp();
    // Back to [eta; eta'] = diag(1, s) xi and p = s^2 p_hat.
    modes.a11(r) = e(0, 0);
    modes.a12(r) = e(0, 1) / s;
    modes.a21(r) = e(1, 0) * s;
    modes.a22(r) = e(1, 1);
    const double gamma_disp = e(0, 2) / (s * s);
    const double gamma_vel = e(1, 2) / s;
    if (hold == InputHold::ZeroOrder) {
      modes.g0_disp(r) = gamma_disp;
      modes.g0_vel(r) = gamma_vel;
    } else {
      modes.g1_disp(r) = e(0, 3) / (s * s);
      modes.g1_vel(r) = e(1, 3) / s;
      modes.g0_disp(r) = gamma_disp - modes.g1_disp(r);
      modes.g0_vel(r) = gamma_vel - modes.g1_vel(r);
    }
  }
  return modes;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
