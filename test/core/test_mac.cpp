// MAC (paper eq. 11), the correlation list, common DOFs, and the mode selection built on them
// (paper §3.1.1) with its carry-over to the fixed-interface modes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "steel_cantilever.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/reduction/common_dofs.h"
#include "tracked_vehicle_dynamics/reduction/fixed_interface_modes.h"
#include "tracked_vehicle_dynamics/reduction/mac.h"
#include "tracked_vehicle_dynamics/reduction/mode_selection.h"

namespace tracked_vehicle_dynamics {
namespace reduction {
namespace {

constexpr double kRoundOff = 1e-12;

Matrix randomShapes(DofIndex rows, DofIndex cols, unsigned seed) {
  std::srand(seed);
  return Matrix::Random(rows, cols);
}

TEST(Mac, OfASetWithItselfHasAUnitDiagonalAndIsSymmetric) {
  const Matrix phi = randomShapes(30, 6, 1);
  const Matrix m = mac(phi, phi);
  ASSERT_EQ(m.rows(), 6);
  ASSERT_EQ(m.cols(), 6);
  for (int j = 0; j < 6; ++j)
    EXPECT_NEAR(m(j, j), 1.0, kRoundOff);
  EXPECT_LT((m - m.transpose()).cwiseAbs().maxCoeff(), kRoundOff);
  EXPECT_GE(m.minCoeff(), 0.0);
  EXPECT_LE(m.maxCoeff(), 1.0);
}

TEST(Mac, SwappingTheSetsTransposes) {
  const Matrix a = randomShapes(20, 4, 2);
  const Matrix b = randomShapes(20, 7, 3);
  EXPECT_LT((mac(a, b) - mac(b, a).transpose()).cwiseAbs().maxCoeff(), kRoundOff);
}

TEST(Mac, IsInvariantToTheScalingOfEachShape) {
  const Matrix a = randomShapes(25, 5, 4);
  const Matrix b = randomShapes(25, 3, 5);
  const Vector scale_a = (Vector(5) << 2.0, -0.5, 1e3, -7.0, 1e-4).finished();
  const Vector scale_b = (Vector(3) << -3.0, 1e-2, 40.0).finished();
  const Matrix scaled = mac(a * scale_a.asDiagonal(), b * scale_b.asDiagonal());
  EXPECT_LT((scaled - mac(a, b)).cwiseAbs().maxCoeff(), kRoundOff);
}

TEST(Mac, ClosedFormsByHand) {
  Matrix a(2, 2), b(2, 2);
  // clang-format off
  a << 1.0, 0.0,
       0.0, 1.0;
  b << 1.0, 1.0,
       1.0, -2.0;
  // clang-format on
  const Matrix m = mac(a, b);
  // (1)^2 / (1 * 2) = 1/2; (1)^2 / (1 * 5) = 1/5; (1)^2 / (1 * 2); (-2)^2 / (1 * 5) = 4/5.
  EXPECT_NEAR(m(0, 0), 0.5, kRoundOff);
  EXPECT_NEAR(m(0, 1), 0.2, kRoundOff);
  EXPECT_NEAR(m(1, 0), 0.5, kRoundOff);
  EXPECT_NEAR(m(1, 1), 0.8, kRoundOff);
  // Orthogonal shapes: 0; a zero shape carries no shape: 0.
  Matrix zero = Matrix::Zero(2, 1);
  EXPECT_EQ(mac(a.col(0), a.col(1))(0, 0), 0.0);
  EXPECT_EQ(mac(zero, b)(0, 0), 0.0);
}

TEST(Mac, RoundOffShapesDoNotCorrelate) {
  // Column 1 is round-off next to column 0 (a mode that does not move on these DOFs): MAC 0,
  // although its direction matches b exactly.
  Matrix a(3, 2);
  // clang-format off
  a << 1.0, 1e-13,
       2.0, 1e-13,
       0.5, 0.0;
  // clang-format on
  Matrix b(3, 1);
  b << 1.0, 1.0, 0.0;
  const Matrix m = mac(a, b);
  EXPECT_GT(m(0, 0), 0.5);
  EXPECT_EQ(m(1, 0), 0.0);
  // Alone in its set it is the largest shape, and correlates fully.
  EXPECT_NEAR(mac(a.col(1), b)(0, 0), 1.0, kRoundOff);
}

TEST(Mac, IsNotMassWeighted) {
  // Two-DOF chain with unequal masses: the modes are M-orthogonal but not orthogonal, so their
  // MAC is not zero. The MAC measures shape likeness, not orthogonality.
  Matrix k(2, 2), m(2, 2);
  // clang-format off
  k << 3.0, -1.0,
      -1.0, 1.0;
  m << 1.0, 0.0,
       0.0, 4.0;
  // clang-format on
  const fem::ModalBasis modes = fem::solveModesDense(k, m);
  EXPECT_NEAR(modes.shapes.col(0).dot(m * modes.shapes.col(1)), 0.0, kRoundOff);
  EXPECT_GT(mac(modes.shapes, modes.shapes)(0, 1), 0.01);
}

TEST(Mac, RejectsMismatchedOrNonFiniteShapes) {
  EXPECT_THROW(mac(Matrix::Ones(3, 2), Matrix::Ones(4, 2)), InputError);
  Matrix bad = Matrix::Ones(3, 2);
  bad(1, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(mac(bad, Matrix::Ones(3, 2)), InputError);
}

// Between eigenspaces: single modes get the plain MAC; a repeated eigenvalue's modes get the MAC
// of their span, the same for any basis of it (a rotation within the pair changes the plain MAC
// but not this), and a shape inside the span has MAC 1 with every mode of the group.
TEST(EigenspaceMac, IsBasisInvariantForRepeatedModesAndPlainOtherwise) {
  const Matrix phi_a = randomShapes(30, 5, 11);
  Matrix phi_b = randomShapes(30, 4, 12);
  // B's modes 1 and 2 are a repeated eigenvalue; B's mode 3 lies in the span of A's 2 and 3.
  phi_b.col(3) = 0.3 * phi_a.col(2) - 2.0 * phi_a.col(3);
  Vector f_a(5), f_b(4);
  f_a << 1.0, 2.0, 3.0, 3.0 * (1.0 + 1e-9), 5.0;  // A: modes 2 and 3 repeated
  f_b << 1.5, 2.5, 2.5, 4.0;                      // B: modes 1 and 2 repeated
  const Matrix plain = mac(phi_a, phi_b);
  const Matrix m = eigenspaceMac(phi_a, f_a, phi_b, f_b);
  // Single with single: the plain MAC.
  for (int j : {0, 1, 4})
    for (int k : {0, 3})
      EXPECT_NEAR(m(j, k), plain(j, k), kRoundOff) << j << "," << k;
  // Group with anything: at least the best plain MAC of its members, one value for the group.
  EXPECT_GE(m(0, 1) + kRoundOff, std::max(plain(0, 1), plain(0, 2)));
  EXPECT_EQ(m(0, 1), m(0, 2));
  EXPECT_EQ(m(2, 1), m(3, 2));
  EXPECT_NEAR(m(2, 3), 1.0, kRoundOff);  // B's mode 3 is in span(A's 2, 3)
  EXPECT_NEAR(m(3, 3), 1.0, kRoundOff);
  // Another basis of B's repeated pair: plain MACs change, the eigenspace MAC does not.
  const double c = std::cos(0.7), s = std::sin(0.7);
  Matrix turned = phi_b;
  turned.col(1) = c * phi_b.col(1) + s * phi_b.col(2);
  turned.col(2) = -s * phi_b.col(1) + c * phi_b.col(2);
  EXPECT_GT((mac(phi_a, turned) - plain).cwiseAbs().maxCoeff(), 0.01);
  EXPECT_LT((eigenspaceMac(phi_a, f_a, turned, f_b) - m).cwiseAbs().maxCoeff(), kRoundOff);
  // A gap below A's 1e-9 splitting keeps A's modes 2 and 3 apart: plain MACs with B's single modes.
  const Matrix narrow = eigenspaceMac(phi_a, f_a, phi_b, f_b, 1e-12);
  for (int j : {2, 3})
    for (int k : {0, 3})
      EXPECT_NEAR(narrow(j, k), plain(j, k), kRoundOff) << j << "," << k;
  EXPECT_GT(m(2, 0), plain(2, 0) + 0.01);
  EXPECT_THROW(eigenspaceMac(phi_a, f_b, phi_b, f_b), InputError);  // 4 frequencies, 5 shapes
}

TEST(CorrelateModes, ListsTheBestMatchAndEveryMatchAboveTheThreshold) {
  Matrix m(3, 4);
  // clang-format off
  m << 0.95, 0.10, 0.72, 0.00,   // best 0, also 2
       0.20, 0.30, 0.10, 0.60,   // best 3, nothing above 0.7
       0.50, 0.80, 0.80, 0.90;   // best 3, then the tie 1, 2 in index order
  // clang-format on
  const std::vector<ModeCorrelation> c = correlateModes(m);
  ASSERT_EQ(c.size(), 3u);
  EXPECT_EQ(c[0].best_match, 0);
  EXPECT_DOUBLE_EQ(c[0].best_mac, 0.95);
  ASSERT_EQ(c[0].matches.size(), 2u);
  EXPECT_EQ(c[0].matches[1].mode, 2);
  EXPECT_EQ(c[1].best_match, 3);
  EXPECT_TRUE(c[1].matches.empty());
  ASSERT_EQ(c[2].matches.size(), 3u);
  EXPECT_EQ(c[2].matches[0].mode, 3);
  EXPECT_EQ(c[2].matches[1].mode, 1);
  EXPECT_EQ(c[2].matches[2].mode, 2);
  EXPECT_THROW(correlateModes(m, 0.0), InputError);
  EXPECT_THROW(correlateModes(m, 1.5), InputError);
}

TEST(CommonDofs, KeepsSharedTranslationsInTheOrderOfA) {
  using fem::DofRef;
  const std::vector<DofRef> a = {{1, 0}, {1, 2}, {1, 4}, {2, 2}, {3, 1}, {7, 2}};
  const std::vector<DofRef> b = {{2, 2}, {1, 2}, {1, 4}, {9, 0}, {3, 1}, {1, 1}};
  const CommonDofs common = commonTranslationalRows(a, b);
  // {1, 4} is a rotation: ignored even though both have it (paper §3.1.1).
  ASSERT_EQ(common.size(), 3);
  EXPECT_EQ(common.dofs[0], (DofRef{1, 2}));
  EXPECT_EQ(common.rows_a, (std::vector<DofIndex>{1, 3, 4}));
  EXPECT_EQ(common.rows_b, (std::vector<DofIndex>{1, 0, 4}));

  Matrix shapes(6, 2);
  for (int i = 0; i < 6; ++i)
    shapes.row(i) << i, 10 * i;
  const Matrix picked = selectRows(shapes, common.rows_b);
  EXPECT_EQ(picked(1, 1), 0.0);
  EXPECT_EQ(picked(2, 0), 4.0);
  EXPECT_THROW(selectRows(shapes, {6}), InputError);
  EXPECT_THROW(commonTranslationalRows({{1, 2}, {1, 2}}, b), InputError);
  EXPECT_THROW(commonTranslationalRows(a, {{1, 6}}), InputError);
}

// A 2 m steel cantilever along x. `planar`: uy, rx, rz held at every node, so only the x-z
// plane motion remains; the 3-D beam then has modes (y bending, torsion) the planar one lacks, as
// the tracked model has track-chain modes the un-tracked one lacks.
fem::System beamModel(bool planar) {
  const int elements = 10;
  fem::Model model = test::steelCantilever(elements);
  if (planar)
    for (int i = 1; i <= elements; ++i)
      model.fixed.push_back(fem::FixedDofs{i, {{false, true, false, true, false, true}}});
  return fem::assemble(model);
}

TEST(ModeSelection, CorrelationKeepsTheModesSharedWithTheReference) {
  const fem::System reference = beamModel(true);
  const fem::System candidate = beamModel(false);
  fem::ModalRequest request;
  request.count = 8;
  const fem::ModalBasis ref_modes = fem::solveModes(reference.stiffness, reference.mass, request);
  const fem::ModalBasis cand_modes = fem::solveModes(candidate.stiffness, candidate.mass, request);
  const CommonDofs common =
      commonTranslationalRows(activeDofRefs(candidate.dofs), activeDofRefs(reference.dofs));
  ASSERT_EQ(common.size(), 20);  // ux and uz of the 10 free nodes
  ModeReference ref;
  ref.mac = mac(selectRows(cand_modes.shapes, common.rows_a),
                selectRows(ref_modes.shapes, common.rows_b));
  ref.frequencies_hz = ref_modes.frequencies_hz;
  ModeSelectionOptions options;
  options.reference_name = "planar";
  const ModeSelection selection = selectModes(cand_modes.frequencies_hz, options, &ref);

  // Kept: the x-z modes, each found in the reference at the same frequency; left out: the modes
  // with lateral (uy) or torsional motion.
  const std::vector<ModeCorrelation> correlation = correlateModes(ref.mac);
  std::vector<int> kept;
  for (const SelectedMode& s : selection.modes) {
    kept.push_back(s.mode);
    const ModeCorrelation& c = correlation[static_cast<std::size_t>(s.mode)];
    EXPECT_GT(c.best_mac, 0.999) << s.reason;
    EXPECT_NEAR(s.frequency_hz, ref_modes.frequencies_hz(c.best_match), 1e-6 * s.frequency_hz);
    EXPECT_EQ(s.reason.rfind("MAC 1.00 with planar mode ", 0), 0u) << s.reason;
  }
  for (int j = 0; j < cand_modes.count(); ++j) {
    double lateral = 0.0, in_plane = 0.0;
    for (DofIndex i = 0; i < candidate.size(); ++i) {
      const int direction = candidate.dofs.dofOf(i).direction;
      const double v = cand_modes.shapes(i, j) * cand_modes.shapes(i, j);
      (direction == 0 || direction == 2 || direction == 4 ? in_plane : lateral) += v;  // ux uz ry
    }
    const bool is_kept = std::find(kept.begin(), kept.end(), j) != kept.end();
    EXPECT_EQ(is_kept, in_plane > lateral) << "mode " << j;
  }
  EXPECT_GT(selection.count(), 0);
  EXPECT_LT(selection.count(), cand_modes.count());
}

TEST(ModeSelection, ReasonsNameTheReferenceModeAndFrequency) {
  ModeReference ref;
  ref.mac.resize(3, 2);
  // clang-format off
  ref.mac << 0.30, 0.20,
             0.86, 0.72,
             0.10, 0.65;
  // clang-format on
  ref.frequencies_hz = (Vector(2) << 24.98, 3.72).finished();  // 3 figures: "25.0", not "25"
  const Vector f = (Vector(3) << 5.0, 8.5, 9.4).finished();
  ModeSelectionOptions options;
  options.reference_name = "un-tracked";
  const ModeSelection s = selectModes(f, options, &ref);
  ASSERT_EQ(s.count(), 1);
  EXPECT_EQ(s.modes[0].mode, 1);
  EXPECT_EQ(s.modes[0].reason, "MAC 0.86 with un-tracked mode 1 (25.0 Hz); also 0.72 with mode 2");
  EXPECT_DOUBLE_EQ(s.highestFrequencyHz(), 8.5);
  options.max_frequency_hz = 8.0;  // the band excludes it
  EXPECT_EQ(selectModes(f, options, &ref).count(), 0);
  EXPECT_THROW(selectModes(f, options), InputError);  // no reference
  ref.frequencies_hz.resize(1);
  EXPECT_THROW(selectModes(f, options, &ref), InputError);
}

TEST(ModeSelection, CountAndBand) {
  const Vector f = (Vector(5) << 0.0, 2.6, 3.7, 12.0, 31.0).finished();
  ModeSelectionOptions options;
  options.rule = ModeSelectionRule::Count;
  options.count = 3;
  const ModeSelection lowest = selectModes(f, options);
  ASSERT_EQ(lowest.count(), 3);
  EXPECT_EQ(lowest.modes[2].mode, 2);
  options.count = 6;
  EXPECT_THROW(selectModes(f, options), InputError);

  options.rule = ModeSelectionRule::FrequencyBand;
  options.min_frequency_hz = 1.0;
  options.max_frequency_hz = 30.0;
  const ModeSelection band = selectModes(f, options);
  ASSERT_EQ(band.count(), 3);
  EXPECT_EQ(band.modes.front().mode, 1);
  EXPECT_EQ(band.modes.back().mode, 3);
  EXPECT_EQ(band.modes[0].reason, "2.60 Hz in the band [1, 30] Hz");
  options.max_frequency_hz = 0.0;
  EXPECT_THROW(selectModes(f, options), InputError);
}

TEST(FixedInterfaceModes, CarryTheSelectionOverAsACountOrAFrequency) {
  ModeSelection selection;
  for (int i = 0; i < 8; ++i)
    selection.modes.push_back(SelectedMode{i, 2.0 + i, ""});
  // Paper Table 5: as many fixed-interface modes as selected global modes.
  const FixedInterfaceModes same = fixedInterfaceModes(selection);
  EXPECT_EQ(same.count, 8);
  EXPECT_EQ(same.max_frequency_hz, 0.0);
  FixedInterfaceOptions options;
  options.extra_modes = 2;
  EXPECT_EQ(fixedInterfaceModes(selection, options).count, 10);

  options.rule = FixedInterfaceRule::UpToFrequency;
  options.frequency_margin = 2.0;
  options.max_count = 50;
  const FixedInterfaceModes band = fixedInterfaceModes(selection, options);
  EXPECT_EQ(band.count, 50);
  EXPECT_DOUBLE_EQ(band.max_frequency_hz, 18.0);
  options.frequency_margin = 0.5;
  EXPECT_THROW(fixedInterfaceModes(selection, options), InputError);
  options.frequency_margin = 1.5;
  EXPECT_THROW(fixedInterfaceModes(ModeSelection{}, options), InputError);
}

TEST(EigenspaceMac, PairOfGroupsIsTheCosineSquaredOfTheirSmallestPrincipalAngle) {
  // A's repeated pair spans {e1, e2}; B's spans {cos t e1 + sin t e3, e4}, given as two mixed
  // vectors. The smallest principal angle between the planes is t (the directions e1 and
  // cos t e1 + sin t e3), the largest is 90 deg (e2 is orthogonal to all of span B): every
  // entry of the group pair is cos^2 t = sigma_max^2, not sigma_min^2 = 0.
  const double t = 0.4;
  Matrix phi_a = Matrix::Zero(5, 2), phi_b = Matrix::Zero(5, 2);
  phi_a.col(0) << 1.0, 1.0, 0.0, 0.0, 0.0;
  phi_a.col(1) << 1.0, -2.0, 0.0, 0.0, 0.0;
  Vector u(5), w(5);
  u << std::cos(t), 0.0, std::sin(t), 0.0, 0.0;
  w << 0.0, 0.0, 0.0, 1.0, 0.0;
  phi_b.col(0) = 0.6 * u + 0.8 * w;
  phi_b.col(1) = -0.8 * u + 0.6 * w;
  Vector f_a(2), f_b(2);
  f_a << 3.0, 3.0;
  f_b << 7.0, 7.0;
  const Matrix m = eigenspaceMac(phi_a, f_a, phi_b, f_b);
  for (int j = 0; j < 2; ++j)
    for (int k = 0; k < 2; ++k)
      EXPECT_NEAR(m(j, k), std::cos(t) * std::cos(t), kRoundOff);
}

}  // namespace
}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
