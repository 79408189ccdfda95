// The sparse counterpart of SecondOrderSystem, for full (unreduced) models used as a reference:
//
//   M q'' + C q' + K q = K_u u + C_u u'          q [n], u [n_inputs] road heights [m]
//   y = H q
//
// Built from a fem::System's mass, damping, stiffness, input_stiffness and input_damping with an
// output matrix H of the caller's (e.g. reduction::outputTerms), or from a dense system by
// toSparse().
#pragma once

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/dynamics/second_order_system.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

struct SparseSecondOrderSystem {
  SparseMatrix mass;                      ///< M [n x n]
  SparseMatrix damping;                   ///< C [n x n]
  SparseMatrix stiffness;                 ///< K [n x n]
  SparseMatrix input_stiffness;           ///< K_u [n x n_inputs]
  SparseMatrix input_damping;             ///< C_u [n x n_inputs]
  SparseMatrix output;                    ///< H [n_outputs x n]
  std::vector<std::string> output_names;  ///< one per row of H (may be empty)
  Vector input_stations;  ///< x station of each input [m] (may be empty), see SecondOrderSystem

  DofIndex size() const { return stiffness.rows(); }
  DofIndex inputCount() const { return input_stiffness.cols(); }
  DofIndex outputCount() const { return output.rows(); }
};

/// Sparse copy of a dense system (exact zeros dropped).
SparseSecondOrderSystem toSparse(const SecondOrderSystem& system);

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
