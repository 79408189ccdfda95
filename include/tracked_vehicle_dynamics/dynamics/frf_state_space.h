// Exact FRF of a second-order system whose damping couples its modes (paper eq. 18 with a
// non-proportional C, e.g. discrete arm dampers), in O(n^2) per frequency instead of a dense
// O(n^3) LU: one Hessenberg reduction of the state matrix serves every frequency (Laub,
// "Efficient multivariable frequency response computations", IEEE TAC 26(2), 1981).
//
// In mass-normalised modal coordinates q = Phi eta (Phi^T M Phi = I, Phi^T K Phi = Omega^2):
//   eta'' + D eta' + Omega^2 eta = Phi^T (K_u u + C_u u'),   D = Phi^T C Phi (full, not diagonal)
// and with the state y = [Omega eta; eta'] (both halves in the units of a modal velocity, so
// the state matrix holds omega_r, not omega_r^2: entries up to 3.7e5 rad/s on the tracked model,
// the ground ties, instead of 1.3e11 rad^2/s^2):
//   y' = A y + [0; Phi^T F],   A = [0  Omega; -Omega  -D]
// A = Q H Q^T once (H upper Hessenberg, Q orthogonal); per frequency
//   (j omega I - H) w = Q_2^T Phi^T F(omega),   y = Q w          (Q_2: Q's lower n rows)
// is Gaussian elimination on a Hessenberg matrix (pivoting between adjacent rows), O((2n)^2).
// Outputs: velocity H Phi eta' = (H Phi Q_2) w, acceleration j omega times it, displacement
// H Phi eta with eta_r = y_r / omega_r (a rigid mode's eta_r = eta_r' / (j omega)).
#pragma once

#include "tracked_vehicle_dynamics/dynamics/frf.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// The FRF of `system` with its whole damping C (no modal damping approximation) per unit road
/// amplitude, [n_frequencies x n_outputs] as frfDirect(); `modal` must be ModalSystem(system)
/// (its modes and projections are reused; its modal damping is not). frequencies_hz [Hz] >= 0.
/// Agrees with frfDirect() to about 3e-8 of the largest response (the tracked reduced model
/// with arm dampers; each output to 1e-5 of its own peak, outputs zero by symmetry to round-off
/// of the largest): the reduction's backward error is eps times |A|, whose largest entries are
/// the ground ties' omega_r (3.7e5 rad/s). 6-7x faster than frfDirect() there (bench_frf: 0.3 s
/// for the reduction, 3.4 s for 1001 solves, against 25 s).
/// Throws InputError for negative or non-finite frequencies or a modal system that is not
/// ModalSystem(system) (sizes, outputs and inputs checked), SolverError when j omega I - A is
/// singular to working precision at a frequency (an undamped resonance on the grid, or a
/// rigid-body mode at 0 Hz), naming the frequency.
ComplexMatrix frfStateSpace(const SecondOrderSystem& system, const ModalSystem& modal,
                            const Vector& frequencies_hz, const InputDelay& delay,
                            OutputQuantity quantity = OutputQuantity::Acceleration);

/// The FRF with the whole damping C by the cheaper exact route, what `tvd frf` does: frfModal()
/// when Phi^T C Phi is diagonal to within kModalDampingCouplingTolerance (proportional damping:
/// eq. 20 is then exact), frfStateSpace() when discrete dampers couple the modes (eq. 20 alone
/// was 29 % low at 20 Hz on a vehicle with arm dampers). `modal` must be ModalSystem(system)
/// without damping ratios; `used_modal`, when given, says which route was taken. Throws as the
/// route taken does.
ComplexMatrix frfExact(const SecondOrderSystem& system, const ModalSystem& modal,
                       const Vector& frequencies_hz, const InputDelay& delay,
                       OutputQuantity quantity = OutputQuantity::Acceleration,
                       bool* used_modal = nullptr);

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
