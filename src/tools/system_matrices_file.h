// matrices.mat (tvd modes --out DIR --matrices): the assembled full model, for an engineer to
// check the tool's modes, statics, FRFs and time responses with code of their own (SciPy,
// MATLAB, Octave) or to take the model elsewhere:
//   M q'' + C q' + K q = f_g + a f_a + K_u u + C_u u'
// over the active DOFs q (rows named by dof_node, dof_direction, dof_labels), u the road height
// under each ground input (input_node; a vehicle's input_station along the road).
#pragma once

#include <string>

#include "output_files.h"
#include "tracked_vehicle_dynamics/fem/model.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/types.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"

namespace tracked_vehicle_dynamics {
namespace tools {

/// What a vehicle adds to the matrices: where its inputs lie and the damping the dynamics add to
/// C (which holds the discrete dampers only).
struct VehicleMatrixExtras {
  Vector input_stations;  ///< x of each ground input along the road [m]
  vehicle::DampingDescription damping;
};

/// Writes `path` (.mat): M, K, C, K_u, C_u (sparse), gravity_load, travel_load, the DOF table
/// (dof_node, dof_direction 0..5 = ux uy uz rx ry rz, dof_labels), input_node, node_id and
/// node_position [m] of every model node, then the vehicle's input_station and damping
/// (damping_model, modal_damping_ratio, rayleigh_alpha [1/s], rayleigh_beta [s]) when given,
/// then `metadata`. Throws InputError naming the file when it cannot be written.
void writeSystemMatrices(const std::string& path, const fem::Model& model, const fem::System& sys,
                         const VehicleMatrixExtras* vehicle, const Metadata& metadata);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
