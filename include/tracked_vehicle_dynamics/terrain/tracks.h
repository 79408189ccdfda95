// The three test tracks of the paper, §4.2.1 (inspired by the CePoliSpe tracks at Montelibretti):
// 30 m long, 5 m wide, flat at entry and exit, sampled every 0.01 m and smoothed by a centred
// 0.2 m moving average (moving_average.h). Where the paper leaves a dimension open the choice is
// fixed here (constants below) and explained:
//
//  long_hill        0.4 m high, 10 m long including 1 m linear ramps in and out. The paper does
//                   not place it; it is centred on the track: ramp up x = 10..11 m, plateau
//                   11..19 m, ramp down 19..20 m, i.e. 10 m of flat run-in and run-out.
//                   Uniform across the width.
//  separated_waves  10 full periods of a sinusoid of 1.8 m wavelength and 0.15 m "depth", read as
//                   peak-to-trough and as hollows below the ground:
//                     h = -(D/2) (1 - cos(2π (x - x0) / λ)),  x0 = 6 m .. x0 + 18 m (centred).
//                   The (1 - cos) form starts and ends at ground level with zero slope, so the
//                   waves join the flat sections without a kink. Uniform across the width.
//  oop_waves        "Svergolatelai": 10 periods of a sinusoid of 1.2 m wavelength, 0.6 m depth
//                   (peak-to-trough), left and right halves in opposite phase. The paper's Fig. 17
//                   shows inner and outer pad rows at different heights, so the amplitude varies
//                   across the width; here linearly with y (a twisted ruled surface):
//                     h = (D/2) (y_t / (W/2)) sin(2π (x - x0) / λ),  x0 = 9 m .. x0 + 12 m,
//                   y_t the lateral position on the track. It is zero-mean across the width, so a
//                   centred vehicle sees pure roll (torsion); the paper's 1 m lateral offset (the
//                   "Y+ offset" of Fig. 17c: towards +y, the left) adds heave, as the paper says.
//
// Lateral offset: the returned Terrain is expressed in the vehicle path frame, in which the
// vehicle centreline drives along y = 0: y = y_t - offset. The offset is a TrackOptions field;
// it defaults to kOopWavesLateralOffset for oop_waves and to 0 for the other tracks.
//
// Smoothing scales a sinusoid by sinc(W/λ) = sin(πW/λ)/(πW/λ): the smoothed waves are 0.98 (1.8 m)
// and 0.955 (1.2 m) of the nominal depth. This follows the paper's procedure (sample, then
// smooth) and is not compensated.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/terrain/terrain.h"

namespace tracked_vehicle_dynamics {
namespace terrain {

constexpr double kTrackLength = 30.0;          ///< [m]
constexpr double kTrackWidth = 5.0;            ///< [m], centred on y_t = 0
constexpr double kTrackSpacing = 0.01;         ///< sampling step [m]
constexpr double kTrackSmoothingWindow = 0.2;  ///< centred moving average [m]
constexpr double kTrackLateralSpacing = 0.5;   ///< spacing of the lateral lines [m]

constexpr double kLongHillHeight = 0.4;   ///< [m]
constexpr double kLongHillLength = 10.0;  ///< foot to foot, ramps included [m]
constexpr double kLongHillRamp = 1.0;     ///< each linear ramp [m]
constexpr double kLongHillStart = 10.0;   ///< foot of the entry ramp [m]

constexpr double kSeparatedWavesDepth = 0.15;      ///< peak-to-trough [m]
constexpr double kSeparatedWavesWavelength = 1.8;  ///< [m]
constexpr int kSeparatedWavesPeriods = 10;
constexpr double kSeparatedWavesStart = 6.0;  ///< [m]

constexpr double kOopWavesDepth = 0.6;       ///< peak-to-trough at the track edges [m]
constexpr double kOopWavesWavelength = 1.2;  ///< [m]
constexpr int kOopWavesPeriods = 10;
constexpr double kOopWavesStart = 9.0;          ///< [m]
constexpr double kOopWavesLateralOffset = 1.0;  ///< vehicle centreline at y_t = +1 m [m]

/// Sampling of a built-in track; the defaults are the paper's.
struct TrackOptions {
  double spacing = kTrackSpacing;                   ///< station step [m], > 0
  double smoothing_window = kTrackSmoothingWindow;  ///< [m], >= 0 (0: no smoothing)
  double lateral_spacing = kTrackLateralSpacing;    ///< lateral line step [m], > 0
  /// Position of the vehicle centreline on the track, y_t [m] (y left); unset: the track's
  /// default (kOopWavesLateralOffset for oop_waves, 0 otherwise).
  std::optional<double> lateral_offset;
};

/// "long_hill", "separated_waves", "oop_waves".
std::vector<std::string> trackNames();
/// Whether `name` is one of trackNames().
bool isBuiltInTrack(const std::string& name);

/// The named built-in track. Throws InputError for an unknown name (listing the known ones) or
/// invalid options (naming the field).
Terrain makeTrack(const std::string& name, const TrackOptions& options = {});

Terrain makeLongHill(const TrackOptions& options = {});
Terrain makeSeparatedWaves(const TrackOptions& options = {});
Terrain makeOopWaves(const TrackOptions& options = {});

/// The lateral offset [m] makeTrack(name) applies when TrackOptions::lateral_offset is unset.
/// Throws InputError for an unknown name.
double defaultLateralOffset(const std::string& name);

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
