#include "tracked_vehicle_dynamics/terrain/interpolation_loss.h"

#include <cmath>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace terrain {

double interpolatedPowerShare(double cycles_per_m, double spacing) {
  const double a = kPi * cycles_per_m * spacing;
  const double sinc = a != 0.0 ? std::sin(a) / a : 1.0;
  const double amplitude = sinc * sinc;
  return amplitude * amplitude;
}

double spacingKeepingPowerShare(double cycles_per_m, double share) {
  if (!(cycles_per_m > 0.0) || !std::isfinite(cycles_per_m))
    throw InputError("spacingKeepingPowerShare: frequency " + brief(cycles_per_m) +
                     " cycles/m must be positive and finite");
  if (!(share > 0.0 && share < 1.0))
    throw InputError("spacingKeepingPowerShare: share " + brief(share) +
                     " must lie strictly between 0 and 1");
  // sinc^4 falls monotonically from 1 to 0 over n dx in [0, 1]: bisect on u = n dx.
  double low = 0.0, high = 1.0;
  for (int i = 0; i < 200 && high - low > 1e-15; ++i) {
    const double mid = 0.5 * (low + high);
    (interpolatedPowerShare(1.0, mid) > share ? low : high) = mid;
  }
  return low / cycles_per_m;
}

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
