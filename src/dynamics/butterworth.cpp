#include "tracked_vehicle_dynamics/dynamics/butterworth.h"

#include <cmath>
#include <string>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

std::vector<AnalogSection> butterworthLowPass(int order, double corner_hz) {
  if (order < 1 || order > 12)
    throw InputError("Butterworth low-pass: the order must be 1..12, got " + std::to_string(order));
  if (!std::isfinite(corner_hz) || !(corner_hz > 0.0))
    throw InputError(
        "Butterworth low-pass: the corner frequency must be a positive number [Hz], got " +
        brief(corner_hz));
  const double wc = kTwoPi * corner_hz;
  std::vector<AnalogSection> sections;
  for (int k = 1; k <= order / 2; ++k) {
    const double phi = kPi * (2.0 * k - 1.0) / (2.0 * order);
    AnalogSection s;
    s.b0 = wc * wc;
    s.a0 = wc * wc;
    s.a1 = 2.0 * std::sin(phi) * wc;
    s.a2 = 1.0;
    s.prewarp_frequency = corner_hz;
    sections.push_back(s);
  }
  if (order % 2 == 1) {
    AnalogSection s;
    s.b0 = wc;
    s.a0 = wc;
    s.a1 = 1.0;
    s.prewarp_frequency = corner_hz;
    sections.push_back(s);
  }
  return sections;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
