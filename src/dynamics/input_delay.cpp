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

InputDelay InputDelay::scaled(const Vector& factors) const {
  if (!factors.allFinite())
    throw InputError("InputDelay: input factors must be finite");
  if (!isSynchronous())
    detail::requireLength("InputDelay::scaled", "input factors", factors, lags_.size());
  InputDelay out = *this;
  out.factors_ = factors;
  return out;
}

Vector InputDelay::antiPhaseFactors(const Vector& lateral) {
  if (!lateral.allFinite())
    throw InputError("InputDelay: input lateral positions must be finite");
  return lateral.unaryExpr([](double y) { return y > 0.0 ? 1.0 : y < 0.0 ? -1.0 : 0.0; });
}

ComplexVector InputDelay::at(double omega, DofIndex input_count) const {
  ComplexVector tau = ComplexVector::Ones(input_count);
  if (!isSynchronous()) {
    detail::requireLength("InputDelay::at", "input stations", lags_, input_count);
    for (DofIndex q = 0; q < input_count; ++q)
      tau(q) = std::polar(1.0, -omega * lags_(q) / speed_);
  }
  if (factors_.size() > 0) {
    detail::requireLength("InputDelay::at", "input factors", factors_, input_count);
    tau = tau.cwiseProduct(factors_.cast<Complex>());
  }
  return tau;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
