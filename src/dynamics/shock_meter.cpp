#include "tracked_vehicle_dynamics/dynamics/shock_meter.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "tracked_vehicle_dynamics/dynamics/butterworth.h"
#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

ShockMeter::ShockMeter(double sample_rate, const ShockOptions& options) {
  if (!std::isfinite(sample_rate) || !(sample_rate > 0.0))
    throw InputError("shock meter: the sample rate must be a positive number [Hz]");
  if (!std::isfinite(options.lowpass_corner_hz) || options.lowpass_corner_hz < 0.0 ||
      options.lowpass_corner_hz >= 0.5 * sample_rate) {
    std::ostringstream m;
    m << "shock meter: the low-pass corner must be in [0, fs/2 = " << 0.5 * sample_rate
      << ") Hz, got " << options.lowpass_corner_hz;
    throw InputError(m.str());
  }
  if (options.lowpass_corner_hz > 0.0)
    lowpass_.emplace(butterworthLowPass(options.lowpass_order, options.lowpass_corner_hz),
                     sample_rate, Discretisation::BilinearPrewarped);
}

void ShockMeter::add(double acceleration) {
  if (!std::isfinite(acceleration))
    throw InputError("shock meter: an acceleration sample is not finite");
  const double a = lowpass_ ? lowpass_->step(acceleration) : acceleration;
  peak_up_ = std::max(peak_up_, a);
  peak_abs_ = std::max(peak_abs_, std::abs(a));
}

void ShockMeter::reset() {
  if (lowpass_)
    lowpass_->reset();
  peak_up_ = 0.0;
  peak_abs_ = 0.0;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
