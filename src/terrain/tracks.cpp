#include "tracked_vehicle_dynamics/terrain/tracks.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <sstream>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/csv_reader.h"
#include "tracked_vehicle_dynamics/terrain/moving_average.h"

namespace tracked_vehicle_dynamics {
namespace terrain {
namespace {

const char* const kLongHill = "long_hill";
const char* const kSeparatedWaves = "separated_waves";
const char* const kOopWaves = "oop_waves";
const char* const kHalfRoundForm = "half_round:H";

/// "a, b, c": the names and forms of trackForms(), for messages.
std::string knownTracks() {
  std::string known;
  for (const std::string& track : trackForms())
    known += (known.empty() ? "" : ", ") + track;
  return known;
}

bool isFixedName(const std::string& name) {
  const std::vector<std::string> names = trackNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

/// A half-round spec, well formed or not: "half_round" alone or followed by ':' and anything.
bool isHalfRoundFamily(const std::string& name) {
  const std::string prefix = kHalfRoundPrefix;  // "half_round:"
  return name == prefix.substr(0, prefix.size() - 1) || name.rfind(prefix, 0) == 0;
}

/// Why `height` [m] is no half-round height (tracks.h: the bounds); empty when it is one.
std::string halfRoundFault(double height) {
  if (std::isfinite(height) && height > 0.0 && height <= kHalfRoundMaxHeight)
    return "";
  std::string fault = "the obstacle height must be in (0, " + brief(kHalfRoundMaxHeight) +
                      "] m, got " + brief(height);
  if (height > kHalfRoundMaxHeight && std::isfinite(height)) {
    fault += " (more than any vehicle's ground clearance: a height in cm or inches?)";
  }
  return fault;
}

/// The height of a half-round spec, or why it has none (`fault` non-empty). Only for names of
/// isHalfRoundFamily().
double parseHalfRound(const std::string& spec, std::string* fault) {
  const std::size_t prefix = std::string(kHalfRoundPrefix).size();
  const std::string text = spec.size() > prefix ? spec.substr(prefix) : "";  // "half_round": ""
  if (text.empty()) {
    *fault = "the obstacle height is missing; give it in metres after the colon, e.g. " +
             halfRoundName(0.2);
    return 0.0;
  }
  // Spelled as in a terrain file: the whole text one number, no blanks or units around it.
  const std::optional<double> height = io::parseNumber(text);
  if (!height) {
    *fault = "the obstacle height '" + text + "' is not a number (metres, e.g. " +
             halfRoundName(0.2) + ")";
    return 0.0;
  }
  *fault = halfRoundFault(*height);
  return *height;
}

void checkOption(bool valid, const std::string& track, const std::string& field, double value,
                 const std::string& requirement) {
  if (!valid) {
    std::ostringstream message;
    message << "track '" << track << "': TrackOptions::" << field << " = " << value << " must be "
            << requirement;
    throw InputError(message.str());
  }
}

void checkOptions(const std::string& track, const TrackOptions& options) {
  checkOption(std::isfinite(options.spacing) && options.spacing > 0.0 &&
                  options.spacing <= kTrackLength / 2.0,
              track, "spacing", options.spacing, "in (0, 15] m");
  checkOption(std::isfinite(options.smoothing_window) && options.smoothing_window >= 0.0, track,
              "smoothing_window", options.smoothing_window, "finite and >= 0 m");
  checkOption(std::isfinite(options.lateral_spacing) && options.lateral_spacing > 0.0, track,
              "lateral_spacing", options.lateral_spacing, "finite and > 0 m");
  if (options.lateral_offset) {
    checkOption(std::isfinite(*options.lateral_offset), track, "lateral_offset",
                *options.lateral_offset, "finite");
  }
}

Vector trackStations(double spacing) {
  // The last station is the last grid point within the 30 m (the track end itself when the
  // spacing divides it); the small tolerance absorbs 30 / 0.01 rounding below 3000.
  const auto n = static_cast<Eigen::Index>(std::floor(kTrackLength / spacing + 1e-9)) + 1;
  Vector x(n);
  for (Eigen::Index i = 0; i < n; ++i)
    x(i) = static_cast<double>(i) * spacing;
  return x;
}

/// Lateral lines y_t across the width, on the track frame (centre y_t = 0).
Vector trackLines(double lateral_spacing) {
  const auto intervals = std::max<Eigen::Index>(
      1, static_cast<Eigen::Index>(std::ceil(kTrackWidth / lateral_spacing - 1e-9)));
  Vector y(intervals + 1);
  for (Eigen::Index j = 0; j <= intervals; ++j) {
    y(j) =
        -kTrackWidth / 2.0 + kTrackWidth * static_cast<double>(j) / static_cast<double>(intervals);
  }
  return y;
}

/// Samples h(x, y_t) on the grid, smooths each line along x, shifts to the path frame.
Terrain buildTrack(const std::string& name, const TrackOptions& options,
                   const std::function<double(double, double)>& surface) {
  checkOptions(name, options);
  const Vector x = trackStations(options.spacing);
  const Vector y_track = trackLines(options.lateral_spacing);
  Matrix h(y_track.size(), x.size());
  for (Eigen::Index j = 0; j < y_track.size(); ++j) {
    for (Eigen::Index i = 0; i < x.size(); ++i)
      h(j, i) = surface(x(i), y_track(j));
  }
  h = movingAverageRows(h, options.spacing, options.smoothing_window);
  const double offset = options.lateral_offset.value_or(defaultLateralOffset(name));
  // Path frame: the vehicle centreline (y = 0) runs at y_t = offset.
  const Vector y_path = y_track.array() - offset;
  return Terrain(x, y_path, h, name);
}

}  // namespace

std::vector<std::string> trackNames() {
  return {kLongHill, kSeparatedWaves, kOopWaves};
}

std::vector<std::string> trackForms() {
  std::vector<std::string> forms = trackNames();
  forms.push_back(kHalfRoundForm);
  return forms;
}

bool isBuiltInTrack(const std::string& name) {
  if (isFixedName(name))
    return true;
  if (!isHalfRoundFamily(name))
    return false;
  std::string fault;
  parseHalfRound(name, &fault);
  return fault.empty();
}

void checkTrackName(const std::string& name) {
  if (isFixedName(name) || halfRoundHeight(name))
    return;  // a bad spec throws its own fault
  throw InputError("unknown track '" + name + "' (known tracks: " + knownTracks() + ")");
}

std::optional<double> halfRoundHeight(const std::string& name) {
  if (!isHalfRoundFamily(name))
    return std::nullopt;
  std::string fault;
  const double height = parseHalfRound(name, &fault);
  if (!fault.empty())
    throw InputError("track '" + name + "': " + fault);
  return height;
}

std::string halfRoundName(double height) {
  // std::to_chars without a precision: the shortest text that reads back as the same double.
  char digits[32];
  const std::to_chars_result result = std::to_chars(digits, digits + sizeof(digits), height);
  return kHalfRoundPrefix + std::string(digits, result.ptr);
}

double defaultLateralOffset(const std::string& name) {
  checkTrackName(name);
  return name == kOopWaves ? kOopWavesLateralOffset : 0.0;
}

Terrain makeTrack(const std::string& name, const TrackOptions& options) {
  checkTrackName(name);  // rejects unknown names with the list of known ones
  if (name == kLongHill)
    return makeLongHill(options);
  if (name == kSeparatedWaves)
    return makeSeparatedWaves(options);
  if (name == kOopWaves)
    return makeOopWaves(options);
  return makeHalfRound(*halfRoundHeight(name), options);
}

Terrain makeLongHill(const TrackOptions& options) {
  const double up_end = kLongHillStart + kLongHillRamp;
  const double down_start = kLongHillStart + kLongHillLength - kLongHillRamp;
  const double down_end = kLongHillStart + kLongHillLength;
  const double slope = kLongHillHeight / kLongHillRamp;
  return buildTrack(kLongHill, options, [=](double x, double) {
    if (x <= kLongHillStart || x >= down_end)
      return 0.0;
    if (x < up_end)
      return slope * (x - kLongHillStart);
    if (x <= down_start)
      return kLongHillHeight;
    return slope * (down_end - x);
  });
}

Terrain makeSeparatedWaves(const TrackOptions& options) {
  const double end = kSeparatedWavesStart + kSeparatedWavesPeriods * kSeparatedWavesWavelength;
  return buildTrack(kSeparatedWaves, options, [=](double x, double) {
    if (x <= kSeparatedWavesStart || x >= end)
      return 0.0;
    const double phase = 2.0 * kPi * (x - kSeparatedWavesStart) / kSeparatedWavesWavelength;
    return -0.5 * kSeparatedWavesDepth * (1.0 - std::cos(phase));
  });
}

Terrain makeOopWaves(const TrackOptions& options) {
  const double end = kOopWavesStart + kOopWavesPeriods * kOopWavesWavelength;
  return buildTrack(kOopWaves, options, [=](double x, double y_track) {
    if (x <= kOopWavesStart || x >= end)
      return 0.0;
    const double phase = 2.0 * kPi * (x - kOopWavesStart) / kOopWavesWavelength;
    // Amplitude linear in y_t: opposite phase left/right, larger on the outer pad rows.
    const double amplitude = 0.5 * kOopWavesDepth * y_track / (0.5 * kTrackWidth);
    return amplitude * std::sin(phase);
  });
}

Terrain makeHalfRound(double height, const TrackOptions& options) {
  const std::string name = halfRoundName(height);
  const std::string fault = halfRoundFault(height);
  if (!fault.empty())
    throw InputError("track '" + name + "': " + fault);
  return buildTrack(name, options, [=](double x, double) {
    const double d = std::abs(x - kHalfRoundCentre);
    if (d >= height)
      return 0.0;
    // sqrt(H² - d²) as sqrt((H - d)(H + d)): no cancellation near the feet, H exactly at d = 0.
    return std::sqrt((height - d) * (height + d));
  });
}

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
