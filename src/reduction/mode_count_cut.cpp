#include "tracked_vehicle_dynamics/reduction/mode_count_cut.h"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <string>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

int eigenvaluesBelow(const SparseMatrix& stiffness, const SparseMatrix& mass, double lambda) {
  if (stiffness.rows() != stiffness.cols() || mass.rows() != stiffness.rows() ||
      mass.cols() != stiffness.cols())
    throw InputError("eigenvaluesBelow: K is " + std::to_string(stiffness.rows()) + " x " +
                     std::to_string(stiffness.cols()) + ", M " + std::to_string(mass.rows()) +
                     " x " + std::to_string(mass.cols()));
  // K - lambda M = L D L^T (with a fill-reducing permutation P, itself a congruence): by
  // Sylvester's law, K - lambda M, hence the pencil shifted by lambda, has as many negative
  // eigenvalues as D has negative entries.
  const SparseMatrix shifted = stiffness - lambda * mass;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt(shifted);
  if (ldlt.info() != Eigen::Success)
    throw SolverError("eigenvaluesBelow: LDL^T of K - " + brief(lambda) +
                      " M failed (an eigenvalue at the shift?)");
  const Vector d = ldlt.vectorD();
  int negative = 0;
  for (Eigen::Index i = 0; i < d.size(); ++i) {
    if (!std::isfinite(d(i)) || d(i) == 0.0)
      throw SolverError("eigenvaluesBelow: zero pivot in the LDL^T of K - " + brief(lambda) + " M");
    negative += d(i) < 0.0 ? 1 : 0;
  }
  return negative;
}

std::optional<ModeCountCut> modeCountCut(const SparseMatrix& stiffness, const SparseMatrix& mass,
                                         const Vector& frequencies_hz, double relative_gap) {
  const auto count = static_cast<int>(frequencies_hz.size());
  if (count == 0)
    return std::nullopt;
  const auto groups = degenerateGroups(frequencies_hz, relative_gap);
  const auto [first, end] = groups.back();  // the group of the last computed mode
  const double top = frequencies_hz(count - 1) * (1.0 + relative_gap);
  // Modes the count left out with frequencies within the gap of the last one belong to its group.
  const int below = eigenvaluesBelow(stiffness, mass, std::pow(kTwoPi * top, 2));
  // A single-vector Lanczos run can return part of a repeated eigenvalue and go on past it.
  const double bottom = frequencies_hz(first) * (1.0 - relative_gap);
  const int missed =
      eigenvaluesBelow(stiffness, mass, std::pow(kTwoPi * bottom, 2)) - static_cast<int>(first);
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
