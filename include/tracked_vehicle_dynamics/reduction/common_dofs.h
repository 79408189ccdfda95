// The DOFs two models share, so that their mode shapes can be compared with the MAC (paper
// §3.1.1: "the MAC application is limited to the common DOFs in both models. Also, rotational
// DOFs are ignored, by preferring equivalent translation DOFs").
#pragma once

#include <vector>

#include "tracked_vehicle_dynamics/fem/dof_map.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

/// The (node, direction) of every active DOF, in active order: the rows of that system's shapes.
std::vector<fem::DofRef> activeDofRefs(const fem::DofMap& dofs);

/// Rows of two shape matrices that hold the same physical DOFs, in the same order.
struct CommonDofs {
  std::vector<fem::DofRef> dofs;  ///< the shared DOFs, in the order of the A list
  std::vector<DofIndex> rows_a;   ///< row of each shared DOF in A's shapes
  std::vector<DofIndex> rows_b;   ///< row of each shared DOF in B's shapes

  DofIndex size() const { return static_cast<DofIndex>(dofs.size()); }
};

/// The translational DOFs (ux, uy, uz) present in both lists (same node id and direction), in
/// the order of `dofs_a`. Throws InputError when a list names a DOF twice or a direction is not
/// in 0..5. Rows of two DOF lists, for any two systems; which nodes two vehicle models share (by
/// id and position) is vehicle::commonTranslationalDofs().
CommonDofs commonTranslationalRows(const std::vector<fem::DofRef>& dofs_a,
                                   const std::vector<fem::DofRef>& dofs_b);

/// The given rows of `shapes` [rows.size() x shapes.cols()]. Throws InputError naming an
/// out-of-range row.
Matrix selectRows(const Matrix& shapes, const std::vector<DofIndex>& rows);

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
