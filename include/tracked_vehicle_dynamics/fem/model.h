// The finite-element model as plain data: nodes (6 DOF each) and the items that connect them.
// Built by the vehicle builder or loaded from a generic FE model YAML file (io/model_yaml.h);
// fem::assemble() turns it into sparse M, K, C over the active DOFs.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace fem {

/// Node reference meaning "the ground" in springs (a fixed point that never moves).
constexpr NodeId kGround = -1;

struct Node {
  NodeId id = 0;
  Vector3 position = Vector3::Zero();  ///< [m], global frame
};

/// Linear elastic isotropic material.
struct Material {
  std::string name;
  double young_modulus = 0.0;  ///< E [Pa]
  double shear_modulus = 0.0;  ///< G [Pa]
  double density = 0.0;        ///< rho [kg/m^3]
};

/// Beam cross-section; local y, z are the principal axes.
struct Section {
  std::string name;
  double area = 0.0;     ///< A [m^2]
  double iy = 0.0;       ///< second moment about local y [m^4]
  double iz = 0.0;       ///< second moment about local z [m^4]
  double torsion = 0.0;  ///< torsion constant J [m^4]
  double shear_factor_y =
      0.0;  ///< Timoshenko shear area factor for shear along y (0 = Euler-Bernoulli)
  double shear_factor_z = 0.0;  ///< same along z
};

/// 3-D two-node beam. Local x runs n1 -> n2; local z is orthogonal to x in the plane of x and
/// `orientation`, local y = z x x (right-handed). Consistent mass. Timoshenko shear flexibility
/// when the section's shear factors are non-zero, Euler-Bernoulli otherwise.
struct Beam {
  NodeId n1 = 0;
  NodeId n2 = 0;
  std::string material;
  std::string section;
  Vector3 orientation = Vector3::UnitZ();  ///< a vector not parallel to the beam axis
  /// Axial force the beam carries at rest [N], tension > 0 (e.g. a tensioned track chain). Its
  /// only effect on the linear model is the beam's geometric stiffness (geometric_stiffness.h).
  double axial_force = 0.0;
};

/// A pre-loaded pin-ended link without elastic stiffness: a force F along n1 -> n2 (tension > 0)
/// carried at rest, e.g. through a rigid joint that holds two nodes apart. It adds only its
/// geometric stiffness (F / L)(I - e e^T) on the nodes' relative translation.
struct Tie {
  NodeId n1 = 0;
  NodeId n2 = 0;
  double force = 0.0;  ///< [N]
  std::string name;
};

/// The pre-load a rigid body carries at rest: forces f_i applied to it at points x_i by pre-loaded
/// members (beams' axial forces, ties), together self-equilibrated (sum f_i = 0, sum x_i x f_i =
/// 0). The body carries them as an internal stress (its compression path); turning the body
/// with that stress in it takes work, a geometric stiffness on its rotation at `node`:
/// K = (sum f.r) I - (1/2) sum (f r^T + r f^T), r = x_i - node (geometric_stiffness.h). Without it
/// a tensioned loop held by the body would resist the whole model's rigid rotation.
struct BodyPreload {
  NodeId node = 0;
  std::vector<Vector3> points;  ///< [m], global frame
  std::vector<Vector3> forces;  ///< [N], applied to the body
  std::string name;
};

/// Six uncoupled springs and viscous dampers along/about the axes of a local frame, between two
/// nodes or between a node and the ground (n2 = kGround). A zero entry means no connection in
/// that direction.
struct Spring {
  NodeId n1 = 0;
  NodeId n2 = kGround;
  Vector6 stiffness = Vector6::Zero();  ///< kx ky kz [N/m], krx kry krz [N m/rad]
  Vector6 damping = Vector6::Zero();    ///< cx cy cz [N s/m], crx cry crz [N m s/rad]
  Matrix3 frame = Matrix3::Identity();  ///< columns: local x, y, z axes in global coordinates
  std::string name;
};

/// Lumped mass or rigid body attached to a node; its centre of gravity sits at node + offset.
struct Mass {
  NodeId node = 0;
  double mass = 0.0;                  ///< [kg]
  Matrix3 inertia = Matrix3::Zero();  ///< about the centre of gravity, global axes [kg m^2]
  Vector3 offset = Vector3::Zero();   ///< centre of gravity - node [m]
  std::string name;
};

/// Master-slave rigid link (RBE2): the selected DOFs of each slave follow the rigid motion of the
/// master, u_s = u_m + theta_m x (x_s - x_m), theta_s = theta_m. Eliminated exactly by a
/// transformation; slaves may themselves be masters of other joints (chains are resolved).
struct RigidJoint {
  NodeId master = 0;
  std::vector<NodeId> slaves;
  std::array<bool, kDofsPerNode> dofs{{true, true, true, true, true, true}};
  std::string name;
};

/// DOFs held at zero displacement.
struct FixedDofs {
  NodeId node = 0;
  std::array<bool, kDofsPerNode> dofs{{true, true, true, true, true, true}};
};

/// One physical DOF: a node and a direction (0..5, see Direction).
struct DofRef {
  NodeId node = 0;
  int direction = 0;
  bool operator==(const DofRef& o) const { return node == o.node && direction == o.direction; }
  bool operator<(const DofRef& o) const {
    return node != o.node ? node < o.node : direction < o.direction;
  }
};

/// The whole model. Items reference nodes by id and beams reference materials/sections by name.
struct Model {
  std::string name;
  std::vector<Node> nodes;
  std::vector<Material> materials;
  std::vector<Section> sections;
  std::vector<Beam> beams;
  std::vector<Spring> springs;
  std::vector<Mass> masses;
  std::vector<RigidJoint> rigid_joints;
  std::vector<FixedDofs> fixed;
  std::vector<Tie> ties;
  std::vector<BodyPreload> body_preloads;
  /// Named DOF sets (inputs, outputs, interface DOFs, ...).
  std::map<std::string, std::vector<DofRef>> dof_sets;
  /// Gravity acceleration vector [m/s^2] used for the gravity load.
  Vector3 gravity = Vector3(0.0, 0.0, -kStandardGravity);

  /// Adds a node and returns its id (ids must be unique; not checked here, see validate()).
  NodeId addNode(NodeId id, const Vector3& position);
  /// Position of the node in `nodes` for each id. Throws InputError on a duplicate id.
  std::unordered_map<NodeId, std::size_t> nodeIndex() const;
  const Material* findMaterial(const std::string& name) const;
  const Section* findSection(const std::string& name) const;
  /// Total mass carried by Mass items and beams [kg].
  double totalMass() const;
};

/// Checks the model for consistency (unknown node ids, duplicate ids, negative or non-finite
/// properties, zero-length beams, beam orientation parallel to the axis, unknown material or
/// section, a slave driven by two joints, rigid-joint cycles). Throws InputError whose message
/// starts with `where` (a file name or "model") and names the item, e.g.
/// "vehicle.yaml: beams[3]: node 17 does not exist".
void validate(const Model& model, const std::string& where = "model");

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
