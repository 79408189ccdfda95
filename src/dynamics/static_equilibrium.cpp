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

Vector staticEquilibrium(const SecondOrderSystem& system, const Vector& heights,
                         const Vector& generalized_force) {
  validateSystem(system);
  const DofIndex n = system.size();
  detail::requireLength("staticEquilibrium", "road heights u0", heights, system.inputCount());
  Vector load = system.input_stiffness * heights;
  if (generalized_force.size() != 0) {
    detail::requireLength("staticEquilibrium", "generalized force f_g", generalized_force, n);
    load += generalized_force;
  }
  // K is symmetric positive (semi-)definite: pivoted LDL^T. A free motion leaves a pivot at
  // rounding level (Eigen then solves in the least-squares sense, so test the pivots).
  const Eigen::LDLT<Matrix> factor(system.stiffness);
  const Vector pivots = factor.vectorD().cwiseAbs();
  if (factor.info() != Eigen::Success ||
      !(pivots.minCoeff() > kSingularPivotRatio * pivots.maxCoeff()) ||
      factor.rcond() < std::numeric_limits<double>::epsilon())
    throw SolverError("staticEquilibrium: stiffness matrix K (" + detail::sizeText(n, n) +
                      ") is singular (free rigid-body motion); no static equilibrium");
  Vector state = Vector::Zero(2 * n);
  state.head(n) = factor.solve(load);
  return state;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
