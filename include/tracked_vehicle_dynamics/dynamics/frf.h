// Comfort frequency response functions per unit road height h (paper §4.1, eqs. 18-25).
//
// With u = tau h e^{j omega t} (tau from InputDelay) and q = x e^{j omega t}:
//   direct (eq. 18):  (-omega^2 M + j omega C + K) x = (j omega C_u + K_u) tau
//   modal (eqs. 19-20): x = sum_r phi_r phi_r^T F / (omega_r^2 + 2 j zeta_r omega_r omega
//                                                    - omega^2),
//                       F = (j omega C_u + K_u) tau
//   outputs: displacement H x [m/m], velocity j omega H x [(m/s)/m],
//            acceleration -omega^2 H x [(m/s^2)/m] (eq. 25).
// Results are complex matrices [n_frequencies x n_outputs], columns in the order of the rows of
// H. The modal form is exact for proportional damping and the modal damping approximation
// otherwise (see ModalSystem).
#pragma once

#include "tracked_vehicle_dynamics/dynamics/input_delay.h"
#include "tracked_vehicle_dynamics/dynamics/modal_system.h"
#include "tracked_vehicle_dynamics/dynamics/output_layout.h"
#include "tracked_vehicle_dynamics/dynamics/second_order_system.h"
#include "tracked_vehicle_dynamics/dynamics/sparse_second_order_system.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// Direct solution of eq. 18 with a dense complex LU per frequency (O(n^3) each): the reference
/// for reduced models. frequencies_hz [Hz] >= 0.
/// Throws InputError for inconsistent sizes or negative frequencies, SolverError when the
/// dynamic stiffness is singular at a frequency (undamped resonance), naming that frequency.
ComplexMatrix frfDirect(const SecondOrderSystem& system, const Vector& frequencies_hz,
                        const InputDelay& delay,
                        OutputQuantity quantity = OutputQuantity::Acceleration);

/// Same for a large sparse (full) model with Eigen::SparseLU: the pattern is analysed once, the
/// values factorised per frequency. Throws as above.
ComplexMatrix frfDirect(const SparseSecondOrderSystem& system, const Vector& frequencies_hz,
                        const InputDelay& delay,
                        OutputQuantity quantity = OutputQuantity::Acceleration);

/// Modal superposition (eq. 20) over all modes of `modal`: O(n (n_inputs + n_outputs)) per
/// frequency. Exact for proportional damping; with discrete dampers it keeps only the diagonal of
/// Phi^T C Phi (modal.maxOffDiagonalDampingRatio() says how much is dropped): frfExact()
/// (frf_state_space.h) chooses for you. Throws InputError for negative frequencies or a delay of
/// the wrong size, SolverError for 0 Hz on the grid of a system with a rigid-body mode (its term is
/// 0/0 there).
ComplexMatrix frfModal(const ModalSystem& modal, const Vector& frequencies_hz,
                       const InputDelay& delay,
                       OutputQuantity quantity = OutputQuantity::Acceleration);

/// Convenience: builds the ModalSystem (damping_ratios zeta_r, empty = from C) and calls the
/// above. Throws as ModalSystem and frfModal do.
ComplexMatrix frfModal(const SecondOrderSystem& system, const Vector& frequencies_hz,
                       const InputDelay& delay,
                       OutputQuantity quantity = OutputQuantity::Acceleration,
                       const Vector& damping_ratios = Vector());

/// |FRF| entry by entry.
Matrix magnitude(const ComplexMatrix& frf);
/// arg(FRF) [rad] entry by entry, in (-pi, pi].
Matrix phase(const ComplexMatrix& frf);

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
