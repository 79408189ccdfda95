// A linear second-order model driven by road displacements, the common currency between the
// reduction (which produces it) and the dynamics (FRF, time simulation):
//
//   M q'' + C q' + K q = K_u u + C_u u'          q [n], u [n_inputs] road heights [m]
//   y = H q                                      y [n_outputs] physical displacements
//
// For a full model q are the active DOFs; for a Craig-Bampton model q = {x_m | x_r}.
#pragma once

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

struct SecondOrderSystem {
  Matrix mass;             ///< M [n x n]
  Matrix damping;          ///< C [n x n]
  Matrix stiffness;        ///< K [n x n]
  Matrix input_stiffness;  ///< K_u [n x n_inputs]
  Matrix input_damping;    ///< C_u [n x n_inputs]
  Matrix output;           ///< H [n_outputs x n]: recovers physical displacements
  std::vector<std::string>
      output_names;  ///< one per row of H, e.g. "hull uz", "road_wheel_left_1 uz"
  /// Longitudinal station of each input relative to the vehicle reference point [m]
  /// (x forward), used for the wheelbase delay tau_q = L_q / v (paper eq. 24).
  Vector input_stations;
  /// Lateral position of each input [m] (y left), used to sample the terrain.
  Vector input_lateral;

  DofIndex size() const { return stiffness.rows(); }
  DofIndex inputCount() const { return input_stiffness.cols(); }
  DofIndex outputCount() const { return output.rows(); }
};

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
