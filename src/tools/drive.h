// How the vehicle advances in a `tvd simulate` run: from the start of the track at a constant
// speed or along a speed profile (speed_profile.h), sample k at time k dt, until the station has
// covered the track (or the profile ends first).
#pragma once

#include <optional>
#include <string>

#include "tracked_vehicle_dynamics/dynamics/road_excitation.h"
#include "tracked_vehicle_dynamics/dynamics/speed_profile.h"
#include "tracked_vehicle_dynamics/terrain/terrain_lines.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace tools {

class Drive {
 public:
  /// Longest run [steps]: 1e7 (2.8 h at 1 ms), whose output table of ~35 columns takes 2.8 GB.
  static constexpr double kMaxSteps = 1e7;

  /// Constant speed [m/s] > 0 from station `start` [m] over `distance` [m], time step dt [s].
  Drive(double start, double distance, double dt, double speed);
  /// Along `profile` (named `profile_name` in errors), until the track's end or the profile's,
  /// whichever comes first. Throws InputError when the profile lasts less than one time step or
  /// that run takes more than kMaxSteps steps.
  Drive(double start, double distance, double dt, dynamics::SpeedProfile profile,
        const std::string& profile_name);

  /// Steps of the run: the samples are 0 .. steps().
  long steps() const { return steps_; }
  /// Station of sample k [m].
  double station(long k) const;
  /// Speed at sample k [m/s].
  double speed(long k) const;
  /// Forward acceleration at sample k [m/s^2]: the profile's exact derivative (piecewise constant
  /// between its rows, SpeedProfile::acceleration), 0 at constant speed.
  double acceleration(long k) const;
  /// Whether the speed follows a profile (else it is constant).
  bool varyingSpeed() const { return profile_.has_value(); }

  /// The road inputs of samples first .. first + count - 1, every input at every sample.
  Matrix denseInputs(const dynamics::RoadExcitation& road, const terrain::TerrainLines& lines,
                     long first, long count) const;
  /// The same series stored by its changes (RoadExcitation::sampleHeldSeries); constant speed
  /// only (at a varying speed a flat run is not a fixed number of steps).
  dynamics::HeldInputSeries heldInputs(const dynamics::RoadExcitation& road,
                                       const terrain::TerrainLines& lines, long first,
                                       long count) const;

 private:
  double start_, dt_, speed_ = 0.0;
  std::optional<dynamics::SpeedProfile> profile_;
  long steps_ = 0;
};

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
