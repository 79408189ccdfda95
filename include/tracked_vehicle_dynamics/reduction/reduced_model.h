// The reduced model: a Craig-Bampton SecondOrderSystem (paper eq. 10) with everything needed to
// use it without the full model (labels, output recovery rows, gravity load) and to tell whether
// a cached copy still matches its description (hash, version). Saved and loaded by
// reduced_model_file.h.
#pragma once

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/dynamics/second_order_system.h"
#include "tracked_vehicle_dynamics/fem/model.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/reduction/craig_bampton.h"
#include "tracked_vehicle_dynamics/reduction/mode_selection.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

/// The software version written into reduced models: TVD_VERSION when the build defines it (the
/// CMake project version), otherwise "0.1.0".
const char* softwareVersion();

/// A physical output y = H x_R: a named nodal DOF. It may be active, fixed (its row of H is zero)
/// or a rigid-joint slave (its row combines the rows of its masters).
struct OutputDof {
  std::string name;  ///< e.g. "hull uz"; empty: "node 12 uz"
  fem::DofRef dof;
};

/// M_R x_R'' + C_R x_R' + K_R x_R = K_u,R u + C_u,R u' + f_g,R,  y = H x_R,  x_R = {x_m | x_r}
/// with k = m + r coordinates: m master DOFs [m, rad] then r fixed-interface modal amplitudes.
struct ReducedModel {
  /// M_R, C_R, K_R [k x k]; K_u, C_u [k x n_inputs]; H [n_outputs x k] with output_names; input
  /// stations/lateral: x and y of the node under each road input [m] (global frame; empty when
  /// a node has no active DOF).
  dynamics::SecondOrderSystem system;
  Vector gravity_load;                    ///< T^T f_g [k] [N, N m]
  std::vector<std::string> dof_labels;    ///< k labels: "node 12 uz", then "mode 3 (12.4 Hz)"
  std::vector<fem::DofRef> masters;       ///< physical DOF of each of the m master coordinates
  Vector fixed_interface_frequencies_hz;  ///< one per fixed-interface mode [Hz]
  std::vector<std::string> input_labels;  ///< one per road input: "node 5 uz"
  /// The global modes the reduction was sized for, with the reason for each.
  std::vector<SelectedMode> selected_modes;
  std::string damping;           ///< describe(DampingOptions)
  std::string description_hash;  ///< hash of the description it was built from (caller's)
  std::string version;           ///< softwareVersion() at creation
  std::string created_utc;       ///< "2024-05-01T12:00:00Z"
  std::string creator;           ///< free text, e.g. "tvd reduce"
  DofIndex full_dof_count = 0;   ///< active DOFs of the full model

  DofIndex size() const { return system.size(); }
  DofIndex masterCount() const { return static_cast<DofIndex>(masters.size()); }
  DofIndex modeCount() const { return fixed_interface_frequencies_hz.size(); }
};

struct ReductionRequest {
  std::vector<DofIndex> masters;      ///< active DOFs, e.g. MasterSelection::masters
  CraigBamptonOptions craig_bampton;  ///< its recovery_dofs are set from `outputs`
  std::vector<OutputDof> outputs;     ///< rows of H
  ModeSelection selection;            ///< recorded with the model for the report
  std::string description_hash;
  std::string creator;
};

/// Each output as a combination of active DOFs, one (active index, coefficient) list per output:
/// its row of the constraint transformation u_phys = T u_active (empty for a fixed DOF, the
/// master's terms for a rigid-joint slave). Throws InputError naming an output on an unknown
/// node or direction.
std::vector<std::vector<std::pair<DofIndex, double>>> outputTerms(
    const fem::DofMap& dofs, const std::vector<OutputDof>& outputs);

/// Output names: each output's name, or its label when empty. Throws InputError for a repeated
/// name.
std::vector<std::string> outputNames(const std::vector<OutputDof>& outputs);

/// x and y [m] of the node under each road input of the system (x forward, y left); both empty
/// when some input's node has no active DOF.
void inputPositions(const fem::System& system, Vector* stations, Vector* lateral);

/// Runs craigBampton() on `system` and packages the result. Throws InputError for an output on
/// an unknown node or bad direction, repeated output names, and whatever craigBampton() throws.
ReducedModel buildReducedModel(const fem::System& system, const ReductionRequest& request);

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
