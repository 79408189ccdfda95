#include "tracked_vehicle_dynamics/dynamics/held_input_series.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

void HeldInputSeries::validate() const {
  if (samples < 1)
    throw InputError("held input series: needs at least one sample, has " +
                     std::to_string(samples));
  const DofIndex n_w = initial.size();
  for (DofIndex j = 0; j < n_w; ++j)
    if (!std::isfinite(initial(j)))
      throw InputError("held input series: initial value of column " + std::to_string(j) +
                       " is not finite");
  std::vector<int> owner(static_cast<std::size_t>(n_w), -1);
  for (std::size_t c = 0; c < channels.size(); ++c) {
    const Channel& ch = channels[c];
    const std::string name = "held input series: channel " + std::to_string(c);
    if (ch.steps.size() != ch.values.size())
      throw InputError(name + " has " + std::to_string(ch.steps.size()) + " steps but " +
                       std::to_string(ch.values.size()) + " values");
    for (const DofIndex j : ch.columns) {
      if (j < 0 || j >= n_w)
        throw InputError(name + ": column " + std::to_string(j) + " outside 0.." +
                         std::to_string(n_w - 1));
      if (owner[static_cast<std::size_t>(j)] >= 0)
        throw InputError(name + ": column " + std::to_string(j) + " is already in channel " +
                         std::to_string(owner[static_cast<std::size_t>(j)]));
      owner[static_cast<std::size_t>(j)] = static_cast<int>(c);
      if (initial(j) != initial(ch.columns.front()))
        throw InputError(
            name + ": column " + std::to_string(j) + " starts at " + std::to_string(initial(j)) +
            ", column " + std::to_string(ch.columns.front()) + " at " +
            std::to_string(initial(ch.columns.front())) + " (one channel is one signal)");
    }
    for (std::size_t e = 0; e < ch.steps.size(); ++e) {
      const long k = ch.steps[e];
      if (k < 1 || k >= samples || (e > 0 && k <= ch.steps[e - 1]))
        throw InputError(name + ": event " + std::to_string(e) + " at step " + std::to_string(k) +
                         " (steps must increase within 1.." + std::to_string(samples - 1) + ")");
      if (!std::isfinite(ch.values[e]))
        throw InputError(name + ": value of event " + std::to_string(e) + " (step " +
                         std::to_string(k) + ") is not finite");
    }
  }
}

Matrix HeldInputSeries::dense() const {
  Matrix w = initial.transpose().replicate(samples, 1);
  for (const Channel& ch : channels) {
    for (std::size_t e = 0; e < ch.steps.size(); ++e) {
      const long end = e + 1 < ch.steps.size() ? ch.steps[e + 1] : samples;
      for (const DofIndex j : ch.columns)
        w.col(j).segment(ch.steps[e], end - ch.steps[e]).setConstant(ch.values[e]);
    }
  }
  return w;
}

Vector HeldInputSeries::row(long k) const {
  Vector w = initial;
  for (const Channel& ch : channels) {
    // The last event at a step <= k.
    const auto it = std::upper_bound(ch.steps.begin(), ch.steps.end(), k);
    if (it == ch.steps.begin())
      continue;
    const double value = ch.values[static_cast<std::size_t>(it - ch.steps.begin() - 1)];
    for (const DofIndex j : ch.columns)
      w(j) = value;
  }
  return w;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
