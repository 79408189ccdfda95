// Modal Geometric Selection Criterion, MoGeSeC (paper §3.1.2, eqs. 12-14; Bonisoli, Delprete,
// Rosso, MSSP 23(3), 2009): picks master DOFs one at a time where the retained modes move most
// and far from the DOFs already picked.
//
//   W_Phi(q) = sum_j |Phi_j(q)|^k_Phi                               (eq. 13, computed once)
//   W_g(q)   = 1                              with no master yet     (eq. 14)
//            = 1 / sum_i d_p(q, i)^(-k_g p)   otherwise, over the masters i chosen so far,
//              d_p(q, i) = ||x_q - x_i||_p the distance between the nodes carrying q and i [m]
//              (the paper's exponent -k_g p; with k_g = p = 2, 1 / sum_i d^-4, as Bonisoli et
//              al.'s squared Euclidean distance to the power -k_g: the nearest masters dominate)
//   W(q)     = W_Phi(q) / max W_Phi  *  W_g(q) / max W_g              (eq. 12)
//
// and the next master is argmax W over the candidates not chosen yet. The maxima are taken over
// the remaining candidates, so the weight of each pick lies in [0, 1]; they only scale W, so the
// choice is that of the unnormalised product.
//
// Co-located DOFs: a candidate at the position of a master (another direction of the same node,
// or a coincident node, within colocation_tolerance) has d = 0, an infinite term in the sum and
// W_g = 0. It is therefore picked only when every remaining candidate is co-located with a master;
// then geometry cannot tell them apart and W_g,N is taken as 1 for all, so the modal weight
// decides. Likewise W_Phi,N = 1 for all when the shapes vanish on every remaining candidate.
// Ties (W within a relative 1e-12) go to the lowest candidate index, so the result is
// deterministic and independent of round-off in symmetric structures.
#pragma once

#include <array>
#include <vector>

#include "tracked_vehicle_dynamics/fem/dof_map.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

struct MogesecOptions {
  int count = 9;                       ///< DOFs picked beyond the initial masters (Table 5: 9)
  double modal_exponent = 2.0;         ///< k_Phi, eq. 13 (2: optimal per Bonisoli et al.)
  double geometric_exponent = 2.0;     ///< k_g, eq. 14 (the distance's exponent is -k_g p)
  double norm_order = 2.0;             ///< p of the distance norm, eq. 14 (2: Euclidean)
  double colocation_tolerance = 1e-9;  ///< [m] distance below which two DOFs are co-located
};

struct MogesecPick {
  DofIndex index = 0;   ///< candidate row of the shapes (mogesec) or active DOF (selectMasters)
  double weight = 0.0;  ///< W = W_Phi,N * W_g,N at the moment of the pick, in [0, 1]
  double modal_weight = 0.0;      ///< W_Phi,N
  double geometric_weight = 0.0;  ///< W_g,N
};

struct MogesecResult {
  std::vector<MogesecPick> picks;  ///< in pick order, never repeating a DOF
  Vector modal_weight;             ///< W_Phi of every candidate (eq. 13), unnormalised
};

/// MoGeSeC over candidate DOFs. shapes: mode shapes [n_candidates x n_modes] restricted to the
/// candidates; positions: the node position of each candidate [m]; initial_masters: candidate
/// rows already chosen (e.g. the wheel centres and the hull DOFs, paper §3.1.2). Throws
/// InputError when sizes disagree, an initial master is out of range or repeated, an option is
/// out of range (count < 0, exponents <= 0, p < 1, tolerance < 0), count exceeds the candidates
/// left, or the shapes are not finite or vanish on every candidate.
MogesecResult mogesec(const Matrix& shapes, const std::vector<Vector3>& positions,
                      const std::vector<DofIndex>& initial_masters, const MogesecOptions& options);

/// Which active DOFs may become masters.
struct CandidateFilter {
  /// Allowed directions (ux uy uz rx ry rz). Default: translations, as the paper ignores
  /// rotations (§3.1.1).
  std::array<bool, kDofsPerNode> directions{{true, true, true, false, false, false}};
  std::vector<NodeId> excluded_nodes;  ///< nodes never picked

  /// Lateral and vertical translations only (uy, uz), the DOFs of the paper's Fig. 12.
  static CandidateFilter lateralAndVertical();
};

/// Active DOFs passing the filter, in active order.
std::vector<DofIndex> candidateDofs(const fem::DofMap& dofs, const CandidateFilter& filter);

struct MasterSelection {
  std::vector<DofIndex> masters;   ///< active DOFs: the initial masters, then the picks
  std::vector<MogesecPick> picks;  ///< the picks; index = active DOF
};

/// MoGeSeC on a system: candidates are the filtered active DOFs plus the initial masters (which
/// need not pass the filter). shapes: modes over all active DOFs [dofs.activeCount() x n_modes],
/// e.g. the selected global modes; initial_masters: active DOFs. Throws InputError as mogesec()
/// and for an initial master that is not an active DOF.
MasterSelection selectMasters(const fem::DofMap& dofs, const ModeShapes& shapes,
                              const std::vector<DofIndex>& initial_masters,
                              const CandidateFilter& filter, const MogesecOptions& options);

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
