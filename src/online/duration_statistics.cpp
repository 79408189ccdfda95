#include "tracked_vehicle_dynamics/online/duration_statistics.h"

#include <algorithm>
#include <cmath>

namespace tracked_vehicle_dynamics {
namespace online {

void DurationStatistics::add(double seconds) {
  const double s = std::isfinite(seconds) ? std::max(seconds, 0.0) : 0.0;
  const double micros = s * 1e6;
  int bin = 0;
  if (micros < kBins) {
    bin = static_cast<int>(micros);
  } else {
    // i = floor(log(micros / kBins) / log(1.01)), the last bin for anything beyond.
    const double wide = std::floor(std::log(micros / kBins) / std::log(kWideRatio));
    bin = kBins + static_cast<int>(std::min(wide, static_cast<double>(kWideBins - 1)));
  }
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
  const int last = kBins + kWideBins - 1;
  for (int bin = 0; bin <= last; ++bin) {
    seen += bins_[static_cast<std::size_t>(bin)];
    if (static_cast<double>(seen) >= wanted && seen > 0) {
      if (bin == last)
        return max_;
      // Upper edge of the bin, never above the true maximum.
      const double edge =
          bin < kBins ? (bin + 1) * 1e-6 : kBins * 1e-6 * std::pow(kWideRatio, bin - kBins + 1);
      return std::min(max_, edge);
    }
  }
  return max_;
}

}  // namespace online
}  // namespace tracked_vehicle_dynamics
