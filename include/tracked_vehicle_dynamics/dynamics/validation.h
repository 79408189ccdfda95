// Up-front dimension checks of the second-order systems consumed by the dynamics module
// (STYLE.md #8): one check per matrix, each message naming the matrix and both sizes.
#pragma once

#include "tracked_vehicle_dynamics/dynamics/second_order_system.h"
#include "tracked_vehicle_dynamics/dynamics/sparse_second_order_system.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// Throws InputError, e.g. "SecondOrderSystem: damping C is 4x3, expected 4x4", when n = 0 or
/// M, C, K [n x n], K_u, C_u [n x n_inputs], H [n_outputs x n], output_names [n_outputs or 0],
/// input_stations / input_lateral [n_inputs or 0] disagree.
void validateSystem(const SecondOrderSystem& system);
/// Same checks for the sparse system.
void validateSystem(const SparseSecondOrderSystem& system);

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
