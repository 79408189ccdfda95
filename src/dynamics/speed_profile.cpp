#include "tracked_vehicle_dynamics/dynamics/speed_profile.h"

#include <algorithm>
#include <cmath>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {
SpeedProfile::SpeedProfile(std::vector<double> time, std::vector<double> speed,
                           const std::string& name)
    : time_(std::move(time)), speed_(std::move(speed)), name_(name) {
  if (time_.size() != speed_.size())
    throw InputError(name + ": " + std::to_string(time_.size()) + " times but " +
                     std::to_string(speed_.size()) + " speeds");
  if (time_.size() < 2)
    throw InputError(name + ": needs at least two samples (time, speed)");
  for (std::size_t k = 0; k < time_.size(); ++k) {
    const std::string sample = name + ": sample " + std::to_string(k) + ": ";
    if (!std::isfinite(time_[k]))
      throw InputError(sample + "time is not a finite number");
    if (!std::isfinite(speed_[k]))
      throw InputError(sample + "speed is not a finite number");
    if (speed_[k] < 0)
      throw InputError(sample + "speed " + brief(speed_[k]) +
                       " m/s is negative (the road inputs assume forward travel)");
    if (k == 0 && time_[k] != 0)
      throw InputError(sample + "the first time must be 0, got " + brief(time_[k]) + " s");
    if (k > 0 && !(time_[k] > time_[k - 1]))
      throw InputError(sample + "time " + brief(time_[k]) + " s is not after the previous one (" +
                       brief(time_[k - 1]) + " s); times must be strictly increasing");
  }
  station_.assign(time_.size(), 0.0);
  for (std::size_t k = 1; k < time_.size(); ++k)
    station_[k] = station_[k - 1] + 0.5 * (speed_[k - 1] + speed_[k]) * (time_[k] - time_[k - 1]);
}

std::size_t SpeedProfile::segment(double t) const {
  // The last sample k with t_k <= t.
  const auto it = std::upper_bound(time_.begin(), time_.end(), t);
  return it == time_.begin() ? 0 : static_cast<std::size_t>(it - time_.begin()) - 1;
}

double SpeedProfile::speed(double t) const {
  const std::size_t k = segment(t);
  if (k + 1 == time_.size())
    return speed_.back();
  const double tau = std::max(t, 0.0) - time_[k];
  return speed_[k] + (speed_[k + 1] - speed_[k]) * tau / (time_[k + 1] - time_[k]);
}

double SpeedProfile::station(double t) const {
  const std::size_t k = segment(t);
  const double tau = std::max(t, 0.0) - time_[k];
  if (k + 1 == time_.size())
    return station_.back() + speed_.back() * tau;
  const double h = time_[k + 1] - time_[k];
  return station_[k] + speed_[k] * tau + (speed_[k + 1] - speed_[k]) * tau * tau / (2.0 * h);
}

double SpeedProfile::acceleration(double t) const {
  const std::size_t k = segment(t);
  if (k + 1 == time_.size())
    return 0.0;  // the speed is held after the last sample
  return (speed_[k + 1] - speed_[k]) / (time_[k + 1] - time_[k]);
}

double SpeedProfile::maxSpeed() const {
  return *std::max_element(speed_.begin(), speed_.end());
}

double SpeedProfile::maxAbsAcceleration(double* at) const {
  double largest = 0.0, when = 0.0;
  for (std::size_t k = 0; k + 1 < time_.size(); ++k) {
    const double a = std::abs(speed_[k + 1] - speed_[k]) / (time_[k + 1] - time_[k]);
    if (a > largest) {
      largest = a;
      when = time_[k];
    }
  }
  if (at)
    *at = when;
  return largest;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
