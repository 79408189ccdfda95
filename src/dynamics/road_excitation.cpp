#include "tracked_vehicle_dynamics/dynamics/road_excitation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <utility>

#include "tracked_vehicle_dynamics/terrain/terrain_lines.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

HeldInputSeries RoadExcitation::sampleHeldSeries(const terrain::TerrainLines& lines,
                                                 double station0, double speed, double dt,
                                                 long first, long count) const {
  const DofIndex n = x_.size();
  HeldInputSeries series;
  series.samples = count;
  series.initial.setZero(2 * n);
  if (count < 1)
    return series;
  const bool skip = speed > 0.0 && dt > 0.0 && std::isfinite(speed * dt);
  // Station of sample j: the expression of sampleSeries(), so the values are the same bits.
  auto station = [&](long j) { return station0 + speed * static_cast<double>(first + j) * dt; };

  // One channel pair (u, u') per distinct (x_q, profile); inputs off the lines get their own.
  std::map<std::pair<std::uint64_t, int>, std::size_t> group_of;
  struct Group {
    DofIndex q;   // the input sampled for the group
    int profile;  // -1: not on a line (sampled at every step)
    std::vector<DofIndex> inputs;
  };
  std::vector<Group> groups;
  for (DofIndex q = 0; q < n; ++q) {
    const int profile = lines.profileOf(y_(q));
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x_(q), sizeof bits);
    if (profile >= 0) {
      const auto [it, inserted] = group_of.emplace(std::make_pair(bits, profile), groups.size());
      if (!inserted) {
        groups[it->second].inputs.push_back(q);
        continue;
      }
    }
    groups.push_back({q, profile, {q}});
  }

  for (const Group& g : groups) {
    HeldInputSeries::Channel height, rate;
    for (const DofIndex q : g.inputs) {
      height.columns.push_back(q);
      rate.columns.push_back(n + q);
    }
    const double xq = x_(g.q), yq = y_(g.q);
    // Height and rate at x = station + x_q, and the end of the flat run x is on (x itself when
    // the profile is not flat there).
    auto sampleAt = [&](double x, double& h, double& rate) {
      if (g.profile < 0) {
        sampleOne(lines, x, yq, speed, h, rate);
        return x;
      }
      double slope = 0.0;
      const double end = lines.sampleRun(g.profile, x, h, slope);
      rate = speed * slope;
      return end;
    };
    double h = 0.0, dh = 0.0;
    double x = station(0) + xq;
    double end = sampleAt(x, h, dh);
    for (const DofIndex q : g.inputs) {
      series.initial(q) = h;
      series.initial(n + q) = dh;
    }
    long j = 0;
    while (true) {
      // Samples after j on the same flat run hold j's values: jump to the first one past it.
      long next = j + 1;
      if (skip && end > x) {
        if (!std::isfinite(end))
          break;
        const double estimate = (end - xq - station0) / (speed * dt) - static_cast<double>(first);
        next =
            std::max(next, static_cast<long>(std::min(estimate, static_cast<double>(count))) - 1);
        while (next > j + 1 && station(next - 1) + xq >= end)
          --next;
        while (next < count && station(next) + xq < end)
          ++next;
      }
      if (next >= count)
        break;
      j = next;
      x = station(j) + xq;
      double hj = 0.0, dhj = 0.0;
      end = sampleAt(x, hj, dhj);
      // Events where the bits change, so dense() gives sampleSeries() exactly (signed zeros).
      if (std::memcmp(&hj, &h, sizeof h) != 0) {
        height.steps.push_back(j);
        height.values.push_back(hj);
        h = hj;
      }
      if (std::memcmp(&dhj, &dh, sizeof dh) != 0) {
        rate.steps.push_back(j);
        rate.values.push_back(dhj);
        dh = dhj;
      }
    }
    series.channels.push_back(std::move(height));
    series.channels.push_back(std::move(rate));
  }
  return series;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
