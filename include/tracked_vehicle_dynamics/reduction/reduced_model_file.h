// The reduced model on disk: a MAT 5 file (the cache of the reduction, and readable by MATLAB,
// Octave and scipy.io.loadmat; for users: doc/reduced_model_file.md). Variables, with k = m + r
// reduced coordinates:
//
//   format_version                 1x1      layout version (kReducedModelFormatVersion)
//   version                        char     software version that wrote it (softwareVersion())
//   description_hash               char     hash of the vehicle description (the caller's)
//   reduction                      char     variant and reduction options (the caller's)
//   created_utc, creator, damping_model  char
//   full_dof_count                 1x1      active DOFs of the full model
//   M_R, K_R, C_R                  k x k    reduced mass, stiffness, damping (paper eq. 9)
//   K_u, C_u                       k x n_in reduced road-input stiffness and damping
//   gravity_load                   k x 1    reduced gravity load [N, N m]
//   travel_load                    k x 1    reduced travel inertia load per unit forward
//                                           acceleration of the path frame [N, N m per m/s^2]
//   H                              n_out x k  output recovery rows, y = H x_R
//   output_names                   cell n_out x 1
//   dof_labels                     cell k x 1  "node 12 uz" ..., "mode 3 (12.4 Hz)" ...
//   input_labels                   cell n_in x 1  "node 5 uz"
//   input_stations, input_lateral  n_in x 1 (or 0 x 1)  x, y of each road input [m]
//   masters                        m x 2    node id, direction (0 ux .. 5 rz) of each master
//   master_positions               m x 3    undeformed x, y, z of each master's node [m]
//   master_groups                  cell m x 1  why each is a master: "road input", "hull", ...
//   fixed_interface_frequencies_hz r x 1    [Hz]
//   selected_mode_numbers          n_sel x 1  1-based global mode numbers (as in the reasons)
//   selected_mode_frequencies_hz   n_sel x 1  [Hz]
//   selected_mode_reasons          cell n_sel x 1
//   reduction_warnings             cell n_w x 1  what the reduction warned about (may be 0 x 1)
//   checksum                       char     FNV-1a 64-bit hash of all the above, written last
//
// The checksum catches what matio does not: values changed inside the file (matio does not
// verify zlib's check value) and a file cut before its last variable.
#pragma once

#include <string>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/reduction/reduced_model.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

/// Layout version of the file above; a file with another one is stale.
// 3: master_positions, master_groups; 4: travel_load; 5: reduction_warnings.
constexpr int kReducedModelFormatVersion = 5;

/// A reduced model file that cannot be used: missing, unreadable, truncated, corrupted,
/// inconsistent, or built from another description, software version or reduction. A cache
/// rebuilds it; a file the user named (`tvd frf --reduced`, the node's ~reduced_model) is
/// refused with the message, to which the caller adds its own advice (the message gives none).
class StaleCacheError : public InputError {
 public:
  using InputError::InputError;
};

struct ReducedModelLoadOptions {
  /// Refuse a file written by another software version: the reduction or the assembly may have
  /// changed even when the description did not.
  bool require_same_version = true;
  /// With require_same_version false: refuse a file of another release (the version before
  /// '+'), and take one of another build of this release (the commit after '+') with a warning
  /// in ReducedModel::warnings. A file the user names is a deliverable: a rebuild of the same
  /// release must not void it; a cache is rebuilt instead.
  bool require_same_release = true;
  /// When not empty, the file's `reduction` must equal it (same variant and reduction options).
  std::string expected_reduction;
  /// Relative symmetry tolerance of M_R, K_R, C_R: max|A - A^T| <= tol * max|A|.
  double symmetry_tolerance = 1e-9;
};

/// Writes the model (atomically: a temporary file renamed into place). Throws InputError when
/// the model is inconsistent (the same checks as loading) or the file cannot be written.
void saveReducedModel(const ReducedModel& model, const std::string& path);

/// Reads and validates a model: the file exists and is a complete MAT file, every variable is
/// present with consistent dimensions and finite values, M_R, K_R and C_R are symmetric, the
/// checksum matches, the format version is kReducedModelFormatVersion, the software version is
/// the current one (unless not required) and the description hash equals `expected_hash`.
/// Throws StaleCacheError whose message starts with the file name and says what is wrong.
ReducedModel loadReducedModel(const std::string& path, const std::string& expected_hash,
                              const ReducedModelLoadOptions& options = {});

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
