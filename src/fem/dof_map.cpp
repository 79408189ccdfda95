#include "tracked_vehicle_dynamics/fem/dof_map.h"

#include <algorithm>
#include <sstream>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace fem {

namespace {

// A physical DOF written as a combination of independent physical DOFs.
using Expression = std::vector<std::pair<DofIndex, double>>;

struct SlaveLink {
  std::size_t joint = 0;
  DofIndex master_node = 0;       // node position of the master
  Vector3 arm = Vector3::Zero();  // x_slave - x_master
};

class Resolver {
 public:
  Resolver(const std::vector<char>& status, const std::vector<int>& link_of,
           const std::vector<SlaveLink>& links)
      : status_(status),
        link_of_(link_of),
        links_(links),
        memo_(status.size()),
        state_(status.size(), 0) {}

  // Iterative (a chain of 200,000 rigid joints overflowed the stack when this recursed), and each
  // expression is merged per DOF: a slave in a chain depends on the 6 DOFs of the chain's root
  // however long the chain is (appending unmerged grew as the square of its length).
  const Expression& resolve(DofIndex root) {
    std::vector<DofIndex> stack{root};
    while (!stack.empty()) {
      const DofIndex p = stack.back();
      if (state_[p] == 2) {
        stack.pop_back();
        continue;
      }
      if (status_[p] != 's') {
        if (status_[p] == 'a')
          memo_[p].emplace_back(p, 1.0);
        state_[p] = 2;
        stack.pop_back();
        continue;
      }
      const SlaveLink& link = links_[link_of_[p]];
      const int d = static_cast<int>(p % kDofsPerNode);
      const DofIndex base = link.master_node * kDofsPerNode;
      // u_s = u_m + theta_m x r:  (theta x r)_d = sum_j c_j theta_j
      const Vector3& r = link.arm;
      const double c[3][3] = {{0.0, r.z(), -r.y()}, {-r.z(), 0.0, r.x()}, {r.y(), -r.x(), 0.0}};
      std::pair<DofIndex, double> terms[4];
      int count = 0;
      terms[count++] = {base + d, 1.0};
      if (d < 3)
        for (int j = 0; j < 3; ++j)
          if (c[d][j] != 0.0)
            terms[count++] = {base + 3 + j, c[d][j]};
      if (state_[p] == 0) {  // first visit: resolve the master's DOFs first
        state_[p] = 1;
        for (int k = 0; k < count; ++k) {
          const DofIndex q = terms[k].first;
          if (state_[q] == 1)
            throw InputError("rigid joints form a cycle through physical DOF " + std::to_string(q));
          if (state_[q] == 0)
            stack.push_back(q);
        }
        continue;
      }
      Expression e;
      for (int k = 0; k < count; ++k)
        append(e, memo_[terms[k].first], terms[k].second);
      memo_[p] = merged(std::move(e));
      state_[p] = 2;
      stack.pop_back();
    }
    return memo_[root];
  }

 private:
  static void append(Expression& e, const Expression& src, double scale) {
    for (const auto& [dof, coef] : src)
      e.emplace_back(dof, coef * scale);
  }
  /// One term per DOF, coefficients summed.
  static Expression merged(Expression e) {
    std::sort(e.begin(), e.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    Expression out;
    for (const auto& term : e) {
      if (!out.empty() && out.back().first == term.first)
        out.back().second += term.second;
      else
        out.push_back(term);
    }
    return out;
  }
  const std::vector<char>& status_;
  const std::vector<int>& link_of_;
  const std::vector<SlaveLink>& links_;
  std::vector<Expression> memo_;
  std::vector<char> state_;
};

}  // namespace

DofMap DofMap::build(const Model& model, const std::vector<bool>& inactive) {
  DofMap map;
  map.node_index_ = model.nodeIndex();
  map.node_ids_.reserve(model.nodes.size());
  map.positions_.reserve(model.nodes.size());
  for (const Node& n : model.nodes) {
    map.node_ids_.push_back(n.id);
    map.positions_.push_back(n.position);
  }
  const DofIndex n_phys = map.physicalCount();
  map.status_.assign(n_phys, 'a');

  auto nodePos = [&](NodeId id, const std::string& where) -> std::size_t {
    const auto it = map.node_index_.find(id);
    if (it == map.node_index_.end())
      throw InputError(where + ": node " + std::to_string(id) + " does not exist");
    return it->second;
  };

  for (std::size_t i = 0; i < model.fixed.size(); ++i) {
    const auto pos = nodePos(model.fixed[i].node, "fixed[" + std::to_string(i) + "]");
    for (int d = 0; d < kDofsPerNode; ++d)
      if (model.fixed[i].dofs[d])
        map.status_[pos * kDofsPerNode + d] = 'f';
  }

  std::vector<int> link_of(n_phys, -1);
  std::vector<SlaveLink> links;
  for (std::size_t j = 0; j < model.rigid_joints.size(); ++j) {
    const RigidJoint& joint = model.rigid_joints[j];
    const std::string where = "rigid_joints[" + std::to_string(j) + "]";
    const auto master = nodePos(joint.master, where);
    for (NodeId slave_id : joint.slaves) {
      const auto slave = nodePos(slave_id, where);
      if (slave == master)
        throw InputError(where + ": node " + std::to_string(slave_id) + " is its own master");
      SlaveLink link;
      link.joint = j;
      link.master_node = static_cast<DofIndex>(master);
      link.arm = map.positions_[slave] - map.positions_[master];
      links.push_back(link);
      for (int d = 0; d < kDofsPerNode; ++d) {
        if (!joint.dofs[d])
          continue;
        const DofIndex p = static_cast<DofIndex>(slave) * kDofsPerNode + d;
        if (map.status_[p] == 'f')
          throw InputError(where + ": node " + std::to_string(slave_id) + " " + directionName(d) +
                           " is both fixed and a rigid-joint slave");
        if (link_of[p] >= 0)
          throw InputError(where + ": node " + std::to_string(slave_id) + " " + directionName(d) +
                           " is already a slave of rigid_joints[" +
                           std::to_string(links[link_of[p]].joint) + "]");
        link_of[p] = static_cast<int>(links.size() - 1);
        map.status_[p] = 's';
      }
    }
  }
  for (DofIndex p = 0; p < static_cast<DofIndex>(inactive.size()) && p < n_phys; ++p)
    if (inactive[p] && map.status_[p] == 'a')
      map.status_[p] = 'n';

  map.physical_to_active_.assign(n_phys, -1);
  for (DofIndex p = 0; p < n_phys; ++p) {
    if (map.status_[p] != 'a')
      continue;
    map.physical_to_active_[p] = static_cast<DofIndex>(map.active_to_physical_.size());
    map.active_to_physical_.push_back(p);
  }

  Resolver resolver(map.status_, link_of, links);
  std::vector<Triplet> triplets;
  triplets.reserve(n_phys * 2);
  for (DofIndex p = 0; p < n_phys; ++p)
    for (const auto& [q, coef] : resolver.resolve(p))
      triplets.emplace_back(p, map.physical_to_active_[q], coef);
  map.transformation_.resize(n_phys, map.activeCount());
  map.transformation_.setFromTriplets(triplets.begin(), triplets.end());
  map.transformation_.makeCompressed();
  return map;
}

DofIndex DofMap::physical(NodeId node, int direction) const {
  const auto it = node_index_.find(node);
  if (it == node_index_.end())
    throw InputError("node " + std::to_string(node) + " does not exist");
  if (direction < 0 || direction >= kDofsPerNode)
    throw InputError("direction " + std::to_string(direction) + " is not in 0..5");
  return static_cast<DofIndex>(it->second) * kDofsPerNode + direction;
}

DofIndex DofMap::active(NodeId node, int direction) const {
  return physical_to_active_[physical(node, direction)];
}

DofIndex DofMap::requireActive(NodeId node, int direction) const {
  const DofIndex p = physical(node, direction);
  if (physical_to_active_[p] >= 0)
    return physical_to_active_[p];
  const char* why = status_[p] == 'f'   ? "fixed"
                    : status_[p] == 's' ? "a rigid-joint slave"
                                        : "not connected (no stiffness and no mass)";
  throw InputError("node " + std::to_string(node) + " " + directionName(direction) +
                   " is not an active DOF: it is " + why);
}

DofRef DofMap::dofOf(DofIndex active_index) const {
  const DofIndex p = active_to_physical_.at(active_index);
  return DofRef{node_ids_[p / kDofsPerNode], static_cast<int>(p % kDofsPerNode)};
}

std::string DofMap::label(DofIndex active_index) const {
  const DofRef d = dofOf(active_index);
  return "node " + std::to_string(d.node) + " " + directionName(d.direction);
}

const Vector3& DofMap::positionOf(DofIndex active_index) const {
  return positions_[active_to_physical_.at(active_index) / kDofsPerNode];
}

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
