// Ride comfort of a time series of acceleration: ISO 2631-1:1997 frequency weighting, weighted
// r.m.s., vibration dose value, running r.m.s. / MTVV and (optionally) absorbed power, both in
// batch (evaluateComfort) and online, one sample at a time (ComfortMeter, e.g. at 1 kHz).
//
// Weightings (ISO 2631-1:1997, Annex A), s = j 2π f:
//   band limiting   H_h = s^2 / (s^2 + ω1 s / Q1 + ω1^2)            high-pass, Q1 = 1/√2
//                   H_l = ω2^2 / (s^2 + ω2 s / Q1 + ω2^2)            low-pass (Butterworth)
//   a-v transition  H_t = (1 + s / ω3) / (1 + s / (Q4 ω4) + s^2 / ω4^2)
//   upward step     H_s = (s^2 + ω5 s / Q5 + ω5^2) / (s^2 + ω6 s / Q6 + ω6^2)
//   W = H_h H_l H_t H_s, ωi = 2π fi, with
//     Wk (vertical, z):   f1 0.4, f2 100, f3 12.5, f4 12.5, Q4 0.63, f5 2.37, Q5 0.91,
//                         f6 3.35, Q6 0.91 Hz
//     Wd (horizontal):    f1 0.4, f2 100, f3 2.0, f4 2.0, Q4 0.63, no upward step
//     We (rotational):    f1 0.4, f2 100, f3 1.0, f4 1.0, Q4 0.63, no upward step
// (|Wk| = 0.482 at 1 Hz and 1.054 at 6.3 Hz, |We| = 0.880 at 1 Hz, as in the standard's
// one-third-octave tables.) We weights an angular acceleration [rad/s^2]; above 1 Hz it falls as
// 1/f, so it rates the angular velocity.
//
// Discretisation (Discretisation, per second-order section; fs the sample rate, T = 1/fs):
//   MatchedMagnitude (default)  poles mapped exactly, z = exp(p T); the numerator (always of
//       degree 2, with the analogue section's zeros at s = 0 kept as zeros at z = 1) is fitted to
//       |H(j2πf)| by relative least squares on a log grid up to fs/2 (weighted down above fs/4),
//       in the squared-magnitude form
//         |B|^2 = A0 cos^2(ω/2) + A1 sin^2(ω/2) + A2 4 cos^2(ω/2) sin^2(ω/2),   ω = 2π f T,
//       linear in
//       A0 = (b0 + b1 + b2)^2, A1 = (b0 - b1 + b2)^2, A2 = -4 b0 b2 (M. Vicanek, "Matched
//       second order digital filters", 2016); the larger root b0 keeps the zeros minimum-phase.
//       A section of two finite zeros as well as two poles, all below fs/12.6 (Wk's upward step
//       from fs ≈ 42 Hz: its poles have |p| = ω6 = 21 rad/s), has its zeros mapped exactly too,
//       z = exp(s_z T), and its gain matched at DC: the fit cannot place zeros whose radius
//       differs from 1 by 2 zeta omega T ~ 1e-4 (at 100 kHz it weighted 8 Hz 11 dB low), while
//       the matched z-transform of equal degrees is within 0.002 dB of this section up to fs/10,
//       1e-5 dB from 1 kHz.
//       For fs from 30 Hz to 100 kHz: within 0.01 dB of |W| up to fs/10 (test_comfort.cpp checks
//       0.1 dB) and 0.05 dB up to fs/4 (0.3 dB for 150 < fs < 250 Hz, from the omitted low-pass
//       below); about 1.5 dB off near Nyquist, where |W| is below -30 dB for fs >= 250 Hz. The
//       phase is the analogue phase plus a time advance of about one sample (0.57 samples at fs =
//       100 Hz, 1.1 at 1 kHz, 1.2 at 5 kHz, up to 2.7 at 100 kHz), constant to 1 degree over the
//       standard's 0.5..80 Hz band (below fs/10): a pure time shift, which none of the metrics
//       below sees.
//   BilinearPrewarped  s = K (1 - z^-1) / (1 + z^-1), K = ω_p / tan(ω_p T / 2), each section
//       pre-warped at its own corner (f1, f2, f4, sqrt(f5 f6)). Exact at the corners, but the
//       frequency axis is compressed by about (π f / fs)^2 / 3 elsewhere: on Wk's -20 dB/decade
//       flank that is 0.27 dB at f = fs/10 for fs = 1 kHz (0.85 dB at 5 kHz, with the low-pass
//       flank), so it meets 0.1 dB only up to about fs/30.
// When f2 > 0.4 fs (fs < 250 Hz) the 100 Hz band-limiting low-pass is left out: its poles lie
// near or above Nyquist, and below fs/10 it changes |W| by less than 0.01 dB.
//
// Metrics of the weighted acceleration a_w(t), sampled at fs over T = N / fs (ISO 2631-1, 6):
//   weighted r.m.s.   a_w,rms = sqrt(1/N Σ a_w^2)                        [m/s^2]
//   VDV               (Σ a_w^4 / fs)^(1/4)                                [m/s^1.75]
//   running r.m.s.    a_w(t0) = sqrt(1/τ ∫ a_w^2(t) exp((t - t0)/τ) dt),  τ = 1 s by default,
//                     as ms_k = (1 - α) ms_{k-1} + α a_w,k^2, α = 1 - exp(-1/(fs τ))
//   MTVV              max over t0 of the running r.m.s.                   [m/s^2]
//   MTVV (linear)     the same of the linear running r.m.s., the mean of the last τ fs
//                     squares (6.3.1's other form, running_window.h)     [m/s^2]
//   peak              max |a_w|                                           [m/s^2]
// and, from these, when the basic method (a_w,rms alone) suffices (BasicMethodRatios):
//   crest factor   peak / a_w,rms            basic method normally sufficient up to 9 (6.2.1)
//   MTVV ratio     MTVV / a_w,rms            additional methods to report above 1.5 (6.3.3);
//                  the standard allows either running r.m.s., so both ratios are tested
//   VDV ratio      VDV / (a_w,rms T^(1/4))   the same above 1.75 (6.3.3)
// (A steady sinusoid gives √2, sqrt(1 + G) ≈ 1 with G the running mean square's ripple at
// twice its frequency, and (3/2)^(1/4) = 1.107.)
//
// Absorbed power (Pradko, Lee & Kaluza, "Theory of human vibration response", ASME 66-WA/BHF-15,
// 1966; Lee & Pradko, "Analytical analysis of human vibration", SAE 680091, 1968) is defined in the
// frequency domain as P = Σ_i K(f_i) a_rms(f_i)^2, K(f) [W/(m/s^2)^2] the vertical absorbed-power
// coefficient; the US Army's mobility models rate a vehicle's ride by the speed at which the
// driver absorbs 6 W. It is computed here in the time domain: the acceleration passes through a
// filter H_p with |H_p(j2πf)|^2 = K(f), and P = mean(z^2) [W] — the same quantity for any signal,
// and the form that runs online.
// The built-in H_p (absorbedPowerVerticalSections) is the vertical filter of Project Chrono
// (projectchrono/chrono, src/chrono/utils/ChFilters.cpp, ChAbsorbed_Power_Vertical, BSD-3; used by
// its "6 W absorbed power speed" tool). Chrono states it as a Tustin-discretised difference
// equation for acceleration in ft/s^2; undoing the bilinear transform gives the analogue
//   H_p(s) = 14.5 s (s + 44) / ((s + 63)(s^2 + 24 s + 750))     [sqrt(W) / (ft/s^2)]
// (zeros 0 and -44 rad/s, poles -63 and -12 ± 24.6j rad/s: a band-pass peaking at 4.5 Hz, where
// K = 0.208 W/(ft/s^2)^2 = 216 W/g^2). Chrono does not say which of the published forms it
// transcribes; test_comfort.cpp checks that the sections below reproduce its coefficients.
// The caller may supply another H_p as analogue sections (ComfortOptions::absorbed_power, in units
// of sqrt(W)/(m/s^2)).
#pragma once

#include <complex>
#include <cstddef>
#include <optional>
#include <vector>

#include "tracked_vehicle_dynamics/dynamics/running_window.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// H(s) = (b0 + b1 s + b2 s^2) / (a0 + a1 s + a2 s^2), s in [rad/s]; poles in the open left
/// half-plane.
struct AnalogSection {
  double b0 = 1.0, b1 = 0.0, b2 = 0.0;
  double a0 = 1.0, a1 = 0.0, a2 = 0.0;
  /// Discretisation::BilinearPrewarped only: the frequency [Hz] at which the discretised section
  /// matches H exactly; 0 = plain bilinear (K = 2 fs). Must be below fs / 2.
  double prewarp_frequency = 0.0;
};

/// How analogue sections become digital biquads (see the file comment).
enum class Discretisation {
  MatchedMagnitude,   ///< exact poles, least-squares magnitude-matched zeros
  BilinearPrewarped,  ///< bilinear transform, pre-warped at each section's corner
};

/// ISO 2631-1 frequency weightings.
enum class Weighting {
  Wk,  ///< vertical (z) at the seat surface, comfort and health
  Wd,  ///< horizontal (x, y) at the seat surface
  We,  ///< rotational (roll, pitch, yaw) at the seat surface, comfort
};

/// Corner frequencies [Hz] and quality factors of an ISO 2631-1 weighting; f5 = f6 = infinity
/// when it has no upward step.
struct Iso2631Parameters {
  double f1, f2, f3, f4, q4, f5, q5, f6, q6;
};

Iso2631Parameters iso2631Parameters(Weighting weighting);
/// The standard's analogue sections: high-pass, low-pass, transition[, upward step].
std::vector<AnalogSection> iso2631Sections(Weighting weighting);
/// The standard's analogue W(j 2π f) at frequency f [Hz].
std::complex<double> iso2631Response(Weighting weighting, double frequency);
/// The built-in vertical absorbed-power filter H_p (file comment) for acceleration in m/s^2:
/// |H_p(j2πf)|^2 = K(f) [W/(m/s^2)^2]. Two sections: s (s + 44) / (s^2 + 24 s + 750) with the
/// gain, and 1 / (s + 63).
std::vector<AnalogSection> absorbedPowerVerticalSections();
/// Product of the sections' analogue responses at frequency f [Hz].
std::complex<double> analogResponse(const std::vector<AnalogSection>& sections, double frequency);

/// A cascade of analogue sections discretised section by section, run as direct-form-II-
/// transposed biquads.
class WeightingFilter {
 public:
  /// sample_rate [Hz] > 0. Throws InputError (naming the section index) when the sample rate is
  /// not positive and finite, a coefficient is not finite, the numerator is zero, a pole is not
  /// in the open left half-plane or (MatchedMagnitude) oscillates at or above fs / 2, or
  /// (BilinearPrewarped) the pre-warping frequency is negative or not below fs / 2.
  WeightingFilter(std::vector<AnalogSection> sections, double sample_rate,
                  Discretisation discretisation = Discretisation::MatchedMagnitude);
  /// The ISO 2631-1 weighting at sample_rate [Hz]. Throws InputError when sample_rate is not
  /// above 2 f4 (and 2 sqrt(f5 f6)) of the weighting: Wk needs > 25 Hz, Wd > 4 Hz,
  /// We > 2 Hz.
  static WeightingFilter iso2631(Weighting weighting, double sample_rate,
                                 Discretisation discretisation = Discretisation::MatchedMagnitude);

  /// Filters one sample, advancing the state.
  double step(double input);
  /// Filters a whole series from rest; the object's own state is untouched.
  Vector filter(const Vector& input) const;
  /// Back to rest (zero state).
  void reset();

  /// The discrete response H(exp(j 2π f / fs)) at frequency f [Hz].
  std::complex<double> response(double frequency) const;
  /// The response of the analogue sections it discretises, at frequency f [Hz].
  std::complex<double> analogResponse(double frequency) const;
  const std::vector<AnalogSection>& sections() const { return sections_; }

 private:
  struct Biquad {
    double b0, b1, b2, a1, a2;  // a0 normalised to 1
    double s1 = 0.0, s2 = 0.0;  // DF-II-T state
    double step(double x);
  };

  static Biquad bilinear(const AnalogSection& section, double sample_rate);
  static Biquad matchedMagnitude(const AnalogSection& section, double sample_rate);

  std::vector<AnalogSection> sections_;
  std::vector<Biquad> biquads_;
  double sample_rate_;
};

/// What evaluateComfort and ComfortMeter measure.
struct ComfortOptions {
  Weighting weighting = Weighting::Wk;
  Discretisation discretisation = Discretisation::MatchedMagnitude;
  /// Integration time τ of the running r.m.s. [s] (ISO 2631-1 recommends 1 s), > 0.
  double running_rms_time = 1.0;
  /// Absorbed-power filter H_p, |H_p(j2πf)|^2 = K(f) [W/(m/s^2)^2] (see the file comment);
  /// empty: absorbed power is not computed.
  std::vector<AnalogSection> absorbed_power;
};

struct ComfortMetrics {
  double weighted_rms = 0.0;             ///< a_w,rms [m/s^2]
  double vdv = 0.0;                      ///< vibration dose value [m/s^1.75]
  double mtvv = 0.0;                     ///< maximum transient vibration value [m/s^2]
  double mtvv_linear = 0.0;              ///< the same by linear integration over τ [m/s^2]
  double peak_weighted = 0.0;            ///< max |a_w| [m/s^2]
  std::optional<double> absorbed_power;  ///< [W], when ComfortOptions::absorbed_power is set
  double duration = 0.0;                 ///< N / fs [s]
  std::size_t samples = 0;
};

/// ISO 2631-1:1997 (8.2, seated comfort) rotational multiplying factors at the supporting seat
/// surface [m/rad]: roll (rx), pitch (ry), yaw (rz).
struct SeatRotationFactors {
  static constexpr double roll = 0.63;
  static constexpr double pitch = 0.40;
  static constexpr double yaw = 0.20;
};

/// Vibration total value of the seat surface's translations (ISO 2631-1 8.2.3, comfort,
/// k_x = k_y = k_z = 1): a_v = sqrt(a_wx^2 + a_wy^2 + a_wz^2) [m/s^2] of the Wd, Wd, Wk weighted
/// r.m.s. values [m/s^2].
double seatTranslationalTotalValue(double x, double y, double z);
/// The same of its rotations: a_r = sqrt((0.63 a_wrx)^2 + (0.40 a_wry)^2 + (0.20 a_wrz)^2)
/// [m/s^2] of the We weighted r.m.s. roll, pitch and yaw accelerations [rad/s^2].
double seatRotationalTotalValue(double roll, double pitch, double yaw);

/// ISO 2631-1:1997's tests of whether the weighted r.m.s. alone describes a signal (6.2.1,
/// 6.3.3): when the signal carries shocks or transients, the standard asks for the VDV or the
/// MTVV to be reported beside a_w,rms. All 0 (and sufficient) for a_w,rms = 0.
struct BasicMethodRatios {
  static constexpr double kMaxCrestFactor = 9.0;  ///< 6.2.1
  static constexpr double kMaxMtvvRatio = 1.5;    ///< 6.3.3, eq. (8)
  static constexpr double kMaxVdvRatio = 1.75;    ///< 6.3.3, eq. (9)
  double crest_factor = 0.0;                      ///< peak |a_w| / a_w,rms
  double mtvv_ratio = 0.0;                        ///< MTVV / a_w,rms
  double mtvv_linear_ratio = 0.0;                 ///< MTVV (linear) / a_w,rms
  double vdv_ratio = 0.0;                         ///< VDV / (a_w,rms T^(1/4))
  /// True when no ratio exceeds its limit: a_w,rms alone is an adequate measure (the MTVV's by
  /// either running r.m.s.: a verdict should not hang on which one the standard let us pick).
  bool basicMethodSufficient() const {
    return crest_factor <= kMaxCrestFactor && mtvv_ratio <= kMaxMtvvRatio &&
           mtvv_linear_ratio <= kMaxMtvvRatio && vdv_ratio <= kMaxVdvRatio;
  }
};
BasicMethodRatios basicMethodRatios(const ComfortMetrics& metrics);

/// Metrics of an acceleration series [m/s^2] sampled at sample_rate [Hz], filters starting at
/// rest; all 0 for an empty series. Throws InputError for a non-finite sample (naming its index),
/// invalid options or sample rate.
ComfortMetrics evaluateComfort(const Vector& acceleration, double sample_rate,
                               const ComfortOptions& options = {});

/// The online form of evaluateComfort: feed one acceleration sample per time step; the getters
/// return the metrics of everything added so far (0 before the first sample). O(1) per sample.
class ComfortMeter {
 public:
  /// sample_rate [Hz]. Throws InputError like evaluateComfort.
  explicit ComfortMeter(double sample_rate, const ComfortOptions& options = {});

  /// Adds one acceleration sample [m/s^2]. Throws InputError if it is not finite (the metrics
  /// are then unchanged).
  void add(double acceleration);
  /// Forgets all samples; filters back to rest.
  void reset();

  double weightedRms() const;                             ///< [m/s^2]
  double vibrationDoseValue() const;                      ///< [m/s^1.75]
  double maximumTransientVibrationValue() const;          ///< MTVV [m/s^2]
  double maximumTransientVibrationValueLinear() const;    ///< MTVV, linear form [m/s^2]
  double peakWeighted() const { return peak_weighted_; }  ///< max |a_w| [m/s^2]
  double runningRms() const;                              ///< running r.m.s. now [m/s^2]
  double lastWeighted() const { return last_weighted_; }  ///< a_w of the last sample [m/s^2]
  std::optional<double> absorbedPower() const;            ///< [W], when configured
  double duration() const;                                ///< [s]
  std::size_t sampleCount() const { return count_; }
  ComfortMetrics metrics() const;

 private:
  WeightingFilter weighting_;
  std::optional<WeightingFilter> absorbed_power_;
  double sample_rate_;
  double running_alpha_;
  std::size_t count_ = 0;
  double sum_squares_ = 0.0;
  double sum_fourth_ = 0.0;
  double sum_power_ = 0.0;
  double running_mean_square_ = 0.0;
  double max_running_mean_square_ = 0.0;
  LinearRunningMeanSquare linear_window_;
  double max_linear_mean_square_ = 0.0;
  double peak_weighted_ = 0.0;
  double last_weighted_ = 0.0;
};

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
