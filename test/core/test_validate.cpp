// fem::validate(): a complete valid model passes, and each kind of inconsistency is reported
// once, as "<where>: <item>[<index>]: <cause>".
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/model.h"

namespace tracked_vehicle_dynamics {
namespace fem {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
const char* const kWhere = "bridge.yaml";

/// Every kind of item, nodes 1..6: a beam 1-2-3 along x, a ground spring at 1, a bushing 3-4 in
/// a rotated frame, a rigid body at 5 slaved to 3, a fixed node 6 and two DOF sets.
Model validModel() {
  Model model;
  model.name = "valid";
  model.addNode(1, Vector3(0.0, 0.0, 0.0));
  model.addNode(2, Vector3(0.5, 0.0, 0.0));
  model.addNode(3, Vector3(1.0, 0.0, 0.0));
  model.addNode(4, Vector3(1.0, 0.0, -0.1));
  model.addNode(5, Vector3(1.0, 0.0, 0.2));
  model.addNode(6, Vector3(2.0, 0.0, 0.0));
  model.materials.push_back({"steel", 210e9, 80.8e9, 7850.0});
  model.sections.push_back({"tube", 7e-4, 2.8e-7, 2.8e-7, 5.6e-7, 0.5, 0.5});
  model.beams.push_back({1, 2, "steel", "tube", Vector3::UnitZ()});
  model.beams.push_back({2, 3, "steel", "tube", Vector3::UnitY()});
  Spring mount;
  mount.n1 = 1;
  mount.stiffness << 1e6, 1e6, 2e6, 1e4, 1e4, 1e4;
  model.springs.push_back(mount);
  Spring bushing;
  bushing.n1 = 3;
  bushing.n2 = 4;
  bushing.stiffness << 5e5, 0, 0, 0, 0, 0;
  bushing.damping << 50, 0, 0, 0, 0, 0;
  bushing.frame = Eigen::AngleAxisd(0.4, Vector3(1, 2, 3).normalized()).toRotationMatrix();
  model.springs.push_back(bushing);
  Mass body;
  body.node = 5;
  body.mass = 12.5;
  body.inertia << 0.2, 0.01, 0.0, 0.01, 0.3, 0.0, 0.0, 0.0, 0.25;
  body.offset = Vector3(0.0, 0.0, 0.05);
  model.masses.push_back(body);
  RigidJoint joint;
  joint.master = 3;
  joint.slaves = {5};
  model.rigid_joints.push_back(joint);
  model.fixed.push_back({6, {{true, true, true, true, true, true}}});
  model.dof_sets["inputs"] = {{1, 2}};
  model.dof_sets["outputs"] = {{5, 2}, {5, 3}};
  return model;
}

struct Case {
  const char* label;
  std::function<void(Model&)> mutate;
  std::string item;   // "beams[0]"
  std::string cause;  // a distinctive part of the message
};

void expectInvalid(const Case& c) {
  SCOPED_TRACE(c.label);
  Model model = validModel();
  c.mutate(model);
  try {
    validate(model, kWhere);
    ADD_FAILURE() << "validate() accepted: " << c.label;
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind(std::string(kWhere) + ": " + c.item + ": ", 0), 0u) << message;
    EXPECT_NE(message.find(c.cause), std::string::npos) << message;
  }
}

TEST(Validate, AcceptsCompleteModel) {
  EXPECT_NO_THROW(validate(validModel(), kWhere));
  EXPECT_NO_THROW(validate(Model{}));
}

TEST(Validate, MessagesFollowTheDocumentedFormat) {
  Model model = validModel();
  model.beams[1].n2 = 17;
  try {
    validate(model, kWhere);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "bridge.yaml: beams[1]: node 17 does not exist");
  }
  model = validModel();
  model.masses[0].mass = -5.0;
  try {
    validate(model, "model.yaml");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "model.yaml: masses[0]: negative mass -5 kg");
  }
  model = validModel();
  model.nodes.push_back(model.nodes[0]);
  try {
    validate(model);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "model: nodes[6]: duplicate node id 1 (also nodes[0])");
  }
}

TEST(Validate, RejectsUnknownNodes) {
  const std::vector<Case> cases = {
      {"beam n1", [](Model& m) { m.beams[0].n1 = 17; }, "beams[0]", "node 17 does not exist"},
      {"spring n1", [](Model& m) { m.springs[1].n1 = 99; }, "springs[1]", "node 99 does not exist"},
      {"spring n2", [](Model& m) { m.springs[1].n2 = 99; }, "springs[1]", "node 99 does not exist"},
      {"mass", [](Model& m) { m.masses[0].node = 7; }, "masses[0]", "node 7 does not exist"},
      {"joint master", [](Model& m) { m.rigid_joints[0].master = 8; }, "rigid_joints[0]",
       "node 8 does not exist"},
      {"joint slave", [](Model& m) { m.rigid_joints[0].slaves.push_back(9); }, "rigid_joints[0]",
       "node 9 does not exist"},
      {"fixed", [](Model& m) { m.fixed[0].node = 10; }, "fixed[0]", "node 10 does not exist"},
      {"set", [](Model& m) { m.dof_sets["outputs"][1].node = 11; }, "sets.outputs[1]",
       "node 11 does not exist"},
  };
  for (const Case& c : cases)
    expectInvalid(c);
}

TEST(Validate, RejectsDuplicates) {
  const std::vector<Case> cases = {
      {"node id", [](Model& m) { m.addNode(3, Vector3(5, 5, 5)); }, "nodes[6]",
       "duplicate node id 3 (also nodes[2])"},
      {"reserved id", [](Model& m) { m.addNode(kGround, Vector3(5, 5, 5)); }, "nodes[6]",
       "node id -1 is reserved for the ground"},
      {"material", [](Model& m) { m.materials.push_back(m.materials[0]); }, "materials[1]",
       "duplicate material name 'steel' (also materials[0])"},
      {"section", [](Model& m) { m.sections.push_back(m.sections[0]); }, "sections[1]",
       "duplicate section name 'tube' (also sections[0])"},
      {"unnamed material", [](Model& m) { m.materials[0].name.clear(); }, "materials[0]",
       "no name"},
  };
  for (const Case& c : cases)
    expectInvalid(c);
}

TEST(Validate, RejectsNonFiniteValues) {
  const std::vector<Case> cases = {
      {"gravity", [](Model& m) { m.gravity.z() = kNaN; }, "gravity", "non-finite"},
      {"coordinate", [](Model& m) { m.nodes[2].position.y() = kNaN; }, "nodes[2]",
       "non-finite coordinates of node 3"},
      {"E", [](Model& m) { m.materials[0].young_modulus = kInf; }, "materials[0]",
       "non-finite Young's modulus E"},
      {"G", [](Model& m) { m.materials[0].shear_modulus = kNaN; }, "materials[0]",
       "non-finite shear modulus G"},
      {"rho", [](Model& m) { m.materials[0].density = kNaN; }, "materials[0]",
       "non-finite density"},
      {"area", [](Model& m) { m.sections[0].area = kNaN; }, "sections[0]", "non-finite area A"},
      {"shear factor", [](Model& m) { m.sections[0].shear_factor_z = kInf; }, "sections[0]",
       "non-finite shear factor shear_factor_z"},
      {"orientation", [](Model& m) { m.beams[1].orientation.x() = kNaN; }, "beams[1]",
       "non-finite orientation"},
      {"stiffness", [](Model& m) { m.springs[0].stiffness[4] = kNaN; }, "springs[0]",
       "non-finite stiffness kry"},
      {"damping", [](Model& m) { m.springs[1].damping[0] = kInf; }, "springs[1]",
       "non-finite damping cx"},
      {"frame", [](Model& m) { m.springs[1].frame(2, 1) = kNaN; }, "springs[1]",
       "non-finite frame"},
      {"mass", [](Model& m) { m.masses[0].mass = kNaN; }, "masses[0]", "non-finite mass"},
      {"inertia", [](Model& m) { m.masses[0].inertia(0, 2) = kInf; }, "masses[0]",
       "non-finite inertia"},
      {"offset", [](Model& m) { m.masses[0].offset.x() = kNaN; }, "masses[0]", "non-finite offset"},
  };
  for (const Case& c : cases)
    expectInvalid(c);
}

TEST(Validate, RejectsNonPhysicalProperties) {
  const std::vector<Case> cases = {
      {"E", [](Model& m) { m.materials[0].young_modulus = 0.0; }, "materials[0]",
       "non-positive Young's modulus E 0 Pa"},
      {"G", [](Model& m) { m.materials[0].shear_modulus = -1.0; }, "materials[0]",
       "non-positive shear modulus G -1 Pa"},
      {"rho", [](Model& m) { m.materials[0].density = -7850.0; }, "materials[0]",
       "negative density rho -7850 kg/m^3"},
      {"A", [](Model& m) { m.sections[0].area = 0.0; }, "sections[0]", "non-positive area A"},
      {"Iy", [](Model& m) { m.sections[0].iy = -1e-8; }, "sections[0]",
       "non-positive second moment Iy"},
      {"Iz", [](Model& m) { m.sections[0].iz = 0.0; }, "sections[0]",
       "non-positive second moment Iz"},
      {"J", [](Model& m) { m.sections[0].torsion = 0.0; }, "sections[0]",
       "non-positive torsion constant J"},
      {"shear factor", [](Model& m) { m.sections[0].shear_factor_y = -0.5; }, "sections[0]",
       "negative shear factor shear_factor_y -0.5"},
      {"large shear factor", [](Model& m) { m.sections[0].shear_factor_z = 9.2e18; }, "sections[0]",
       "shear factor shear_factor_z 9.2e+18 is above 1: the shear area"},
      {"stiffness", [](Model& m) { m.springs[0].stiffness[2] = -2e6; }, "springs[0]",
       "negative stiffness kz -2e+06 N/m"},
      {"rotational damping", [](Model& m) { m.springs[1].damping[5] = -1.0; }, "springs[1]",
       "negative damping crz -1 N m s/rad"},
      {"mass", [](Model& m) { m.masses[0].mass = -5.0; }, "masses[0]", "negative mass -5 kg"},
      {"inertia diagonal", [](Model& m) { m.masses[0].inertia(1, 1) = -0.3; }, "masses[0]",
       "negative inertia Iyy -0.3 kg m^2"},
      {"inertia symmetry", [](Model& m) { m.masses[0].inertia(0, 1) = 0.05; }, "masses[0]",
       "not symmetric"},
      {"inertia definiteness",
       [](Model& m) { m.masses[0].inertia(0, 1) = m.masses[0].inertia(1, 0) = 0.5; }, "masses[0]",
       "not positive semi-definite"},
  };
  for (const Case& c : cases)
    expectInvalid(c);
}

TEST(Validate, RejectsBadGeometry) {
  const std::vector<Case> cases = {
      {"coincident nodes", [](Model& m) { m.nodes[1].position = m.nodes[0].position; }, "beams[0]",
       "zero-length beam: nodes 1 and 2 coincide"},
      {"same node", [](Model& m) { m.beams[1].n2 = 2; }, "beams[1]", "zero-length beam"},
      {"parallel orientation", [](Model& m) { m.beams[1].orientation = Vector3(-3, 0, 0); },
       "beams[1]", "orientation vector is parallel to the beam axis"},
      {"zero orientation", [](Model& m) { m.beams[0].orientation.setZero(); }, "beams[0]",
       "orientation vector is zero"},
      {"unknown material", [](Model& m) { m.beams[1].material = "alu"; }, "beams[1]",
       "material 'alu' does not exist"},
      {"unknown section", [](Model& m) { m.beams[0].section = "rod"; }, "beams[0]",
       "section 'rod' does not exist"},
      {"spring to itself", [](Model& m) { m.springs[1].n2 = 3; }, "springs[1]",
       "spring connects node 3 to itself"},
      {"spring from ground", [](Model& m) { m.springs[0].n1 = kGround; }, "springs[0]",
       "must be a node, not the ground"},
      {"frame not orthonormal", [](Model& m) { m.springs[1].frame *= 1.01; }, "springs[1]",
       "frame is not orthonormal"},
      {"frame left-handed", [](Model& m) { m.springs[1].frame.col(2) *= -1.0; }, "springs[1]",
       "frame is left-handed"},
  };
  for (const Case& c : cases)
    expectInvalid(c);
}

TEST(Validate, RejectsBadConstraints) {
  const std::vector<Case> cases = {
      {"no slaves", [](Model& m) { m.rigid_joints[0].slaves.clear(); }, "rigid_joints[0]",
       "rigid joint has no slaves"},
      {"no DOFs", [](Model& m) { m.rigid_joints[0].dofs.fill(false); }, "rigid_joints[0]",
       "constrains no DOFs"},
      {"own slave", [](Model& m) { m.rigid_joints[0].slaves.push_back(3); }, "rigid_joints[0]",
       "master node 3 is also its own slave"},
      {"slave twice in a joint", [](Model& m) { m.rigid_joints[0].slaves.push_back(5); },
       "rigid_joints[0]", "slave node 5 is listed twice"},
      {"slave of two joints",
       [](Model& m) {
         RigidJoint other;
         other.master = 2;
         other.slaves = {5};
         other.dofs = {{false, false, true, false, false, false}};
         m.rigid_joints.push_back(other);
       },
       "rigid_joints[1]", "slave node 5 uz is already driven by rigid_joints[0]"},
      {"two-joint cycle",
       [](Model& m) {
         RigidJoint back;
         back.master = 5;
         back.slaves = {3};
         back.dofs = {{false, false, false, true, false, false}};
         m.rigid_joints[0].dofs = {{true, true, true, false, false, false}};
         m.rigid_joints.push_back(back);
       },
       "rigid_joints[1]",
       "rigid joints form a cycle (master -> slave): node 3 -> node 5 -> node 3"},
      {"three-joint cycle",
       [](Model& m) {
         m.rigid_joints[0] = RigidJoint{1, {2}, {{true, false, false, false, false, false}}, ""};
         m.rigid_joints.push_back({2, {4}, {{false, true, false, false, false, false}}, ""});
         m.rigid_joints.push_back({4, {1}, {{false, false, true, false, false, false}}, ""});
       },
       "rigid_joints[2]", "node 1 -> node 2 -> node 4 -> node 1"},
      {"fixed slave",
       [](Model& m) {
         m.fixed.push_back({5, {{false, false, true, false, false, false}}});
       },
       "fixed[1]", "node 5 uz is both fixed and a rigid-joint slave (of rigid_joints[0])"},
      {"fixed nothing", [](Model& m) { m.fixed[0].dofs.fill(false); }, "fixed[0]",
       "no DOFs selected"},
  };
  for (const Case& c : cases)
    expectInvalid(c);
}

TEST(Validate, RejectsBadDofSets) {
  const std::vector<Case> cases = {
      {"direction 6", [](Model& m) { m.dof_sets["inputs"][0].direction = 6; }, "sets.inputs[0]",
       "direction 6 is out of range 0..5"},
      {"direction -1", [](Model& m) { m.dof_sets["outputs"][1].direction = -1; }, "sets.outputs[1]",
       "direction -1 is out of range 0..5"},
      {"repeated DOF",
       [](Model& m) {
         m.dof_sets["outputs"].push_back({5, 2});
       },
       "sets.outputs[2]", "node 5 uz is listed twice"},
      {"empty name",
       [](Model& m) {
         m.dof_sets[""] = {{1, 0}};
       },
       "sets", "empty name"},
  };
  for (const Case& c : cases)
    expectInvalid(c);
}

TEST(Validate, AcceptsLegitimateEdgeCases) {
  Model model = validModel();
  // A chain of joints (3 drives 5, 5 drives 2's rotations) is resolved, not a cycle.
  model.rigid_joints.push_back({5, {2}, {{false, false, false, true, true, true}}, "chain"});
  // One node slaved in different DOFs to two masters is not "driven twice".
  model.rigid_joints.push_back({1, {2}, {{true, true, true, false, false, false}}, "split"});
  // A slender rod: inertia with a zero principal moment is semi-definite, hence valid.
  model.masses.push_back({6, 1.0, Vector3(0.0, 1.0, 1.0).asDiagonal(), Vector3::Zero(), "rod"});
  // A spring with zero stiffness in some directions and a short (but not zero) beam.
  model.addNode(7, Vector3(2.0, 0.0, 1e-6));
  model.beams.push_back({6, 7, "steel", "tube", Vector3::UnitX()});
  // Massless material (a stiffness-only link) and a frame typed with 9 digits.
  model.materials.push_back({"massless", 1e9, 4e8, 0.0});
  model.springs[1].frame << 0.707106781, -0.707106781, 0, 0.707106781, 0.707106781, 0, 0, 0, 1;
  EXPECT_NO_THROW(validate(model, kWhere));
}

// brief(), the numbers of every error message: six digits, but a value given with up to ten is
// shown as given, so a rejected value never reads as the bound it breaks.
TEST(Brief, ShowsAGivenValueExactlyAndAComputedOneShort) {
  EXPECT_EQ(brief(3.5), "3.5");
  EXPECT_EQ(brief(1.2e-5), "1.2e-05");
  EXPECT_EQ(brief(200.0), "200");
  EXPECT_EQ(brief(200.0001), "200.0001");  // "must be in (0, 200], got 200.0001"
  EXPECT_EQ(brief(-0.123456789), "-0.123456789");
  EXPECT_EQ(brief(0.1 + 0.2), "0.3");  // 0.30000000000000004: no ten-digit decimal is it
  EXPECT_EQ(brief(1.0 / 3.0), "0.333333");
  EXPECT_EQ(brief(kInf), "inf");
  EXPECT_EQ(brief(kNaN), "nan");
  EXPECT_EQ(brief(-kNaN), "nan");  // not "-nan": a NaN's sign bit means nothing
  EXPECT_EQ(brief(-0.0), "0");     // not "-0"
  EXPECT_EQ(brief(-kInf), "-inf");
  // beyond(): the rejected value never reads as the bound, however many digits that takes.
  EXPECT_EQ(beyond(200.00000001, 200.0), "200.00000001");
  EXPECT_EQ(beyond(200.0001 / 3.6 * 3.6, 200.0).substr(0, 8), "200.0001");
  EXPECT_EQ(beyond(250.0, 200.0), "250");
  EXPECT_EQ(beyond(200.0, 200.0), "200");
}

// editDistance(), the "did you mean" of the node's parameters and of the command lines.
TEST(EditDistance, CountsInsertionsDeletionsAndSubstitutions) {
  EXPECT_EQ(editDistance("", ""), 0u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("abc", ""), 3u);
  EXPECT_EQ(editDistance("track", "track"), 0u);
  EXPECT_EQ(editDistance("trak", "track"), 1u);  // one insertion
  EXPECT_EQ(editDistance("speed_timout", "speed_timeout"), 1u);
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);  // the textbook case
  EXPECT_EQ(editDistance("sitting", "kitten"), 3u);  // symmetric
  EXPECT_EQ(editDistance("flaw", "lawn"), 2u);
}

}  // namespace
}  // namespace fem
}  // namespace tracked_vehicle_dynamics
