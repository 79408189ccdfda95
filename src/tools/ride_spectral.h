// `tvd ride --iso8608 CLASS`: the ride-limiting speed by the spectral method
// (dynamics/spectral_ride.h) instead of a time-domain run over a terrain.
#pragma once

#include "ride_options.h"

namespace tracked_vehicle_dynamics {
namespace tools {

/// The absorbed-power limit speed of every chosen point on the PSD of the ISO 8608 class
/// `opt.iso_class`: each speed of the sweep and of the bisection evaluated spectrally, one modal
/// system for all. Prints the table (or --json) and writes --out. Throws InputError for bad
/// options (before the model is reduced or loaded).
void runSpectralRide(const RideOptions& opt);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
