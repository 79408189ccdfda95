// Geometric (initial-stress) stiffness of pre-loaded members against closed forms: a tensioned
// and a compressed simply supported beam, a beaded string, and a tensioned loop held by a rigid
// body, which must turn freely as a whole.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "expect_input_error.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/geometric_stiffness.h"
#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/static_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"

namespace tvd = tracked_vehicle_dynamics;
using tvd::kPi;
using tvd::Matrix;
using tvd::Matrix3;
using tvd::Vector;
using tvd::Vector3;
using tvd::fem::Model;
using Vector12 = Eigen::Matrix<double, 12, 1>;

namespace {

constexpr double kE = 210e9, kRho = 7850.0, kArea = 5e-3, kIy = 4e-6, kIz = 1e-6;
constexpr double kLength = 2.0;
/// Hermite elements converge as h^4: with 40 elements the first bending eigenvalue is within
/// 1e-6 of the continuum; 1e-5 leaves room and still fails a wrong coefficient (1 %).
constexpr double kBeamTolerance = 1e-5;

/// Simply supported steel beam along x (pins at both ends, torsion held at node 0), every beam
/// under the axial force N.
Model simplySupported(int elements, double axial_force) {
  Model m;
  for (int i = 0; i <= elements; ++i)
    m.addNode(i, Vector3(kLength * i / elements, 0.0, 0.0));
  m.materials.push_back({"steel", kE, 81e9, kRho});
  m.sections.push_back({"bar", kArea, kIy, kIz, 2e-6, 0.0, 0.0});
  for (int i = 0; i < elements; ++i) {
    tvd::fem::Beam beam{i, i + 1, "steel", "bar", Vector3::UnitZ()};
    beam.axial_force = axial_force;
    m.beams.push_back(beam);
  }
  m.fixed.push_back({0, {{true, true, true, true, false, false}}});
  m.fixed.push_back({elements, {{false, true, true, false, false, false}}});
  return m;
}

double firstEigenvalue(const Model& model) {
  const tvd::fem::System s = tvd::fem::assemble(model);
  const tvd::fem::ModalBasis b = tvd::fem::solveModesDense(Matrix(s.stiffness), Matrix(s.mass));
  return b.eigenvalues(0);
}

/// omega_1^2 of a pinned-pinned Euler beam under axial force N (tension > 0), bending about its
/// weak axis: (pi / L)^4 E I / (rho A) + (pi / L)^2 N / (rho A).
double pinnedPinnedEigenvalue(double axial_force) {
  const double k = kPi / kLength;
  return (std::pow(k, 4) * kE * kIz + k * k * axial_force) / (kRho * kArea);
}

TEST(GeometricStiffness, TensionRaisesAPinnedBeamsFirstModeAsTheClosedForm) {
  const double n = 50e3;  // a tenth of the Euler load
  EXPECT_NEAR(firstEigenvalue(simplySupported(40, 0.0)) / pinnedPinnedEigenvalue(0.0), 1.0,
              kBeamTolerance);
  const double tensioned = firstEigenvalue(simplySupported(40, n));
  EXPECT_NEAR(tensioned / pinnedPinnedEigenvalue(n), 1.0, kBeamTolerance);
  // The geometric term itself, N / P_Euler = 9.6 % of the eigenvalue here, not only the sum.
  EXPECT_GT(tensioned / pinnedPinnedEigenvalue(0.0), 1.09);
}

TEST(GeometricStiffness, HalfTheEulerLoadHalvesThePinnedBeamsFirstEigenvalue) {
  const double euler = kPi * kPi * kE * kIz / (kLength * kLength);
  EXPECT_NEAR(firstEigenvalue(simplySupported(40, -0.5 * euler)) /
                  firstEigenvalue(simplySupported(40, 0.0)),
              0.5, kBeamTolerance);
}

TEST(GeometricStiffness, BeyondTheEulerLoadTheModesAndTheStaticsSayUnstable) {
  const double euler = kPi * kPi * kE * kIz / (kLength * kLength);
  auto dense = [](const Model& model) {
    const tvd::fem::System s = tvd::fem::assemble(model);
    return tvd::fem::solveModesDense(Matrix(s.stiffness), Matrix(s.mass));
  };
  EXPECT_EQ(tvd::fem::unstableModesWarning(dense(simplySupported(20, -0.5 * euler))), "");
  // A free body's rigid-body modes come out as round-off either side of 0: not unstable, to
  // -1e-8 of the largest |omega^2| (here -4e-5); beyond that, one is.
  tvd::fem::ModalBasis free_body;
  free_body.eigenvalues = (Vector(3) << -1e-6, 2e-7, 4e3).finished();
  EXPECT_EQ(tvd::fem::unstableModesWarning(free_body), "");
  free_body.eigenvalues(0) = -1e-4;
  EXPECT_NE(tvd::fem::unstableModesWarning(free_body).find("1 mode has omega^2 < 0"),
            std::string::npos);
  // At twice the weak axis's Euler load omega_1^2 = -omega_0^2, one mode (the strong axis, 4
  // times stiffer, and the weak axis's second mode, 16 - 8 > 0, hold).
  const tvd::fem::ModalBasis buckled = dense(simplySupported(20, -2.0 * euler));
  EXPECT_NEAR(buckled.eigenvalues(0) / -pinnedPinnedEigenvalue(0.0), 1.0, 1e-3);
  EXPECT_EQ(buckled.frequencies_hz(0), 0.0);
  const std::string warning = tvd::fem::unstableModesWarning(buckled);
  EXPECT_NE(warning.find("1 mode has omega^2 < 0"), std::string::npos) << warning;
  EXPECT_NE(warning.find("compressive pre-load beyond buckling"), std::string::npos) << warning;
  const Model model = simplySupported(20, -2.0 * euler);
  const tvd::fem::System s = tvd::fem::assemble(model);
  EXPECT_TRUE(s.prestressed);
  try {
    tvd::fem::solveStatic(s, Vector::Ones(s.size()));
    ADD_FAILURE() << "an indefinite K was factorised";
  } catch (const tvd::SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("pre-loads make it unstable"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(tvd::fem::assemble(simplySupported(20, 0.0)).prestressed);
}

TEST(GeometricStiffness, BeamMatrixIsSymmetricAndFreeOfRigidMotionButTheTurn) {
  const tvd::fem::Section bar{"bar", kArea, kIy, kIz, 2e-6, 0.0, 0.0};
  const Vector3 x1(0.1, -0.2, 0.3), x2(0.5, 0.4, 0.1);
  const double n = 7e3, l = (x2 - x1).norm();
  const tvd::Matrix12 k = tvd::fem::beamGeometricStiffness(x1, x2, Vector3::UnitZ(), bar, n);
  EXPECT_LT((k - k.transpose()).cwiseAbs().maxCoeff(), 1e-9 * k.cwiseAbs().maxCoeff());
  const Vector3 e = (x2 - x1) / l;
  for (int axis = 0; axis < 3; ++axis) {
    Vector12 translation = Vector12::Zero();
    translation(axis) = translation(6 + axis) = 1.0;
    EXPECT_LT((k * translation).norm(), 1e-9 * n);
    // A rigid turn theta about a: u = theta x (x - x1) at node 2; its energy 2 V = N L |a x e|^2.
    const Vector3 a = Vector3::Unit(axis);
    Vector12 turn = Vector12::Zero();
    turn.segment<3>(3) = a;
    turn.segment<3>(6) = a.cross(x2 - x1);
    turn.segment<3>(9) = a;
    EXPECT_NEAR(turn.dot(k * turn), n * l * a.cross(e).squaredNorm(), 1e-9 * n * l);
  }
}

// Twisted by phi over its length, a bar's fibre at radius r tilts by r phi / L; the axial stress
// N / A acting through that tilt stores 2 V = (N / A) I_p phi^2 / L, I_p = I_y + I_z (the term
// that lowers a column's torsional buckling load): in local axes, and about the member's own
// axis in global ones.
TEST(GeometricStiffness, AUniformTwistStoresTheAxialStressThroughTheFibresTilt) {
  const tvd::fem::Section bar{"bar", kArea, kIy, kIz, 2e-6, 0.0, 0.0};
  const double n = 7e3, l = 0.8, phi = 0.3;
  const double expected = n / kArea * (kIy + kIz) * phi * phi / l;
  Vector12 twist = Vector12::Zero();
  twist(9) = phi;  // rx2: node 2 turned about the member's axis, node 1 held
  const tvd::Matrix12 local = tvd::fem::beamLocalGeometricStiffness(bar, l, n);
  EXPECT_NEAR(twist.dot(local * twist), expected, 1e-12 * expected);
  const Vector3 x1(0.1, -0.2, 0.3), x2(0.5, 0.4, 0.1);
  const Vector3 e = (x2 - x1).normalized();
  Vector12 turned = Vector12::Zero();
  turned.segment<3>(9) = phi * e;
  const tvd::Matrix12 global = tvd::fem::beamGeometricStiffness(x1, x2, Vector3::UnitZ(), bar, n);
  const double along = n / kArea * (kIy + kIz) * phi * phi / (x2 - x1).norm();
  EXPECT_NEAR(turned.dot(global * turned), along, 1e-9 * along);
}

/// N beads of mass m, spacing h, on ties of tension T between fixed ends: the beaded string,
/// omega_k = 2 sqrt(T / (m h)) sin(k pi / (2 (N + 1))), each twice (across y and z).
TEST(GeometricStiffness, TiesMakeABeadedStringWithItsExactFrequencies) {
  const int beads = 5;
  const double m = 2.5, h = 0.4, t = 900.0;
  Model model;
  for (int i = 0; i <= beads + 1; ++i)
    model.addNode(i, Vector3(h * i, 0.3, -0.1));
  for (int i = 0; i <= beads; ++i)
    model.ties.push_back({i, i + 1, t, "span"});
  for (int i = 1; i <= beads; ++i) {
    model.masses.push_back({i, m, Matrix3::Zero(), Vector3::Zero(), "bead"});
    model.fixed.push_back({i, {{true, false, false, true, true, true}}});
  }
  model.fixed.push_back({0});
  model.fixed.push_back({beads + 1});
  const tvd::fem::System s = tvd::fem::assemble(model);
  ASSERT_EQ(s.size(), 2 * beads);
  const tvd::fem::ModalBasis b = tvd::fem::solveModesDense(Matrix(s.stiffness), Matrix(s.mass));
  for (int k = 1; k <= beads; ++k) {
    const double omega = 2.0 * std::sqrt(t / (m * h)) * std::sin(k * kPi / (2.0 * (beads + 1)));
    for (int twice = 0; twice < 2; ++twice)
      EXPECT_NEAR(std::sqrt(b.eigenvalues(2 * (k - 1) + twice)), omega, 1e-9 * omega) << k;
  }
}

/// A square loop of side a in the x-y plane under tension T, its corners rigid with a body
/// (node 0, off the square's centre).
Model tensionedSquare(double t, double a, bool with_body_preload) {
  Model model;
  model.addNode(0, Vector3(1.0, 1.0, 1.0));
  const Vector3 centre(0.3, -0.2, 0.5);
  const Vector3 corners[4] = {centre + Vector3(-a, -a, 0) / 2, centre + Vector3(a, -a, 0) / 2,
                              centre + Vector3(a, a, 0) / 2, centre + Vector3(-a, a, 0) / 2};
  for (int i = 0; i < 4; ++i)
    model.addNode(i + 1, corners[i]);
  tvd::fem::RigidJoint body;
  body.master = 0;
  body.slaves = {1, 2, 3, 4};
  model.rigid_joints.push_back(body);
  model.masses.push_back({0, 100.0, 10.0 * Matrix3::Identity(), Vector3::Zero(), "body"});
  tvd::fem::BodyPreload preload;
  preload.node = 0;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    model.ties.push_back({i + 1, j + 1, t, "side"});
    // The pull of the two sides on corner i, which the body holds.
    const Vector3 pull = t * ((corners[j] - corners[i]).normalized() +
                              (corners[(i + 3) % 4] - corners[i]).normalized());
    preload.points.push_back(corners[i]);
    preload.forces.push_back(pull);
  }
  if (with_body_preload)
    model.body_preloads.push_back(preload);
  return model;
}

TEST(GeometricStiffness, ALoopHeldByARigidBodyLeavesTheBodyFreeToTurn) {
  const double t = 4e4, a = 2.0;
  // The loop alone resists the rigid turn by T sum L (I - e e^T) = 2 a T diag(1, 1, 2).
  const tvd::fem::System loop = tvd::fem::assemble(tensionedSquare(t, a, false));
  ASSERT_EQ(loop.size(), 6);
  const Matrix k = Matrix(loop.stiffness);
  EXPECT_NEAR(k(3, 3), 2.0 * a * t, 1e-9 * a * t);
  EXPECT_NEAR(k(4, 4), 2.0 * a * t, 1e-9 * a * t);
  EXPECT_NEAR(k(5, 5), 4.0 * a * t, 1e-9 * a * t);
  // With the body's pre-load its compression path takes that back: nothing resists any rigid
  // motion.
  const tvd::fem::System held = tvd::fem::assemble(tensionedSquare(t, a, true));
  EXPECT_LT(Matrix(held.stiffness).cwiseAbs().maxCoeff(), 1e-9 * a * t);
}

TEST(GeometricStiffness, BodyPreloadStiffnessDoesNotDependOnTheCentreWhenBalanced) {
  const Model model = tensionedSquare(3e3, 1.5, true);
  const auto& p = model.body_preloads.front();
  const Matrix3 k1 = tvd::fem::bodyPreloadStiffness(Vector3::Zero(), p.points, p.forces);
  const Matrix3 k2 = tvd::fem::bodyPreloadStiffness(Vector3(4, -7, 2), p.points, p.forces);
  EXPECT_LT((k1 - k2).cwiseAbs().maxCoeff(), 1e-9 * k1.cwiseAbs().maxCoeff());
}

TEST(GeometricStiffness, AnUnbalancedBodyPreloadOrAPointlessTieIsRefusedByName) {
  Model unbalanced = tensionedSquare(3e3, 1.5, true);
  unbalanced.body_preloads.front().forces.pop_back();
  unbalanced.body_preloads.front().points.pop_back();
  tvd::expectInputError([&] { tvd::fem::assemble(unbalanced); },
                        {"body_preloads[0]", "not self-equilibrated"});
  // Forces that sum to nothing but turn the body (a couple) are no self-equilibrated pre-load.
  Model couple = tensionedSquare(3e3, 1.5, true);
  auto& p = couple.body_preloads.front();
  p.points.push_back(p.points[0]);
  p.forces.push_back(Vector3(0.0, 0.0, 1e3));
  p.points.push_back(p.points[1]);  // 1.5 m along x from the first: a couple about y
  p.forces.push_back(Vector3(0.0, 0.0, -1e3));
  tvd::expectInputError([&] { tvd::fem::assemble(couple); },
                        {"body_preloads[0]", "not self-equilibrated"});
  // One force of 1e155 N: the sum's norm overflows to inf, which no tolerance of it refused.
  Model overflow = tensionedSquare(3e3, 1.5, true);
  overflow.body_preloads.front().forces.front() = Vector3(1e155, 1e155, 0.0);
  tvd::expectInputError([&] { tvd::fem::assemble(overflow); },
                        {"body_preloads[0]", "too large to sum in a double"});
  Model short_tie = tensionedSquare(3e3, 1.5, false);
  short_tie.ties.push_back({1, 1, 10.0, "loop"});
  tvd::expectInputError([&] { tvd::fem::assemble(short_tie); }, {"ties[4]", "zero-length tie"});
  Model nan_force = simplySupported(4, std::nan(""));
  tvd::expectInputError([&] { tvd::fem::assemble(nan_force); }, {"beams[0]", "axial force"});
}

}  // namespace
