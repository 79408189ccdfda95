// The assembled linear system  M x'' + C x' + K x = f  over the active DOFs.
#pragma once

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/fem/dof_map.h"
#include "tracked_vehicle_dynamics/fem/model.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace fem {

/// Sparse symmetric system matrices over the active DOFs [n x n], n = dofs.activeCount().
struct System {
  SparseMatrix mass;       ///< M [kg, kg m, kg m^2]
  SparseMatrix stiffness;  ///< K [N/m, N/rad, N m/rad]
  SparseMatrix damping;    ///< C from discrete dampers [N s/m, ...]
  Vector gravity_load;     ///< f_g = T^T M_phys a_g [N, N m]
  /// Travel inertia per unit forward acceleration of the path frame: f_a = -T^T M_phys e_x with
  /// e_x = (1, 0, 0) on every node's translations [N, N m per m/s^2]. The model lives in the path
  /// frame, which translates with the station s(t); when the speed changes (a = dv/dt) every
  /// mass feels -m a along x, so the load on the structure is a(t) f_a.
  Vector travel_load;
  DofMap dofs;
  /// K holds the geometric stiffness of pre-loads (Model::ties, body_preloads, beams' axial
  /// forces): a compressive one can make it singular or indefinite (buckling).
  bool prestressed = false;
  /// Ground springs as road inputs: the force on the structure is K_u u + C_u u' where u holds
  /// the vertical ground displacement under each grounded spring in `ground_inputs` order.
  SparseMatrix input_stiffness;       ///< K_u [n x n_inputs]
  SparseMatrix input_damping;         ///< C_u [n x n_inputs]
  std::vector<DofRef> ground_inputs;  ///< the node under each input (direction uz)
  /// Named DOF sets resolved to active indices (entries that are not active are dropped and
  /// listed in `dropped_set_entries`).
  std::map<std::string, std::vector<DofIndex>> dof_sets;
  std::vector<std::string> dropped_set_entries;

  DofIndex size() const { return stiffness.rows(); }
  /// The static load of a steady forward acceleration a [m/s^2] (braking < 0): f_g + a f_a;
  /// f_g itself at a = 0.
  Vector steadyLoad(double forward_acceleration) const {
    return gravity_load + forward_acceleration * travel_load;
  }
};

/// Options of the assembly.
struct AssemblyOptions {
  /// Drop physical DOFs that receive neither stiffness nor mass (e.g. the rotations of a node
  /// joined only by translational springs); they are decoupled, so dropping them is exact and
  /// keeps K and M free of empty rows.
  bool drop_null_dofs = true;
};

/// Assembles M, K, C, the gravity load and the road-input matrices of a validated model.
/// Throws InputError for inconsistent models (see validate()).
System assemble(const Model& model, const AssemblyOptions& options = {});

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
