// Sums of harmonics on a regular grid by the chirp z-transform (Bluestein's algorithm).
//
// A random road (iso8608.h) is h(x_j) = Σ_k a_k cos(2π k Δn x_j + φ_k) at x_j = j s: with
// r = s Δn (spacing over road length) it is the real part of
//   H_j = Σ_{k=k0}^{k0+K-1} c_k e^{i 2π r k j},   c_k = a_k e^{i φ_k},   j = 0 .. N-1,
// a DFT-like sum at a frequency step r that need not be 1/N (a road length that is not a whole
// number of spacings). Summed term by term it costs N K cosines: 3.8e9 for 2.6 km at 5 mm, over a
// minute. With 2 k j = k^2 + j^2 - (j - k)^2 it is a convolution with a chirp,
//   H_j = w_j Σ_k (c_k w_k) conj(w_{j-k}),   w_m = e^{i π r m^2},
// done by FFTs of a power-of-two size P >= N + K - 1: O(P log P).
#pragma once

#include <complex>
#include <vector>

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace terrain {

/// Re Σ_{p=0}^{K-1} c[p] e^{i 2π r (first + p) j} for j = 0 .. count-1, by the chirp
/// z-transform: the same as the term-by-term sum to round-off of order 1e-15 Σ|c_p| (the chirp
/// phases are reduced exactly, so long roads lose nothing to phase growth). Requires count >= 1,
/// first >= 0 and |r| <= 1 (std::invalid_argument otherwise); an empty c gives zeros.
Vector harmonicSum(const std::vector<std::complex<double>>& c, long long first, double r,
                   Eigen::Index count);

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
