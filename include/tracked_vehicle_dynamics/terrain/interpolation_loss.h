// What linear interpolation between a terrain's stations keeps of a road's spectrum. A simulation
// reads the road between samples dx apart by linear interpolation, i.e. the samples convolved
// with a triangle of base 2 dx, whose transform is sinc^2: a harmonic of n cycles/m keeps
//
//   H(n) = sinc(pi n dx)^2 of its amplitude,  |H|^2 = sinc(pi n dx)^4 of its power (PSD),
//
// sinc(a) = sin(a)/a (plus aliases, which the sampling folds below 1/(2 dx)). At ISO 8608's band
// top, 2.83 cycles/m, 0.17 m keeps 19 % of the PSD and the default 0.05 m 88 %.
#pragma once

namespace tracked_vehicle_dynamics {
namespace terrain {

/// sinc(pi n dx)^4: the share of the power of a harmonic of `cycles_per_m` that linear
/// interpolation between stations `spacing` [m] apart passes on (1 at n dx = 0, 0 at n dx = 1).
double interpolatedPowerShare(double cycles_per_m, double spacing);

/// The largest spacing [m] whose interpolatedPowerShare() at `cycles_per_m` is `share` (in
/// (0, 1)), on the main lobe (n dx < 1): solved by bisection to round-off. 0.8 at 2.83 cycles/m
/// gives 0.0647 m. Throws InputError for a share outside (0, 1) or a non-positive frequency.
double spacingKeepingPowerShare(double cycles_per_m, double share);

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
