// Springs, masses, rigid joints and solver errors against hand-solved cases.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/sparse_cholesky.h"
#include "tracked_vehicle_dynamics/fem/spring_element.h"
#include "tracked_vehicle_dynamics/fem/static_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"

namespace tvd = tracked_vehicle_dynamics;
using tvd::kPi;
using tvd::fem::Model;

namespace {

constexpr double kRelTolerance = 1e-9;

tvd::fem::Spring springAlong(tvd::NodeId a, tvd::NodeId b, int direction, double k) {
  tvd::fem::Spring s;
  s.n1 = a;
  s.n2 = b;
  s.stiffness(direction) = k;
  return s;
}

tvd::fem::Mass pointMass(tvd::NodeId node, double m) {
  tvd::fem::Mass mass;
  mass.node = node;
  mass.mass = m;
  return mass;
}

// Fixes every DOF of a node except the listed direction.
tvd::fem::FixedDofs allBut(tvd::NodeId node, int free_direction) {
  tvd::fem::FixedDofs f;
  f.node = node;
  f.dofs.fill(true);
  f.dofs[free_direction] = false;
  return f;
}

// The message of the SolverError the statics of `model` must raise (its stiffness is singular);
// empty, with a failure recorded, when it solves.
std::string singularStaticsMessage(const Model& model) {
  const tvd::fem::System sys = tvd::fem::assemble(model);
  try {
    tvd::fem::solveStatic(sys, sys.gravity_load);
  } catch (const tvd::SolverError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a SolverError";
  return std::string();
}

// n masses m in a vertical line on springs k, the first to ground (uz free only): the chains
// whose closed-form eigenvalues the SpringMassChain tests check.
tvd::fem::System groundedChain(int n, double k, double m) {
  Model model;
  for (int i = 1; i <= n; ++i) {
    model.addNode(i, tvd::Vector3(0, 0, 0.1 * i));
    model.masses.push_back(pointMass(i, m));
    model.fixed.push_back(allBut(i, 2));
    model.springs.push_back(springAlong(i, i == 1 ? tvd::fem::kGround : i - 1, 2, k));
  }
  return tvd::fem::assemble(model);
}

}  // namespace

TEST(SpringMassChain, EigenvaluesMatchClosedForm) {
  // n equal masses in a line, the first tied to ground, the last free:
  // omega_j^2 = 4 k/m sin^2((2j - 1) pi / (2 (2n + 1))), j = 1..n.
  const int n = 10;
  const double k = 1e5, m = 2.0;
  const tvd::fem::System sys = groundedChain(n, k, m);
  ASSERT_EQ(sys.size(), n);
  tvd::fem::ModalRequest req;
  req.count = n;
  const tvd::fem::ModalBasis basis = tvd::fem::solveModes(sys.stiffness, sys.mass, req);
  for (int j = 1; j <= n; ++j) {
    const double s = std::sin((2 * j - 1) * kPi / (2 * (2 * n + 1)));
    const double expected = 4 * k / m * s * s;
    EXPECT_NEAR(basis.eigenvalues(j - 1), expected, kRelTolerance * expected) << "mode " << j;
  }
  // One road input (the grounded spring), K_u = k on the first mass.
  ASSERT_EQ(sys.input_stiffness.cols(), 1);
  EXPECT_DOUBLE_EQ(sys.input_stiffness.coeff(sys.dofs.requireActive(1, 2), 0), k);
}

TEST(SpringMassChain, LargeChainUsesLanczosAndMatchesClosedForm) {
  const int n = 400;
  const double k = 2e6, m = 5.0;
  const tvd::fem::System sys = groundedChain(n, k, m);
  tvd::fem::ModalRequest req;
  req.count = 15;
  const tvd::fem::ModalBasis basis = tvd::fem::solveModes(sys.stiffness, sys.mass, req);
  for (int j = 1; j <= 15; ++j) {
    const double s = std::sin((2 * j - 1) * kPi / (2 * (2 * n + 1)));
    EXPECT_NEAR(basis.eigenvalues(j - 1), 4 * k / m * s * s, 1e-8 * 4 * k / m * s * s);
  }
}

TEST(SpringMassChain, EveryModeOfALargeChainIsReturned) {
  // Asked for all n modes (by count, or by a limit above the highest), the sparse path returned
  // n - 1: Lanczos cannot deliver the last. The closed form above holds for the highest too.
  const int n = 250;
  const double k = 2e6, m = 5.0;
  const tvd::fem::System sys = groundedChain(n, k, m);
  ASSERT_EQ(sys.size(), n);
  tvd::fem::ModalRequest by_count;
  by_count.count = n + 5;
  tvd::fem::ModalRequest by_limit;
  by_limit.count = n;
  by_limit.max_frequency_hz = 1.01 * std::sqrt(4 * k / m) / (2 * kPi);  // above omega_max
  for (const tvd::fem::ModalRequest& req : {by_count, by_limit}) {
    const tvd::fem::ModalBasis basis = tvd::fem::solveModes(sys.stiffness, sys.mass, req);
    ASSERT_EQ(basis.count(), n) << "limit " << req.max_frequency_hz;
    for (int j : {1, n - 1, n}) {
      const double s = std::sin((2 * j - 1) * kPi / (2 * (2 * n + 1)));
      EXPECT_NEAR(basis.eigenvalues(j - 1), 4 * k / m * s * s, 1e-8 * 4 * k / m * s * s)
          << "mode " << j;
    }
  }
}

TEST(SpringElement, OffsetSpringCarriesNoForceUnderRigidRotation) {
  // Two nodes apart along x joined by a full 6-component bushing: a rigid rotation of both
  // nodes must not strain it (the bushing acts at the midpoint through rigid offsets).
  Model model;
  model.addNode(1, tvd::Vector3(0, 0, 0));
  model.addNode(2, tvd::Vector3(0.5, 0.1, -0.2));
  tvd::fem::Spring s;
  s.n1 = 1;
  s.n2 = 2;
  s.stiffness << 1e6, 2e6, 3e6, 1e3, 2e3, 3e3;
  model.springs.push_back(s);
  model.masses.push_back(pointMass(1, 1.0));
  model.masses.push_back(pointMass(2, 1.0));
  tvd::fem::AssemblyOptions options;
  options.drop_null_dofs = false;
  const tvd::fem::System sys = tvd::fem::assemble(model, options);
  tvd::Vector rigid(12);
  const tvd::Vector3 theta(0.01, -0.02, 0.03), u0(1, 2, 3);
  for (int n = 0; n < 2; ++n) {
    const tvd::Vector3 x = model.nodes[n].position;
    rigid.segment<3>(6 * n) = u0 + theta.cross(x);
    rigid.segment<3>(6 * n + 3) = theta;
  }
  EXPECT_LT((sys.stiffness * rigid).norm(), 1e-9 * 3e6);
}

TEST(SpringElement, LocalFrameRotatesStiffness) {
  // A spring with stiffness only along a local axis at 45 deg in x-z acts along that axis.
  Model model;
  model.addNode(1, tvd::Vector3(0, 0, 0));
  tvd::fem::Spring s;
  s.n1 = 1;
  s.stiffness(0) = 1000.0;
  const double c = std::sqrt(0.5);
  s.frame << c, 0, -c, 0, 1, 0, c, 0, c;  // columns: local x = (c,0,c), y, z = (-c,0,c)
  model.springs.push_back(s);
  model.masses.push_back(pointMass(1, 1.0));
  tvd::fem::AssemblyOptions options;
  options.drop_null_dofs = false;
  const tvd::fem::System sys = tvd::fem::assemble(model, options);
  EXPECT_NEAR(sys.stiffness.coeff(0, 0), 500.0, 1e-9);
  EXPECT_NEAR(sys.stiffness.coeff(0, 2), 500.0, 1e-9);
  EXPECT_NEAR(sys.stiffness.coeff(2, 2), 500.0, 1e-9);
  EXPECT_NEAR(sys.stiffness.coeff(1, 1), 0.0, 1e-12);
}

TEST(RigidJoint, EliminationEqualsTheMergedRigidBody) {
  // A rigid body made of three point masses joined by a rigid joint, on four ground springs,
  // must have exactly the modes of one rigid body carrying the same mass and inertia.
  const double m = 10.0;
  const tvd::Vector3 p[3] = {{0.4, 0.0, 0.1}, {-0.3, 0.5, 0.0}, {0.0, -0.2, 0.6}};
  const tvd::Vector3 corners[4] = {{1, 1, 0}, {1, -1, 0}, {-1, 1, 0}, {-1, -1, 0}};
  tvd::Vector6 k;
  k << 1e4, 2e4, 3e4, 0, 0, 0;

  Model split;
  split.addNode(100, tvd::Vector3::Zero());
  tvd::fem::RigidJoint joint;
  joint.master = 100;
  for (int i = 0; i < 3; ++i) {
    split.addNode(i + 1, p[i]);
    split.masses.push_back(pointMass(i + 1, m));
    joint.slaves.push_back(i + 1);
  }
  for (int c = 0; c < 4; ++c) {
    split.addNode(10 + c, corners[c]);
    joint.slaves.push_back(10 + c);
    tvd::fem::Spring s;
    s.n1 = 10 + c;
    s.stiffness = k;
    split.springs.push_back(s);
  }
  split.rigid_joints.push_back(joint);

  Model merged;
  merged.addNode(100, tvd::Vector3::Zero());
  tvd::fem::Mass body;
  body.node = 100;
  body.mass = 3 * m;
  tvd::Vector3 cg = (p[0] + p[1] + p[2]) / 3.0;
  body.offset = cg;
  for (const auto& x : p) {
    const tvd::Vector3 r = x - cg;
    body.inertia += m * (r.squaredNorm() * tvd::Matrix3::Identity() - r * r.transpose());
  }
  merged.masses.push_back(body);
  for (int c = 0; c < 4; ++c) {
    merged.addNode(10 + c, corners[c]);
    tvd::fem::Spring s;
    s.n1 = 10 + c;
    s.stiffness = k;
    merged.springs.push_back(s);
  }
  tvd::fem::RigidJoint corners_joint;
  corners_joint.master = 100;
  corners_joint.slaves = {10, 11, 12, 13};
  merged.rigid_joints.push_back(corners_joint);

  const tvd::fem::System a = tvd::fem::assemble(split);
  const tvd::fem::System b = tvd::fem::assemble(merged);
  ASSERT_EQ(a.size(), 6);
  ASSERT_EQ(b.size(), 6);
  EXPECT_LT((tvd::Matrix(a.mass) - tvd::Matrix(b.mass)).norm(), 1e-10 * tvd::Matrix(b.mass).norm());
  EXPECT_LT((tvd::Matrix(a.stiffness) - tvd::Matrix(b.stiffness)).norm(), 1e-10);
  const auto ma = tvd::fem::solveModesDense(tvd::Matrix(a.stiffness), tvd::Matrix(a.mass));
  const auto mb = tvd::fem::solveModesDense(tvd::Matrix(b.stiffness), tvd::Matrix(b.mass));
  for (int i = 0; i < 6; ++i)
    EXPECT_NEAR(ma.eigenvalues(i), mb.eigenvalues(i), 1e-9 * mb.eigenvalues(i));
}

// A chain of rigid joints (joint i: master i, slave i + 1) is one rigid body however long: each
// physical DOF is a combination of at most the root's 6, found without recursion (100,000 links
// once overflowed the stack, and unmerged expressions grew as the square of the length).
TEST(RigidJoint, LongChainIsOneRigidBodyOfBoundedTerms) {
  const int n = 100000;
  const double spacing = 0.01, m = 1.0;
  Model chain;
  for (int i = 1; i <= n; ++i) {
    chain.addNode(i, tvd::Vector3(i * spacing, 0.0, 0.0));
    chain.masses.push_back(pointMass(i, m));
    if (i > 1) {
      tvd::fem::RigidJoint joint;
      joint.master = i - 1;
      joint.slaves.push_back(i);
      chain.rigid_joints.push_back(joint);
    }
  }
  tvd::fem::Spring ground;
  ground.n1 = 1;
  ground.stiffness << 1e4, 1e4, 1e4, 1e4, 1e4, 1e4;
  chain.springs.push_back(ground);
  const tvd::fem::System sys = tvd::fem::assemble(chain);
  ASSERT_EQ(sys.size(), 6);
  // At most 3 terms per translation (u + theta x r), 1 per rotation.
  EXPECT_LE(sys.dofs.transformation().nonZeros(), static_cast<Eigen::Index>(n) * 12);
  const tvd::Matrix mass(sys.mass);
  EXPECT_NEAR(mass(0, 0), n * m, 1e-9 * n * m);  // ux of the root carries every mass
  // theta_z of the root about its own node: sum of m (x_i - x_1)^2.
  double inertia = 0.0;
  for (int i = 1; i <= n; ++i)
    inertia += m * std::pow((i - 1) * spacing, 2);
  EXPECT_NEAR(mass(5, 5), inertia, 1e-9 * inertia);
}

TEST(RigidJoint, RevoluteJointLeavesOneRotationFree) {
  // A pendulum-like lever: the arm node follows the pivot in all DOFs but ry; a torsion spring
  // k_t about y and a tip mass m at arm length a give omega^2 = k_t / (m a^2).
  const double kt = 5e5, m = 1200.0, a = 0.5;
  Model model;
  model.addNode(1, tvd::Vector3(0, 0, 0));   // pivot, clamped
  model.addNode(2, tvd::Vector3(0, 0, 0));   // arm root
  model.addNode(3, tvd::Vector3(-a, 0, 0));  // wheel centre
  model.fixed.push_back({1, {{true, true, true, true, true, true}}});
  tvd::fem::RigidJoint revolute;
  revolute.master = 1;
  revolute.slaves = {2};
  revolute.dofs = {{true, true, true, true, false, true}};
  model.rigid_joints.push_back(revolute);
  tvd::fem::RigidJoint arm;
  arm.master = 2;
  arm.slaves = {3};
  model.rigid_joints.push_back(arm);
  tvd::fem::Spring torsion;
  torsion.n1 = 1;
  torsion.n2 = 2;
  torsion.stiffness(4) = kt;
  model.springs.push_back(torsion);
  model.masses.push_back(pointMass(3, m));
  const tvd::fem::System sys = tvd::fem::assemble(model);
  ASSERT_EQ(sys.size(), 1);
  const auto basis = tvd::fem::solveModesDense(tvd::Matrix(sys.stiffness), tvd::Matrix(sys.mass));
  EXPECT_NEAR(basis.eigenvalues(0), kt / (m * a * a), 1e-9 * kt / (m * a * a));
  // A vertical load F at the wheel centre deflects it by F a^2 / k_t.
  tvd::Vector f = tvd::Vector::Constant(1, 0.0);
  const tvd::Vector load = tvd::Vector::Zero(1);
  // Load through the constraint transformation: f_active = T^T f_phys.
  tvd::Vector f_phys = tvd::Vector::Zero(sys.dofs.physicalCount());
  f_phys(sys.dofs.physical(3, 2)) = -1000.0;
  f = sys.dofs.transformation().transpose() * f_phys;
  const auto r = tvd::fem::solveStatic(sys, f);
  EXPECT_NEAR(tvd::fem::physicalDisplacement(sys, r.displacement, 3, 2), -1000.0 * a * a / kt,
              1e-12);
}

TEST(RigidJoint, ConflictingConstraintsAreRejected) {
  Model model;
  model.addNode(1, tvd::Vector3::Zero());
  model.addNode(2, tvd::Vector3::UnitX());
  model.fixed.push_back({2, {{true, false, false, false, false, false}}});
  tvd::fem::RigidJoint j;
  j.master = 1;
  j.slaves = {2};
  model.rigid_joints.push_back(j);
  model.masses.push_back(pointMass(1, 1.0));
  try {
    tvd::fem::assemble(model);
    FAIL() << "expected an InputError";
  } catch (const tvd::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("node 2 ux is both fixed and a rigid-joint slave"),
              std::string::npos)
        << e.what();
  }
}

TEST(StaticSolver, SingularStiffnessNamesTheFreeMotion) {
  // Masses on vertical springs only: free to translate along x and y and to rotate about z.
  Model model;
  model.addNode(1, tvd::Vector3(0, 0, 0));
  model.addNode(2, tvd::Vector3(1, 0, 0));
  model.addNode(3, tvd::Vector3(0, 1, 0));
  tvd::fem::RigidJoint j;
  j.master = 1;
  j.slaves = {2, 3};
  model.rigid_joints.push_back(j);
  for (int n = 1; n <= 3; ++n) {
    model.masses.push_back(pointMass(n, 1.0));
    model.springs.push_back(springAlong(n, tvd::fem::kGround, 2, 1e4));
  }
  // Lateral and yaw restraint but nothing along x.
  model.springs.push_back(springAlong(1, tvd::fem::kGround, 1, 1e4));
  model.springs.push_back(springAlong(2, tvd::fem::kGround, 1, 1e4));
  const std::string message = singularStaticsMessage(model);
  EXPECT_NE(message.find("rigid-body translation along x"), std::string::npos) << message;
}

TEST(StaticSolver, AStiffnessWithNothingInItNamesTheFreeMotion) {
  // One mass held in every direction but z, and no spring at all: K is the 1 x 1 zero matrix,
  // which the sparse factorisation's symbolic analysis refuses outright. Still a free motion,
  // named as such, not a solver failure.
  Model model;
  model.addNode(1, tvd::Vector3(0, 0, 0));
  model.masses.push_back(pointMass(1, 2.0));
  tvd::fem::FixedDofs fixed;
  fixed.node = 1;
  fixed.dofs[2] = false;  // uz
  model.fixed.push_back(fixed);
  const std::string message = singularStaticsMessage(model);
  EXPECT_NE(message.find("free motion: rigid-body translation along z"), std::string::npos)
      << message;
  tvd::fem::SparseCholesky chol;
  EXPECT_FALSE(chol.factorize(tvd::fem::assemble(model).stiffness));
  EXPECT_EQ(chol.rcond(), 0.0);
}

TEST(StaticSolver, SingularStiffnessNamesAMechanismByItsDofs) {
  // Two masses on vertical ground springs, joined along x; the first held along x and y too. The
  // second is free along y alone: no motion of the whole, a mechanism of node 2 uy.
  Model model;
  model.addNode(1, tvd::Vector3(0, 0, 0));
  model.addNode(2, tvd::Vector3(1, 0, 0));
  for (int n = 1; n <= 2; ++n) {
    model.masses.push_back(pointMass(n, 1.0));
    model.springs.push_back(springAlong(n, tvd::fem::kGround, 2, 1e4));
  }
  model.springs.push_back(springAlong(1, tvd::fem::kGround, 0, 1e4));
  model.springs.push_back(springAlong(1, tvd::fem::kGround, 1, 1e4));
  model.springs.push_back(springAlong(1, 2, 0, 1e4));
  const std::string message = singularStaticsMessage(model);
  EXPECT_NE(message.find("free motion: a mechanism involving node 2 uy ("), std::string::npos)
      << message;
  EXPECT_EQ(message.find("rigid-body"), std::string::npos) << message;
  EXPECT_EQ(message.find("more"), std::string::npos) << message;  // one free motion, one DOF
}

TEST(StaticSolver, ManyFreeMotionsAreCountedNotMixed) {
  // N masses on vertical ground springs, free along x and y: 2N free motions, of which the
  // whole's translations along x and y and rotation about z are rigid-body ones; the other
  // 2N - 3 are mechanisms of all the x and y DOFs. Beyond the 24 sought the message says so.
  for (const int count : {10, 13}) {
    SCOPED_TRACE(count);
    Model model;
    for (int n = 1; n <= count; ++n) {
      model.addNode(n, tvd::Vector3(n, 0.3 * (n % 3), 0));
      model.masses.push_back(pointMass(n, 1.0));
      model.springs.push_back(springAlong(n, tvd::fem::kGround, 2, 1e4));
      tvd::fem::FixedDofs rotations;
      rotations.node = n;
      rotations.dofs = {false, false, false, true, true, true};
      model.fixed.push_back(rotations);
    }
    const std::string message = singularStaticsMessage(model);
    if (count == 10) {
      for (const char* motion : {"rigid-body translation along x", "rigid-body translation along y",
                                 "rigid-body rotation about z; 17 mechanisms involving node"})
        EXPECT_NE(message.find(motion), std::string::npos) << message;
      EXPECT_NE(message.find(" and 12 more DOFs"), std::string::npos) << message;  // 20 - 8
      EXPECT_EQ(message.find("uz"), std::string::npos) << message;  // held by its spring
      EXPECT_EQ(message.find("perhaps more"), std::string::npos) << message;
    } else {
      EXPECT_NE(message.find("perhaps more free motions (only the first 24 were sought)"),
                std::string::npos)
          << message;
    }
  }
}

TEST(StaticSolver, GroundReactionsBalanceGravity) {
  Model model;
  model.addNode(1, tvd::Vector3(0, 0, 1));
  model.fixed.push_back(allBut(1, 2));
  model.masses.push_back(pointMass(1, 50.0));
  model.springs.push_back(springAlong(1, tvd::fem::kGround, 2, 2e5));
  const tvd::fem::System sys = tvd::fem::assemble(model);
  const auto r = tvd::fem::solveStatic(sys, sys.gravity_load);
  EXPECT_NEAR(r.displacement(0), -50.0 * tvd::kStandardGravity / 2e5, 1e-15);
}

// 80 copies of 5 Hz among 300 distinct frequencies of 1..100 Hz, uncoupled (K diagonal, M
// unequal masses): a Krylov space holds one vector per distinct eigenvalue, so a Lanczos run
// returns few copies; the solver's Sylvester count must bring back every one, for a count and
// for a frequency limit (where recovered copies must not push modes under the limit out).
TEST(ModalSolver, EveryCopyOfAManyfoldEigenvalueIsReturned) {
  std::vector<double> hz;
  for (int i = 0; i < 300; ++i)
    hz.push_back(1.0 + 99.0 * i / 299.0);
  for (int i = 0; i < 80; ++i)
    hz.push_back(5.0);
  const auto n = static_cast<Eigen::Index>(hz.size());
  std::vector<tvd::Triplet> k, m;
  for (Eigen::Index i = 0; i < n; ++i) {
    const double mass = 1.0 + 0.01 * static_cast<double>(i % 7);
    m.emplace_back(i, i, mass);
    k.emplace_back(i, i, mass * std::pow(2.0 * kPi * hz[static_cast<std::size_t>(i)], 2));
  }
  tvd::SparseMatrix ks(n, n), ms(n, n);
  ks.setFromTriplets(k.begin(), k.end());
  ms.setFromTriplets(m.begin(), m.end());
  std::vector<double> sorted = hz;
  std::sort(sorted.begin(), sorted.end());

  tvd::fem::ModalRequest by_count;
  by_count.count = 100;  // 13 distinct below 5 Hz, the 80 copies, 7 above
  const tvd::fem::ModalBasis lowest = tvd::fem::solveModes(ks, ms, by_count);
  ASSERT_EQ(lowest.count(), 100);
  EXPECT_EQ(lowest.missed, 0);
  EXPECT_EQ(tvd::fem::missedModesWarning(lowest), "");
  for (int i = 0; i < 100; ++i)
    EXPECT_NEAR(lowest.frequencies_hz(i), sorted[static_cast<std::size_t>(i)], 1e-9) << i;

  tvd::fem::ModalRequest by_limit;
  by_limit.count = 300;
  by_limit.max_frequency_hz = 6.0;  // 16 distinct up to 5.97 Hz and the 80 copies
  const tvd::fem::ModalBasis below = tvd::fem::solveModes(ks, ms, by_limit);
  ASSERT_EQ(below.count(), 96);
  EXPECT_EQ(below.missed, 0);
  for (int i = 0; i < 96; ++i)
    EXPECT_NEAR(below.frequencies_hz(i), sorted[static_cast<std::size_t>(i)], 1e-9) << i;

  // What cannot be recovered is said, with how many and below which frequency.
  tvd::fem::ModalBasis short_of_some = lowest;
  short_of_some.missed = 3;
  EXPECT_NE(tvd::fem::missedModesWarning(short_of_some)
                .find("returned 100 modes up to " + tvd::brief(lowest.frequencies_hz(99)) +
                      " Hz but the system has 3 more below that frequency"),
            std::string::npos)
      << tvd::fem::missedModesWarning(short_of_some);
}

TEST(ModalSolver, BadRequestsAreRejected) {
  tvd::SparseMatrix k(3, 3), m(4, 4);
  tvd::fem::ModalRequest req;
  EXPECT_THROW(tvd::fem::solveModes(k, m, req), tvd::InputError);
  tvd::SparseMatrix m3(3, 3);
  req.count = 0;
  EXPECT_THROW(tvd::fem::solveModes(k, m3, req), tvd::InputError);
}

TEST(SpringElement, OffsetBushingActsAtTheMidpointOfItsNodes) {
  // A lateral spring k_y between nodes a distance L apart along x acts at p = (x1 + x2) / 2:
  // the y motion of p carried from node i is u_iy + rz_i (p - x_i)_x, so the stretch is
  // d = u2y - u1y - L/2 (rz1 + rz2) and 1/2 k_y d^2 gives K(rz_i, rz_j) = k_y L^2 / 4 for both
  // nodes and K(uy1, rz1) = k_y L / 2. Naming the nodes the other way round is the same spring.
  const double k = 2.0e5, length = 0.8;
  tvd::fem::Spring s = springAlong(1, 2, 1, k);
  const tvd::Vector3 x1(0.1, 0.2, 0.3), x2 = x1 + tvd::Vector3(length, 0.0, 0.0);
  const tvd::Matrix12 stiffness = tvd::fem::springMatrices(s, x1, x2).stiffness;
  const double quarter = k * length * length / 4.0;
  EXPECT_NEAR(stiffness(5, 5), quarter, kRelTolerance * quarter);
  EXPECT_NEAR(stiffness(11, 11), quarter, kRelTolerance * quarter);
  EXPECT_NEAR(stiffness(5, 11), quarter, kRelTolerance * quarter);
  EXPECT_NEAR(stiffness(1, 5), k * length / 2.0, kRelTolerance * k * length);
  // Swapping the nodes permutes the 6-DOF blocks and leaves the matrix otherwise unchanged.
  s.n1 = 2;
  s.n2 = 1;
  const tvd::Matrix12 swapped = tvd::fem::springMatrices(s, x2, x1).stiffness;
  tvd::Matrix12 permutation = tvd::Matrix12::Zero();
  permutation.topRightCorner<6, 6>().setIdentity();
  permutation.bottomLeftCorner<6, 6>().setIdentity();
  EXPECT_LT((permutation * swapped * permutation - stiffness).norm(), kRelTolerance * k);
}

// An infinite entry (springs of 1e308 N/m summed) is named as such, in K or M, not reported as
// "M is not positive definite".
TEST(DenseModalSolver, NamesTheMatrixWithANonFiniteEntry) {
  tvd::Matrix k = tvd::Matrix::Identity(3, 3), m = tvd::Matrix::Identity(3, 3);
  k(1, 1) = 1e308;
  k(1, 1) += 1e308;  // overflows to +inf
  for (const auto& [kk, mm, name] :
       {std::make_tuple(k, m, std::string("K")), std::make_tuple(m, k, std::string("M"))}) {
    try {
      tvd::fem::solveModesDense(kk, mm);
      ADD_FAILURE() << "accepted a non-finite " << name;
    } catch (const tvd::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(name + " has a non-finite entry"), std::string::npos)
          << e.what();
    }
  }
  EXPECT_EQ(tvd::fem::solveModesDense(m, m).count(), 3);
}
