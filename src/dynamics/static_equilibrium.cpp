#include "tracked_vehicle_dynamics/dynamics/static_equilibrium.h"

#include <limits>

#include "checks.h"
#include "tracked_vehicle_dynamics/dynamics/validation.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

namespace {

// Smallest pivot of K relative to the largest below which K is singular: far below any physical
// stiffness ratio (2e10 N/m tyres on 1e3 N/m mounts give ~1e-8), far above rounding (~1e-16).
constexpr double kSingularPivotRatio = 1e-13;

}  // namespace

StaticEquilibriumSolver::StaticEquilibriumSolver(const SecondOrderSystem& system,
                                                 const Vector& generalized_force)
    : input_stiffness_(system.input_stiffness), generalized_force_(generalized_force) {
  validateSystem(system);
  const DofIndex n = system.size();
  if (generalized_force_.size() != 0)
    detail::requireLength("staticEquilibrium", "generalized force f_g", generalized_force_, n);
  // K is symmetric positive (semi-)definite: pivoted LDL^T. A free motion leaves a pivot at
  // rounding level (Eigen then solves in the least-squares sense, so test the pivots).
  factor_.compute(system.stiffness);
  const Vector pivots = factor_.vectorD().cwiseAbs();
  if (factor_.info() != Eigen::Success ||
      !(pivots.minCoeff() > kSingularPivotRatio * pivots.maxCoeff()) ||
      factor_.rcond() < std::numeric_limits<double>::epsilon())
    throw SolverError("staticEquilibrium: stiffness matrix K (" + detail::sizeText(n, n) +
                      ") is singular (free rigid-body motion); no static equilibrium");
}

Vector StaticEquilibriumSolver::solve(const Vector& heights) const {
  const DofIndex n = size();
  detail::requireLength("staticEquilibrium", "road heights u0", heights, inputCount());
  Vector load = input_stiffness_ * heights;
  if (generalized_force_.size() != 0)
    load += generalized_force_;
  Vector state = Vector::Zero(2 * n);
  state.head(n) = factor_.solve(load);
  return state;
}

Vector staticEquilibrium(const SecondOrderSystem& system, const Vector& heights,
                         const Vector& generalized_force) {
  return StaticEquilibriumSolver(system, generalized_force).solve(heights);
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
