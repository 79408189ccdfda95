#include "tracked_vehicle_dynamics/terrain/moving_average.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace terrain {
namespace {

/// Value of the piecewise-linear interpolant at t (in sample units), edges held.
double interpolant(const Vector& h, double t) {
  const Eigen::Index n = h.size();
  if (t <= 0.0)
    return h(0);
  if (t >= static_cast<double>(n - 1))
    return h(n - 1);
  const auto k = static_cast<Eigen::Index>(std::floor(t));
  const double w = t - static_cast<double>(k);
  return w == 0.0 ? h(k) : (1.0 - w) * h(k) + w * h(k + 1);
}

/// ∫_a^b of the interpolant (sample units): it is linear between consecutive integers, held
/// constant outside the samples, so the trapezoidal rule on integer breakpoints is exact.
double integral(const Vector& h, double a, double b) {
  double sum = 0.0;
  double t0 = a;
  double h0 = interpolant(h, a);
  while (t0 < b) {
    const double t1 = std::min(b, std::floor(t0) + 1.0);
    const double h1 = interpolant(h, t1);
    sum += 0.5 * (h0 + h1) * (t1 - t0);
    t0 = t1;
    h0 = h1;
  }
  return sum;
}

void checkArguments(double spacing, double window) {
  if (!std::isfinite(spacing) || spacing <= 0.0) {
    std::ostringstream message;
    message << "moving average: spacing " << spacing << " m must be positive and finite";
    throw InputError(message.str());
  }
  if (!std::isfinite(window) || window < 0.0) {
    std::ostringstream message;
    message << "moving average: window " << window << " m must be non-negative and finite";
    throw InputError(message.str());
  }
}

}  // namespace

Vector movingAverage(const Vector& samples, double spacing, double window) {
  checkArguments(spacing, window);
  for (Eigen::Index i = 0; i < samples.size(); ++i) {
    if (!std::isfinite(samples(i))) {
      throw InputError("moving average: sample " + std::to_string(i) + " is not finite");
    }
  }
  const double half = 0.5 * window / spacing;  // half window in sample units
  if (samples.size() == 0 || half == 0.0)
    return samples;
  Vector smoothed(samples.size());
  for (Eigen::Index i = 0; i < samples.size(); ++i) {
    const double centre = static_cast<double>(i);
    smoothed(i) = integral(samples, centre - half, centre + half) / (2.0 * half);
  }
  return smoothed;
}

Matrix movingAverageRows(const Matrix& rows, double spacing, double window) {
  checkArguments(spacing, window);
  Matrix smoothed(rows.rows(), rows.cols());
  for (Eigen::Index r = 0; r < rows.rows(); ++r) {
    smoothed.row(r) = movingAverage(rows.row(r).transpose(), spacing, window).transpose();
  }
  return smoothed;
}

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
