#include "tracked_vehicle_dynamics/terrain/terrain_plausibility.h"

#include <algorithm>
#include <cmath>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace terrain {
namespace {

std::string slopeText(const SteepestSlope& s) {
  const double degrees = std::atan(s.slope) * kRadToDegree;
  return "slopes up to " + brief(s.slope) + " m/m (" + brief(std::round(degrees * 10) / 10) +
         " deg) at x = " + brief(s.station) + " m, y = " + brief(s.lateral) +
         " m, steeper than ground a tracked vehicle drives on (the paper's steepest test track, "
         "oop_waves, reaches 1.5 m/m): heights in mm read as m? The linear model runs it, but its "
         "small-angle kinematics and bonded ground do not hold there";
}

std::string spacingText(double spacing) {
  return "sampled every " + brief(spacing) + " m (median spacing), coarser than " +
         brief(kCoarsestPlausibleSpacing) +
         " m: the road wheels (0.5-1 m apart) and the track pads see no feature shorter than " +
         brief(2 * spacing) + " m; stations in mm read as m?";
}

// Every height the same: no spacing can miss a feature of it.
bool flat(const Matrix& h) {
  return h.size() == 0 || (h.array() == h(0, 0)).all();
}

}  // namespace

SteepestSlope steepestSlope(const Vector& x, const Vector& lateral, const Matrix& h) {
  SteepestSlope steepest;
  for (Eigen::Index j = 0; j < h.rows(); ++j)
    for (Eigen::Index i = 0; i + 1 < x.size(); ++i) {
      const double slope = std::abs(h(j, i + 1) - h(j, i)) / (x(i + 1) - x(i));
      if (slope > steepest.slope)
        steepest = {slope, x(i), lateral(j)};
    }
  return steepest;
}

SteepestSlope steepestSlope(const Terrain& terrain) {
  return steepestSlope(terrain.stations(), terrain.lateral(), terrain.heights());
}

double medianSpacing(const Vector& x) {
  if (x.size() < 2)
    return 0.0;
  std::vector<double> d(static_cast<std::size_t>(x.size() - 1));
  for (Eigen::Index i = 0; i + 1 < x.size(); ++i)
    d[static_cast<std::size_t>(i)] = x(i + 1) - x(i);
  const auto middle = d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2);
  std::nth_element(d.begin(), middle, d.end());
  return *middle;  // the upper median for an even count: a warning, not a statistic
}

bool isSampledProfile(const Terrain& terrain) {
  const Vector& x = terrain.stations();
  if (x.size() < 2 || flat(terrain.heights()))
    return false;  // a single station, or flat: any spacing describes it
  const double median = medianSpacing(x);
  Eigen::Index alike = 0;
  for (Eigen::Index i = 0; i + 1 < x.size(); ++i)
    alike += std::abs(x(i + 1) - x(i) - median) <= kUniformSpacingTolerance * median;
  return static_cast<double>(alike) >= kUniformSpacingShare * static_cast<double>(x.size() - 1);
}

std::vector<std::string> terrainWarnings(const std::string& name, const Terrain& terrain) {
  std::vector<std::string> warnings;
  const SteepestSlope s = steepestSlope(terrain);
  if (s.slope > kSteepestPlausibleSlope)
    warnings.push_back(name + ": " + slopeText(s));
  const double spacing = medianSpacing(terrain.stations());
  if (spacing > kCoarsestPlausibleSpacing &&
      (isSampledProfile(terrain) ||
       (!flat(terrain.heights()) && spacing > kCoarsestPlausibleBreakpoints)))
    warnings.push_back(name + ": " + spacingText(spacing));
  return warnings;
}

std::vector<std::string> patchWarnings(double start, double spacing, const Vector& lateral,
                                       const Matrix& heights, const TerrainBuffer& buffer,
                                       bool flat_ground, PatchStep* step_out) {
  std::vector<std::string> warnings;
  if (step_out != nullptr)
    *step_out = PatchStep{};
  if (lateral.size() == 0 || heights.rows() != lateral.size() || heights.cols() == 0 ||
      !(spacing > 0.0) || !std::isfinite(start))
    return warnings;  // addPatch refuses it and says why
  const Vector x = Vector::LinSpaced(heights.cols(), start,
                                     start + spacing * static_cast<double>(heights.cols() - 1));
  const SteepestSlope s = steepestSlope(x, lateral, heights);
  if (s.slope > kSteepestPlausibleSlope)
    warnings.push_back(slopeText(s));
  if (heights.cols() > 1 && spacing > kCoarsestPlausibleSpacing)
    warnings.push_back(spacingText(spacing));
  // The step a contact meets entering the patch: from what it reads (or holds) just before.
  const PatchStep step = patchStep(start, lateral, heights, buffer, flat_ground);
  if (step_out != nullptr)
    *step_out = step;
  if (step.implausible()) {
    const bool has_terrain = !std::isnan(buffer.heightBefore(start, lateral(0)));
    warnings.push_back(
        "starts " + brief(std::abs(step.step)) + " m " + (step.step > 0 ? "above" : "below") + " " +
        (has_terrain ? "the terrain before it (" + brief(step.reference) + " m"
                     : std::string("the flat ground the vehicle stands on since the start or "
                                   "reset (0 m")) +
        " at y = " + brief(step.lateral) +
        " m), a step no tracked vehicle drives: heights are relative to "
        "the ground plane of the start (z = 0), not altitudes?");
  }
  return warnings;
}

PatchStep patchStep(double start, const Vector& lateral, const Matrix& heights,
                    const TerrainBuffer& buffer, bool flat_ground) {
  PatchStep out;
  if (lateral.size() == 0 || heights.rows() != lateral.size() || heights.cols() == 0 ||
      !std::isfinite(start))
    return out;
  const bool has_terrain = !std::isnan(buffer.heightBefore(start, lateral(0)));
  if (!has_terrain && !flat_ground)
    return out;
  out.known = true;
  for (Eigen::Index j = 0; j < lateral.size(); ++j) {
    const double before = has_terrain ? buffer.heightBefore(start, lateral(j)) : 0.0;
    if (std::abs(heights(j, 0) - before) > std::abs(out.step)) {
      out.step = heights(j, 0) - before;
      out.reference = before;
      out.lateral = lateral(j);
    }
  }
  return out;
}

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
