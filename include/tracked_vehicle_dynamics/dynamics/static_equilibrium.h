// Initial state at rest under a constant load: K q0 = K_u u0 + f_g, q0' = 0, so that a
// simulation started there with w = [u0; 0] stays there (no start-up transient).
#pragma once

#include "tracked_vehicle_dynamics/dynamics/second_order_system.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// State z0 = [K^-1 (K_u u0 + f_g); 0] [2n] for road heights u0 [n_inputs] [m] and an optional
/// constant generalised force f_g [n] [N, N m] (empty: none; e.g. gravity).
/// Throws InputError for wrong lengths, SolverError when K is singular (a free rigid-body motion
/// has no static equilibrium).
Vector staticEquilibrium(const SecondOrderSystem& system, const Vector& heights,
                         const Vector& generalized_force = Vector());

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
