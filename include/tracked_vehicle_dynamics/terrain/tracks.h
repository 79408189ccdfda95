// The three test tracks of the paper, §4.2.1 (inspired by the CePoliSpe tracks at Montelibretti),
// and the NRMM half-round obstacle: 30 m long, 5 m wide, flat at entry and exit, sampled every
// 0.01 m and smoothed by a centred 0.2 m moving average (moving_average.h). Where the paper (or
// NRMM) leaves a dimension open the choice is fixed here (constants below) and explained:
//
//  long_hill        "A 0.4 m tall hill 10 m long with entering and exiting 1 m long linear
//                   ramps": the 10 m is the top, the ramps come on either side (12 m foot to
//                   foot). The paper's Fig. 18 holds the hull still on the hill over 7-12 m of
//                   track location, about 5 m: a 10 m top less the paper vehicle's 4.68 m
//                   between first and last axle leaves 5.32 m; an 8 m top (10 m foot to foot)
//                   would leave 3.32 m. The paper does not place it: ramp up x = 10..11 m, top
//                   11..21 m, ramp down 21..22 m, i.e. 10 m of flat run-in (as the half round's
//                   below) and 8 m of run-out: the rear wheel, 2.34 m behind the reference
//                   station, leaves the hill with the station at 24.34 m, 5.66 m before the end.
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
//  half_round:H     The obstacle of the NATO Reference Mobility Model (NRMM) ride tests, which
//                   rate a vehicle by the speed at which the driver's seat first sees a 2.5 g peak
//                   vertical acceleration driving over it: a half-cylinder of radius H [m] lying
//                   across the whole width (usually 0.1-0.3 m, 4-12 in), on the flat:
//                     h = sqrt(H² - (x - xc)²) for |x - xc| <= H, 0 elsewhere,  xc = 10 m.
//                   Uniform across the width. H is part of the name ("half_round:0.2": a
//                   parameterised built-in track; trackForms() lists it as "half_round:H").
//                   Position: xc = 10 m, where the long hill starts. The run starts with the hull
//                   reference point at x = 0, so the front road wheel (3 l = 2.34 m ahead of it on
//                   the paper vehicle, the hull 7.6 m long) has 10 - H - 2.34 >= 6.6 m of flat
//                   ahead: the vehicle starts in static equilibrium and meets the obstacle
//                   without a transient of its own. The rear wheel leaves it at station
//                   xc + H + 2.34 m (12.64 m at H = 0.3 m), leaving over 17 m to ring down on
//                   the flat: at 10 km/h 6 s, 23 periods of the lowest pitch/bounce mode (3.7 Hz,
//                   un-tracked); there the hull's heave and acceleration over the last 2 m are
//                   0.4 % and 0.2 % of their peaks (un-tracked, H = 0.15 m). The peak
//                   acceleration, the NRMM measure, comes while the wheels cross the obstacle (at
//                   5 to 40 km/h), well inside the run.
//                   Bounds: 0 < H <= kHalfRoundMaxHeight = 1 m. The model is linear: it keeps
//                   every pad on the road (no lift-off) and has no belly contact, so a large H
//                   gives only numbers no vehicle would see: above the ground clearance (0.45 m
//                   on the paper vehicle) a real hull strikes a half-round lying across its whole
//                   width. 1 m keeps a margin above any vehicle's clearance and still refuses a
//                   height given in cm or inches (half_round:20).
//                   Smoothed like the other tracks (below): the model's contacts are pad soles
//                   tied stiffly to the road, each reading the profile at one station (its
//                   centre, by default); the unsmoothed semicircle's vertical tangents at its feet
//                   would drive them with a slope of sqrt(2 H / spacing) over the first sampling
//                   interval (4.5 for H = 0.1 m: a 25 m/s vertical velocity at 20 km/h), where a
//                   real chain's 0.16 m links and rubber pads bridge the foot. The 0.2 m moving
//                   average is the paper's stand-in for that enveloping; on the continuous
//                   profile it conserves the cross-section πH²/2 and lowers the crest to
//                     h_s(xc) = (1/W) ∫_{-W/2}^{W/2} sqrt(H² - u²) du
//                             = [a sqrt(H² - a²) + H² asin(a / H)] / W,  a = min(W/2, H)
//                   (a circular segment; the whole half-disc, πH²/(2W), when H <= W/2), i.e.
//                   0.785 H (π/4) at H = 0.1 m, 0.920 H at 0.15 m, 0.957 H at 0.2 m and
//                   0.981 H at 0.3 m. On the 0.01 m samples the steep feet lose a little of
//                   both (the sampled semicircle misses the sliver under its vertical tangents):
//                   `tvd terrain` gives crests of 0.776 H, 0.919 H, 0.956 H and 0.981 H and
//                   98.8 % of the area at H = 0.1 m (99.6 % at 0.2 m). This is not compensated:
//                   a profile of exact crest height is TrackOptions::smoothing_window = 0 (then
//                   the feet are as steep as above).
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

constexpr double kLongHillHeight = 0.4;  ///< [m]
constexpr double kLongHillTop = 10.0;    ///< the flat top, between the ramps [m]
constexpr double kLongHillRamp = 1.0;    ///< each linear ramp [m]
constexpr double kLongHillStart = 10.0;  ///< foot of the entry ramp [m]
/// Foot to foot, ramps included [m].
constexpr double kLongHillLength = kLongHillTop + 2.0 * kLongHillRamp;

constexpr double kSeparatedWavesDepth = 0.15;      ///< peak-to-trough [m]
constexpr double kSeparatedWavesWavelength = 1.8;  ///< [m]
constexpr int kSeparatedWavesPeriods = 10;
constexpr double kSeparatedWavesStart = 6.0;  ///< [m]

constexpr double kOopWavesDepth = 0.6;       ///< peak-to-trough at the track edges [m]
constexpr double kOopWavesWavelength = 1.2;  ///< [m]
constexpr int kOopWavesPeriods = 10;
constexpr double kOopWavesStart = 9.0;          ///< [m]
constexpr double kOopWavesLateralOffset = 1.0;  ///< vehicle centreline at y_t = +1 m [m]

constexpr double kHalfRoundCentre = 10.0;                ///< crest station xc [m]
constexpr double kHalfRoundMaxHeight = 1.0;              ///< largest radius H accepted [m]
constexpr const char* kHalfRoundPrefix = "half_round:";  ///< a half-round track's name is this + H

/// Sampling of a built-in track; the defaults are the paper's.
struct TrackOptions {
  double spacing = kTrackSpacing;                   ///< station step [m], > 0
  double smoothing_window = kTrackSmoothingWindow;  ///< [m], >= 0 (0: no smoothing)
  double lateral_spacing = kTrackLateralSpacing;    ///< lateral line step [m], > 0
  /// Position of the vehicle centreline on the track, y_t [m] (y left); unset: the track's
  /// default (kOopWavesLateralOffset for oop_waves, 0 otherwise).
  std::optional<double> lateral_offset;
};

/// The built-in tracks of fixed name, each a makeTrack() name as it stands: "long_hill",
/// "separated_waves", "oop_waves".
std::vector<std::string> trackNames();
/// Every built-in track for listings (help, error messages): trackNames() and the parameterised
/// form "half_round:H", which is not itself a track name.
std::vector<std::string> trackForms();
/// Whether `name` is a built-in track: one of trackNames() or a well-formed half-round spec
/// ("half_round:0.2"; halfRoundHeight() does not throw on it).
bool isBuiltInTrack(const std::string& name);
/// Throws InputError unless isBuiltInTrack(name): for a half-round spec the fault in it
/// (halfRoundHeight()), for anything else "unknown track 'NAME'" listing trackForms().
void checkTrackName(const std::string& name);

/// The named built-in track. Throws InputError for an unknown name (listing the known ones), a
/// malformed half-round spec (naming it), or invalid options (naming the field).
Terrain makeTrack(const std::string& name, const TrackOptions& options = {});

Terrain makeLongHill(const TrackOptions& options = {});
Terrain makeSeparatedWaves(const TrackOptions& options = {});
Terrain makeOopWaves(const TrackOptions& options = {});
/// The half-round obstacle of radius `height` [m], named halfRoundName(height). Throws
/// InputError naming that name unless 0 < height <= kHalfRoundMaxHeight.
Terrain makeHalfRound(double height, const TrackOptions& options = {});

/// The obstacle height H [m] of a half-round spec "half_round:H" (H a number of metres spelled as
/// in a terrain file, "0.2" or "2e-1", with nothing before or after it). nullopt when `name` is no
/// half-round spec at all (neither "half_round" nor starting "half_round:"); InputError naming
/// the spec when H is missing, not a number, not finite or outside (0, kHalfRoundMaxHeight].
std::optional<double> halfRoundHeight(const std::string& name);
/// The spec of the half-round track of height H [m]: kHalfRoundPrefix and the shortest decimal
/// that reads back as H ("half_round:0.2"); halfRoundHeight() of it is H exactly.
std::string halfRoundName(double height);

/// The lateral offset [m] makeTrack(name) applies when TrackOptions::lateral_offset is unset.
/// Throws InputError for an unknown name.
double defaultLateralOffset(const std::string& name);

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
