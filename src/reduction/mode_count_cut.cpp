#include "tracked_vehicle_dynamics/reduction/mode_count_cut.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "tracked_vehicle_dynamics/fem/eigenvalue_count.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

std::optional<ModeCountCut> modeCountCut(const SparseMatrix& stiffness, const SparseMatrix& mass,
                                         const Vector& frequencies_hz, double relative_gap) {
  const auto count = static_cast<int>(frequencies_hz.size());
  if (count == 0)
    return std::nullopt;
  const auto groups = degenerateGroups(frequencies_hz, relative_gap);
  const auto [first, end] = groups.back();  // the group of the last computed mode
  const double top = frequencies_hz(count - 1) * (1.0 + relative_gap);
  // Modes the count left out with frequencies within the gap of the last one belong to its group.
  const int below = fem::eigenvaluesBelow(stiffness, mass, std::pow(kTwoPi * top, 2));
  // A single-vector Lanczos run can return part of a repeated eigenvalue and go on past it.
  const double bottom = frequencies_hz(first) * (1.0 - relative_gap);
  const int missed = fem::eigenvaluesBelow(stiffness, mass, std::pow(kTwoPi * bottom, 2)) -
                     static_cast<int>(first);
  if (below <= count && missed <= 0)
    return std::nullopt;
  ModeCountCut cut;
  cut.missed = std::max(missed, 0);
  cut.frequency_hz = frequencies_hz(first);
  cut.kept = static_cast<int>(end - first);
  cut.size = below - static_cast<int>(first) - cut.missed;
  cut.fewer = static_cast<int>(first);
  cut.more = below;
  return cut;
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
