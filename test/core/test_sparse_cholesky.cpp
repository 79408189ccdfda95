// SparseCholesky's sparse right-hand-side solve (used for the constraint modes K_ss^-1 K_sm):
// solved in blocks of 64 columns, it must equal a dense solve for every column, including those
// of a last, narrower block.
#include <gtest/gtest.h>

#include <vector>

#include "expect_input_error.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/sparse_cholesky.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tvd = tracked_vehicle_dynamics;

namespace {

// A spring chain fixed at both ends with every third node also on a spring to ground:
// symmetric positive definite, banded, n x n.
tvd::SparseMatrix springChain(tvd::DofIndex n) {
  std::vector<tvd::Triplet> t;
  for (tvd::DofIndex i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 + (i % 3 == 0 ? 0.5 : 0.0));
    if (i + 1 < n) {
      t.emplace_back(i, i + 1, -1.0);
      t.emplace_back(i + 1, i, -1.0);
    }
  }
  tvd::SparseMatrix k(n, n);
  k.setFromTriplets(t.begin(), t.end());
  k.makeCompressed();
  return k;
}

// 150 columns (blocks of 64, 64 and 22), each with a few entries and one empty column.
tvd::SparseMatrix sparseLoads(tvd::DofIndex n, tvd::DofIndex columns) {
  std::vector<tvd::Triplet> t;
  for (tvd::DofIndex j = 0; j < columns; ++j) {
    if (j == 70)
      continue;  // an empty column: a zero solution
    t.emplace_back((7 * j) % n, j, 1.0 + 0.01 * static_cast<double>(j));
    t.emplace_back((13 * j + 5) % n, j, -0.5);
  }
  tvd::SparseMatrix b(n, columns);
  b.setFromTriplets(t.begin(), t.end());
  b.makeCompressed();
  return b;
}

}  // namespace

TEST(SparseCholesky, SparseRightHandSidesInBlocksEqualTheDenseSolve) {
  const tvd::DofIndex n = 300, columns = 150;
  const tvd::SparseMatrix k = springChain(n);
  const tvd::SparseMatrix b = sparseLoads(n, columns);
  tvd::fem::SparseCholesky cholesky;
  ASSERT_TRUE(cholesky.factorize(k));
  const tvd::Matrix x = cholesky.solve(b);
  ASSERT_EQ(x.rows(), n);
  ASSERT_EQ(x.cols(), columns);
  const tvd::Matrix dense = tvd::Matrix(k).llt().solve(tvd::Matrix(b));
  EXPECT_LT((x - dense).cwiseAbs().maxCoeff(), 1e-10 * dense.cwiseAbs().maxCoeff());
  // The residual of every column, the last block's included.
  EXPECT_LT((tvd::Matrix(k * x) - tvd::Matrix(b)).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_EQ(x.col(70).cwiseAbs().maxCoeff(), 0.0);
}

TEST(SparseCholesky, SparseSolveRefusesAWrongSizeOrAMissingFactorisation) {
  const tvd::SparseMatrix k = springChain(10);
  tvd::fem::SparseCholesky cholesky;
  EXPECT_THROW(cholesky.solve(sparseLoads(10, 3)), tvd::SolverError);
  ASSERT_TRUE(cholesky.factorize(k));
  tvd::expectInputError([&] { cholesky.solve(sparseLoads(11, 3)); }, "right-hand side has 11 rows");
}

// The Lanczos hot path's in-place solve keeps its right-hand-side buffer between calls: after a
// refactorisation of another size it must solve the new system (it wrote past the old, smaller
// buffer), and without a factorisation it refuses (it read a null solution).
TEST(SparseCholesky, InPlaceSolveFollowsARefactorisationOfAnotherSize) {
  tvd::fem::SparseCholesky cholesky;
  std::vector<double> in(40, 1.0), out(40, 0.0);
  EXPECT_THROW(cholesky.solveInPlace(in.data(), out.data()), tvd::SolverError);
  for (const tvd::DofIndex n : {10, 40, 25}) {
    const tvd::SparseMatrix k = springChain(n);
    ASSERT_TRUE(cholesky.factorize(k));
    cholesky.solveInPlace(in.data(), out.data());
    const tvd::Vector x = Eigen::Map<const tvd::Vector>(out.data(), n);
    EXPECT_LT((k * x - tvd::Vector::Ones(n)).cwiseAbs().maxCoeff(), 1e-12) << n << " rows";
  }
}
