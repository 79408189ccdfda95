#include "drive.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace tools {

Drive::Drive(double start, double distance, double dt, double speed)
    : start_(start), dt_(dt), speed_(speed) {
  const double samples = std::ceil(distance / speed / dt);
  if (samples > kMaxSteps) {
    std::ostringstream message;
    message << "simulate: " << distance << " m at " << speed * kKmhPerMs << " km/h take " << samples
            << " time steps of " << dt << " s; at most " << kMaxSteps;
    throw InputError(message.str());
  }
  steps_ = static_cast<long>(samples);
}

Drive::Drive(double start, double distance, double dt, dynamics::SpeedProfile profile,
             const std::string& profile_name)
    : start_(start), dt_(dt), profile_(std::move(profile)) {
  const double samples = std::floor(profile_->endTime() / dt * (1 + 1e-12));
  if (samples < 1) {
    std::ostringstream message;
    message << profile_name << ": the profile lasts " << profile_->endTime()
            << " s, less than one time step (" << dt << " s)";
    throw InputError(message.str());
  }
  // The run ends at the first sample at or past the track's end, else at the profile's last; the
  // step limit applies to that run, not to the profile (which may outlast the track). The station
  // never decreases (speeds >= 0), so a bisection over the samples a run may take finds the end.
  const long limit = static_cast<long>(std::min(samples, kMaxSteps + 1));
  if (profile_->station(limit * dt) < distance) {
    if (samples > kMaxSteps) {
      std::ostringstream message;
      message << profile_name << ": the profile lasts " << profile_->endTime() << " s, " << samples
              << " time steps of " << dt << " s, and does not reach the track's end (" << distance
              << " m) within " << kMaxSteps << " steps; at most " << kMaxSteps;
      throw InputError(message.str());
    }
    steps_ = limit;  // the profile ends before the track
    return;
  }
  long lo = 0, hi = limit;  // station(lo dt) < distance <= station(hi dt)
  while (hi - lo > 1) {
    const long mid = lo + (hi - lo) / 2;
    (profile_->station(mid * dt) >= distance ? hi : lo) = mid;
  }
  steps_ = hi;
  if (steps_ > kMaxSteps) {
    std::ostringstream message;
    message << profile_name << ": the run to the track's end (" << distance
            << " m) takes more than " << kMaxSteps << " time steps of " << dt << " s";
    throw InputError(message.str());
  }
}

double Drive::station(long k) const {
  return start_ + (profile_ ? profile_->station(k * dt_) : speed_ * k * dt_);
}

double Drive::speed(long k) const {
  return profile_ ? profile_->speed(k * dt_) : speed_;
}

double Drive::acceleration(long k) const {
  return profile_ ? profile_->acceleration(k * dt_) : 0.0;
}

Matrix Drive::denseInputs(const dynamics::RoadExcitation& road, const terrain::TerrainLines& lines,
                          long first, long count) const {
  if (!profile_)
    return road.sampleSeries(lines, start_, speed_, dt_, first, count);
  Vector stations(count), speeds(count);
  for (long j = 0; j < count; ++j) {
    stations(j) = station(first + j);
    speeds(j) = speed(first + j);
  }
  return road.sampleSeries(lines, stations, speeds);
}

dynamics::HeldInputSeries Drive::heldInputs(const dynamics::RoadExcitation& road,
                                            const terrain::TerrainLines& lines, long first,
                                            long count) const {
  if (profile_)
    throw std::logic_error("Drive::heldInputs: constant speed only");
  return road.sampleHeldSeries(lines, start_, speed_, dt_, first, count);
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
