// Map between physical DOFs (node, direction) and the active DOFs of the assembled system.
// Physical DOFs are either active, fixed (held at zero) or dependent (rigid-joint slaves).
// The constraint transformation u_phys = T u_active eliminates rigid joints exactly.
#pragma once

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/fem/model.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace fem {

class DofMap {
 public:
  /// Number of physical DOFs (6 per node).
  DofIndex physicalCount() const { return static_cast<DofIndex>(node_ids_.size()) * kDofsPerNode; }
  /// Number of active (independent, unconstrained) DOFs.
  DofIndex activeCount() const { return static_cast<DofIndex>(active_to_physical_.size()); }

  /// Physical index of (node, direction) = 6 * node position + direction. Throws InputError for
  /// an unknown node.
  DofIndex physical(NodeId node, int direction) const;
  /// Active index of (node, direction), or -1 when that DOF is fixed or a rigid-joint slave.
  DofIndex active(NodeId node, int direction) const;
  /// Active index or InputError naming the DOF and why it is not active.
  DofIndex requireActive(NodeId node, int direction) const;
  /// The physical DOF behind an active index.
  DofRef dofOf(DofIndex active_index) const;
  /// "node 12 uz"
  std::string label(DofIndex active_index) const;
  /// Global position of the node that carries an active DOF [m].
  const Vector3& positionOf(DofIndex active_index) const;

  /// u_phys = T u_active [physicalCount x activeCount].
  const SparseMatrix& transformation() const { return transformation_; }

  const std::vector<NodeId>& nodeIds() const { return node_ids_; }

  /// Builds the map: fixed DOFs removed, rigid-joint slaves expressed in their ultimate masters.
  /// `inactive` (optional, size physicalCount) marks further physical DOFs to drop (no stiffness
  /// and no mass). Throws InputError on conflicting constraints (a fixed DOF that is also a slave).
  static DofMap build(const Model& model, const std::vector<bool>& inactive = {});

 private:
  std::vector<NodeId> node_ids_;    // by node position
  std::vector<Vector3> positions_;  // by node position
  std::unordered_map<NodeId, std::size_t> node_index_;
  std::vector<DofIndex> physical_to_active_;  // -1 when not active
  std::vector<DofIndex> active_to_physical_;
  std::vector<char> status_;  // 'a' active, 'f' fixed, 's' slave, 'n' null
  SparseMatrix transformation_;
};

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
