// Model files: round trips are exact, the shipped examples and the documented example load, and
// every kind of bad input is rejected with a message naming the file, the key path and the cause.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "sanitizer_build.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/model.h"
#include "tracked_vehicle_dynamics/fem/static_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/io/model_yaml.h"

#ifndef TVD_SOURCE_DIR
#define TVD_SOURCE_DIR "."
#endif

namespace tracked_vehicle_dynamics {
namespace io {
namespace {

namespace fs = std::filesystem;

constexpr double kMassTolerance = 1e-12;  // [kg], relative to a few kg

std::string sourcePath(const std::string& relative) {
  return std::string(TVD_SOURCE_DIR) + "/" + relative;
}

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The same number of items in `a` and `b`, and each of the given fields equal item by item
/// (EXPECT_EQ: bitwise for finite values), the failing item named `what[i]`.
template <typename Item, typename... Field>
void expectItemsEqual(const char* what, const std::vector<Item>& a, const std::vector<Item>& b,
                      Field Item::*... fields) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto expect = [&](auto field) {
      EXPECT_EQ(a[i].*field, b[i].*field) << what << "[" << i << "]";
    };
    (expect(fields), ...);
  }
}

/// Exact (bitwise for finite values) equality of every field.
void expectModelsEqual(const fem::Model& a, const fem::Model& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.gravity, b.gravity);
  expectItemsEqual("nodes", a.nodes, b.nodes, &fem::Node::id, &fem::Node::position);
  expectItemsEqual("materials", a.materials, b.materials, &fem::Material::name,
                   &fem::Material::young_modulus, &fem::Material::shear_modulus,
                   &fem::Material::density);
  expectItemsEqual("sections", a.sections, b.sections, &fem::Section::name, &fem::Section::area,
                   &fem::Section::iy, &fem::Section::iz, &fem::Section::torsion,
                   &fem::Section::shear_factor_y, &fem::Section::shear_factor_z);
  expectItemsEqual("beams", a.beams, b.beams, &fem::Beam::n1, &fem::Beam::n2, &fem::Beam::material,
                   &fem::Beam::section, &fem::Beam::orientation, &fem::Beam::axial_force);
  expectItemsEqual("springs", a.springs, b.springs, &fem::Spring::n1, &fem::Spring::n2,
                   &fem::Spring::stiffness, &fem::Spring::damping, &fem::Spring::frame,
                   &fem::Spring::name);
  expectItemsEqual("masses", a.masses, b.masses, &fem::Mass::node, &fem::Mass::mass,
                   &fem::Mass::inertia, &fem::Mass::offset, &fem::Mass::name);
  expectItemsEqual("rigid_joints", a.rigid_joints, b.rigid_joints, &fem::RigidJoint::master,
                   &fem::RigidJoint::slaves, &fem::RigidJoint::dofs, &fem::RigidJoint::name);
  expectItemsEqual("fixed", a.fixed, b.fixed, &fem::FixedDofs::node, &fem::FixedDofs::dofs);
  expectItemsEqual("ties", a.ties, b.ties, &fem::Tie::n1, &fem::Tie::n2, &fem::Tie::force,
                   &fem::Tie::name);
  expectItemsEqual("body_preloads", a.body_preloads, b.body_preloads, &fem::BodyPreload::node,
                   &fem::BodyPreload::points, &fem::BodyPreload::forces, &fem::BodyPreload::name);
  EXPECT_EQ(a.dof_sets, b.dof_sets);
}

/// Values chosen to break naive formatting: thirds, pi, tiny and huge exponents, negative ids,
/// names YAML would misread, full inertia tensors and a rotated spring frame.
fem::Model awkwardModel() {
  fem::Model model;
  model.name = "round: trip # test";
  model.gravity = Vector3(0.1, -1.0 / 3.0, -9.80665);
  model.addNode(-5, Vector3(0.0, 0.0, 0.0));
  model.addNode(2, Vector3(1.0 / 3.0, M_PI, -1e-300));
  model.addNode(1000000000000, Vector3(2.0 / 3.0, 6.02214076e23 * 1e-23, 1e-7));
  model.addNode(4, Vector3(1.0, 0.0, 0.1 + 0.2));
  model.materials.push_back({"steel", 210e9, 210e9 / 2.6, 7850.0});
  model.materials.push_back({"~", 1.0 / 7.0, 2.0 / 7.0, 0.0});
  model.sections.push_back({"tube", 7.037167544041138e-4, 2.7726440123522074e-07,
                            2.7726440123522074e-07, 5.545288024704415e-07, 0.5, 0.0});
  model.sections.push_back({"123", 1e-4, 1e-8, 2e-8, 3e-8, 0.0, 5.0 / 6.0});
  model.beams.push_back({-5, 2, "steel", "tube", Vector3(0.0, 0.0, 1.0)});
  model.beams.push_back({2, 1000000000000, "~", "123", Vector3(0.1, 0.7, -0.2)});
  model.beams.back().axial_force = -1e3 / 3.0;
  model.ties.push_back({-5, 4, 1e4 / 7.0, "tie: A"});
  // A pre-load pair along the line through its points: balanced, as validation asks.
  const Vector3 p(1.0 / 3.0, M_PI, -1e-3), d(0.7, -0.2, 0.1);
  model.body_preloads.push_back({4, {p, Vector3(p + d)}, {1e3 / 7.0 * d, -1e3 / 7.0 * d}, "null"});
  fem::Spring ground;
  ground.n1 = 4;
  ground.stiffness << 1e6, 2e6, 3.3e6, 0.0, 1.0 / 3.0, 5e4;
  ground.damping << 0.0, 0.0, 120.5, 0.0, 0.0, 1e-3;
  ground.name = "";
  model.springs.push_back(ground);
  fem::Spring bushing;
  bushing.n1 = 2;
  bushing.n2 = 4;
  bushing.stiffness << 0.0, 0.0, 7e5, 0.0, 0.0, 0.0;
  bushing.frame = Eigen::AngleAxisd(0.3, Vector3(1, 2, 3).normalized()).toRotationMatrix();
  bushing.name = "bushing \"A\"";
  model.springs.push_back(bushing);
  fem::Mass body;
  body.node = 4;
  body.mass = 12.345678901234567;
  body.inertia << 0.2, -0.01, 0.003, -0.01, 0.3, 0.0, 0.003, 0.0, 0.25;
  body.offset = Vector3(0.0, 1e-17, 0.05);
  body.name = "null";
  model.masses.push_back(body);
  model.masses.push_back({-5, 0.5, Vector3(1e-4, 2e-4, 3e-4).asDiagonal(), Vector3::Zero(), ""});
  model.rigid_joints.push_back({2, {-5}, {{true, false, true, false, true, false}}, "hinge"});
  model.rigid_joints.push_back({4, {1000000000000}, {{true, true, true, true, true, true}}, ""});
  model.fixed.push_back({2, {{false, false, false, true, true, true}}});
  model.dof_sets["inputs"] = {{4, 2}};
  model.dof_sets["outputs: all"] = {{2, 5}, {2, 0}, {1000000000000, 3}};
  model.dof_sets["empty"] = {};
  return model;
}

class ModelYamlTest : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = fs::path(::testing::TempDir()) / ("tvd_model_yaml_" + std::to_string(::getpid()));
    fs::create_directories(directory_);
  }
  void TearDown() override {
    std::error_code ignored;
    fs::remove_all(directory_, ignored);
  }

  std::string write(const std::string& name, const std::string& text) const {
    const std::string path = (directory_ / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  /// Loads `text` from `name` and expects an InputError that starts with the file name and
  /// contains each of `parts` (the key path, the cause, the line).
  void expectLoadError(const std::string& name, const std::string& text,
                       const std::vector<std::string>& parts) const {
    SCOPED_TRACE(name);
    const std::string path = write(name, text);
    try {
      loadModelYaml(path);
      ADD_FAILURE() << "loaded without error: " << name;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
      for (const std::string& part : parts) {
        EXPECT_NE(message.find(part), std::string::npos)
            << "missing '" << part << "' in: " << message;
      }
    }
  }

  fs::path directory_;
};

// A valid document that the bad-input cases below modify one line at a time.
const char* const kBase =
    "name: base\n"                                                    // line 1
    "nodes:\n"                                                        // line 2
    "  - {id: 1, x: [0, 0, 0]}\n"                                     // line 3
    "  - {id: 2, x: [1, 0, 0]}\n"                                     // line 4
    "materials:\n"                                                    // line 5
    "  - {name: steel, E: 2.1e11, nu: 0.3, rho: 7850}\n"              // line 6
    "sections:\n"                                                     // line 7
    "  - {name: sq, A: 4.0e-4, Iy: 1.0e-8, Iz: 1.0e-8, J: 2.0e-8}\n"  // line 8
    "beams:\n"                                                        // line 9
    "  - {nodes: [1, 2], material: steel, section: sq}\n"             // line 10
    "springs:\n"                                                      // line 11
    "  - {nodes: [2, ground], k: [1, 1, 1, 0, 0, 0]}\n"               // line 12
    "masses:\n"                                                       // line 13
    "  - {node: 2, mass: 1.5}\n"                                      // line 14
    "rigid_joints:\n"                                                 // line 15
    "  - {master: 1, slaves: [2], dofs: \"4\"}\n"                     // line 16
    "fixed:\n"                                                        // line 17
    "  - {node: 1, dofs: \"123\"}\n"                                  // line 18
    "sets:\n"                                                         // line 19
    "  tip: [{node: 2, dof: uz}]\n";                                  // line 20

std::string replaced(const std::string& from, const std::string& to) {
  std::string text = kBase;
  const std::size_t at = text.find(from);
  if (at == std::string::npos) {
    ADD_FAILURE() << "test setup: '" << from << "' not in the base document";
    return text;
  }
  return text.replace(at, from.size(), to);
}

TEST_F(ModelYamlTest, BaseDocumentLoads) {
  const fem::Model model = loadModelYaml(write("base.yaml", kBase));
  EXPECT_EQ(model.name, "base");
  EXPECT_EQ(model.nodes.size(), 2u);
  EXPECT_EQ(model.materials[0].shear_modulus, 2.1e11 / 2.6);
  EXPECT_EQ(model.springs[0].n2, fem::kGround);
  EXPECT_EQ(model.rigid_joints[0].dofs,
            (std::array<bool, 6>{{false, false, false, true, false, false}}));
}

TEST_F(ModelYamlTest, SaveThenLoadReproducesTheModelExactly) {
  const fem::Model original = awkwardModel();
  ASSERT_NO_THROW(fem::validate(original));
  const std::string path = (directory_ / "awkward.yaml").string();
  saveModelYaml(original, path);
  const fem::Model loaded = loadModelYaml(path);
  expectModelsEqual(original, loaded);
  EXPECT_EQ(formatModelYaml(loaded), readText(path));  // a fixed point after one save
}

// YAML 1.1 (PyYAML, ROS's rosparam) reads 1e-05 as a string: a float needs its '.', which the
// writer puts before the exponent.
TEST_F(ModelYamlTest, WrittenExponentsAreYaml11Floats) {
  const fem::Model model =
      loadModelYaml(write("tiny_x.yaml", replaced("x: [1, 0, 0]", "x: [1e-05, 0, 0]")));
  const std::string text = formatModelYaml(model);
  EXPECT_NE(text.find("1.0e-05"), std::string::npos) << text;
  EXPECT_EQ(text.find("[1e-05"), std::string::npos) << text;
}

TEST_F(ModelYamlTest, EmptyModelRoundTrips) {
  fem::Model empty;
  empty.gravity = Vector3(0.0, -0.0, -1.62);  // the Moon; -0.0 must survive too
  const std::string path = (directory_ / "empty.yaml").string();
  saveModelYaml(empty, path);
  const fem::Model loaded = loadModelYaml(path);
  expectModelsEqual(empty, loaded);
  EXPECT_TRUE(std::signbit(loaded.gravity.y()));
}

TEST_F(ModelYamlTest, LoadSaveLoadOfTheExamplesIsExact) {
  for (const char* name : {"cantilever_beam", "spring_mass_chain", "free_free_beam"}) {
    SCOPED_TRACE(name);
    const fem::Model first =
        loadModelYaml(sourcePath(std::string("config/models/") + name + ".yaml"));
    const std::string copy = (directory_ / (std::string(name) + ".yaml")).string();
    saveModelYaml(first, copy);
    expectModelsEqual(first, loadModelYaml(copy));
  }
}

TEST_F(ModelYamlTest, CantileverExample) {
  const fem::Model model = loadModelYaml(sourcePath("config/models/cantilever_beam.yaml"));
  EXPECT_EQ(model.name, "cantilever_beam");
  EXPECT_EQ(model.nodes.size(), 21u);
  EXPECT_EQ(model.beams.size(), 20u);
  EXPECT_EQ(model.nodes.back().position, Vector3(1.0, 0.0, 0.0));
  ASSERT_EQ(model.fixed.size(), 1u);
  EXPECT_EQ(model.fixed[0].node, 1);
  // rho A L + tip mass = 7850 * 4e-4 * 1 + 1
  EXPECT_NEAR(model.totalMass(), 3.14 + 1.0, kMassTolerance);
  ASSERT_EQ(model.dof_sets.count("tip"), 1u);
  EXPECT_EQ(model.dof_sets.at("tip"), (std::vector<fem::DofRef>{{21, 2}}));
  EXPECT_EQ(model.gravity, Vector3(0.0, 0.0, -kStandardGravity));
}

TEST_F(ModelYamlTest, SpringMassChainExample) {
  const fem::Model model = loadModelYaml(sourcePath("config/models/spring_mass_chain.yaml"));
  EXPECT_EQ(model.nodes.size(), 10u);
  EXPECT_EQ(model.springs.size(), 10u);
  EXPECT_EQ(model.springs[0].n2, fem::kGround);
  EXPECT_EQ(model.springs[3].stiffness, (Vector6() << 0, 0, 1e4, 0, 0, 0).finished());
  EXPECT_EQ(model.springs[3].damping, (Vector6() << 0, 0, 5, 0, 0, 0).finished());
  // Only uz stays free at each node: 10 DOFs.
  int free_dofs = 0;
  for (const fem::FixedDofs& fixed : model.fixed) {
    for (bool held : fixed.dofs)
      free_dofs += held ? 0 : 1;
  }
  EXPECT_EQ(free_dofs, 10);
  EXPECT_EQ(model.fixed.size(), 10u);
  EXPECT_NEAR(model.totalMass(), 10.0, kMassTolerance);
}

TEST_F(ModelYamlTest, FreeFreeBeamExample) {
  const fem::Model model = loadModelYaml(sourcePath("config/models/free_free_beam.yaml"));
  EXPECT_EQ(model.beams.size(), 10u);
  EXPECT_TRUE(model.fixed.empty());
  EXPECT_TRUE(model.rigid_joints.empty());
  EXPECT_NEAR(model.totalMass(), 0.54, kMassTolerance);
  EXPECT_EQ(model.dof_sets.at("ends").size(), 2u);
}

// Its statics are refused naming the six rigid-body motions: the zero-energy vectors the
// eigen-solver returns are mixtures of them (they were named as one translation and five
// "mechanisms").
TEST_F(ModelYamlTest, FreeFreeBeamStaticsNameTheSixRigidBodyMotions) {
  const fem::System system =
      fem::assemble(loadModelYaml(sourcePath("config/models/free_free_beam.yaml")));
  try {
    fem::solveStatic(system, system.gravity_load);
    FAIL() << "expected a SolverError";
  } catch (const SolverError& e) {
    const std::string message = e.what();
    for (const char* motion : {"translation along x", "translation along y", "translation along z",
                               "rotation about x", "rotation about y", "rotation about z"})
      EXPECT_NE(message.find(std::string("rigid-body ") + motion), std::string::npos) << message;
    EXPECT_EQ(message.find("mechanism"), std::string::npos) << message;
  }
}

// Asked for its rigid-body modes alone, the free beam is not "unstable": their eigenvalues are
// round-off either side of 0 (-4e-5 .. 1.5e-5 rad^2/s^2), judged against the whole solve's scale,
// not the largest of them (the warning said "4 modes have omega^2 < 0" for any count up to 6).
// The same modes of a longer beam (the shift-invert solver, above 200 DOFs) as well.
TEST_F(ModelYamlTest, FreeFreeBeamRigidBodyModesAloneAreNotUnstable) {
  const fem::Model beam = loadModelYaml(sourcePath("config/models/free_free_beam.yaml"));
  fem::Model longer = beam;
  longer.nodes.clear();
  longer.beams.clear();
  for (int i = 0; i <= 40; ++i) {
    longer.nodes.push_back(beam.nodes.front());
    longer.nodes.back().id = i + 1;
    longer.nodes.back().position = Vector3(0.0125 * i, 0.0, 0.0);
    if (i > 0) {
      longer.beams.push_back(beam.beams.front());
      longer.beams.back().n1 = i;
      longer.beams.back().n2 = i + 1;
    }
  }
  longer.dof_sets.clear();
  for (const fem::Model* model : std::vector<const fem::Model*>{&beam, &longer}) {
    const fem::System system = fem::assemble(*model);
    SCOPED_TRACE(system.size());
    for (const int count : {1, 4, 6, 7}) {
      fem::ModalRequest request;
      request.count = count;
      const fem::ModalBasis basis = fem::solveModes(system.stiffness, system.mass, request);
      EXPECT_EQ(fem::unstableModesWarning(basis), "") << count << " modes";
      EXPECT_GT(basis.zero_tolerance,
                basis.eigenvalues.head(std::min(count, 6)).cwiseAbs().maxCoeff());
    }
  }
}

TEST_F(ModelYamlTest, DocumentedExampleLoads) {
  const std::string doc = readText(sourcePath("doc/model_file.md"));
  const std::string fence = "```yaml\n";
  const std::size_t begin = doc.find(fence);
  ASSERT_NE(begin, std::string::npos);
  const std::size_t end = doc.find("```", begin + fence.size());
  ASSERT_NE(end, std::string::npos);
  const fem::Model model =
      parseModelYaml(doc.substr(begin + fence.size(), end - begin - fence.size()), "doc");
  EXPECT_EQ(model.name, "bracket_demo");
  ASSERT_EQ(model.springs.size(), 2u);
  EXPECT_EQ(model.springs[1].n2, fem::kGround);
  // frame rows are the local axes: local x along global z.
  EXPECT_EQ(model.springs[1].frame.col(0), Vector3(0, 0, 1));
  EXPECT_EQ(model.springs[1].stiffness[0], 5.0e5);
  EXPECT_EQ(model.fixed[0].dofs, (std::array<bool, 6>{{false, false, false, true, true, true}}));
}

TEST_F(ModelYamlTest, AlternativeSpellingsAreEquivalent) {
  const fem::Model model = parseModelYaml(
      "nodes:\n"
      "  - {id: 1, x: [0, 0, 0]}\n"
      "  - {id: 2, x: [+1.5, 0, 0]}\n"
      "materials:\n"
      "  - {name: m, E: 100, G: 40, rho: 1}\n"
      "springs:\n"
      "  - {nodes: [1], kz: 3, crx: 4}\n"
      "  - {nodes: [1, 2], c: [1, 2, 3, 4, 5, 6]}\n"
      "masses:\n"
      "  - {node: 1, mass: 1, inertia: [1, 2, 3, 0.1, 0.2, 0.3]}\n"
      "  - {node: 1, mass: 1, inertia: [[1, 0.1, 0.3], [0.1, 2, 0.2], [0.3, 0.2, 3]]}\n"
      "  - {node: 2, mass: 1, inertia: [1, 2, 3]}\n"
      "rigid_joints:\n"
      "  - {master: 1, slaves: [2], dofs: [ux, 3, RZ]}\n"
      "fixed:\n"
      "  - {node: 1}\n"
      "  - {node: 2, dofs: 5}\n"
      "sets:\n"
      "  s: [{node: 2, dof: 6}, {node: 1, dof: Rx}]\n"
      "beams:\n",
      "alt");
  EXPECT_EQ(model.name, "");
  EXPECT_EQ(model.gravity, Vector3(0.0, 0.0, -kStandardGravity));
  EXPECT_EQ(model.nodes[1].position.x(), 1.5);
  EXPECT_EQ(model.materials[0].shear_modulus, 40.0);
  EXPECT_EQ(model.springs[0].n2, fem::kGround);
  EXPECT_EQ(model.springs[0].stiffness, (Vector6() << 0, 0, 3, 0, 0, 0).finished());
  EXPECT_EQ(model.springs[0].damping, (Vector6() << 0, 0, 0, 4, 0, 0).finished());
  EXPECT_EQ(model.springs[1].stiffness, Vector6::Zero());
  EXPECT_EQ(model.springs[1].damping, (Vector6() << 1, 2, 3, 4, 5, 6).finished());
  EXPECT_EQ(model.masses[0].inertia, model.masses[1].inertia);
  EXPECT_EQ(model.masses[0].inertia(1, 2), 0.2);
  EXPECT_EQ(model.masses[0].inertia(2, 0), 0.3);
  EXPECT_EQ(model.masses[2].inertia, Vector3(1, 2, 3).asDiagonal().toDenseMatrix());
  EXPECT_EQ(model.rigid_joints[0].dofs,
            (std::array<bool, 6>{{true, false, true, false, false, true}}));
  EXPECT_EQ(model.fixed[0].dofs, (std::array<bool, 6>{{true, true, true, true, true, true}}));
  EXPECT_EQ(model.fixed[1].dofs, (std::array<bool, 6>{{false, false, false, false, true, false}}));
  EXPECT_EQ(model.dof_sets.at("s"), (std::vector<fem::DofRef>{{2, 5}, {1, 3}}));
  EXPECT_TRUE(model.beams.empty());
}

TEST_F(ModelYamlTest, RejectsMissingKeys) {
  expectLoadError("no_material.yaml", replaced("material: steel, section: sq", "section: sq"),
                  {"beams[0].material: required key is missing", "(line 10)"});
  expectLoadError("no_nodes.yaml", "name: empty\n", {"nodes: required key is missing"});
  expectLoadError("no_x.yaml", replaced("{id: 2, x: [1, 0, 0]}", "{id: 2}"),
                  {"nodes[1].x: required key is missing", "(line 4)"});
  expectLoadError(
      "no_modulus.yaml", replaced("nu: 0.3, ", ""),
      {"materials[0]: required key G (shear modulus) or nu (Poisson's ratio) is missing"});
  expectLoadError("no_spring_constants.yaml", replaced("k: [1, 1, 1, 0, 0, 0]", "name: s"),
                  {"springs[0]: no stiffness or damping given"});
  expectLoadError("null_value.yaml", replaced("mass: 1.5", "mass: "),
                  {"masses[0].mass: expected a number, got nothing"});
}

TEST_F(ModelYamlTest, RejectsWrongTypes) {
  expectLoadError("string_number.yaml", replaced("E: 2.1e11", "E: abc"),
                  {"materials[0].E: expected a number, got 'abc'", "(line 6)"});
  expectLoadError("quoted_number.yaml", replaced("rho: 7850", "rho: \"7850\""),
                  {"materials[0].rho: expected a number, got the string \"7850\""});
  expectLoadError("list_for_string.yaml", replaced("material: steel", "material: [steel]"),
                  {"beams[0].material: expected a string, got a list"});
  expectLoadError("fractional_id.yaml", replaced("{id: 2,", "{id: 2.5,"),
                  {"nodes[1].id: expected an integer, got '2.5'"});
  expectLoadError("octal_looking_id.yaml", replaced("{id: 2,", "{id: 0x2,"),
                  {"nodes[1].id: expected an integer, got '0x2'"});
  expectLoadError("short_vector.yaml", replaced("x: [1, 0, 0]", "x: [1, 0]"),
                  {"nodes[1].x: expected a list of 3 numbers [x, y, z], got 2 entries"});
  expectLoadError("bool_number.yaml", replaced("mass: 1.5", "mass: true"),
                  {"masses[0].mass: expected a number, got 'true'"});
  expectLoadError("nodes_map.yaml",
                  replaced("nodes:\n  - {id: 1, x: [0, 0, 0]}\n  - {id: 2, x: [1, 0, 0]}\n",
                           "nodes: {id: 1}\n"),
                  {"nodes: expected a list of nodes {id, x: [x, y, z]}, got a map", "(line 2)"});
  expectLoadError("three_beam_nodes.yaml", replaced("nodes: [1, 2]", "nodes: [1, 2, 3]"),
                  {"beams[0].nodes: expected two node ids [n1, n2], got 3 entries"});
  expectLoadError("spring_ground_first.yaml", replaced("nodes: [2, ground]", "nodes: [ground, 2]"),
                  {"springs[0].nodes[0]: expected an integer, got 'ground'"});
  expectLoadError("spring_three_nodes.yaml", replaced("nodes: [2, ground]", "nodes: [1, 2, 3]"),
                  {"springs[0].nodes: expected [n1, n2], [n1, ground] or [n1] (to ground), got 3"});
  expectLoadError("short_k.yaml", replaced("k: [1, 1, 1, 0, 0, 0]", "k: [1, 1, 1]"),
                  {"springs[0].k: expected a list of 6 values", "got 3 entries"});
  expectLoadError("bad_inertia.yaml", replaced("mass: 1.5", "mass: 1.5, inertia: [1, 2, 3, 4]"),
                  {"masses[0].inertia: expected [Ixx, Iyy, Izz]", "got 4 entries"});
  expectLoadError(
      "bad_frame.yaml",
      replaced("k: [1, 1, 1, 0, 0, 0]", "k: [1, 1, 1, 0, 0, 0], frame: [[1, 0, 0], [0, 1, 0]]"),
      {"springs[0].frame: expected the local axes", "got 2 entries"});
  expectLoadError("slaves_scalar.yaml", replaced("slaves: [2]", "slaves: 2"),
                  {"rigid_joints[0].slaves: expected a list of slave node ids, got '2'"});
  expectLoadError("set_not_list.yaml",
                  replaced("tip: [{node: 2, dof: uz}]", "tip: {node: 2, dof: uz}"),
                  {"sets.tip: expected a list of {node, dof}, got a map"});
  expectLoadError("reserved_id.yaml", replaced("{id: 2,", "{id: -1,"),
                  {"nodes[1].id: node id -1 is reserved for the ground"});
}

TEST_F(ModelYamlTest, RejectsBadDofs) {
  expectLoadError("dof_digit.yaml", replaced("dofs: \"123\"", "dofs: \"127\""),
                  {"fixed[0].dofs: invalid DOFs '127'", "digits 1-6"});
  expectLoadError("dof_repeated.yaml", replaced("dofs: \"123\"", "dofs: \"113\""),
                  {"fixed[0].dofs: DOF ux is listed twice"});
  expectLoadError("dof_name.yaml", replaced("dofs: \"4\"", "dofs: [ux, uw]"),
                  {"rigid_joints[0].dofs[1]: unknown DOF 'uw'"});
  expectLoadError("dof_empty.yaml", replaced("dofs: \"4\"", "dofs: []"),
                  {"rigid_joints[0].dofs: no DOFs given"});
  expectLoadError("set_dof.yaml", replaced("dof: uz", "dof: 7"),
                  {"sets.tip[0].dof: unknown DOF '7'"});
  // A set item names one DOF: two digits are not the first of them.
  expectLoadError("set_dofs_digits.yaml", replaced("dof: uz", "dof: \"12\""),
                  {"sets.tip[0].dof: unknown DOF '12'"});
  expectLoadError("set_dof_key.yaml", replaced("dof: uz", "dofs: uz"),
                  {"sets.tip[0].dofs: unknown key (allowed keys: node, dof)"});
}

TEST_F(ModelYamlTest, RejectsNonFiniteNumbers) {
  expectLoadError("nan.yaml", replaced("x: [1, 0, 0]", "x: [1, 0, .nan]"),
                  {"nodes[1].x[2]: value .nan is not a finite number", "(line 4)"});
  expectLoadError("inf.yaml", replaced("E: 2.1e11", "E: .inf"),
                  {"materials[0].E: value .inf is not a finite number"});
  expectLoadError("minus_inf.yaml", replaced("k: [1, 1, 1, 0, 0, 0]", "k: [1, 1, -.Inf, 0, 0, 0]"),
                  {"springs[0].k[2]: value -.Inf is not a finite number"});
  expectLoadError("c_nan.yaml", replaced("mass: 1.5", "mass: nan"),
                  {"masses[0].mass: value nan is not a finite number"});
  expectLoadError("overflow.yaml", replaced("rho: 7850", "rho: 1e400"),
                  {"materials[0].rho: number 1e400 is out of range"});
}

TEST_F(ModelYamlTest, RejectsGravityBeyondAHundredG) {
  // Standard gravity in mm/s^2: the statics would print a sag a thousand times too large.
  expectLoadError("gravity_mm.yaml", std::string(kBase) + "gravity: [0, 0, -9806.65]\n",
                  {"gravity: magnitude 9806.65 m/s^2 is beyond 1000 m/s^2", "a value in mm/s^2?"});
  expectLoadError("gravity_huge.yaml", std::string(kBase) + "gravity: [0, 0, -9.8e300]\n",
                  {"gravity: magnitude 9.8e+300 m/s^2"});
  // Just beyond the bound reads as typed, not as the bound.
  expectLoadError("gravity_edge.yaml", std::string(kBase) + "gravity: [0, 0, -1000.0001]\n",
                  {"gravity: magnitude 1000.0001 m/s^2 is beyond 1000 m/s^2"});
  // The Moon, Jupiter, a 100 g shock and the bound itself stay accepted.
  for (const char* gravity :
       {"[0, 0, -1.62]", "[0, 0, -24.79]", "[0, 0, -980.665]", "[0, 0, -1000]"}) {
    const std::string path =
        write("gravity_ok.yaml", std::string(kBase) + "gravity: " + gravity + "\n");
    EXPECT_NO_THROW(loadModelYaml(path)) << gravity;
  }
}

// Another of the package's files is named for what it is, not by its first "unknown key".
TEST_F(ModelYamlTest, NamesAnotherKindOfFile) {
  expectLoadError("vehicle.yaml", readText(sourcePath("config/vehicles/paper_vehicle.yaml")),
                  {"not an FE model file", "this is a vehicle description"});
  expectLoadError("terrain.yaml", readText(sourcePath("config/tracks/bump.yaml")),
                  {"not an FE model file", "this is a terrain file"});
  // A model file's own keys decide: a typo beside them is still named key by key.
  expectLoadError("with_heights.yaml", std::string(kBase) + "heights: [0, 1]\n",
                  {"heights: unknown key"});
}

TEST_F(ModelYamlTest, RejectsUnknownAndRepeatedKeys) {
  expectLoadError("top_typo.yaml", replaced("beams:\n", "beam:\n"),
                  {"beam: unknown key (allowed keys: name, gravity, nodes,", "(line 9)"});
  expectLoadError("item_typo.yaml", replaced("material: steel", "materail: steel"),
                  {"beams[0].materail: unknown key (allowed keys: nodes, material, section, "
                   "orientation, axial_force)"});
  expectLoadError("spring_typo.yaml", replaced("k: [1, 1, 1, 0, 0, 0]", "kz: 1, kzz: 2"),
                  {"springs[0].kzz: unknown key"});
  expectLoadError("repeated_key.yaml", replaced("rho: 7850", "rho: 7850, E: 1"),
                  {"materials[0].E: key given twice (also on line 6)"});
  expectLoadError("repeated_top.yaml", std::string(kBase) + "name: again\n",
                  {"name: key given twice (also on line 1)", "(line 21)"});
  expectLoadError(
      "both_g_nu.yaml", replaced("nu: 0.3", "nu: 0.3, G: 8e10"),
      {"materials[0]: give either G (shear modulus) or nu (Poisson's ratio), not both"});
  expectLoadError("bad_nu.yaml", replaced("nu: 0.3", "nu: 0.7"),
                  {"materials[0].nu: Poisson's ratio 0.7 is outside (-1, 0.5]"});
  // Both ends of (-1, 0.5]: -1 (G = E / 0) refused by its range, 0.5 (incompressible) taken with
  // G = E / (2 (1 + nu)) = E / 3.
  expectLoadError("nu_minus_one.yaml", replaced("nu: 0.3", "nu: -1"),
                  {"materials[0].nu: Poisson's ratio -1 is outside (-1, 0.5]"});
  const fem::Model incompressible =
      loadModelYaml(write("nu_half.yaml", replaced("nu: 0.3", "nu: 0.5")));
  EXPECT_EQ(incompressible.materials[0].shear_modulus, 2.1e11 / 3.0);
  expectLoadError("k_and_kx.yaml",
                  replaced("k: [1, 1, 1, 0, 0, 0]", "k: [1, 1, 1, 0, 0, 0], kx: 3"),
                  {"springs[0]: give either k: [6 values] or the keys kx..krz, not both"});
}

TEST_F(ModelYamlTest, ReportsValidationErrorsWithTheFileName) {
  expectLoadError("unknown_node.yaml", replaced("nodes: [1, 2]", "nodes: [1, 17]"),
                  {"beams[0]: node 17 does not exist"});
  const std::string path = write("negative_mass.yaml", replaced("mass: 1.5", "mass: -5"));
  try {
    loadModelYaml(path);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": masses[0]: negative mass -5 kg");
  }
  expectLoadError("unknown_material.yaml", replaced("material: steel", "material: alu"),
                  {"beams[0]: material 'alu' does not exist"});
  expectLoadError("self_slave.yaml", replaced("slaves: [2]", "slaves: [1]"),
                  {"rigid_joints[0]: master node 1 is also its own slave"});
  expectLoadError("spring_to_itself.yaml", replaced("nodes: [2, ground]", "nodes: [2, 2]"),
                  {"springs[0]: spring connects node 2 to itself"});
  expectLoadError("left_handed.yaml",
                  replaced("k: [1, 1, 1, 0, 0, 0]",
                           "k: [1, 1, 1, 0, 0, 0], frame: [[0, 1, 0], [1, 0, 0], [0, 0, 1]]"),
                  {"springs[0]: frame is left-handed"});
}

TEST_F(ModelYamlTest, RejectsUnreadableOrNonYamlFiles) {
  expectLoadError("syntax.yaml", "nodes: [{id: 1, x: [0, 0, 0]}\nname: x\n",
                  {": line ", "invalid YAML"});
  expectLoadError("empty.yaml", "", {"the file is empty"});
  expectLoadError("comment_only.yaml", "# nothing here\n", {"the file is empty"});
  expectLoadError("scalar.yaml", "just some text\n",
                  {"expected a map with keys name, gravity, nodes", "got 'just some text'"});
  expectLoadError("list.yaml", "- 1\n- 2\n", {"expected a map with keys", "got a list"});
  // A CSV given for a model: its start is quoted, not all of it.
  std::string csv = "x_m,z_m\n";
  for (int i = 0; i < 2000; ++i)
    csv += std::to_string(i) + ",0\n";
  const std::string path = write("table.csv", csv);
  try {
    loadModelYaml(path);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_LT(message.size(), 300u) << message.size();
    EXPECT_NE(message.find("got 'x_m,z_m 0,0 1,0 2,0"), std::string::npos) << message;
    EXPECT_NE(message.find("... ("), std::string::npos) << message;
  }
  expectLoadError("binary.yaml",
                  std::string("\x7f"
                              "ELF\0\0\x01",
                              7),
                  {"binary content"});
  expectLoadError("two_documents.yaml", std::string(kBase) + "---\n" + kBase,
                  {"holds 2 YAML documents"});

  const std::string missing = (directory_ / "does_not_exist.yaml").string();
  try {
    loadModelYaml(missing);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), missing + ": file not found");
  }
  try {
    loadModelYaml(directory_.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is a directory"), std::string::npos) << e.what();
  }
}

// An error message is one line whatever the file holds: a newline, CR or escape sequence from a
// key or a value is shown as \xNN (raw, a CR sent the cursor back over the message's start).
TEST_F(ModelYamlTest, ControlCharactersInTheFileAreShownEscaped) {
  expectLoadError("newline_value.yaml", replaced("x: [1, 0, 0]", "x: [1, 0, \"0\\n tvd: ok\\r\"]"),
                  {"nodes[1].x[2]: expected a number, got the string \"0\\x0a tvd: ok\\x0d\""});
  expectLoadError("escape_key.yaml", replaced("name: base", "\"bad\\nkey\\e[31m\": base"),
                  {"bad\\x0akey\\x1b[31m: unknown key"});
  for (const std::string name : {"newline_value.yaml", "escape_key.yaml"}) {
    try {
      loadModelYaml((directory_ / name).string());
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find_first_of("\n\r\x1b"), std::string::npos) << message;
    }
  }
}

// A lone CR is a line break in YAML 1.2 (old Mac line endings), as in the CSV readers: the
// document reads as with LF (yaml-cpp alone read one line: "the file is empty" after a comment).
TEST_F(ModelYamlTest, CarriageReturnLineEndingsRead) {
  std::string mac = std::string("# a model saved with CR line endings\n") + kBase;
  for (char& c : mac)
    if (c == '\n')
      c = '\r';
  const fem::Model from_cr = loadModelYaml(write("cr.yaml", mac));
  const fem::Model from_lf = loadModelYaml(write("lf.yaml", kBase));
  EXPECT_EQ(from_cr.name, "base");
  EXPECT_EQ(from_cr.nodes.size(), from_lf.nodes.size());
  EXPECT_EQ(from_cr.springs.size(), from_lf.springs.size());
  EXPECT_EQ(from_cr.masses.size(), from_lf.masses.size());
  // CR LF stays one break: the lines (named in messages) are those of the LF file.
  std::string dos;
  for (const char c : replaced("mass: 1.5}", "mass: 1.5, colour: red}"))
    dos += c == '\n' ? std::string("\r\n") : std::string(1, c);
  expectLoadError("dos.yaml", dos, {"colour: unknown key", "(line 14)"});
}

/// Loads `path` with at most 1 GB of address space (not under a sanitizer, whose shadow memory
/// needs more) and exits 0 when it is refused with exactly `expected`.
[[noreturn]] void exitOnRefusal(const std::string& path, const std::string& expected) {
#ifndef TVD_SANITIZER_BUILD
  const rlim_t gigabyte = rlim_t{1} << 30;
  const rlimit limit{gigabyte, gigabyte};
  ::setrlimit(RLIMIT_AS, &limit);
#endif
  try {
    loadModelYaml(path);
  } catch (const InputError& e) {
    std::exit(e.what() == expected ? 0 : 2);
  } catch (...) {
    std::exit(3);
  }
  std::exit(4);
}

// yaml-cpp never got past a ',' where a document, or what follows a flow collection, should
// start ("[1],": a typo of a list's end): it yielded empty documents there until memory ran out.
// Now it is refused at its place. Each case runs in a child limited to 1 GB, so that a
// regression fails the test at once instead of exhausting the machine.
TEST_F(ModelYamlTest, AStrayCommaIsRefusedNotParsedForever) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {",\n", "line 1, column 1"},
      {"# a model\n,name: base\n", "line 2, column 1"},
      {"[1],\n", "line 1, column 4"},
      {"{name: base},\n", "line 1, column 13"},
      {"name: base\n...\n,\n", "line 3, column 1"},
  };
  for (const auto& [text, place] : cases) {
    const std::string path = write("comma.yaml", text);
    const std::string expected =
        path + ": " + place + ": invalid YAML: unexpected ',' (not a value, nor after one)";
    EXPECT_EXIT(exitOnRefusal(path, expected), ::testing::ExitedWithCode(0), "") << text;
  }
}

// yaml-cpp refuses a document nested about 500 deep (its guard against a stack overflow) as
// "bad file": the message says what is wrong, for lists and for block maps.
TEST_F(ModelYamlTest, DeeplyNestedFileIsNamedAsSuch) {
  const std::string lists = "name: " + std::string(1000, '[') + std::string(1000, ']') + "\n";
  expectLoadError("deep_lists.yaml", lists,
                  {"line 1, column ",
                   "invalid YAML: nested too deep (lists and maps more than "
                   "about 500 levels within one another"});
  std::string maps;
  for (int i = 0; i < 1000; ++i)
    maps += std::string(2 * i, ' ') + "k" + std::to_string(i) + ":\n";
  expectLoadError("deep_maps.yaml", maps, {"invalid YAML: nested too deep"});
  // 100 levels read, and fail on the schema instead.
  const std::string shallow = "name: " + std::string(100, '[') + std::string(100, ']') + "\n";
  expectLoadError("shallow.yaml", shallow, {"name"});
}

TEST_F(ModelYamlTest, SaveToAnUnwritablePathThrows) {
  const std::string path = (directory_ / "no_such_dir" / "model.yaml").string();
  EXPECT_THROW(saveModelYaml(awkwardModel(), path), Error);
}

}  // namespace
}  // namespace io
}  // namespace tracked_vehicle_dynamics
