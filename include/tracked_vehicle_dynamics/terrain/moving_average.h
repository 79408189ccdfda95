// Centred moving average of a sampled road profile (paper §4.2.1: "a centered spatial moving
// average on 0.2 m track length is implemented to avoid removable discontinuity").
//
//   h_s(x) = (1/W) ∫_{x-W/2}^{x+W/2} h(ξ) dξ
//
// evaluated exactly for the piecewise-linear interpolant of the samples, with the edge values
// held beyond both ends (flat run-in/run-out, as Terrain does). When W/spacing is an even integer
// this is the trapezoidal moving average over W/spacing + 1 samples. Being exact, it keeps the
// closed forms: a linear stretch is unchanged, a corner of slope change s becomes the parabola
// h_s = s (x - x_c + W/2)^2 / (2 W) for |x - x_c| < W/2 (s W / 8 at the corner), and a sinusoid of
// wavelength λ is scaled by sin(π W / λ) / (π W / λ).
#pragma once

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace terrain {

/// Smooths `samples` (spacing [m] apart) with a centred window of `window` [m]; window 0 returns
/// the samples unchanged. Throws InputError for spacing <= 0, window < 0, non-finite arguments
/// or samples (naming the sample index).
Vector movingAverage(const Vector& samples, double spacing, double window);

/// movingAverage() applied to each row of `rows` (one profile per row, e.g. Terrain::heights()).
Matrix movingAverageRows(const Matrix& rows, double spacing, double window);

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
