#include "tracked_vehicle_dynamics/online/duration_statistics.h"

#include <algorithm>
#include <cmath>

namespace tracked_vehicle_dynamics {
namespace online {

void DurationStatistics::add(double seconds) {
  const double s = std::isfinite(seconds) ? std::max(seconds, 0.0) : 0.0;
  const double micros = s * 1e6;
  const int bin = micros >= kBins - 1 ? kBins - 1 : static_cast<int>(micros);
  ++bins_[static_cast<std::size_t>(bin)];
  ++count_;
  sum_ += s;
  max_ = std::max(max_, s);
}

void DurationStatistics::clear() {
  *this = DurationStatistics();
}

double DurationStatistics::mean() const {
  return count_ == 0 ? 0.0 : sum_ / static_cast<double>(count_);
}

double DurationStatistics::percentile(double fraction) const {
  if (count_ == 0)
    return 0.0;
  const double wanted = std::clamp(fraction, 0.0, 1.0) * static_cast<double>(count_);
  std::uint64_t seen = 0;
  for (int bin = 0; bin < kBins; ++bin) {
    seen += bins_[static_cast<std::size_t>(bin)];
    if (static_cast<double>(seen) >= wanted && seen > 0) {
      // Upper edge of the bin, never above the true maximum.
      return bin == kBins - 1 ? max_ : std::min(max_, (bin + 1) * 1e-6);
    }
  }
  return max_;
}

}  // namespace online
}  // namespace tracked_vehicle_dynamics
