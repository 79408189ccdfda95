// Refinement of the low modes of a dense generalised eigen-solve (K phi = lambda M phi) of a
// structure held to ground, whose eigenvalues span more decades than the dense solver resolves.
//
// The dense solver (Cholesky of M, then a symmetric tridiagonal QR) has an absolute eigenvalue
// error of a few n eps lambda_max. A vehicle on stiff ties spans more decades than that
// resolves: ground springs of 9e14 N/m under pads of a few hundred grams give lambda_max ~ 1e15
// rad^2/s^2, and its 0.7 Hz chain modes (omega^2 = 18) came out within a few rad^2/s^2, below
// 1e-12 lambda_max, so they were taken for rigid-body modes and the hull drifted off on flat road
// (review 157). Their shapes are as loose: two low modes r, s mix by about
// eps lambda_max / |lambda_r - lambda_s|, 1e-5 on a light vehicle's 0.17 and 0.45 Hz modes, so
// two solves of one (K, M) disagree by that much (review 164: the modal damping built on one
// solve looked coupled, 1.9e-5, in the other's modes).
#pragma once

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace fem {

/// Modes below this fraction of lambda_max are refined: the dense solver gives them to an
/// absolute n eps lambda_max, a relative error of 1e-8 and more below it (400 coordinates).
constexpr double kRefineBelow = 1e-6;
/// K_ii / (Cholesky pivot)^2 above this: a near-mechanism (a free body's rigid motion survives
/// the factorisation as a pivot of rounding size), not a structure held to ground; the modes
/// are then left as the dense solver gives them. Nastran's MAXRATIO warns at 1e7.
constexpr double kMaxPivotRatio = 1e10;

/// `lambda` (ascending) and `shapes` (M-normalised columns) of a dense solve of (K, M), both
/// symmetric. When K is positive definite (held to ground), inverse subspace iteration gives the
/// modes below kRefineBelow max |lambda| to their own relative accuracy: with K = L L^T,
/// accurate on such graded matrices (the stiff ties sit on the diagonal), X' = K^-1 M X and the
/// Rayleigh-Ritz pair
///   K_p = X'^T (M X) (= X'^T K X' with no product by K, whose cancellation is the error),
///   M_p = X'^T M X',
/// and the higher modes are made M-orthogonal to the refined ones again. Returns whether the
/// low modes were refined (then none is rigid); false leaves both unchanged (no mode that low,
/// every mode that low, K not positive definite or a near-mechanism).
bool refineLowModes(const Matrix& stiffness, const Matrix& mass, Vector* lambda, Matrix* shapes);

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
