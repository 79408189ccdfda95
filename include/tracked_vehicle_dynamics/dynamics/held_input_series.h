// An input series w_k [n_samples x n_w] stored by its changes, for Simulator::simulate().
//
// Road inputs change only where the terrain under a contact is not flat, and contacts on a
// laterally uniform profile at the same station see the same signal. A dense series of the
// tracked vehicle over the 30 m long hill at 5 km/h is 21,601 x 720 doubles (124 MB), almost all
// of it repeated values; reading it alone costs more than simulating it. Here each *channel* is
// one scalar signal shared by one or more columns of w, given as the samples where it is set:
//   w_k(j) = value of the last event of j's channel at a step <= k, or initial(j) before it,
// (a sample-and-hold), so flat terrain costs nothing and a shared signal is stored once. Columns
// in no channel hold initial(j) throughout.
#pragma once

#include <vector>

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

struct HeldInputSeries {
  struct Channel {
    std::vector<DofIndex> columns;  ///< columns of w carrying this signal (distinct)
    std::vector<long> steps;        ///< sample indices of the events, increasing, in [1, samples)
    std::vector<double> values;     ///< the signal from each event on (same length as steps)
  };

  long samples = 0;  ///< n_samples (>= 1 to simulate)
  Vector initial;    ///< w_0 [n_w]
  std::vector<Channel> channels;

  DofIndex inputCount() const { return initial.size(); }
  /// Throws InputError naming the channel (and column, event) when the series is inconsistent:
  /// samples < 1, a column out of range or in two channels, columns of one channel with
  /// different initial values, steps not increasing or outside
  /// [1, samples), lengths that differ, a value (or initial entry) not finite.
  void validate() const;
  /// w_k for every k [samples x n_w] (tests, and the engines without a held path).
  Matrix dense() const;
  /// w at sample k [n_w].
  Vector row(long k) const;
};

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
