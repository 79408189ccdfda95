// Sparse Cholesky factorisation A = L L^T of a symmetric positive definite matrix (CHOLMOD,
// simplicial or supernodal), kept behind one narrow class so that solvers share one factorisation
// and check its status (STYLE.md #9).
#pragma once

#include <functional>
#include <memory>

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace fem {

/// Below this rcond() a factorisation that succeeded is treated as singular: CHOLMOD refuses
/// only a pivot that is zero or negative, and a singular matrix's pivot may round to a tiny
/// positive one; a free motion's displacement is then round-off amplified by 1/rcond. The
/// vehicles' stiffness matrices have 1e-6 .. 1e-8.
constexpr double kSingularRcond = 1e-14;

class SparseCholesky {
 public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  /// Symbolic analysis (fill-reducing ordering) of the pattern of A (full symmetric storage).
  void analyze(const SparseMatrix& a);
  /// Numeric factorisation; returns false if A is not positive definite. analyze() is called
  /// first if it was not.
  bool factorize(const SparseMatrix& a);
  /// Reciprocal condition estimate (min diag L / max diag L)^2; 0 when not factorised.
  double rcond() const;
  /// x = A^-1 b for one or many right-hand sides.
  Matrix solve(const Matrix& b) const;
  Vector solve(const Vector& b) const;
  /// x = A^-1 b for a sparse b (e.g. the constraint modes' K_sm), solved in blocks of columns
  /// into the result: neither a dense copy of b nor a second copy of x is made (b and x of the
  /// tracked vehicle's constraint modes are 43 MB each).
  Matrix solve(const SparseMatrix& b) const;
  /// The same solve, handing each block of solution columns [first, first + x.cols()) to `sink`
  /// instead of gathering them: the caller stores them where it wants them (no n x k result).
  void solve(
      const SparseMatrix& b,
      const std::function<void(DofIndex first, const Eigen::Ref<const Matrix>& x)>& sink) const;
  /// y = A^-1 x on raw buffers of length rows() (the Lanczos hot path).
  void solveInPlace(const double* x, double* y) const;
  DofIndex rows() const { return rows_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  DofIndex rows_ = 0;
};

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
