// Whether a terrain looks like ground a tracked vehicle drives on, or like a unit mistake
// (heights in millimetres read as metres, stations in millimetres read as metres, altitudes where
// heights relative to the start ground are expected). Such terrain still runs: the linear model
// takes any heights, but its small-angle kinematics and bonded ground say nothing true there, so
// the user is told.
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/terrain/terrain.h"
#include "tracked_vehicle_dynamics/terrain/terrain_buffer.h"

namespace tracked_vehicle_dynamics {
namespace terrain {

/// Steepest |dh/dx| taken as ground [m/m]: 2 (63 degrees). The paper's steepest test track,
/// oop_waves (0.6 m deep at 1.2 m wavelength, smoothed over 0.2 m), reaches 1.5; a 10 m bump
/// over a few metres, or a 0.15 m wave written in mm, reaches far beyond.
constexpr double kSteepestPlausibleSlope = 2.0;
/// Coarsest median station spacing taken as a road profile [m]. Road wheels stand 0.5-1 m apart
/// (0.78 m on the paper vehicle) and a track pad is 0.16 m long: a profile sampled every few
/// metres carries no wavelength the running gear responds to. The paper samples every 0.01 m;
/// the same file with stations in mm read as m is sampled every 10 m and 1000 times as long.
constexpr double kCoarsestPlausibleSpacing = 1.0;
/// Largest height step between a patch arriving online and the terrain before it [m]: a vertical
/// obstacle a tracked vehicle climbs is under 1 m. A larger one is almost always altitudes (or a
/// datum change) where heights relative to the start ground are expected.
constexpr double kLargestPlausibleStep = 1.0;

/// The steepest slope of the grid: |h(x_{i+1}) - h(x_i)| / (x_{i+1} - x_i) over every line.
struct SteepestSlope {
  double slope = 0.0;    ///< [m/m], >= 0
  double station = 0.0;  ///< x_i of the interval [m]
  double lateral = 0.0;  ///< the line's y [m]
};
/// stations [n_x] increasing, lateral [n_y], heights [n_y x n_x] (as Terrain's).
SteepestSlope steepestSlope(const Vector& stations, const Vector& lateral, const Matrix& heights);
SteepestSlope steepestSlope(const Terrain& terrain);

/// The median of the station spacings x_{i+1} - x_i [m] (0 for a single station): a flat run-in
/// given by two samples 50 m apart does not make a finely sampled profile coarse.
double medianSpacing(const Vector& stations);

/// A sampled profile: its heights not all equal, and at least kUniformSpacingShare of its
/// spacings within kUniformSpacingTolerance of the median (a survey's jitter of a few per cent
/// included). Not one: a list of breakpoints (a flat run given by its two ends, a step by its
/// corners: spacings of 2, 0.2 and 1.8 m), which describes a piecewise-linear road exactly at any
/// spacing, as the examples in config/tracks do.
constexpr double kUniformSpacingShare = 0.9;
constexpr double kUniformSpacingTolerance = 0.25;
bool isSampledProfile(const Terrain& terrain);
/// A median spacing no road profile has, sampled or by breakpoints [m]: a breakpoint list in mm
/// read as m (the 6 m step profile becomes 6 km long) is still named.
constexpr double kCoarsestPlausibleBreakpoints = 100.0;

/// The warnings to print for a terrain named `name` (the track or file), each starting with the
/// name: a slope beyond kSteepestPlausibleSlope (how steep, where) and a median spacing beyond
/// kCoarsestPlausibleSpacing for a sampled profile (isSampledProfile), beyond
/// kCoarsestPlausibleBreakpoints for any other but a flat one. Empty for ground that looks like
/// ground.
std::vector<std::string> terrainWarnings(const std::string& name, const Terrain& terrain);

/// The same for a patch arriving online (stations start + k spacing, as TerrainBuffer::addPatch
/// takes, already checked by it), plus the step at its first station from the terrain the
/// vehicle reads before it: `buffer` (before the patch is added) where it holds terrain at or
/// before `start`, else, with `flat_ground` (no terrain since a start or reset: the contacts
/// stand on z = 0), the flat ground. A step beyond kLargestPlausibleStep is named with its sign
/// and reference. The texts do not name the patch; the caller does. Safe on any input (a patch
/// addPatch refuses gets no warnings, or ones the caller drops with the patch): call it before
/// the patch is added, since the step is from the terrain without it. `step`, when given,
/// receives the patchStep() it judged (unknown for a patch it does not judge), so a caller that
/// needs the step too does not compute it again.
struct PatchStep;
std::vector<std::string> patchWarnings(double start, double spacing, const Vector& lateral,
                                       const Matrix& heights, const TerrainBuffer& buffer,
                                       bool flat_ground, PatchStep* step = nullptr);

/// The step a contact meets entering a patch (heights [n_y x n_x] on lines `lateral`) at its
/// first station `start`: over the lines j, the largest |h(j, 0) - before_j|, before_j what the
/// buffer reads just before `start` on that line (TerrainBuffer::heightBefore), or 0 with
/// `flat_ground` when the buffer holds nothing at or before `start`.
struct PatchStep {
  bool known = false;      ///< false: nothing to step from (then the rest is 0)
  double step = 0.0;       ///< h(j, 0) - before_j of the largest [m]
  double reference = 0.0;  ///< before_j [m]
  double lateral = 0.0;    ///< y_j [m]
  /// |step| > kLargestPlausibleStep: the terrain after it sits that far off the ground before.
  bool implausible() const { return known && std::abs(step) > kLargestPlausibleStep; }
};
PatchStep patchStep(double start, const Vector& lateral, const Matrix& heights,
                    const TerrainBuffer& buffer, bool flat_ground);

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
