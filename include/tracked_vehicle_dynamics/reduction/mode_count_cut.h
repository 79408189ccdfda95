// Whether a count of lowest modes cuts through a repeated eigenvalue. The vectors a solver
// returns for part of a degenerate eigenspace are any part of it, picked by round-off, so a MAC
// against them (eigenspaceMac) depends on round-off unless the group is complete.
#pragma once

#include <optional>

#include "tracked_vehicle_dynamics/fem/eigenvalue_count.h"
#include "tracked_vehicle_dynamics/reduction/mac.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

/// A degenerate group cut by the count: the lowest `kept` of its `size` modes are among the
/// computed ones.
struct ModeCountCut {
  double frequency_hz = 0.0;  ///< the group's (lowest) frequency
  int kept = 0;               ///< modes of the group among the computed ones
  int size = 0;               ///< modes of the group in all
  int fewer = 0;  ///< the largest count below that does not cut it (its first mode's index)
  int more = 0;   ///< the smallest count above that does not cut it
  /// Modes of the system below the group that the computed ones lack (> 0 when the solver
  /// returned part of a repeated eigenvalue below and went on past it).
  int missed = 0;
};

/// Whether the modes `frequencies_hz` (the lowest of (K, M), ascending) end inside a group of
/// modes within `relative_gap` of each other in frequency (as degenerateGroups() forms them): the
/// group of the last computed mode is counted in full with fem::eigenvaluesBelow() just above its
/// frequency; fem::eigenvaluesBelow() just below it checks that no mode below is missing. Empty
/// when the count ends at a gap and no mode is missing.
std::optional<ModeCountCut> modeCountCut(const SparseMatrix& stiffness, const SparseMatrix& mass,
                                         const Vector& frequencies_hz,
                                         double relative_gap = kDegenerateRelativeGap);

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
