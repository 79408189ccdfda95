// Ride on an ISO 8608 random road in the frequency domain (the spectral method): for a linear
// model at constant speed the output PSD follows from the road's PSD and the travelled FRF, with
// no road realisation and no time integration.
//
// Road: one-sided displacement PSD in spatial frequency n [cycles/m] (terrain/iso8608.h)
//   G_d(n) = G_d(n0) (n / n0)^-w  on [n_min, n_max], 0 outside.
// At speed v a profile passes under an input as a time signal of one-sided PSD
//   S_h(f) = G_d(f / v) / v   [m^2/Hz],  f in [v n_min, v n_max]
// (n = f / v, dn = df / v: the same variance ∫ S_h df = ∫ G_d dn).
// Every input q meets a profile feature L_q / v after the front-most input (input_delay.h, the
// wheelbase filter), so the acceleration of output i per unit road height is (frf.h, eq. 20)
//   H_v,i(f) = -ω^2 Σ_r (H Φ)_ir η_r,   η_r = Σ_q (Φ^T K_u + jω Φ^T C_u)_rq τ_q / D_r(ω),
//   τ_q = exp(-jω L_q / v),   D_r = ω_r^2 - ω^2 + j d_r ω,   ω = 2π f.
// Output PSD:
//   Uniform (one profile across the width):           S_a = |H_v|^2 S_h
//   IndependentSides (left y > 0 and right y < 0 profiles uncorrelated, each of PSD G_d; their
//   cross-spectrum is zero, so the two sides' responses add in power):
//                                                      S_a = (|H_v,L|^2 + |H_v,R|^2) S_h
//   H_v,side from that side's inputs only. An input in the centre strip |y| < gap / 2 sees the
//   blend h = w_L h_L + (1 - w_L) h_R, w_L = (y + gap/2) / gap, as terrain::makeIso8608 builds
//   it, and so enters H_v,L with weight w_L and H_v,R with 1 - w_L.
// Metrics of each output (trapezoidal rule in f on the grid below), as ComfortMeter measures them
// in the time domain on a long stationary run:
//   r.m.s. acceleration      a_rms = sqrt(∫ S_a df)                    [m/s^2]
//   ISO 2631-1 weighted      a_w   = sqrt(∫ |W(j2πf)|^2 S_a df)        [m/s^2]  (comfort.h)
//       W = W_k unless SpectralRideOptions::weightings gives the output another (W_d for x and
//       y, W_e for an angular acceleration, whose a_w is then in rad/s^2)
//   absorbed power           P     = ∫ K(f) S_a df,  K = |H_p(j2πf)|^2 [W]      (comfort.h)
// Peaks (the 2.5 g criterion) have no counterpart: a PSD gives the variance of a Gaussian
// response, not the largest value of one road or obstacle.
//
// Grid: log-spaced over [v n_min, v n_max], points_per_decade per decade, both ends included;
// the trapezoid's error falls as the step h = ln(10) / points_per_decade squared. At the default
// 400 per decade (a step of 0.58 %, some 17 points across the half-power band of a 5 %-damped
// resonance) the bundled vehicle's P, a_w and a_rms are within 4.2e-4 (tracked) and 1.6e-4
// (un-tracked) of those on a 100x finer grid, worst over 5-70 km/h, both lateral correlations;
// 4000 per decade: 100x closer. Most of it is the wheelbase filter's ripple of |H_v|^2, period
// v / L in f, which the grid samples 1 / (L h n_max) times per period at the top of the band (12
// for L = 5 m). On the road alone the rule errs by h^2 w (w + 1) / 12 (1.7e-5 for w = 2).
// A resonance with ζ near or below h (its half-power band spans about two steps or fewer) would
// be integrated up to 0.4 % wrong at ζ = h, 9 % at h/2, 25 % at h/3, with a sign that changes with
// speed, and a band end cutting a peak costs a few % too; grid() gives such a mode (ζ < 1.5 h, or
// ζ < 5 h with a band end within f_r (1 ± 5ζ)) points of its own (33 evenly across
// f_r (1 ± 2ζ), then geometrically, 2 % farther each, out to f_r (1 ± max(10h, 10ζ))), which bring
// the error
// under 5e-4 of the band's integral for any ζ > 0.
// Cost per speed: the modal forces of a block of frequencies come from one real matrix product,
// [Φ^T K_u | Φ^T C_u] (inputs grouped: those at one station and on one side share τ and are summed
// once, at construction: the tracked model's 360 inputs lie at 30 stations) times [Re τ, Im τ;
// -ω Im τ, ω Re τ]. On the tracked reduced model (431 DOFs): 5 ms per speed, 11 ms with
// independent sides, after 0.1 s for the modes.
//
// Damping that couples the modes (discrete arm dampers: D = Φ^T C Φ not diagonal) is taken whole
// when given (the constructor's modal_damping): η then comes from the complex modes of the
// first-order form, with y = [Ω η; η'] (both halves modal velocities, as frf_state_space.h):
//   y' = A y + [0; F],   A = [0 Ω; -Ω -D] = V Λ V^-1,   z = V^-1 y,
//   z_i = (V^-1 [0; I] F)_i / (jω - λ_i),   η' = V_2 z (V_2: V's lower n rows),
//   H_v = jω H Φ η' = jω (H Φ V_2) z,
// which is eq. 18, exactly, for any A with independent eigenvectors (a damped structure's; one
// dense non-symmetric eigen-solve, about 1 s for the tracked model's 862 states, then the same
// products per frequency with 2n complex modes instead of n real ones).
#pragma once

#include <vector>

#include "tracked_vehicle_dynamics/dynamics/comfort.h"
#include "tracked_vehicle_dynamics/dynamics/input_delay.h"
#include "tracked_vehicle_dynamics/dynamics/modal_system.h"
#include "tracked_vehicle_dynamics/terrain/iso8608.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// An ISO 8608 road as a PSD: the class, its band and slope, and how the two sides relate.
/// Defaults: those of terrain::Iso8608Options, so the PSD is that of `tvd terrain`'s roads.
struct RoadSpectrum {
  char road_class = 'C';                                           ///< 'A'..'H' (either case)
  double min_frequency = terrain::Iso8608Options{}.min_frequency;  ///< n_min [cycles/m]
  double max_frequency = terrain::Iso8608Options{}.max_frequency;  ///< n_max [cycles/m]
  double waviness = terrain::Iso8608Options{}.waviness;            ///< w [-]
  terrain::LateralCorrelation correlation = terrain::LateralCorrelation::Uniform;
  double side_gap = terrain::Iso8608Options{}.side_gap;  ///< centre blending strip [m]
};

/// S_h(f) = G_d(f / v) / v [m^2/Hz] at frequency f [Hz] and speed v [m/s] > 0; 0 outside
/// [v n_min, v n_max]. Throws InputError for an invalid road (class, band, waviness) or speed.
double temporalRoadPsd(const RoadSpectrum& road, double frequency, double speed);

struct SpectralRideOptions {
  static constexpr double kMinPointsPerDecade = 10.0;
  static constexpr double kMaxPointsPerDecade = 1e5;
  /// Grid density [points per decade of frequency], in [kMinPointsPerDecade,
  /// kMaxPointsPerDecade].
  double points_per_decade = 400.0;
  /// Keep the grid and S_a per output in the result (SpectralRideResult::psd).
  bool keep_psd = false;
  /// ISO 2631-1 weighting of each output's a_w, in the order of the output rows; empty: Wk for
  /// every output.
  std::vector<Weighting> weightings;
};

/// Φ^T C Φ [modes x modes] of `system` on the modes of `modal` (ModalSystem(system)): the whole
/// damping in modal coordinates, for SpectralRide. Throws InputError when sizes differ.
Matrix modalDamping(const ModalSystem& modal, const SecondOrderSystem& system);

/// Throws InputError for an invalid road (class A..H, band 0 < n_min < n_max, waviness > 0, side
/// gap > 0 with independent sides) or options (points_per_decade in [10, 1e5], a grid of at most
/// 1e6 points): what SpectralRide checks before it looks at the model.
void checkSpectralInput(const RoadSpectrum& road, const SpectralRideOptions& options);

/// What the spectral method gives at one output.
struct SpectralOutput {
  double rms = 0.0;             ///< a_rms [m/s^2]
  double weighted_rms = 0.0;    ///< a_w, ISO 2631-1, the output's weighting [m/s^2, rad/s^2]
  double absorbed_power = 0.0;  ///< P [W]
};

struct SpectralRideResult {
  double speed = 0.0;                   ///< v [m/s]
  std::vector<SpectralOutput> outputs;  ///< one per output row, in the order given
  /// ∫ S_h df by the same rule on the same grid [m^2]: the band variance of the road up to the
  /// integration error (closed form: terrain::iso8608Variance).
  double road_variance = 0.0;
  Vector frequencies_hz;  ///< the grid [Hz] (when keep_psd)
  Vector road_psd;        ///< S_h on the grid [m^2/Hz] (when keep_psd)
  Matrix psd;             ///< S_a [n_frequencies x n_outputs] [(m/s^2)^2/Hz] (when keep_psd)
};

class SpectralRide {
 public:
  /// modal: the model's modes (built once; nothing of it is kept but the products below), with
  /// its input stations [m] (x forward). input_lateral: y of each input [m] (y left), with any
  /// lateral offset of the path already added. output_rows: rows of the system's H (e.g. the
  /// row of "crew_seat uz"), whose accelerations are rated. Throws InputError for an invalid
  /// road (class, band 0 < n_min < n_max, waviness > 0, side gap > 0 with independent sides),
  /// stations or lateral positions missing or not one per input or not finite, no output row or
  /// one out of range, and as checkSpectralInput.
  /// modal_damping: Φ^T C Φ whole [modes x modes] (modalDamping()); when it couples the modes
  /// (maxOffDiagonalRatio above kModalDampingCouplingTolerance) the response is exact by complex
  /// modes (see above); empty, or diagonal: eq. 20 with `modal`'s damping coefficients. Throws
  /// InputError for a matrix of the wrong size or not finite, SolverError when the eigen-solve
  /// fails or its eigenvectors are not independent to working precision. Throws InputError when
  /// options.weightings is neither empty nor one per output row.
  SpectralRide(const ModalSystem& modal, const Vector& input_lateral,
               const std::vector<DofIndex>& output_rows, const RoadSpectrum& road,
               const SpectralRideOptions& options = {}, const Matrix& modal_damping = Matrix());

  /// The metrics at speed v [m/s]. Throws InputError unless v > 0 and finite, SolverError when
  /// the response is not finite at a frequency of the grid (an undamped mode on it).
  SpectralRideResult evaluate(double speed) const;
  /// Each mode above 0 Hz, by ascending frequency: its natural frequency ω_r / 2π and damping
  /// ratio d_r / (2 ω_r), or with the complex modes, of each conjugate pair λ = -ζω ± jω_d,
  /// ω_d / 2π and -Re λ / |λ|. The log grid (step h = ln(10) / points_per_decade) resolves a
  /// resonance whose half-power band, 2ζ f, spans a few steps; grid() adds points around those
  /// with ζ < 1.5 h, and around those a band end cuts. An undamped one (ζ = 0) has no finite
  /// integral at all.
  struct ModeDamping {
    double frequency_hz = 0.0;
    double ratio = 0.0;
  };
  const std::vector<ModeDamping>& modeDamping() const { return mode_damping_; }

  /// The frequency grid [Hz] at speed v [m/s]: log-spaced over [v n_min, v n_max], with local
  /// points around each resonance the log grid does not resolve (ζ < 1.5 ln(10) /
  /// points_per_decade, or ζ < 5 h with a band end within f_r (1 ± 5ζ); see the file comment),
  /// ascending.
  Vector grid(double speed) const;
  /// Input groups per side after merging inputs that share a station (and side weight).
  std::vector<DofIndex> inputGroupCounts() const;
  const RoadSpectrum& road() const { return road_; }
  /// The same model, sides and modes on the road with its band's top at max_frequency
  /// [cycles/m], with `options`: no second eigen-solve. Throws as the constructor for a band or
  /// options it refuses (weightings included).
  SpectralRide withMaxFrequency(double max_frequency, const SpectralRideOptions& options) const;
  /// True when the damping couples the modes and the complex modes carry the response.
  bool complexModes() const { return complex_modes_; }

 private:
  /// One side's excitation (Uniform: one side, the whole width).
  struct Side {
    Vector lags;   ///< L_g [m] of each input group
    Matrix input;  ///< [modes x 2 G]: [Φ^T K_u W | Φ^T C_u W], W sums a group's columns
    /// Complex modes: Re and Im of V^-1 [0; input] [2 modes x 2 G], apart so that each block
    /// of frequencies costs two real products, not one complex one (four).
    Matrix complex_input_re, complex_input_im;
  };

  /// The complex modes when modal_damping couples the modes (see the constructor); else nothing.
  void setComplexModes(const ModalSystem& modal, const Matrix& modal_damping);
  /// modeDamping()'s list, from the real or the complex modes.
  std::vector<ModeDamping> computeModeDamping() const;
  /// Σ_sides |H_v,side|^2 [grid x outputs] by eq. 20 (real modes) or by the complex modes.
  Matrix realModeGain(const Vector& f, double speed) const;
  /// Throws InputError unless options_.weightings is empty or one per output.
  void checkWeightings() const;
  Matrix complexModeGain(const Vector& f, double speed) const;

  std::vector<Side> sides_;
  Vector omega_squared_;  ///< ω_r^2 [rad^2/s^2]
  Vector damping_;        ///< d_r [1/s]
  Matrix output_;         ///< rows of H Φ [n_outputs x modes]
  bool complex_modes_ = false;
  ComplexVector eigenvalues_;              ///< λ_i of A [2 modes]
  ComplexMatrix complex_output_;           ///< rows of H Φ V_2 [n_outputs x 2 modes]
  std::vector<ModeDamping> mode_damping_;  ///< modeDamping()
  RoadSpectrum road_;
  SpectralRideOptions options_;
};

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
