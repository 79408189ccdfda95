// MoGeSeC master selection (paper §3.1.2, eqs. 12-14): a case computed by hand, ties and
// co-located DOFs, and the picks on a beam.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "steel_cantilever.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/reduction/mogesec.h"

namespace tracked_vehicle_dynamics {
namespace reduction {
namespace {

constexpr double kRoundOff = 1e-12;

TEST(Mogesec, HandComputedCase) {
  // Four candidates on the x axis, one mode; candidate 3 sits at the position of candidate 2
  // (two directions of one node). Initial master: candidate 0.
  //   W_Phi = phi^2                    = 1, 4, 1, 2.25
  // Pick 1: W_g = 1 / d^-4 from x = 0  =  -, 1, 81, 81   -> W = W_Phi/4 * W_g/81
  //                                    =  -, 1/324, 1/4, 0.5625  -> candidate 3
  // Pick 2: candidate 2 is co-located with 3: W_g = 0; candidate 1: 1 / (1 + 1/16) = 16/17
  //         -> candidate 1 with W = 1 * 1
  // Pick 3: only candidate 2 is left, W_g = 0 for all: geometry cannot rank, W = W_Phi,N = 1.
  Matrix shapes(4, 1);
  shapes << 1.0, 2.0, 1.0, 1.5;
  const std::vector<Vector3> positions = {Vector3(0, 0, 0), Vector3(1, 0, 0), Vector3(3, 0, 0),
                                          Vector3(3, 0, 0)};
  MogesecOptions options;
  options.count = 3;
  const MogesecResult result = mogesec(shapes, positions, {0}, options);
  ASSERT_EQ(result.picks.size(), 3u);
  EXPECT_EQ(result.picks[0].index, 3);
  EXPECT_NEAR(result.picks[0].weight, 0.5625, kRoundOff);
  EXPECT_NEAR(result.picks[0].modal_weight, 0.5625, kRoundOff);
  EXPECT_NEAR(result.picks[0].geometric_weight, 1.0, kRoundOff);
  EXPECT_EQ(result.picks[1].index, 1);
  EXPECT_NEAR(result.picks[1].weight, 1.0, kRoundOff);
  EXPECT_EQ(result.picks[2].index, 2);
  EXPECT_NEAR(result.picks[2].geometric_weight, 1.0, kRoundOff);
  EXPECT_NEAR(result.modal_weight(3), 2.25, kRoundOff);
}

TEST(Mogesec, GeometricWeightUsesTheDistanceToThePowerMinusKgTimesP) {
  // Masters at x = 0 and 2; candidate A (index 2) at x = 1, B (index 3) at x = -0.8, equal
  // modal weights. Eq. 14 with k_g = p = 2: W_g(A) = 1 / (1 + 1) = 0.5,
  // W_g(B) = 1 / (0.8^-4 + 2.8^-4) = 0.407 -> A. With the exponent k_g alone (d^-2) B would win:
  // 1 / (0.8^-2 + 2.8^-2) = 0.592 > 0.5. With p = 1 (the same distances on the axis) the
  // exponent is k_g p = 2 and B wins.
  Matrix shapes = Matrix::Ones(4, 1);
  const std::vector<Vector3> positions = {Vector3(0, 0, 0), Vector3(2, 0, 0), Vector3(1, 0, 0),
                                          Vector3(-0.8, 0, 0)};
  MogesecOptions options;
  options.count = 1;
  MogesecResult result = mogesec(shapes, positions, {0, 1}, options);
  EXPECT_EQ(result.picks[0].index, 2);
  EXPECT_NEAR(result.picks[0].geometric_weight, 1.0, kRoundOff);  // A has the largest W_g
  options.norm_order = 1.0;
  result = mogesec(shapes, positions, {0, 1}, options);
  EXPECT_EQ(result.picks[0].index, 3);
}

TEST(Mogesec, TiesGoToTheLowestIndex) {
  // Mirror-symmetric candidates around the initial master: equal weights up to round-off.
  Matrix shapes(5, 2);
  // clang-format off
  shapes << 1.0, 0.5,
            1.0, -0.5,
            0.0, 0.0,
            1.0, 0.5,
            1.0, -0.5;
  // clang-format on
  const std::vector<Vector3> positions = {Vector3(-2, 0, 0), Vector3(-1, 0, 0), Vector3(0, 0, 0),
                                          Vector3(1, 0, 0), Vector3(2, 0, 0)};
  MogesecOptions options;
  options.count = 2;
  const MogesecResult result = mogesec(shapes, positions, {2}, options);
  EXPECT_EQ(result.picks[0].index, 0);  // ties with 4
  EXPECT_EQ(result.picks[1].index, 4);  // farthest from 0 and 2
}

TEST(Mogesec, RejectsBadInput) {
  const Matrix shapes = Matrix::Ones(3, 2);
  const std::vector<Vector3> positions(3, Vector3::Zero());
  MogesecOptions options;
  options.count = 1;
  EXPECT_THROW(mogesec(shapes, {Vector3::Zero()}, {}, options), InputError);
  EXPECT_THROW(mogesec(shapes, positions, {3}, options), InputError);
  EXPECT_THROW(mogesec(shapes, positions, {1, 1}, options), InputError);
  options.count = 3;
  EXPECT_THROW(mogesec(shapes, positions, {0}, options), InputError);  // 2 left
  options.count = 1;
  EXPECT_THROW(mogesec(Matrix::Zero(3, 2), positions, {}, options), InputError);
  options.geometric_exponent = 0.0;
  EXPECT_THROW(mogesec(shapes, positions, {}, options), InputError);
  options.geometric_exponent = 2.0;
  options.norm_order = 0.5;
  EXPECT_THROW(mogesec(shapes, positions, {}, options), InputError);
}

// A 2 m steel cantilever along x with `elements` beams, clamped at node 0, and its lowest modes.
struct Beam {
  fem::System system;
  fem::ModalBasis modes;
};

Beam cantilever(int elements, int modes) {
  fem::Model model = test::steelCantilever(elements);
  Beam beam{fem::assemble(model), {}};
  fem::ModalRequest request;
  request.count = modes;
  beam.modes = fem::solveModes(beam.system.stiffness, beam.system.mass, request);
  return beam;
}

TEST(Mogesec, FirstPickWithoutMastersHasTheLargestModalWeight) {
  const Beam beam = cantilever(30, 6);
  const std::vector<DofIndex> candidates = candidateDofs(beam.system.dofs, CandidateFilter{});
  Matrix shapes(static_cast<DofIndex>(candidates.size()), beam.modes.count());
  std::vector<Vector3> positions;
  for (std::size_t r = 0; r < candidates.size(); ++r) {
    shapes.row(static_cast<DofIndex>(r)) = beam.modes.shapes.row(candidates[r]);
    positions.push_back(beam.system.dofs.positionOf(candidates[r]));
  }
  MogesecOptions options;
  options.count = 1;
  const MogesecResult result = mogesec(shapes, positions, {}, options);
  DofIndex expected;
  shapes.rowwise().squaredNorm().maxCoeff(&expected);
  EXPECT_EQ(result.picks[0].index, expected);
  EXPECT_DOUBLE_EQ(result.picks[0].weight, 1.0);
  EXPECT_DOUBLE_EQ(result.picks[0].geometric_weight, 1.0);
}

TEST(Mogesec, PicksSpreadAlongTheBeamWithoutRepeats) {
  const int elements = 30;
  const Beam beam = cantilever(elements, 6);
  const fem::DofMap& dofs = beam.system.dofs;
  MogesecOptions options;
  options.count = 8;
  const MasterSelection selection =
      selectMasters(dofs, beam.modes.shapes, {}, CandidateFilter{}, options);
  ASSERT_EQ(selection.masters.size(), 8u);
  ASSERT_EQ(selection.picks.size(), 8u);

  std::set<DofIndex> distinct(selection.masters.begin(), selection.masters.end());
  EXPECT_EQ(distinct.size(), 8u);
  // Co-located DOFs have W_g = 0: each pick is at a different node while free nodes remain.
  std::set<NodeId> nodes;
  std::vector<double> x;
  for (const DofIndex m : selection.masters) {
    const fem::DofRef d = dofs.dofOf(m);
    EXPECT_LT(d.direction, 3) << "only translations are candidates";
    nodes.insert(d.node);
    x.push_back(dofs.positionOf(m).x());
  }
  EXPECT_EQ(nodes.size(), 8u);
  // Spread: the picks span most of the beam and no two are adjacent nodes.
  std::sort(x.begin(), x.end());
  EXPECT_GT(x.back() - x.front(), 1.0);
  const double spacing = 2.0 / elements;
  for (std::size_t i = 1; i < x.size(); ++i)
    EXPECT_GT(x[i] - x[i - 1], 1.5 * spacing);
  // Weights of the picks lie in [0, 1]; the first one is 1.
  EXPECT_DOUBLE_EQ(selection.picks[0].weight, 1.0);
  for (const MogesecPick& p : selection.picks) {
    EXPECT_GE(p.weight, 0.0);
    EXPECT_LE(p.weight, 1.0);
  }

  // Deterministic.
  const MasterSelection again =
      selectMasters(dofs, beam.modes.shapes, {}, CandidateFilter{}, options);
  EXPECT_EQ(again.masters, selection.masters);
}

TEST(Mogesec, InitialMastersAndFilters) {
  const int elements = 20;
  const Beam beam = cantilever(elements, 6);
  const fem::DofMap& dofs = beam.system.dofs;
  // The tip: uz and its rotation ry (not a candidate direction, yet a valid initial master).
  const std::vector<DofIndex> initial = {dofs.requireActive(elements, 2),
                                         dofs.requireActive(elements, 4)};
  MogesecOptions options;
  options.count = 5;
  CandidateFilter filter = CandidateFilter::lateralAndVertical();
  filter.excluded_nodes = {elements / 2};
  const MasterSelection selection =
      selectMasters(dofs, beam.modes.shapes, initial, filter, options);
  ASSERT_EQ(selection.masters.size(), 7u);
  EXPECT_EQ(selection.masters[0], initial[0]);
  EXPECT_EQ(selection.masters[1], initial[1]);
  for (const MogesecPick& p : selection.picks) {
    const fem::DofRef d = dofs.dofOf(p.index);
    EXPECT_TRUE(d.direction == 1 || d.direction == 2) << dofs.label(p.index);
    EXPECT_NE(d.node, elements) << "co-located with the initial masters";
    EXPECT_NE(d.node, elements / 2) << "excluded node";
  }
  EXPECT_THROW(selectMasters(dofs, beam.modes.shapes, {dofs.activeCount()}, filter, options),
               InputError);
  EXPECT_THROW(selectMasters(dofs, beam.modes.shapes.topRows(5), {}, filter, options), InputError);
}

}  // namespace
}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
