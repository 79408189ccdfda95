// Initial state at rest under a constant load: K q0 = K_u u0 + f_g, q0' = 0, so that a
// simulation started there with w = [u0; 0] stays there (no start-up transient).
#pragma once

#include <Eigen/Cholesky>

#include "tracked_vehicle_dynamics/dynamics/second_order_system.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// Static equilibrium of one system for any road heights, K factored once:
///   K q0 = f_g + K_u u0,   q0' = 0,   z0 = [q0; 0]                        [2n]
/// with K [n x n], K_u [n x n_inputs], u0 the road heights under the inputs [m] and f_g a
/// constant generalised force [n] [N, N m] (gravity). Linear in u0: a uniform height h under
/// every input lifts a vehicle that stands only on its road inputs rigidly by h (K r_h = K_u h 1
/// for the rigid vertical translation r_h), so q0(h 1) = q0(0) + r_h. A solve costs
/// O(n^2 + n n_inputs), so a simulator can be reset to the equilibrium on a new terrain at run
/// time (OnlineVehicle::resetTo).
class StaticEquilibriumSolver {
 public:
  /// Factors K. Throws InputError for a wrong length of f_g (empty: none) or an invalid system,
  /// SolverError when K is singular (a free rigid-body motion has no static equilibrium).
  explicit StaticEquilibriumSolver(const SecondOrderSystem& system,
                                   const Vector& generalized_force = Vector());

  /// z0 = [q0; 0] [2n] for road heights u0 [n_inputs] [m]. Throws InputError for a wrong length.
  Vector solve(const Vector& heights) const;

  DofIndex size() const { return input_stiffness_.rows(); }
  Eigen::Index inputCount() const { return input_stiffness_.cols(); }

 private:
  Eigen::LDLT<Matrix> factor_;
  Matrix input_stiffness_;    // K_u
  Vector generalized_force_;  // f_g, empty: none
};

/// State z0 = [K^-1 (K_u u0 + f_g); 0] [2n] for road heights u0 [n_inputs] [m] and an optional
/// constant generalised force f_g [n] [N, N m] (empty: none; e.g. gravity): one
/// StaticEquilibriumSolver solve. Throws InputError for wrong lengths, SolverError when K is
/// singular (a free rigid-body motion has no static equilibrium).
Vector staticEquilibrium(const SecondOrderSystem& system, const Vector& heights,
                         const Vector& generalized_force = Vector());

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
