// Reading of model files (schema: doc/model_file.md). Schema errors are reported here with the
// key path and line; consistency between items is fem::validate()'s job.
#include "tracked_vehicle_dynamics/io/model_yaml.h"

#include <algorithm>
#include <array>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/yaml_file_kind.h"
#include "tracked_vehicle_dynamics/io/yaml_reader.h"

namespace tracked_vehicle_dynamics {
namespace io {
namespace {

using DofFlags = std::array<bool, kDofsPerNode>;

const char* const kGroundName = "ground";
const char* const kStiffnessKeys[kDofsPerNode] = {"kx", "ky", "kz", "krx", "kry", "krz"};
const char* const kDampingKeys[kDofsPerNode] = {"cx", "cy", "cz", "crx", "cry", "crz"};
const char* const kDofHelp =
    "DOFs are written as digits 1-6 (\"123456\", 1-3 translations, 4-6 rotations) or as a list "
    "of names [ux, uy, uz, rx, ry, rz]";
/// Largest gravity magnitude a model file may give [m/s^2]: about 100 g.
constexpr double kMaxGravity = 1000.0;

/// The elements of an optional list; an absent or empty (null) key means no items.
std::vector<YamlValue> optionalList(const YamlValue& root, const char* key,
                                    const std::string& what) {
  const std::optional<YamlValue> list = root.find(key);
  if (!list || list->isNull())
    return {};
  return list->elements(what);
}

NodeId readNodeId(const YamlValue& value) {
  const NodeId id = value.asInteger();
  if (id == fem::kGround) {
    value.fail("node id " + std::to_string(id) + " is reserved for the ground");
  }
  return id;
}

/// One direction: a name (ux..rz) or a single digit 1-6.
int readDirection(const YamlValue& value) {
  const std::string text = value.asString();
  int direction = parseDirection(text);
  if (direction < 0 && text.size() == 1 && text[0] >= '1' && text[0] <= '6') {
    direction = text[0] - '1';
  }
  if (direction < 0) {
    value.fail("unknown DOF '" + text + "'; " + kDofHelp);
  }
  return direction;
}

DofFlags readDofs(const YamlValue& value) {
  DofFlags dofs{};
  auto add = [&dofs](const YamlValue& where, int direction) {
    if (dofs[static_cast<std::size_t>(direction)]) {
      where.fail(std::string("DOF ") + directionName(direction) + " is listed twice");
    }
    dofs[static_cast<std::size_t>(direction)] = true;
  };
  if (value.isScalar()) {
    const std::string text = value.asString();
    const int named = parseDirection(text);
    if (named >= 0) {
      add(value, named);
    } else {
      for (const char c : text) {
        if (c < '1' || c > '6')
          value.fail("invalid DOFs '" + text + "'; " + kDofHelp);
        add(value, c - '1');
      }
    }
  } else {
    for (const YamlValue& item : value.elements(std::string("DOFs; ") + kDofHelp)) {
      add(item, readDirection(item));
    }
  }
  if (std::none_of(dofs.begin(), dofs.end(), [](bool b) { return b; })) {
    value.fail(std::string("no DOFs given; ") + kDofHelp);
  }
  return dofs;
}

/// A 3x3 matrix written as a list of three rows.
Matrix3 readRows(const YamlValue& value, const std::string& what) {
  const std::vector<YamlValue> rows = value.elements(3, what);
  Matrix3 matrix;
  for (int r = 0; r < 3; ++r) {
    const std::vector<YamlValue> row = rows[static_cast<std::size_t>(r)].elements(3, what);
    for (int c = 0; c < 3; ++c)
      matrix(r, c) = row[static_cast<std::size_t>(c)].asNumber();
  }
  return matrix;
}

fem::Node readNode(const YamlValue& value) {
  value.expectMap({"id", "x"});
  return fem::Node{readNodeId(value["id"]), value["x"].asVector3()};
}

fem::Material readMaterial(const YamlValue& value) {
  value.expectMap({"name", "E", "G", "nu", "rho"});
  fem::Material material;
  material.name = value["name"].asString();
  material.young_modulus = value["E"].asNumber();
  const std::optional<YamlValue> shear = value.find("G");
  const std::optional<YamlValue> poisson = value.find("nu");
  if (shear && poisson) {
    value.fail("give either G (shear modulus) or nu (Poisson's ratio), not both");
  }
  if (shear) {
    material.shear_modulus = shear->asNumber();
  } else if (poisson) {
    const double nu = poisson->asNumber();
    // Outside (-1, 0.5] an isotropic material has a negative or infinite bulk or shear modulus.
    if (nu <= -1.0 || nu > 0.5) {
      std::ostringstream text;
      text << "Poisson's ratio " << nu << " is outside (-1, 0.5]";
      poisson->fail(text.str());
    }
    material.shear_modulus = material.young_modulus / (2.0 * (1.0 + nu));
  } else {
    value.fail("required key G (shear modulus) or nu (Poisson's ratio) is missing");
  }
  material.density = value["rho"].asNumber();
  return material;
}

fem::Section readSection(const YamlValue& value) {
  value.expectMap({"name", "A", "Iy", "Iz", "J", "shear_factor_y", "shear_factor_z"});
  fem::Section section;
  section.name = value["name"].asString();
  section.area = value["A"].asNumber();
  section.iy = value["Iy"].asNumber();
  section.iz = value["Iz"].asNumber();
  section.torsion = value["J"].asNumber();
  if (const auto factor = value.find("shear_factor_y"))
    section.shear_factor_y = factor->asNumber();
  if (const auto factor = value.find("shear_factor_z"))
    section.shear_factor_z = factor->asNumber();
  return section;
}

fem::Beam readBeam(const YamlValue& value) {
  value.expectMap({"nodes", "material", "section", "orientation", "axial_force"});
  fem::Beam beam;
  const std::vector<YamlValue> nodes = value["nodes"].elements(2, "two node ids [n1, n2]");
  beam.n1 = readNodeId(nodes[0]);
  beam.n2 = readNodeId(nodes[1]);
  beam.material = value["material"].asString();
  beam.section = value["section"].asString();
  if (const auto orientation = value.find("orientation"))
    beam.orientation = orientation->asVector3();
  if (const auto force = value.find("axial_force"))
    beam.axial_force = force->asNumber();
  return beam;
}

/// Six spring constants given either as a list `list_key: [6 values]` or one key per direction.
/// Returns whether any of the keys was present.
bool readSixValues(const YamlValue& value, const char* list_key, const char* const keys[],
                   Vector6& out) {
  const std::optional<YamlValue> list = value.find(list_key);
  bool individual = false;
  for (int d = 0; d < kDofsPerNode; ++d)
    individual = individual || value.has(keys[d]);
  if (list && individual) {
    value.fail(std::string("give either ") + list_key + ": [6 values] or the keys " + keys[0] +
               ".." + keys[5] + ", not both");
  }
  if (list) {
    const std::vector<YamlValue> items =
        list->elements(kDofsPerNode, "a list of 6 values [x, y, z, rx, ry, rz]");
    for (int d = 0; d < kDofsPerNode; ++d)
      out[d] = items[static_cast<std::size_t>(d)].asNumber();
  }
  for (int d = 0; d < kDofsPerNode; ++d) {
    if (const auto item = value.find(keys[d]))
      out[d] = item->asNumber();
  }
  return list || individual;
}

fem::Spring readSpring(const YamlValue& value) {
  value.expectMap({"name", "nodes", "k", "kx", "ky", "kz", "krx", "kry", "krz", "c", "cx", "cy",
                   "cz", "crx", "cry", "crz", "frame"});
  fem::Spring spring;
  if (const auto name = value.find("name"))
    spring.name = name->asString();
  const YamlValue nodes = value["nodes"];
  const std::vector<YamlValue> ends = nodes.elements("[n1, n2], [n1, ground] or [n1] (to ground)");
  if (ends.empty() || ends.size() > 2) {
    nodes.fail("expected [n1, n2], [n1, ground] or [n1] (to ground), got " +
               std::to_string(ends.size()) + " entries");
  }
  spring.n1 = readNodeId(ends[0]);
  const bool to_ground =
      ends.size() == 1 || (ends[1].isScalar() && ends[1].asString() == kGroundName);
  spring.n2 = to_ground ? fem::kGround : readNodeId(ends[1]);
  const bool has_stiffness = readSixValues(value, "k", kStiffnessKeys, spring.stiffness);
  const bool has_damping = readSixValues(value, "c", kDampingKeys, spring.damping);
  if (!has_stiffness && !has_damping) {
    value.fail("no stiffness or damping given (k, kx..krz, c, cx..crz)");
  }
  if (const auto frame = value.find("frame")) {
    // Written as the list of the local axes, so each YAML row is a column of the rotation.
    spring.frame = readRows(*frame, "the local axes [[x axis], [y axis], [z axis]], each 3 numbers")
                       .transpose();
  }
  return spring;
}

Matrix3 readInertia(const YamlValue& value) {
  const std::string what =
      "[Ixx, Iyy, Izz], [Ixx, Iyy, Izz, Ixy, Iyz, Ixz] or a 3x3 matrix [[..], [..], [..]]";
  const std::vector<YamlValue> items = value.elements(what);
  if (items.size() == 3 && items[0].isSequence()) {
    return readRows(value, what);
  }
  if (items.size() != 3 && items.size() != 6) {
    value.fail("expected " + what + ", got " + std::to_string(items.size()) + " entries");
  }
  std::vector<double> v;
  for (const YamlValue& item : items)
    v.push_back(item.asNumber());
  Matrix3 inertia = Vector3(v[0], v[1], v[2]).asDiagonal();
  if (v.size() == 6) {
    inertia(0, 1) = inertia(1, 0) = v[3];
    inertia(1, 2) = inertia(2, 1) = v[4];
    inertia(0, 2) = inertia(2, 0) = v[5];
  }
  return inertia;
}

fem::Mass readMass(const YamlValue& value) {
  value.expectMap({"name", "node", "mass", "inertia", "offset"});
  fem::Mass mass;
  if (const auto name = value.find("name"))
    mass.name = name->asString();
  mass.node = readNodeId(value["node"]);
  mass.mass = value["mass"].asNumber();
  if (const auto inertia = value.find("inertia"))
    mass.inertia = readInertia(*inertia);
  if (const auto offset = value.find("offset"))
    mass.offset = offset->asVector3();
  return mass;
}

fem::RigidJoint readRigidJoint(const YamlValue& value) {
  value.expectMap({"name", "master", "slaves", "dofs"});
  fem::RigidJoint joint;
  if (const auto name = value.find("name"))
    joint.name = name->asString();
  joint.master = readNodeId(value["master"]);
  for (const YamlValue& slave : value["slaves"].elements("a list of slave node ids")) {
    joint.slaves.push_back(readNodeId(slave));
  }
  if (const auto dofs = value.find("dofs"))
    joint.dofs = readDofs(*dofs);
  return joint;
}

fem::Tie readTie(const YamlValue& value) {
  value.expectMap({"name", "nodes", "force"});
  fem::Tie tie;
  if (const auto name = value.find("name"))
    tie.name = name->asString();
  const std::vector<YamlValue> nodes = value["nodes"].elements(2, "two node ids [n1, n2]");
  tie.n1 = readNodeId(nodes[0]);
  tie.n2 = readNodeId(nodes[1]);
  tie.force = value["force"].asNumber();
  return tie;
}

fem::BodyPreload readBodyPreload(const YamlValue& value) {
  value.expectMap({"name", "node", "points", "forces"});
  fem::BodyPreload body;
  if (const auto name = value.find("name"))
    body.name = name->asString();
  body.node = readNodeId(value["node"]);
  for (const YamlValue& point : value["points"].elements("a list of points [x, y, z]"))
    body.points.push_back(point.asVector3());
  for (const YamlValue& force : value["forces"].elements("a list of forces [fx, fy, fz]"))
    body.forces.push_back(force.asVector3());
  return body;
}

fem::FixedDofs readFixed(const YamlValue& value) {
  value.expectMap({"node", "dofs"});
  fem::FixedDofs fixed;
  fixed.node = readNodeId(value["node"]);
  if (const auto dofs = value.find("dofs"))
    fixed.dofs = readDofs(*dofs);
  return fixed;
}

std::vector<fem::DofRef> readSet(const YamlValue& value) {
  std::vector<fem::DofRef> dofs;
  for (const YamlValue& item : value.elements("a list of {node, dof}")) {
    item.expectMap({"node", "dof"});
    dofs.push_back(fem::DofRef{readNodeId(item["node"]), readDirection(item["dof"])});
  }
  return dofs;
}

fem::Model readModel(const YamlValue& root) {
  expectNotOtherYamlFile(root, YamlFileKind::FeModel);
  root.expectMap({"name", "gravity", "nodes", "materials", "sections", "beams", "springs", "masses",
                  "rigid_joints", "fixed", "ties", "body_preloads", "sets"});
  fem::Model model;
  if (const auto name = root.find("name"))
    model.name = name->asString();
  if (const auto gravity = root.find("gravity")) {
    model.gravity = gravity->asVector3();
    // The file is SI: 1000 m/s^2 is about 100 g, far beyond any load case, and the statics it
    // feeds is linear in g, so a value in mm/s^2 (9806.65) or a typo would print as a sag of
    // kilometres or overflow instead of failing here.
    const double magnitude = model.gravity.stableNorm();
    if (magnitude > kMaxGravity)
      gravity->fail("magnitude " + beyond(magnitude, kMaxGravity) + " m/s^2 is beyond " +
                    brief(kMaxGravity) +
                    " m/s^2 (about 100 g): the file is SI (a value in mm/s^2?)");
  }
  for (const YamlValue& node : root["nodes"].elements("a list of nodes {id, x: [x, y, z]}")) {
    model.nodes.push_back(readNode(node));
  }
  for (const YamlValue& item : optionalList(root, "materials", "a list of materials")) {
    model.materials.push_back(readMaterial(item));
  }
  for (const YamlValue& item : optionalList(root, "sections", "a list of sections")) {
    model.sections.push_back(readSection(item));
  }
  for (const YamlValue& item : optionalList(root, "beams", "a list of beams")) {
    model.beams.push_back(readBeam(item));
  }
  for (const YamlValue& item : optionalList(root, "springs", "a list of springs")) {
    model.springs.push_back(readSpring(item));
  }
  for (const YamlValue& item : optionalList(root, "masses", "a list of masses")) {
    model.masses.push_back(readMass(item));
  }
  for (const YamlValue& item : optionalList(root, "rigid_joints", "a list of rigid joints")) {
    model.rigid_joints.push_back(readRigidJoint(item));
  }
  for (const YamlValue& item : optionalList(root, "fixed", "a list of fixed DOFs")) {
    model.fixed.push_back(readFixed(item));
  }
  for (const YamlValue& item : optionalList(root, "ties", "a list of pre-loaded ties")) {
    model.ties.push_back(readTie(item));
  }
  for (const YamlValue& item :
       optionalList(root, "body_preloads", "a list of rigid bodies' pre-loads")) {
    model.body_preloads.push_back(readBodyPreload(item));
  }
  if (const auto sets = root.find("sets"); sets && !sets->isNull()) {
    for (const auto& [name, set] : sets->entries())
      model.dof_sets[name] = readSet(set);
  }
  return model;
}

fem::Model readAndValidate(const YamlValue& root) {
  fem::Model model;
  try {
    model = readModel(root);
  } catch (const YAML::Exception& e) {
    // yaml-cpp reports some problems only when a node is accessed.
    throw InputError(root.file() + ": line " + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
  fem::validate(model, root.file());
  return model;
}

}  // namespace

fem::Model loadModelYaml(const std::string& path) {
  return readAndValidate(YamlValue::loadFile(path));
}

fem::Model parseModelYaml(const std::string& text, const std::string& where) {
  return readAndValidate(YamlValue::parse(text, where));
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics
