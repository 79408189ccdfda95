// Random road profiles of ISO 8608:2016 classes A..H by harmonic superposition.
//
// Displacement PSD (one-sided, spatial frequency n [cycles/m]):
//   G_d(n) = G_d(n0) (n / n0)^(-w),   n0 = 0.1 cycles/m, waviness w = 2,
//   G_d(n0) = 16e-6 m^3 for class A (the geometric mean of the class), x4 per class (B = 64e-6,
//   ..., H = 4^7 * 16e-6 m^3).
//
// Profile of length L: harmonics at n_k = k Δn, Δn = 1/L (so the profile is L-periodic and the
// harmonics are orthogonal on [0, L)):
//   h(x) = Σ_k a_k cos(2π n_k x + φ_k),   a_k^2 / 2 = ∫ G_d(n) dn over the bin
//          [n_k - Δn/2, n_k + Δn/2] ∩ [n_min, n_max],
// so the profile variance is exactly ∫ G_d over the generated band [max(n_min, Δn/2), n_max].
// Harmonics at or above the Nyquist frequency 1/(2 spacing) are left out (n_max must not exceed
// it). Phases φ_k are uniform on [0, 2π) from std::mt19937_64(seed), converted with 53 explicit
// bits (not std::uniform_real_distribution, whose algorithm differs between standard libraries),
// so a seed gives the same road everywhere.
//
// Lateral correlation: by default both tracks of the vehicle see the same profile (fully
// correlated, uniform across the width): the worst case for heave and pitch, no roll input.
// IndependentSides draws a second, independent profile for the left half (y > 0).
#pragma once

#include <cstdint>

#include "tracked_vehicle_dynamics/terrain/terrain.h"

namespace tracked_vehicle_dynamics {
namespace terrain {

/// Reference spatial frequency n0 of ISO 8608 [cycles/m].
constexpr double kIso8608ReferenceFrequency = 0.1;

enum class LateralCorrelation {
  /// One profile across the whole width (lines at y = ±W/2).
  Uniform,
  /// Right half (y < 0) and left half (y > 0) independent; lines at ±W/2 and ±side_gap/2
  /// (Iso8608Options::side_gap), the height blends linearly across the centre strip
  /// |y| < side_gap/2.
  IndependentSides,
};

struct Iso8608Options {
  double min_frequency = 0.011;  ///< lowest spatial frequency [cycles/m] (ISO 8608 band)
  double max_frequency = 2.83;   ///< highest spatial frequency [cycles/m] (ISO 8608 band)
  double waviness = 2.0;         ///< w, PSD slope exponent
  LateralCorrelation correlation = LateralCorrelation::Uniform;
  /// Raised-cosine taper over this length at both ends [m]: the road then starts and ends at
  /// h = 0, joining the held flat run-in/run-out without a step. 0 = no taper.
  double taper_length = 0.0;
  /// Width of the centre blending strip of IndependentSides [m].
  double side_gap = 0.1;
};

/// G_d(n0) of a class [m^3]; road_class 'A'..'H' (either case). Throws InputError otherwise.
double iso8608ReferencePsd(char road_class);

/// G_d(n) = G_d(n0) (n / n0)^(-waviness) [m^3] at spatial frequency n > 0 [cycles/m].
/// Throws InputError for an invalid class or n <= 0.
double iso8608Psd(char road_class, double n, double waviness = 2.0);

/// ∫ G_d(n) dn over [n_low, n_high] [m^2], the variance of a profile of that band.
/// Throws InputError for an invalid class or 0 < n_low <= n_high violated.
double iso8608Variance(char road_class, double n_low, double n_high, double waviness = 2.0);

/// A random road of class road_class ('A'..'H'), stations 0, spacing, ..., length [m], lateral
/// lines spanning width [m] centred on y = 0, deterministic for a seed. Throws InputError for an
/// invalid class, length <= 0, width < 0, spacing <= 0 or > length, a band outside
/// (0, 1/(2 spacing)] or empty, waviness <= 0, taper_length < 0 or > length / 2, with
/// IndependentSides a side_gap outside (0, width), and a length and spacing beyond 2e7 stations.
/// Each profile is summed by the chirp z-transform (harmonic_sum.h): O(N log N) in the N stations
/// (2.6 km at 5 mm, 520,001 stations and 7,300 harmonics: `tvd terrain` writes it, CSV and all,
/// in 0.5-1 s).
Terrain makeIso8608(char road_class, double length, double width, double spacing,
                    std::uint64_t seed, const Iso8608Options& options = {});

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
