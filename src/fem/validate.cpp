// fem::validate(): every consistency check on a Model, in file order, throwing at the first
// failure with "<where>: <item>[<index>]: <what is wrong>".
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/model.h"

namespace tracked_vehicle_dynamics {
namespace fem {
namespace {

/// A beam shorter than this fraction of the model's coordinate scale (at least 1 m) has
/// coincident nodes: its stiffness would scale with 1/L^3 and swamp the system.
constexpr double kCoincidentTolerance = 1e-12;
/// sin(angle) between a beam axis and its orientation vector below which the local frame is
/// undefined (the orientation is "parallel").
constexpr double kParallelSineTolerance = 1e-6;
/// Largest |R^T R - I| entry accepted for a spring frame; frames typed by hand with ~9 digits
/// pass, a frame that is merely "nearly" a rotation does not.
constexpr double kOrthonormalTolerance = 1e-6;
/// Relative tolerance for the symmetry and semi-definiteness of an inertia tensor.
constexpr double kInertiaTolerance = 1e-9;
/// A body pre-load's resultant (and moment / model size) as a share of its forces' sum: round-off
/// of forces summed from members' directions, far below a load that was meant.
constexpr double kPreloadBalanceTolerance = 1e-9;

const char* const kStiffnessNames[kDofsPerNode] = {"kx", "ky", "kz", "krx", "kry", "krz"};
const char* const kDampingNames[kDofsPerNode] = {"cx", "cy", "cz", "crx", "cry", "crz"};
const char* const kInertiaNames[3] = {"Ixx", "Iyy", "Izz"};

std::string dofLabel(NodeId node, int direction) {
  return "node " + std::to_string(node) + " " + directionName(direction);
}

class Validator {
 public:
  Validator(const Model& model, const std::string& where) : model_(model), where_(where) {}

  void run() {
    checkGravity();
    checkNodes();
    checkMaterials();
    checkSections();
    for (std::size_t i = 0; i < model_.beams.size(); ++i)
      checkBeam(i);
    for (std::size_t i = 0; i < model_.springs.size(); ++i)
      checkSpring(i);
    for (std::size_t i = 0; i < model_.masses.size(); ++i)
      checkMass(i);
    for (std::size_t i = 0; i < model_.rigid_joints.size(); ++i)
      checkRigidJoint(i);
    checkRigidJointCycles();
    for (std::size_t i = 0; i < model_.fixed.size(); ++i)
      checkFixed(i);
    for (std::size_t i = 0; i < model_.ties.size(); ++i)
      checkTie(i);
    for (std::size_t i = 0; i < model_.body_preloads.size(); ++i)
      checkBodyPreload(i);
    for (const auto& [name, dofs] : model_.dof_sets)
      checkSet(name, dofs);
  }

 private:
  [[noreturn]] void fail(const std::string& item, const std::string& what) const {
    throw InputError(where_ + ": " + item + ": " + what);
  }
  static std::string item(const char* list, std::size_t index) {
    return std::string(list) + "[" + std::to_string(index) + "]";
  }

  void requireNode(const std::string& label, NodeId id) const {
    if (node_index_.count(id) == 0) {
      fail(label, "node " + std::to_string(id) + " does not exist");
    }
  }
  void requireFinite(const std::string& label, double value, const std::string& what) const {
    if (!std::isfinite(value)) {
      fail(label, "non-finite " + what + " (" + brief(value) + ")");
    }
  }
  void requirePositive(const std::string& label, double value, const std::string& what,
                       const char* unit) const {
    requireFinite(label, value, what);
    if (value <= 0.0) {
      fail(label, "non-positive " + what + " " + brief(value) + (*unit ? " " : "") + unit);
    }
  }
  void requireNonNegative(const std::string& label, double value, const std::string& what,
                          const char* unit) const {
    requireFinite(label, value, what);
    if (value < 0.0) {
      fail(label, "negative " + what + " " + brief(value) + (*unit ? " " : "") + unit);
    }
  }

  /// n2 - n1 of a two-node element (`what`: "beam", "tie"), whose nodes must not coincide: its
  /// stiffness grows as a power of 1/L.
  Vector3 requireLength(const std::string& label, NodeId n1, NodeId n2, const char* what) const {
    const Vector3 d =
        model_.nodes[node_index_.at(n2)].position - model_.nodes[node_index_.at(n1)].position;
    if (d.norm() <= kCoincidentTolerance * scale_) {
      fail(label, std::string("zero-length ") + what + ": nodes " + std::to_string(n1) + " and " +
                      std::to_string(n2) + " coincide");
    }
    return d;
  }

  void checkGravity() const {
    if (!model_.gravity.allFinite()) {
      fail("gravity", "non-finite gravity vector");
    }
  }

  void checkNodes() {
    for (std::size_t i = 0; i < model_.nodes.size(); ++i) {
      const Node& node = model_.nodes[i];
      if (node.id == kGround) {
        // kGround is how springs say "the ground"; a node with that id would be ambiguous.
        fail(item("nodes", i),
             "node id " + std::to_string(kGround) + " is reserved for the ground");
      }
      const auto [it, inserted] = node_index_.emplace(node.id, i);
      if (!inserted) {
        fail(item("nodes", i), "duplicate node id " + std::to_string(node.id) + " (also nodes[" +
                                   std::to_string(it->second) + "])");
      }
      if (!node.position.allFinite()) {
        fail(item("nodes", i), "non-finite coordinates of node " + std::to_string(node.id));
      }
      // Beyond 1e9 m a coordinate is a unit mistake, and lengths squared lose all precision
      // (1e300 overflowed into a misleading "orientation parallel to the axis").
      if (node.position.cwiseAbs().maxCoeff() > 1e9) {
        fail(item("nodes", i),
             "coordinates of node " + std::to_string(node.id) + " lie beyond 1e9 m");
      }
      scale_ = std::max(scale_, node.position.cwiseAbs().maxCoeff());
    }
  }

  void checkMaterials() const {
    std::map<std::string, std::size_t> seen;
    for (std::size_t i = 0; i < model_.materials.size(); ++i) {
      const Material& material = model_.materials[i];
      const std::string label = item("materials", i);
      if (material.name.empty()) {
        fail(label, "material has no name");
      }
      if (!seen.emplace(material.name, i).second) {
        fail(label, "duplicate material name '" + material.name + "' (also materials[" +
                        std::to_string(seen[material.name]) + "])");
      }
      requirePositive(label, material.young_modulus, "Young's modulus E", "Pa");
      requirePositive(label, material.shear_modulus, "shear modulus G", "Pa");
      requireNonNegative(label, material.density, "density rho", "kg/m^3");
    }
  }

  void checkSections() const {
    std::map<std::string, std::size_t> seen;
    for (std::size_t i = 0; i < model_.sections.size(); ++i) {
      const Section& section = model_.sections[i];
      const std::string label = item("sections", i);
      if (section.name.empty()) {
        fail(label, "section has no name");
      }
      if (!seen.emplace(section.name, i).second) {
        fail(label, "duplicate section name '" + section.name + "' (also sections[" +
                        std::to_string(seen[section.name]) + "])");
      }
      requirePositive(label, section.area, "area A", "m^2");
      requirePositive(label, section.iy, "second moment Iy", "m^4");
      requirePositive(label, section.iz, "second moment Iz", "m^4");
      requirePositive(label, section.torsion, "torsion constant J", "m^4");
      // The shear area factor x A cannot exceed the section's area (uniform shear: 1; 5/6 a
      // rectangle, 0.5 a thin tube): 9.2e18 was accepted, a typo that only made the beam
      // Euler-Bernoulli (Phi -> 0), which 0 says.
      for (const auto& [factor, key] :
           {std::pair<double, const char*>{section.shear_factor_y, "shear_factor_y"},
            {section.shear_factor_z, "shear_factor_z"}}) {
        requireNonNegative(label, factor, std::string("shear factor ") + key, "");
        if (factor > 1.0)
          fail(label, std::string("shear factor ") + key + " " + brief(factor) +
                          " is above 1: the shear area (factor x A) cannot exceed the section's "
                          "area (5/6 for a rectangle, 0.5 for a thin tube; 0 for Euler-Bernoulli)");
      }
    }
  }

  void checkBeam(std::size_t i) const {
    const Beam& beam = model_.beams[i];
    const std::string label = item("beams", i);
    requireNode(label, beam.n1);
    requireNode(label, beam.n2);
    if (model_.findMaterial(beam.material) == nullptr) {
      fail(label, "material '" + beam.material + "' does not exist");
    }
    if (model_.findSection(beam.section) == nullptr) {
      fail(label, "section '" + beam.section + "' does not exist");
    }
    requireFinite(label, beam.axial_force, "axial force");
    const Vector3 axis = requireLength(label, beam.n1, beam.n2, "beam");
    if (!beam.orientation.allFinite()) {
      fail(label, "non-finite orientation vector");
    }
    if (beam.orientation.norm() == 0.0) {
      fail(label, "orientation vector is zero");
    }
    const double sine = axis.normalized().cross(beam.orientation.normalized()).norm();
    if (sine < kParallelSineTolerance) {
      fail(label, "orientation vector is parallel to the beam axis (nodes " +
                      std::to_string(beam.n1) + " -> " + std::to_string(beam.n2) + ")");
    }
  }

  void checkSpring(std::size_t i) const {
    const Spring& spring = model_.springs[i];
    const std::string label = item("springs", i);
    if (spring.n1 == kGround) {
      fail(label, "the first node must be a node, not the ground");
    }
    requireNode(label, spring.n1);
    if (spring.n2 != kGround) {
      requireNode(label, spring.n2);
    }
    if (spring.n1 == spring.n2) {
      fail(label, "spring connects node " + std::to_string(spring.n1) + " to itself");
    }
    for (int d = 0; d < kDofsPerNode; ++d) {
      requireNonNegative(label, spring.stiffness[d], std::string("stiffness ") + kStiffnessNames[d],
                         d < 3 ? "N/m" : "N m/rad");
      requireNonNegative(label, spring.damping[d], std::string("damping ") + kDampingNames[d],
                         d < 3 ? "N s/m" : "N m s/rad");
    }
    if (!spring.frame.allFinite()) {
      fail(label, "non-finite frame");
    }
    const double orthonormality_error =
        (spring.frame.transpose() * spring.frame - Matrix3::Identity()).cwiseAbs().maxCoeff();
    if (orthonormality_error > kOrthonormalTolerance) {
      fail(label, "frame is not orthonormal (max |R^T R - I| = " + brief(orthonormality_error) +
                      "; the axes must be unit vectors at right angles)");
    }
    if (spring.frame.determinant() < 0.0) {
      fail(label, "frame is left-handed (z must equal x cross y)");
    }
  }

  void checkTie(std::size_t i) const {
    const Tie& tie = model_.ties[i];
    const std::string label = item("ties", i);
    requireNode(label, tie.n1);
    requireNode(label, tie.n2);
    requireFinite(label, tie.force, "force");
    // Its stiffness is F / L: a tie needs a length to turn through.
    requireLength(label, tie.n1, tie.n2, "tie");
  }

  void checkBodyPreload(std::size_t i) const {
    const BodyPreload& body = model_.body_preloads[i];
    const std::string label = item("body_preloads", i);
    requireNode(label, body.node);
    if (body.points.size() != body.forces.size()) {
      fail(label, std::to_string(body.points.size()) + " points but " +
                      std::to_string(body.forces.size()) + " forces");
    }
    Vector3 force = Vector3::Zero(), moment = Vector3::Zero();
    double total = 0.0;
    const Vector3& centre = model_.nodes[node_index_.at(body.node)].position;
    for (std::size_t k = 0; k < body.points.size(); ++k) {
      if (!body.points[k].allFinite() || !body.forces[k].allFinite()) {
        fail(label, "non-finite point or force " + std::to_string(k));
      }
      force += body.forces[k];
      moment += (body.points[k] - centre).cross(body.forces[k]);
      total += body.forces[k].norm();
    }
    // Its stiffness is that of a self-equilibrated load (the body's internal stress); a resultant
    // would be a load on the model, which a pre-load is not.
    // Forces whose sum overflows (1e155 N: its norm is inf, and inf > 1e-9 inf is false) would
    // pass as balanced.
    if (!std::isfinite(total) || !std::isfinite(force.norm()) || !std::isfinite(moment.norm()))
      fail(label, "the forces are too large to sum in a double (" + brief(total) + " N in all)");
    if (force.norm() > kPreloadBalanceTolerance * total ||
        moment.norm() > kPreloadBalanceTolerance * total * scale_) {
      fail(label, "the forces are not self-equilibrated (resultant " + brief(force.norm()) +
                      " N, moment " + brief(moment.norm()) + " N m, of " + brief(total) +
                      " N in all)");
    }
  }

  void checkMass(std::size_t i) const {
    const Mass& mass = model_.masses[i];
    const std::string label = item("masses", i);
    requireNode(label, mass.node);
    requireNonNegative(label, mass.mass, "mass", "kg");
    if (!mass.offset.allFinite()) {
      fail(label, "non-finite offset");
    }
    if (!mass.inertia.allFinite()) {
      fail(label, "non-finite inertia tensor");
    }
    for (int d = 0; d < 3; ++d) {
      if (mass.inertia(d, d) < 0.0) {
        fail(label, std::string("negative inertia ") + kInertiaNames[d] + " " +
                        brief(mass.inertia(d, d)) + " kg m^2");
      }
    }
    const double magnitude = mass.inertia.cwiseAbs().maxCoeff();
    if ((mass.inertia - mass.inertia.transpose()).cwiseAbs().maxCoeff() >
        kInertiaTolerance * magnitude) {
      fail(label, "inertia tensor is not symmetric");
    }
    const Eigen::SelfAdjointEigenSolver<Matrix3> eigen(mass.inertia, Eigen::EigenvaluesOnly);
    const double smallest = eigen.eigenvalues().minCoeff();
    if (smallest < -kInertiaTolerance * magnitude) {
      fail(label, "inertia tensor is not positive semi-definite (principal moment " +
                      brief(smallest) + " kg m^2)");
    }
  }

  void checkRigidJoint(std::size_t i) {
    const RigidJoint& joint = model_.rigid_joints[i];
    const std::string label = item("rigid_joints", i);
    requireNode(label, joint.master);
    if (joint.slaves.empty()) {
      fail(label, "rigid joint has no slaves");
    }
    if (std::none_of(joint.dofs.begin(), joint.dofs.end(), [](bool b) { return b; })) {
      fail(label, "rigid joint constrains no DOFs");
    }
    std::set<NodeId> slaves;
    for (const NodeId slave : joint.slaves) {
      requireNode(label, slave);
      if (slave == joint.master) {
        fail(label, "master node " + std::to_string(slave) + " is also its own slave");
      }
      if (!slaves.insert(slave).second) {
        fail(label, "slave node " + std::to_string(slave) + " is listed twice");
      }
      for (int d = 0; d < kDofsPerNode; ++d) {
        if (!joint.dofs[static_cast<std::size_t>(d)])
          continue;
        const auto [it, inserted] = slave_joint_.emplace(DofRef{slave, d}, i);
        if (!inserted) {
          fail(label, "slave " + dofLabel(slave, d) + " is already driven by rigid_joints[" +
                          std::to_string(it->second) + "]");
        }
      }
      children_[joint.master].push_back({slave, i});
    }
  }

  // A cycle (A slave of B, B slave of A, possibly through intermediate joints) leaves no
  // independent master to express the slaves in, so the constraint cannot be eliminated.
  void checkRigidJointCycles() const {
    std::map<NodeId, char> state;  // absent: unvisited, 'g': on the current path, 'b': done
    std::vector<NodeId> path;
    for (const RigidJoint& joint : model_.rigid_joints) {
      if (state.count(joint.master) == 0) {
        visit(joint.master, state, path);
      }
    }
  }
  // Depth-first without recursion: a chain of 200,000 rigid joints overflowed the stack.
  void visit(NodeId root, std::map<NodeId, char>& state, std::vector<NodeId>& path) const {
    std::vector<std::size_t> next_child;  // per node on `path`: its next child to visit
    state[root] = 'g';
    path.push_back(root);
    next_child.push_back(0);
    while (!path.empty()) {
      const NodeId node = path.back();
      const auto children = children_.find(node);
      const std::size_t k = next_child.back()++;
      if (children == children_.end() || k >= children->second.size()) {
        state[node] = 'b';
        path.pop_back();
        next_child.pop_back();
        continue;
      }
      const auto& [slave, joint] = children->second[k];
      const auto it = state.find(slave);
      if (it == state.end()) {
        state[slave] = 'g';
        path.push_back(slave);
        next_child.push_back(0);
      } else if (it->second == 'g') {
        std::string cycle;
        const auto start = std::find(path.begin(), path.end(), slave);
        for (auto p = start; p != path.end(); ++p) {
          cycle += "node " + std::to_string(*p) + " -> ";
        }
        fail(item("rigid_joints", joint), "rigid joints form a cycle (master -> slave): " + cycle +
                                              "node " + std::to_string(slave));
      }
    }
  }

  void checkFixed(std::size_t i) const {
    const FixedDofs& fixed = model_.fixed[i];
    const std::string label = item("fixed", i);
    requireNode(label, fixed.node);
    if (std::none_of(fixed.dofs.begin(), fixed.dofs.end(), [](bool b) { return b; })) {
      fail(label, "no DOFs selected");
    }
    for (int d = 0; d < kDofsPerNode; ++d) {
      if (!fixed.dofs[static_cast<std::size_t>(d)])
        continue;
      const auto it = slave_joint_.find(DofRef{fixed.node, d});
      if (it != slave_joint_.end()) {
        // A fixed slave would silently constrain its master; fix the master instead.
        fail(label, dofLabel(fixed.node, d) +
                        " is both fixed and a rigid-joint slave (of rigid_joints[" +
                        std::to_string(it->second) + "]); fix the master instead");
      }
    }
  }

  void checkSet(const std::string& name, const std::vector<DofRef>& dofs) const {
    if (name.empty()) {
      fail("sets", "a DOF set has an empty name");
    }
    std::set<DofRef> seen;
    for (std::size_t k = 0; k < dofs.size(); ++k) {
      const std::string label = "sets." + name + "[" + std::to_string(k) + "]";
      requireNode(label, dofs[k].node);
      if (dofs[k].direction < 0 || dofs[k].direction >= kDofsPerNode) {
        fail(label, "direction " + std::to_string(dofs[k].direction) +
                        " is out of range 0..5 (ux, uy, uz, rx, ry, rz)");
      }
      // A repeated DOF would give two identical columns in an input or master set.
      if (!seen.insert(dofs[k]).second) {
        fail(label, dofLabel(dofs[k].node, dofs[k].direction) + " is listed twice");
      }
    }
  }

  const Model& model_;
  const std::string& where_;
  std::unordered_map<NodeId, std::size_t> node_index_;
  double scale_ = 1.0;                         // [m], largest |coordinate|, at least 1
  std::map<DofRef, std::size_t> slave_joint_;  // slave DOF -> joint driving it
  std::map<NodeId, std::vector<std::pair<NodeId, std::size_t>>> children_;  // master -> slaves
};

}  // namespace

void validate(const Model& model, const std::string& where) {
  Validator(model, where).run();
}

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
