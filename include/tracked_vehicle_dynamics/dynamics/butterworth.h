// Butterworth low-pass filters as analogue sections (comfort.h: AnalogSection), for the peak
// acceleration of obstacle-crossing (shock_meter.h) and wherever a signal must be band-limited
// before its peak is read.
//
// An n-th order Butterworth low-pass of corner ω_c = 2π f_c has its poles evenly spaced on the
// circle |s| = ω_c in the left half-plane, s_k = ω_c (-sin φ_k ± j cos φ_k), at angles
// φ_k = π (2k - 1) / (2n) from the imaginary axis. Pairing conjugate poles gives, for
// k = 1 .. ⌊n/2⌋, the sections
//   H_k(s) = ω_c^2 / (s^2 + 2 sin(φ_k) ω_c s + ω_c^2),   φ_k = π (2k - 1) / (2n),
// (quality factor Q_k = 1 / (2 sin φ_k): 0.541 and 1.307 for n = 4), and for odd n the real pole
//   H_0(s) = ω_c / (s + ω_c).
// Their product has |H(j ω)|^2 = 1 / (1 + (ω / ω_c)^(2n)): -3.01 dB at f_c for every order.
// Every section is marked for pre-warping at f_c (AnalogSection::prewarp_frequency), so that
// with Discretisation::BilinearPrewarped the digital filter is the textbook digital Butterworth
// (as scipy.signal.butter designs it): exactly -3.01 dB at f_c, a zero at the Nyquist frequency.
#pragma once

#include <vector>

#include "tracked_vehicle_dynamics/dynamics/comfort.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// The sections of an order-`order` Butterworth low-pass with corner `corner_hz` [Hz]: ⌊n/2⌋
/// second-order sections, then one first-order section for odd n, each pre-warped at the corner.
/// Throws InputError when the order is not in 1..12 or the corner is not positive and finite.
std::vector<AnalogSection> butterworthLowPass(int order, double corner_hz);

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
