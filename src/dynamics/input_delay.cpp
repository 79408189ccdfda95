#include "tracked_vehicle_dynamics/dynamics/input_delay.h"

#include <cmath>

#include "checks.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

InputDelay InputDelay::synchronous() {
  return InputDelay(Vector(), 0.0);
}

InputDelay InputDelay::travelling(const Vector& stations, double speed) {
  if (stations.size() == 0)
    throw InputError("InputDelay: no input station given");
  if (!stations.allFinite())
    throw InputError("InputDelay: input stations must be finite");
  if (!(speed > 0.0) || !std::isfinite(speed))
    throw InputError("InputDelay: speed must be positive and finite, got " + std::to_string(speed) +
                     " m/s");
  // L_q = x_front - x_q (eq. 24 uses tau_q = L_q / v).
  const Vector lags = Vector::Constant(stations.size(), stations.maxCoeff()) - stations;
  return InputDelay(lags, speed);
}

ComplexVector InputDelay::at(double omega, DofIndex input_count) const {
  if (isSynchronous())
    return ComplexVector::Ones(input_count);
  detail::requireLength("InputDelay::at", "input stations", lags_, input_count);
  ComplexVector tau(input_count);
  for (DofIndex q = 0; q < input_count; ++q)
    tau(q) = std::polar(1.0, -omega * lags_(q) / speed_);
  return tau;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
