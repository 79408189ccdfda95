// Exact discretisation of a continuous StateSpace with a fixed step h by the augmented matrix
// exponential (Van Loan 1978; drake's DiscreteTimeApproximation). With B' = [B f0] (the constant
// forcing f0 is a input held at 1, exact for both holds):
//
// zero-order hold, w(t) = w[k] on [t_k, t_k+1):
//   exp([A B'; 0 0] h) = [Phi Gamma; 0 I]
//   Phi = e^{A h},  Gamma = int_0^h e^{A s} ds B'
//   z[k+1] = Phi z[k] + Gamma w[k]
//
// first-order (triangle) hold, w(t) linear between w[k] and w[k+1]:
//   exp([A h  B' h  0; 0 0 I; 0 0 0]) = [Phi Gamma Gamma2; 0 I I; 0 0 I]
//   Gamma2 = int_0^h e^{A s} (1 - s/h) ds B'
//   z[k+1] = Phi z[k] + (Gamma - Gamma2) w[k] + Gamma2 w[k+1]
//
// Both are exact (to rounding) for any stiffness: a tyre spring of 2e10 N/m on 30 kg
// (omega h = 26 rad at h = 1 ms) is integrated without any stability limit. The output
// equation y = C z + D w + y0 is unchanged.
#pragma once

#include "tracked_vehicle_dynamics/dynamics/state_space.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// e^X [n x n] by scaling and squaring with a degree-13 Pade approximant (Eigen's
/// MatrixFunctions) after a diagonal balancing X_b = D^-1 X D with D a power-of-two scaling
/// (exact), so that e^X = D e^{X_b} D^-1. Balancing matters here: the state [q; q'] mixes units,
/// and M^-1 K reaches 1e9 s^-2, which would otherwise cost ~20 extra squarings and accuracy.
/// Throws InputError for a non-square or non-finite matrix.
Matrix matrixExponential(const Matrix& x);

/// Discrete system with sample_time = dt [s] and the given hold (equations above); the state is
/// the continuous one (no FOH coordinate shift), outputs and names are copied.
/// Throws InputError when `continuous` is invalid or already discrete, or dt <= 0.
StateSpace discretize(const StateSpace& continuous, double dt,
                      InputHold hold = InputHold::ZeroOrder);

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
