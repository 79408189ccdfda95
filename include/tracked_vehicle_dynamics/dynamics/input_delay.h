// Delay vector tau of a harmonic road excitation u0 = tau h (paper eqs. 21-24).
//
//   synchronous (eq. 22): tau_q = 1, every input lifted together (upper bound of the response).
//   travelled at speed v (eqs. 23-24): tau_q(omega) = exp(-j omega L_q / v),
//     L_q = max_p x_p - x_q >= 0, x the input stations (x forward).
// Sign convention: the front-most input meets a profile feature first (L = 0, phase 0); an input
// L_q behind it meets the same feature L_q / v seconds later, hence the phase lag -omega L_q / v
// with the e^{+j omega t} convention of eq. 16. This is the "wheelbase filter".
//
// Anti-phase (beyond the paper): tau_q times s_q = +1 for an input left of the centre line
// (y_q > 0), -1 right of it (0 on it): the two tracks' roads move in opposite phase, each by h,
// which rolls (and sways and yaws) the vehicle instead of lifting it; half the sum of the in-phase
// and anti-phase FRFs is the response to the left track's road alone.
#pragma once

#include <complex>

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

using Complex = std::complex<double>;
using ComplexVector = Eigen::VectorXcd;
using ComplexMatrix = Eigen::MatrixXcd;

class InputDelay {
 public:
  /// tau = 1 (eq. 22).
  static InputDelay synchronous();
  /// stations x_q [m] (x forward, e.g. SecondOrderSystem::input_stations), speed v [m/s] > 0.
  /// Throws InputError for an empty or non-finite station vector or v <= 0.
  static InputDelay travelling(const Vector& stations, double speed);

  /// These delays with input q's amplitude times factors(q) (e.g. antiPhaseFactors()).
  /// Throws InputError for non-finite factors or another count than a travelling delay's.
  InputDelay scaled(const Vector& factors) const;
  /// s_q = +1 for an input left of the centre line (lateral y_q > 0), -1 right of it, 0 on it.
  static Vector antiPhaseFactors(const Vector& lateral);

  /// tau(omega) [input_count] at omega [rad/s]. Throws InputError when a travelling delay has a
  /// different number of stations, or scaled() factors a different number of inputs.
  ComplexVector at(double omega, DofIndex input_count) const;

  bool isSynchronous() const { return lags_.size() == 0; }
  /// L_q [m] behind the front-most input (empty when synchronous).
  const Vector& lags() const { return lags_; }
  /// v [m/s] (0 when synchronous).
  double speed() const { return speed_; }
  /// s_q of scaled() (empty: 1 for every input).
  const Vector& factors() const { return factors_; }

 private:
  InputDelay(Vector lags, double speed) : lags_(std::move(lags)), speed_(speed) {}

  Vector lags_;
  double speed_ = 0.0;
  Vector factors_;
};

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
