#include "tracked_vehicle_dynamics/dynamics/running_window.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

std::size_t LinearRunningMeanSquare::windowSamples(double sample_rate, double time) {
  const double n = std::round(sample_rate * time);
  if (!(n <= static_cast<double>(LinearRunningMeanSquare::kMaxWindow)))
    throw InputError("comfort: a running r.m.s. over " + brief(time) + " s at " +
                     brief(sample_rate) + " Hz needs " + brief(n) + " samples, more than " +
                     brief(static_cast<double>(LinearRunningMeanSquare::kMaxWindow)) +
                     " (ISO 2631-1 recommends 1 s)");
  return std::max<std::size_t>(1, static_cast<std::size_t>(n));
}

LinearRunningMeanSquare::LinearRunningMeanSquare(double sample_rate, double time)
    : squares_(windowSamples(sample_rate, time), 0.0) {}

double LinearRunningMeanSquare::add(double square) {
  sum_ += square - squares_[next_];
  squares_[next_] = square;
  if (++next_ == squares_.size()) {
    next_ = 0;
    sum_ = std::accumulate(squares_.begin(), squares_.end(), 0.0);
  }
  return value();
}

double LinearRunningMeanSquare::value() const {
  return std::max(sum_, 0.0) / static_cast<double>(squares_.size());
}

void LinearRunningMeanSquare::reset() {
  std::fill(squares_.begin(), squares_.end(), 0.0);
  next_ = 0;
  sum_ = 0.0;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
