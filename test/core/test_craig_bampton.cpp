// Craig-Bampton reduction (paper eqs. 3-10) on a steel cantilever: identities of the basis, the
// Rayleigh-Ritz bound and convergence, Guyan static exactness, and the damping models.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>
#include <utility>

#include "expect_input_error.h"
#include "steel_cantilever.h"
#include "tracked_vehicle_dynamics/dynamics/modal_system.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/reduction/craig_bampton.h"
#include "tracked_vehicle_dynamics/reduction/reduced_damping.h"

namespace tracked_vehicle_dynamics {
namespace reduction {
namespace {

constexpr double kExactTolerance = 1e-8;       // relative, identities up to round-off
constexpr double kFirstModesTolerance = 0.01;  // relative, paper-style "within 1 %"
constexpr double kRitzSlack = 1e-9;            // relative round-off allowed below the full value

// A 2 m steel cantilever along x, clamped at node 0, with `elements` Euler-Bernoulli beams
// (Iy != Iz so that the y and z bending modes are distinct). `tip_support` adds a grounded
// spring-damper under the tip (a road input, a damper).
fem::System cantilever(int elements, bool tip_support = false) {
  fem::Model model = test::steelCantilever(elements);
  if (tip_support) {
    fem::Spring spring;
    spring.n1 = elements;
    spring.n2 = fem::kGround;
    spring.stiffness(2) = 2e5;
    spring.damping(2) = 500.0;
    spring.name = "tip support";
    model.springs.push_back(spring);
  }
  return fem::assemble(model);
}

// uy and uz at the middle node and at the tip.
std::vector<DofIndex> masters(const fem::System& system, int elements) {
  const fem::DofMap& d = system.dofs;
  return {d.requireActive(elements, 2), d.requireActive(elements / 2, 2),
          d.requireActive(elements, 1), d.requireActive(elements / 2, 1)};
}

std::vector<DofIndex> slavesOf(DofIndex n, const std::vector<DofIndex>& masters) {
  std::vector<DofIndex> out;
  for (DofIndex i = 0; i < n; ++i)
    if (std::find(masters.begin(), masters.end(), i) == masters.end())
      out.push_back(i);
  return out;
}

double relativeError(const Matrix& a, const Matrix& b) {
  return (a - b).norm() / std::max(b.norm(), 1e-300);
}

TEST(CraigBampton, AllFixedInterfaceModesReproduceTheFullEigenvalues) {
  const fem::System system = cantilever(10);
  const std::vector<DofIndex> m = masters(system, 10);
  CraigBamptonOptions options;
  options.fixed_interface.count = static_cast<int>(system.size()) - static_cast<int>(m.size());
  const CraigBamptonResult cb = craigBampton(system, m, options);
  ASSERT_EQ(cb.size(), system.size());

  const fem::ModalBasis full = fem::solveModesDense(Matrix(system.stiffness), Matrix(system.mass));
  const fem::ModalBasis reduced = fem::solveModesDense(cb.stiffness, cb.mass);
  for (int i = 0; i < full.count(); ++i)
    EXPECT_NEAR(reduced.eigenvalues(i), full.eigenvalues(i), kExactTolerance * full.eigenvalues(i))
        << "mode " << i;
}

TEST(CraigBampton, TruncatedBasisConvergesFromAbove) {
  const int elements = 40;  // 240 DOFs: the fixed-interface modes come from Lanczos
  const fem::System system = cantilever(elements);
  const fem::ModalBasis full = fem::solveModesDense(Matrix(system.stiffness), Matrix(system.mass));
  const std::vector<DofIndex> m = masters(system, elements);

  double previous_error = 1e300;
  for (const int r : {2, 6, 12}) {
    CraigBamptonOptions options;
    options.fixed_interface.count = r;
    const CraigBamptonResult cb = craigBampton(system, m, options);
    ASSERT_EQ(cb.size(), static_cast<DofIndex>(m.size()) + r);
    ASSERT_EQ(cb.modeCount(), r);
    const fem::ModalBasis reduced = fem::solveModesDense(cb.stiffness, cb.mass);
    for (int i = 0; i < reduced.count(); ++i)
      EXPECT_GE(reduced.frequencies_hz(i), full.frequencies_hz(i) * (1.0 - kRitzSlack))
          << "Rayleigh-Ritz bound, r = " << r << ", mode " << i;
    double error = 0.0;
    for (int i = 0; i < 6; ++i)
      error = std::max(error, reduced.frequencies_hz(i) / full.frequencies_hz(i) - 1.0);
    EXPECT_LE(error, previous_error) << "r = " << r;
    previous_error = error;
    if (r >= 6) {
      EXPECT_LT(error, kFirstModesTolerance) << "first six modes, r = " << r;
    }
  }
}

TEST(CraigBampton, MasterRowsOfTheBasisAreTheIdentity) {
  const fem::System system = cantilever(12);
  const std::vector<DofIndex> m = masters(system, 12);
  CraigBamptonOptions options;
  options.fixed_interface.count = 5;
  options.keep_transformation = true;
  const CraigBamptonResult cb = craigBampton(system, m, options);
  ASSERT_EQ(cb.transformation.rows(), system.size());
  ASSERT_EQ(cb.transformation.cols(), 9);
  for (std::size_t i = 0; i < m.size(); ++i)
    for (DofIndex j = 0; j < cb.transformation.cols(); ++j)
      EXPECT_EQ(cb.transformation(m[i], j), static_cast<DofIndex>(i) == j ? 1.0 : 0.0);
}

TEST(CraigBampton, ConstraintModesSolveTheSlaveStatics) {
  const fem::System system = cantilever(12);
  const std::vector<DofIndex> m = masters(system, 12);
  CraigBamptonOptions options;
  options.fixed_interface.count = 3;
  options.keep_transformation = true;
  const CraigBamptonResult cb = craigBampton(system, m, options);
  const std::vector<DofIndex> s = slavesOf(system.size(), m);
  const Matrix k = Matrix(system.stiffness);
  const Matrix phi_c = cb.transformation(s, Eigen::seqN(0, m.size()));
  const Matrix k_ss = k(s, s);
  const Matrix k_sm = k(s, m);
  // Eq. 4: K_ss Phi_C + K_sm = 0.
  EXPECT_LT((k_ss * phi_c + k_sm).norm(), kExactTolerance * k_sm.norm());
}

TEST(CraigBampton, StiffnessIsBlockDiagonalAndModesAreMassNormalised) {
  const fem::System system = cantilever(12);
  const std::vector<DofIndex> m = masters(system, 12);
  CraigBamptonOptions options;
  options.fixed_interface.count = 6;
  const CraigBamptonResult cb = craigBampton(system, m, options);
  const auto nm = static_cast<DofIndex>(m.size());
  const Matrix coupling = cb.stiffness.block(0, nm, nm, 6);
  EXPECT_LT(coupling.norm(), kExactTolerance * cb.stiffness.norm());
  const Matrix modal_k = cb.stiffness.bottomRightCorner(6, 6);
  EXPECT_LT(relativeError(modal_k, Matrix(cb.fixed_interface_eigenvalues.asDiagonal())),
            kExactTolerance);
  EXPECT_LT(relativeError(cb.mass.bottomRightCorner(6, 6), Matrix::Identity(6, 6)),
            kExactTolerance);
  EXPECT_EQ(cb.stiffness, cb.stiffness.transpose());
  EXPECT_EQ(cb.mass, cb.mass.transpose());
}

TEST(CraigBampton, FixedInterfaceModesAreEigenpairsOfTheSlavePartition) {
  // Φ_N^T K_ss Φ_N = Λ and Φ_N^T M_ss Φ_N = I hold for any Ritz set; the eigen-equation
  // K_ss φ_r = λ_r M_ss φ_r and the lowest λ of a dense solve of (K_ss, M_ss) pin the modes
  // themselves (240 DOFs: the Lanczos path).
  const int elements = 40;
  const fem::System system = cantilever(elements);
  const std::vector<DofIndex> m = masters(system, elements);
  const int r = 8;
  CraigBamptonOptions options;
  options.fixed_interface.count = r;
  options.keep_transformation = true;
  const CraigBamptonResult cb = craigBampton(system, m, options);
  const std::vector<DofIndex> s = slavesOf(system.size(), m);
  const Matrix k_ss = Matrix(system.stiffness)(s, s);
  const Matrix m_ss = Matrix(system.mass)(s, s);
  const fem::ModalBasis dense = fem::solveModesDense(k_ss, m_ss);
  ASSERT_EQ(cb.modeCount(), r);
  for (int j = 0; j < r; ++j) {
    const Vector phi = cb.transformation(s, static_cast<Eigen::Index>(m.size()) + j);
    const double lambda = cb.fixed_interface_eigenvalues(j);
    EXPECT_LT((k_ss * phi - lambda * (m_ss * phi)).norm(), 1e-8 * (k_ss * phi).norm())
        << "mode " << j;
    EXPECT_NEAR(lambda, dense.eigenvalues(j), 1e-10 * dense.eigenvalues(j)) << "mode " << j;
  }
}

TEST(CraigBampton, GuyanStiffnessIsExactForLoadsOnTheMasters) {
  const fem::System system = cantilever(16);
  const std::vector<DofIndex> m = masters(system, 16);
  CraigBamptonOptions options;
  options.fixed_interface.count = 4;
  options.keep_transformation = true;
  const CraigBamptonResult cb = craigBampton(system, m, options);

  Vector f = Vector::Zero(system.size());
  f(m[0]) = -1500.0;  // tip, z [N]
  f(m[1]) = 700.0;    // middle, z
  f(m[2]) = 300.0;    // tip, y
  const Vector x_full = Matrix(system.stiffness).ldlt().solve(f);
  const Vector f_r = cb.transformation.transpose() * f;
  const Vector x_r = cb.stiffness.ldlt().solve(f_r);
  for (std::size_t i = 0; i < m.size(); ++i)
    EXPECT_NEAR(x_r(static_cast<DofIndex>(i)), x_full(m[i]), kExactTolerance * x_full.norm())
        << "master " << i;
  // The fixed-interface modes carry no static load from the masters.
  EXPECT_LT(x_r.tail(4).norm(), kExactTolerance * x_full.norm());
}

TEST(CraigBampton, InputsGravityAndRecoveryAreProjected) {
  const fem::System system = cantilever(12, true);
  ASSERT_EQ(system.input_stiffness.cols(), 1);
  const std::vector<DofIndex> m = masters(system, 12);
  CraigBamptonOptions options;
  options.fixed_interface.count = 4;
  options.keep_transformation = true;
  options.recovery_dofs = {system.dofs.requireActive(3, 2), m[1]};
  const CraigBamptonResult cb = craigBampton(system, m, options);
  const Matrix& t = cb.transformation;
  EXPECT_LT(relativeError(cb.input_stiffness, t.transpose() * Matrix(system.input_stiffness)),
            kExactTolerance);
  EXPECT_LT(relativeError(cb.input_damping, t.transpose() * Matrix(system.input_damping)),
            kExactTolerance);
  EXPECT_LT(relativeError(cb.gravity_load, t.transpose() * system.gravity_load), kExactTolerance);
  // The travel inertia per unit forward acceleration reduces the same way (T^T f_a).
  ASSERT_GT(system.travel_load.norm(), 0.0);
  EXPECT_LT(relativeError(cb.travel_load, t.transpose() * system.travel_load), kExactTolerance);
  EXPECT_EQ(cb.recovery.row(0), t.row(options.recovery_dofs[0]));
  EXPECT_EQ(cb.recovery.row(1), t.row(m[1]));
  EXPECT_LT(relativeError(cb.damping, t.transpose() * Matrix(system.damping) * t), kExactTolerance);
  EXPECT_GT(cb.damping.norm(), 0.0);
}

TEST(CraigBampton, RayleighDampingAddsToTheDampers) {
  const fem::System system = cantilever(12, true);
  const std::vector<DofIndex> m = masters(system, 12);
  CraigBamptonOptions options;
  options.fixed_interface.count = 4;
  const CraigBamptonResult discrete = craigBampton(system, m, options);
  options.damping.model = DampingModel::Rayleigh;
  options.damping.alpha = 0.8;
  options.damping.beta = 2e-4;
  const CraigBamptonResult rayleigh = craigBampton(system, m, options);
  const Matrix expected = discrete.damping + 0.8 * discrete.mass + 2e-4 * discrete.stiffness;
  EXPECT_LT(relativeError(rayleigh.damping, expected), kExactTolerance);
}

TEST(CraigBampton, ModalDampingGivesTheRatioInEveryReducedMode) {
  const fem::System system = cantilever(12, true);
  const std::vector<DofIndex> m = masters(system, 12);
  CraigBamptonOptions options;
  options.fixed_interface.count = 4;
  const CraigBamptonResult discrete = craigBampton(system, m, options);
  options.damping.model = DampingModel::Modal;
  options.damping.modal_ratio = 0.03;
  const CraigBamptonResult modal = craigBampton(system, m, options);
  const fem::ModalBasis modes = fem::solveModesDense(modal.stiffness, modal.mass);
  const Matrix structural =
      modes.shapes.transpose() * (modal.damping - discrete.damping) * modes.shapes;
  const Vector expected = 2.0 * 0.03 * modes.eigenvalues.cwiseSqrt();
  EXPECT_LT(relativeError(structural, Matrix(expected.asDiagonal())), kExactTolerance);

  options.damping.modal_ratios = Vector::Constant(3, 0.02);  // 8 reduced modes, not 3
  EXPECT_THROW(craigBampton(system, m, options), InputError);
}

// reducedDamping() refuses what no damping model means, naming the coefficient and its value
// (the vehicle description refuses them first; a caller of the core alone meets these).
TEST(ReducedDamping, RefusesNegativeOrNonFiniteCoefficientsAndMismatchedSizes) {
  const Matrix m = Matrix::Identity(2, 2);
  const Matrix k = Eigen::Vector2d(4.0, 9.0).asDiagonal();
  const Matrix c = Matrix::Zero(2, 2);
  DampingOptions rayleigh;
  rayleigh.model = DampingModel::Rayleigh;
  rayleigh.alpha = -0.1;
  expectInputError([&] { reducedDamping(m, k, c, rayleigh); },
                   {"reducedDamping: alpha = -0.1", "finite and non-negative"});
  rayleigh.alpha = 0.0;
  rayleigh.beta = std::numeric_limits<double>::quiet_NaN();
  expectInputError([&] { reducedDamping(m, k, c, rayleigh); }, "reducedDamping: beta = nan");
  DampingOptions modal;
  modal.model = DampingModel::Modal;
  modal.modal_ratios = (Vector(2) << 0.02, -0.01).finished();
  expectInputError([&] { reducedDamping(m, k, c, modal); },
                   "reducedDamping: modal damping ratio = -0.01");
  modal.modal_ratios = Vector::Constant(3, 0.02);
  expectInputError([&] { reducedDamping(m, k, c, modal); },
                   "3 modal damping ratios for 2 reduced modes");
  expectInputError([&] { reducedDamping(m, k, Matrix::Zero(3, 3), DampingOptions()); },
                   "M_R 2x2, K_R 2x2 and C_R 3x3 must be square of one size");
  // Zero coefficients are no damping at all, not an error; a valid ratio gives 2 zeta omega.
  rayleigh.beta = 0.0;
  EXPECT_EQ(reducedDamping(m, k, c, rayleigh), c);
  // (Filled in place: a fixed-size temporary assigned to it drew a false -Warray-bounds from
  // GCC 12.)
  modal.modal_ratios = (Vector(2) << 0.05, 0.1).finished();
  const Matrix modal_c = reducedDamping(m, k, c, modal);
  EXPECT_NEAR(modal_c(0, 0), 2.0 * 0.05 * 2.0, 1e-12);  // omega = 2 rad/s
  EXPECT_NEAR(modal_c(1, 1), 2.0 * 0.1 * 3.0, 1e-12);   // omega = 3 rad/s
  EXPECT_NEAR(modal_c(0, 1), 0.0, 1e-12);
}

// Modal damping on a system whose eigenvalues span eleven decades, as a reduced vehicle's on
// its ground ties: heavy bodies (1 t) on soft springs with modes near 0.1-0.5 Hz, each hung
// from a light sole (0.3 kg) on a 2e10 N/m tie. A dense solve mixes the low modes by about
// eps lambda_max over their gaps; C built on one solve and seen in ModalSystem's (refined)
// modes looked coupled (7e-7 here; review 164: 1.9e-5 on a light vehicle, so the FRF left
// the modal solution). Built on the refined modes it stays diagonal to rounding.
TEST(ReducedDamping, ModalDampingStaysUncoupledInTheModesOfAStiffTiedSystem) {
  constexpr int kBodies = 12;
  const int n = 2 * kBodies;
  Matrix m = Matrix::Zero(n, n), k = Matrix::Zero(n, n);
  // Interleaved (sole, body, sole, body, ...), as a reduction's masters and modes mix them.
  auto spring = [&](int a, int b, double stiffness) {
    k(a, a) += stiffness;
    if (b >= 0) {
      k(b, b) += stiffness;
      k(a, b) -= stiffness;
      k(b, a) -= stiffness;
    }
  };
  for (int i = 0; i < kBodies; ++i) {
    const int sole = 2 * i, body = 2 * i + 1;
    m(sole, sole) = 0.3;
    m(body, body) = 1000.0 * (1.0 + 0.05 * i);
    spring(sole, -1, 2e10);                     // the tie to ground
    spring(body, sole, 2e3 * (1.0 + 0.1 * i));  // the suspension
    if (i > 0)
      spring(body, 2 * i - 1, 1.5e3);  // the chain between bodies
  }
  DampingOptions modal;
  modal.model = DampingModel::Modal;
  modal.modal_ratio = 0.05;
  dynamics::SecondOrderSystem system;
  system.mass = m;
  system.stiffness = k;
  system.damping = reducedDamping(m, k, Matrix::Zero(n, n), modal);
  system.input_stiffness = Matrix::Zero(n, 1);
  system.input_damping = Matrix::Zero(n, 1);
  system.output = Matrix::Identity(n, n);
  system.output_names.resize(static_cast<std::size_t>(n));
  const dynamics::ModalSystem modes(system);
  EXPECT_LT(modes.naturalFrequencies()(0) / (2.0 * kPi), 0.5);
  EXPECT_GT(modes.naturalFrequencies()(n - 1) / modes.naturalFrequencies()(0), 1e5);
  EXPECT_LT(modes.maxOffDiagonalDampingRatio(), 1e-9);
}

TEST(CraigBampton, BareMatricesGiveTheSameReducedSystem) {
  const fem::System system = cantilever(12, true);
  const std::vector<DofIndex> m = masters(system, 12);
  CraigBamptonOptions options;
  options.fixed_interface.count = 4;
  const CraigBamptonResult a = craigBampton(system, m, options);
  const CraigBamptonResult b =
      craigBampton(system.stiffness, system.mass, system.damping, m, options);
  EXPECT_EQ(a.stiffness, b.stiffness);
  EXPECT_EQ(a.mass, b.mass);
  EXPECT_EQ(a.damping, b.damping);
  EXPECT_EQ(b.input_stiffness.cols(), 0);
  EXPECT_EQ(b.gravity_load, Vector::Zero(b.size()));
  EXPECT_EQ(b.travel_load, Vector::Zero(b.size()));
  // Temporaries (a scaled K, no damping) are copied, not referenced: the reducer outlives them.
  const CraigBamptonReducer reducer(SparseMatrix(2.0 * system.stiffness), system.mass,
                                    SparseMatrix(), m);
  const std::vector<double> overwrite(4096, 1e300);  // reuses the temporaries' memory, if freed
  const CraigBamptonResult c = reducer.reduce(options);
  const SparseMatrix k2 = 2.0 * system.stiffness, none;
  const CraigBamptonResult d = craigBampton(k2, system.mass, none, m, options);
  EXPECT_EQ(c.stiffness, d.stiffness);
  EXPECT_EQ(c.mass, d.mass);
  EXPECT_EQ(c.damping, d.damping);
  EXPECT_LT((c.stiffness - 2.0 * a.stiffness).cwiseAbs().maxCoeff(),
            1e-12 * a.stiffness.cwiseAbs().maxCoeff());
  EXPECT_EQ(overwrite.size(), 4096U);
}

// The reducer does the partition, constraint modes and master blocks once (vehicle_reduction.cpp
// raises the fixed-interface count on it): each count it gives is eq. 9's full projection
// T^T (.) T, whatever the masters (the tip's damper and road input a master, a slave, or no
// masters at all), on the Lanczos and the dense path, and does not depend on the counts asked
// for before.
TEST(CraigBampton, OneReducerGivesEveryModeCountAsTheFullProjection) {
  const fem::System system = cantilever(12, true);
  const DofIndex n = system.size();
  const fem::DofMap& d = system.dofs;
  const std::vector<std::vector<DofIndex>> master_sets = {
      masters(system, 12),  // the tip (damper, road input) among them
      {d.requireActive(4, 2), d.requireActive(8, 2), d.requireActive(4, 1), d.requireActive(8, 1)},
      {}};
  for (const std::vector<DofIndex>& m : master_sets) {
    const auto mc = static_cast<DofIndex>(m.size());
    const CraigBamptonReducer reducer(system, m);
    EXPECT_EQ(reducer.masters(), m);
    EXPECT_EQ(reducer.slaveCount(), n - mc);
    EXPECT_TRUE(reducer.builtOn(system));
    const bool tip_is_slave = std::find(m.begin(), m.end(), d.requireActive(12, 2)) == m.end();
    // 40 of the 68-72 slave DOFs take the dense solver (more than half).
    for (const int r : {6, 2, 0, 40, 6}) {
      SCOPED_TRACE("masters " + std::to_string(mc) + ", r = " + std::to_string(r));
      CraigBamptonOptions options;
      options.fixed_interface.count = r;
      options.keep_transformation = true;
      options.recovery_dofs = {d.requireActive(5, 2), d.requireActive(12, 2)};
      if (mc == 0 && r == 0) {
        EXPECT_THROW(reducer.reduce(options), InputError);  // empty basis
        continue;
      }
      const CraigBamptonResult cb = reducer.reduce(options);
      ASSERT_EQ(cb.size(), mc + r);
      const Matrix& t = cb.transformation;
      if (mc > 0) {
        EXPECT_EQ(t(m, Eigen::all), Matrix::Identity(mc, mc + r));
      }
      EXPECT_LT(relativeError(cb.mass, t.transpose() * Matrix(system.mass) * t), kExactTolerance);
      EXPECT_LT(relativeError(cb.stiffness, t.transpose() * Matrix(system.stiffness) * t),
                kExactTolerance);
      EXPECT_LT(relativeError(cb.damping, t.transpose() * Matrix(system.damping) * t),
                kExactTolerance);
      EXPECT_EQ(cb.mass, cb.mass.transpose());
      EXPECT_EQ(cb.damping, cb.damping.transpose());
      EXPECT_LT(relativeError(cb.input_stiffness, t.transpose() * Matrix(system.input_stiffness)),
                kExactTolerance);
      EXPECT_LT(relativeError(cb.input_damping, t.transpose() * Matrix(system.input_damping)),
                kExactTolerance);
      EXPECT_LT(relativeError(cb.gravity_load, t.transpose() * system.gravity_load),
                kExactTolerance);
      EXPECT_LT(relativeError(cb.travel_load, t.transpose() * system.travel_load), kExactTolerance);
      EXPECT_EQ(cb.recovery.row(0), t.row(options.recovery_dofs[0]));
      EXPECT_EQ(cb.recovery.row(1), t.row(options.recovery_dofs[1]));
      // With the tip a slave, its damper and road input reach the fixed-interface modes.
      if (tip_is_slave && r > 0) {
        EXPECT_GT(cb.damping.bottomRightCorner(r, r).norm(), 0.0);
        EXPECT_GT(cb.input_stiffness.bottomRows(r).norm(), 0.0);
      }
      // The same numbers as a reduction from scratch with that count.
      const CraigBamptonResult fresh = craigBampton(system, m, options);
      EXPECT_EQ(cb.mass, fresh.mass);
      EXPECT_EQ(cb.damping, fresh.damping);
      EXPECT_EQ(cb.input_damping, fresh.input_damping);
      EXPECT_EQ(cb.transformation, fresh.transformation);
    }
  }
  const CraigBamptonReducer reducer(system, masters(system, 12));
  CraigBamptonOptions too_many;
  too_many.fixed_interface.count = static_cast<int>(n) - 3;
  EXPECT_THROW(reducer.reduce(too_many), InputError);
  const fem::System copy = system;
  EXPECT_FALSE(reducer.builtOn(copy));
  // A bad master is named before the options are judged against it.
  std::vector<DofIndex> repeated(static_cast<std::size_t>(n) + 1, 0);
  too_many.fixed_interface.count = static_cast<int>(n);
  try {
    craigBampton(system, repeated, too_many);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("listed twice"), std::string::npos) << e.what();
  }
}

TEST(CraigBampton, PresolvedModesGiveTheReductionOfTheirLeadingCount) {
  // reduce(options, modes) on a solve for more modes: the leading count, as reduce(options)
  // solves them. Bit for bit when the modes were solved for that very count; to the eigen-solve's
  // convergence from a larger solve (Lanczos for 6 of 12 modes, and the dense path for 40).
  const fem::System system = cantilever(30, true);
  const fem::DofMap& d = system.dofs;
  const CraigBamptonReducer reducer(system, masters(system, 30));
  CraigBamptonOptions options;
  options.recovery_dofs = {d.requireActive(12, 2), d.requireActive(30, 2)};
  for (const auto& [r, solved] : {std::pair<int, int>{6, 6}, {6, 12}, {12, 40}, {40, 120}}) {
    SCOPED_TRACE(std::to_string(r) + " of " + std::to_string(solved));
    options.fixed_interface.count = solved;
    const fem::ModalBasis modes = reducer.fixedInterfaceModes(options);
    ASSERT_EQ(modes.count(), solved);
    options.fixed_interface.count = r;
    const CraigBamptonResult fresh = reducer.reduce(options);
    const CraigBamptonResult reused = reducer.reduce(options, modes);
    ASSERT_EQ(reused.modeCount(), r);
    ASSERT_EQ(reused.size(), fresh.size());
    if (r == solved) {
      EXPECT_EQ(reused.mass, fresh.mass);
      EXPECT_EQ(reused.stiffness, fresh.stiffness);
      EXPECT_EQ(reused.damping, fresh.damping);
      EXPECT_EQ(reused.recovery, fresh.recovery);
    }
    // The reduced eigenvalues do not depend on the sign or rotation of degenerate mode shapes.
    const fem::ModalBasis a = fem::solveModesDense(reused.stiffness, reused.mass);
    const fem::ModalBasis b = fem::solveModesDense(fresh.stiffness, fresh.mass);
    EXPECT_LT(relativeError(a.eigenvalues, b.eigenvalues), kExactTolerance);
    EXPECT_LT(relativeError(reused.fixed_interface_eigenvalues, fresh.fixed_interface_eigenvalues),
              kExactTolerance);
    EXPECT_EQ(reused.fixed_interface_eigenvalues, modes.eigenvalues.head(r));
    EXPECT_EQ(reused.seconds.fixed_interface_modes, 0.0);  // nothing solved
  }
  // A frequency limit cuts the leading modes as the solver cuts them.
  options.fixed_interface = {20, 0.0};
  const fem::ModalBasis modes = reducer.fixedInterfaceModes(options);
  const double limit = 0.5 * (modes.frequencies_hz(4) + modes.frequencies_hz(5));
  options.fixed_interface = {12, limit};
  EXPECT_EQ(reducer.reduce(options, modes).modeCount(), 5);
  EXPECT_EQ(reducer.reduce(options).modeCount(), 5);
  // Fewer modes than asked, or modes of another slave set, are a caller's mistake.
  options.fixed_interface = {21, 0.0};
  EXPECT_THROW(reducer.reduce(options, modes), std::logic_error);
  const CraigBamptonReducer other(system, {d.requireActive(30, 2)});
  options.fixed_interface = {6, 0.0};
  EXPECT_THROW(other.reduce(options, modes), std::logic_error);
}

TEST(CraigBampton, OneProjectionGivesTheReductionOfEachLeadingCount) {
  // vehicle_reduction.cpp projects the modes of its largest count once and takes each smaller
  // count's blocks as leading columns, rows and corners: the same model as projecting the
  // leading modes alone (to rounding; bit for bit with all of them), dampers and road input
  // on a slave included.
  const fem::System system = cantilever(30, true);
  const fem::DofMap& d = system.dofs;
  const CraigBamptonReducer reducer(system, masters(system, 10));  // the tip is a slave
  CraigBamptonOptions options;
  options.recovery_dofs = {d.requireActive(12, 2), d.requireActive(30, 2)};
  options.fixed_interface.count = 12;
  const FixedInterfaceProjection projection = reducer.project(reducer.fixedInterfaceModes(options));
  ASSERT_EQ(projection.count(), 12);
  EXPECT_GT(projection.damping_coupling.norm(), 0.0);
  EXPECT_GT(projection.input_stiffness.norm(), 0.0);
  for (const int r : {12, 5, 0, 1}) {
    SCOPED_TRACE("r = " + std::to_string(r));
    options.fixed_interface.count = r;
    const CraigBamptonResult reused = reducer.reduce(options, projection);
    const CraigBamptonResult alone = reducer.reduce(options, projection.modes);
    ASSERT_EQ(reused.modeCount(), r);
    ASSERT_EQ(reused.size(), alone.size());
    if (r == 12) {
      EXPECT_EQ(reused.mass, alone.mass);
      EXPECT_EQ(reused.damping, alone.damping);
      EXPECT_EQ(reused.input_damping, alone.input_damping);
    }
    EXPECT_LT(relativeError(reused.mass, alone.mass), kExactTolerance);
    EXPECT_EQ(reused.stiffness, alone.stiffness);
    EXPECT_LT(relativeError(reused.damping, alone.damping), kExactTolerance);
    EXPECT_LT(relativeError(reused.input_stiffness, alone.input_stiffness), kExactTolerance);
    EXPECT_LT(relativeError(reused.input_damping, alone.input_damping), kExactTolerance);
    EXPECT_LT(relativeError(reused.gravity_load, alone.gravity_load), kExactTolerance);
    EXPECT_LT(relativeError(reused.travel_load, alone.travel_load), kExactTolerance);
    EXPECT_EQ(reused.recovery, alone.recovery);
    EXPECT_EQ(reused.fixed_interface_eigenvalues, projection.modes.eigenvalues.head(r));
    EXPECT_EQ(reused.mass, reused.mass.transpose());
  }
  // A frequency limit keeps the leading modes under it, as the solver would.
  const double limit =
      0.5 * (projection.modes.frequencies_hz(3) + projection.modes.frequencies_hz(4));
  options.fixed_interface = {10, limit};
  EXPECT_EQ(reducer.reduce(options, projection).modeCount(), 4);
  // More modes than projected, or another reducer's projection, are a caller's mistake.
  options.fixed_interface = {13, 0.0};
  EXPECT_THROW(reducer.reduce(options, projection), std::logic_error);
  const CraigBamptonReducer other(system, masters(system, 10));
  options.fixed_interface = {6, 0.0};
  EXPECT_THROW(other.reduce(options, projection), std::logic_error);
  const CraigBamptonReducer more_slaves(system, {d.requireActive(10, 2)});
  EXPECT_THROW(more_slaves.project(projection.modes), std::logic_error);
}

TEST(CraigBampton, FrequencyLimitedFixedInterfaceModes) {
  const fem::System system = cantilever(40);
  const std::vector<DofIndex> m = masters(system, 40);
  CraigBamptonOptions options;
  options.fixed_interface.count = 50;
  options.fixed_interface.max_frequency_hz = 1000.0;
  const CraigBamptonResult cb = craigBampton(system, m, options);
  ASSERT_GT(cb.modeCount(), 0);
  EXPECT_LE(cb.fixed_interface_frequencies_hz.maxCoeff(), 1000.0);
  options.fixed_interface = {static_cast<int>(cb.modeCount()) + 1, 0.0};
  const CraigBamptonResult one_more = craigBampton(system, m, options);
  EXPECT_GT(one_more.fixed_interface_frequencies_hz(cb.modeCount()), 1000.0);
}

TEST(CraigBampton, RejectsBadInput) {
  const fem::System system = cantilever(8);
  const std::vector<DofIndex> m = masters(system, 8);
  CraigBamptonOptions options;
  EXPECT_THROW(craigBampton(system, {m[0], m[0]}, options), InputError);
  EXPECT_THROW(craigBampton(system, {system.size()}, options), InputError);
  EXPECT_THROW(craigBampton(system, {}, options), InputError);  // empty basis
  options.fixed_interface.count = static_cast<int>(system.size());
  EXPECT_THROW(craigBampton(system, m, options), InputError);  // r > s
  options.fixed_interface.count = 2;
  options.recovery_dofs = {-1};
  EXPECT_THROW(craigBampton(system, m, options), InputError);
}

TEST(CraigBampton, MastersThatLeaveARigidMotionFreeAreReported) {
  // Free-free beam: K is singular, and one master DOF cannot restrain all six rigid motions.
  fem::Model model = test::steelCantilever(4);
  model.fixed.clear();
  const fem::System system = fem::assemble(model);
  EXPECT_THROW(craigBampton(system, {system.dofs.requireActive(0, 2)}, {}), SolverError);
  // Clamping all six DOFs of one node restrains them: the reduction succeeds, rigid modes included.
  std::vector<DofIndex> node0;
  for (int d = 0; d < kDofsPerNode; ++d)
    node0.push_back(system.dofs.requireActive(0, d));
  CraigBamptonOptions options;
  options.fixed_interface.count = 4;
  const CraigBamptonResult cb = craigBampton(system, node0, options);
  const fem::ModalBasis reduced = fem::solveModesDense(cb.stiffness, cb.mass);
  EXPECT_LT(reduced.frequencies_hz.head(6).cwiseAbs().maxCoeff(), 1e-3);  // six rigid-body modes
  EXPECT_GT(reduced.frequencies_hz(6), 1.0);
  // Node 0's ux, uy, uz, rx, ry and uz at two other nodes leave the rotation about z through
  // node 0 free: K_ss is singular, but its zero pivot may round to a tiny positive one that
  // CHOLMOD factorises (review 134, on a 10-element free-free beam: T off by 2.6 from the
  // pseudo-inverse's). Refused by the rcond bound whatever the rounding does.
  for (int elements : {4, 10}) {
    fem::Model free_beam = test::steelCantilever(elements);
    free_beam.fixed.clear();
    const fem::System beam = fem::assemble(free_beam);
    const fem::DofMap& d = beam.dofs;
    const std::vector<DofIndex> almost = {
        d.requireActive(0, 0),           d.requireActive(0, 1), d.requireActive(0, 2),
        d.requireActive(0, 3),           d.requireActive(0, 4), d.requireActive(elements, 2),
        d.requireActive(elements / 2, 2)};
    for (double scale : {1.0, 1.0000001}) {
      SCOPED_TRACE("elements " + std::to_string(elements) + ", K x " + std::to_string(scale));
      const SparseMatrix k = beam.stiffness * scale;
      EXPECT_THROW(craigBampton(k, beam.mass, SparseMatrix(), almost, {}), SolverError);
    }
  }
}

}  // namespace
}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
