// Exact per-mode discretisation of decoupled modal equations
//
//   eta'' + d eta' + omega^2 eta = p(t)                       (one per mode, d = 2 zeta omega)
//   [eta; eta'][k+1] = Phi_r [eta; eta'][k] + g0_r p[k] + g1_r p[k+1]
//
// Phi_r = e^{A_r h} with A_r = [0 1; -omega^2 -d]; for 0 <= zeta < 1, with
// omega_d = omega sqrt(1 - zeta^2), c = cos(omega_d h), s = sin(omega_d h):
//   Phi_r = e^{-zeta omega h} [c + zeta omega s / omega_d,   s / omega_d;
//                              -omega^2 s / omega_d,          c - zeta omega s / omega_d]
//   zero-order hold:  g0 = A^-1 (Phi - I) [0; 1] = [(1 - phi22 - d phi12) / omega^2;  phi12],
//                     g1 = 0
//   first-order hold: g1 = int_0^h e^{A s} (1 - s/h) ds [0; 1],  g0 = (ZOH g0) - g1.
// These are evaluated, for every regime (under-, critically, over-damped, rigid-body
// omega = 0), by the 4x4 Van Loan exponential of the same mode in the balanced coordinates
// [eta; eta'/s], s = max(omega, 1/h), which keeps the argument norm ~ omega h and is exact to
// rounding; the closed form above is what it reproduces.
#pragma once

#include "tracked_vehicle_dynamics/dynamics/state_space.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

struct DiscreteModes {
  Vector a11, a12, a21, a22;  ///< Phi_r entries per mode [n_modes]
  Vector g0_disp, g0_vel;     ///< g0_r: weights of p[k]
  Vector g1_disp, g1_vel;     ///< g1_r: weights of p[k+1] (zero for a zero-order hold)
  double sample_time = 0.0;   ///< h [s]
  InputHold hold = InputHold::ZeroOrder;

  DofIndex modeCount() const { return a11.size(); }
};

/// omega [rad/s] >= 0 and d [1/s] >= 0 per mode (same length), dt [s] > 0.
/// Throws InputError for mismatched lengths, negative or non-finite values, or dt <= 0.
DiscreteModes discretizeModes(const Vector& frequencies, const Vector& damping_coefficients,
                              double dt, InputHold hold = InputHold::ZeroOrder);

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
