// modeCountCut(): a count of lowest modes that ends inside a repeated eigenvalue is found, with
// the group's size and the counts that would not cut it; eigenvaluesBelow() against the closed
// form of a system whose eigenvalues are chosen.
#include <gtest/gtest.h>

#include <Eigen/QR>

#include <cmath>
#include <vector>

#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/reduction/mode_count_cut.h"

namespace tracked_vehicle_dynamics {
namespace reduction {
namespace {

// K phi = lambda M phi with the eigenvalues (2 pi f)^2 of `hz`: M = diag(m) with unequal masses,
// K = M^1/2 Q diag(lambda) Q^T M^1/2 with Q a random orthogonal matrix, so every DOF is coupled
// and a repeated eigenvalue's vectors are not coordinate axes.
struct ChosenSystem {
  SparseMatrix k, m;
  Vector frequencies_hz;  // all, ascending, as the dense solver returns them
};

ChosenSystem chosenSystem(const std::vector<double>& hz) {
  const auto n = static_cast<Eigen::Index>(hz.size());
  std::srand(7);
  const Matrix q = Eigen::HouseholderQR<Matrix>(Matrix::Random(n, n)).householderQ();
  Vector lambda(n), sqrt_m(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    lambda(i) = std::pow(kTwoPi * hz[static_cast<std::size_t>(i)], 2);
    sqrt_m(i) = std::sqrt(1.0 + 0.5 * static_cast<double>(i));
  }
  const Matrix k =
      sqrt_m.asDiagonal() * q * lambda.asDiagonal() * q.transpose() * sqrt_m.asDiagonal();
  const Matrix m = Matrix(sqrt_m.array().square().matrix().asDiagonal());
  ChosenSystem s;
  s.k = k.sparseView();
  s.m = m.sparseView();
  s.frequencies_hz = fem::solveModesDense(k, m).frequencies_hz;
  return s;
}

// 1, 2 Hz, then 3 Hz three times, then 4 and 5 Hz.
const std::vector<double> kRepeatedThird = {1.0, 2.0, 3.0, 3.0, 3.0, 4.0, 5.0};

TEST(EigenvaluesBelow, CountsTheChosenEigenvalues) {
  const ChosenSystem s = chosenSystem(kRepeatedThird);
  auto below = [&](double hz) { return fem::eigenvaluesBelow(s.k, s.m, std::pow(kTwoPi * hz, 2)); };
  EXPECT_EQ(below(0.5), 0);
  EXPECT_EQ(below(1.5), 1);
  EXPECT_EQ(below(2.9), 2);
  EXPECT_EQ(below(3.0 * (1 + 1e-6)), 5);  // the whole repeated eigenvalue, just above it
  EXPECT_EQ(below(4.5), 6);
  EXPECT_EQ(below(9.0), 7);
}

TEST(ModeCountCut, FindsACountEndingInsideARepeatedEigenvalue) {
  const ChosenSystem s = chosenSystem(kRepeatedThird);
  for (int count : {3, 4}) {
    const std::optional<ModeCountCut> cut = modeCountCut(s.k, s.m, s.frequencies_hz.head(count));
    ASSERT_TRUE(cut.has_value()) << count;
    EXPECT_NEAR(cut->frequency_hz, 3.0, 1e-9);
    EXPECT_EQ(cut->kept, count - 2);
    EXPECT_EQ(cut->size, 3);
    EXPECT_EQ(cut->fewer, 2);  // stop before the group ...
    EXPECT_EQ(cut->more, 5);   // ... or after all of it
  }
}

TEST(ModeCountCut, CountsAtAGapAreNotCuts) {
  const ChosenSystem s = chosenSystem(kRepeatedThird);
  for (int count : {1, 2, 5, 6, 7})
    EXPECT_FALSE(modeCountCut(s.k, s.m, s.frequencies_hz.head(count)).has_value()) << count;
}

// A solver that returned two of the three 3 Hz modes and went on to 4 Hz: the computed modes are
// not the lowest ones, which the count below the last group reveals.
TEST(ModeCountCut, FindsAModeMissingBelowTheLastGroup) {
  const ChosenSystem s = chosenSystem(kRepeatedThird);
  Vector returned(5);
  returned << s.frequencies_hz(0), s.frequencies_hz(1), s.frequencies_hz(2), s.frequencies_hz(3),
      s.frequencies_hz(5);
  const std::optional<ModeCountCut> cut = modeCountCut(s.k, s.m, returned);
  ASSERT_TRUE(cut.has_value());
  EXPECT_EQ(cut->missed, 1);
  EXPECT_NEAR(cut->frequency_hz, 4.0, 1e-9);
}

TEST(ModeCountCut, AGroupOfTheLowestModesHasNoSmallerCount) {
  const ChosenSystem s = chosenSystem({3.0, 3.0, 3.0, 4.0});
  const std::optional<ModeCountCut> cut = modeCountCut(s.k, s.m, s.frequencies_hz.head(1));
  ASSERT_TRUE(cut.has_value());
  EXPECT_EQ(cut->kept, 1);
  EXPECT_EQ(cut->size, 3);
  EXPECT_EQ(cut->fewer, 0);
  EXPECT_EQ(cut->more, 3);
}

}  // namespace
}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
