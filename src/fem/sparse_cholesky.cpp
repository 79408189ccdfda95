#include "tracked_vehicle_dynamics/fem/sparse_cholesky.h"

#include <cholmod.h>

#include <algorithm>
#include <cstring>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace fem {

struct SparseCholesky::Impl {
  cholmod_common common;
  cholmod_factor* factor = nullptr;
  bool factorised = false;
  // Work buffers reused by solveInPlace (cholmod_solve2 keeps them allocated).
  mutable cholmod_dense* x = nullptr;
  mutable cholmod_dense* y = nullptr;
  mutable cholmod_dense* e = nullptr;
  mutable cholmod_dense* b = nullptr;

  Impl() {
    cholmod_start(&common);
    // Simplicial or supernodal by CHOLMOD's flop heuristic: the track-chain matrices are banded
    // with small supernodes, where the simplicial solve (no BLAS calls) is about twice as fast.
    common.supernodal = CHOLMOD_AUTO;
    common.final_ll = 1;
    common.print = 0;
    common.error_handler = nullptr;
  }
  ~Impl() {
    if (factor)
      cholmod_free_factor(&factor, &common);
    for (cholmod_dense** d : {&x, &y, &e, &b})
      if (*d)
        cholmod_free_dense(d, &common);
    cholmod_finish(&common);
  }

  // A view of the lower triangle of a full symmetric Eigen matrix, without copying values.
  static cholmod_sparse view(const SparseMatrix& a) {
    cholmod_sparse s;
    std::memset(&s, 0, sizeof(s));
    s.nrow = a.rows();
    s.ncol = a.cols();
    s.nzmax = a.nonZeros();
    s.p = const_cast<int*>(a.outerIndexPtr());
    s.i = const_cast<int*>(a.innerIndexPtr());
    s.x = const_cast<double*>(a.valuePtr());
    s.stype = -1;  // use the lower triangle
    s.itype = CHOLMOD_INT;
    s.xtype = CHOLMOD_REAL;
    s.dtype = CHOLMOD_DOUBLE;
    s.sorted = 1;
    s.packed = 1;
    return s;
  }
};

SparseCholesky::SparseCholesky() : impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;

void SparseCholesky::analyze(const SparseMatrix& a) {
  if (a.rows() != a.cols())
    throw InputError("sparse Cholesky: matrix is " + std::to_string(a.rows()) + "x" +
                     std::to_string(a.cols()) + ", not square");
  if (!a.isCompressed())
    throw InputError("sparse Cholesky: matrix must be compressed");
  if (impl_->factor)
    cholmod_free_factor(&impl_->factor, &impl_->common);
  cholmod_sparse s = Impl::view(a);
  impl_->factor = cholmod_analyze(&s, &impl_->common);
  if (!impl_->factor)
    throw SolverError("sparse Cholesky: symbolic analysis failed (CHOLMOD)");
  impl_->factorised = false;
  rows_ = a.rows();
}

bool SparseCholesky::factorize(const SparseMatrix& a) {
  // A matrix with no entry at all (a stiffness with nothing on its free DOFs) is singular, not
  // a failure: CHOLMOD's symbolic analysis refuses it outright.
  if (a.rows() > 0 && a.nonZeros() == 0 && a.rows() == a.cols()) {
    impl_->factorised = false;
    return false;
  }
  if (!impl_->factor || a.rows() != rows_)
    analyze(a);
  cholmod_sparse s = Impl::view(a);
  cholmod_factorize(&s, impl_->factor, &impl_->common);
  impl_->factorised = impl_->common.status == CHOLMOD_OK &&
                      impl_->factor->minor == static_cast<std::size_t>(a.rows());
  return impl_->factorised;
}

double SparseCholesky::rcond() const {
  if (!impl_->factorised)
    return 0.0;
  return cholmod_rcond(impl_->factor, &impl_->common);
}

Matrix SparseCholesky::solve(const Matrix& rhs) const {
  if (!impl_->factorised)
    throw SolverError("sparse Cholesky: solve before a successful factorisation");
  if (rhs.rows() != rows_)
    throw InputError("sparse Cholesky: right-hand side has " + std::to_string(rhs.rows()) +
                     " rows, expected " + std::to_string(rows_));
  cholmod_dense b;
  std::memset(&b, 0, sizeof(b));
  b.nrow = rhs.rows();
  b.ncol = rhs.cols();
  b.nzmax = rhs.size();
  b.d = rhs.rows();
  b.x = const_cast<double*>(rhs.data());
  b.xtype = CHOLMOD_REAL;
  b.dtype = CHOLMOD_DOUBLE;
  cholmod_dense* x = cholmod_solve(CHOLMOD_A, impl_->factor, &b, &impl_->common);
  if (!x)
    throw SolverError("sparse Cholesky: solve failed (CHOLMOD)");
  Matrix out = Eigen::Map<Matrix>(static_cast<double*>(x->x), rhs.rows(), rhs.cols());
  cholmod_free_dense(&x, &impl_->common);
  return out;
}

void SparseCholesky::solve(
    const SparseMatrix& rhs,
    const std::function<void(DofIndex first, const Eigen::Ref<const Matrix>& x)>& sink) const {
  if (!impl_->factorised)
    throw SolverError("sparse Cholesky: solve before a successful factorisation");
  if (rhs.rows() != rows_)
    throw InputError("sparse Cholesky: right-hand side has " + std::to_string(rhs.rows()) +
                     " rows, expected " + std::to_string(rows_));
  // Blocks of 64 columns: wide enough for the supernodal solve's level-3 BLAS, small enough that
  // the block and CHOLMOD's buffers stay a few MB. The block and the solution buffer are allocated
  // once and reused by cholmod_solve2 for every block (reallocated only for a narrower last one).
  constexpr DofIndex kBlock = 64;
  struct Dense {  // frees a CHOLMOD dense matrix on every path out
    cholmod_dense* d = nullptr;
    cholmod_common* common;
    ~Dense() {
      if (d)
        cholmod_free_dense(&d, common);
    }
  } block{nullptr, &impl_->common}, x{nullptr, &impl_->common}, y{nullptr, &impl_->common},
      e{nullptr, &impl_->common};  // y, e: CHOLMOD's workspaces, apart from solveInPlace's
  for (DofIndex first = 0; first < rhs.cols(); first += kBlock) {
    const DofIndex width = std::min<DofIndex>(kBlock, rhs.cols() - first);
    if (!block.d || static_cast<DofIndex>(block.d->ncol) != width) {
      if (block.d)
        cholmod_free_dense(&block.d, &impl_->common);
      block.d = cholmod_allocate_dense(rows_, width, rows_, CHOLMOD_REAL, &impl_->common);
      if (!block.d)
        throw SolverError("sparse Cholesky: out of memory for a block of right-hand sides");
    }
    Eigen::Map<Matrix> b(static_cast<double*>(block.d->x), rows_, width);
    b.setZero();
    for (DofIndex j = 0; j < width; ++j)
      for (SparseMatrix::InnerIterator it(rhs, first + j); it; ++it)
        b(it.row(), j) = it.value();
    if (!cholmod_solve2(CHOLMOD_A, impl_->factor, block.d, nullptr, &x.d, nullptr, &y.d, &e.d,
                        &impl_->common) ||
        !x.d)
      throw SolverError("sparse Cholesky: solve failed (CHOLMOD)");
    sink(first, Eigen::Map<const Matrix>(static_cast<double*>(x.d->x), rows_, width));
  }
}

Matrix SparseCholesky::solve(const SparseMatrix& rhs) const {
  Matrix out(rows_, rhs.cols());
  solve(rhs, [&](DofIndex first, const Eigen::Ref<const Matrix>& x) {
    out.middleCols(first, x.cols()) = x;
  });
  return out;
}

Vector SparseCholesky::solve(const Vector& rhs) const {
  return solve(Matrix(rhs)).col(0);
}

void SparseCholesky::solveInPlace(const double* in, double* out) const {
  if (!impl_->factorised)
    throw SolverError("sparse Cholesky: solve before a successful factorisation");
  // b is kept between calls; a refactorisation of another size (analyze()) needs a new one.
  // cholmod_solve2 resizes x, y and e itself.
  if (impl_->b && impl_->b->nrow != static_cast<std::size_t>(rows_))
    cholmod_free_dense(&impl_->b, &impl_->common);
  if (!impl_->b)
    impl_->b = cholmod_allocate_dense(rows_, 1, rows_, CHOLMOD_REAL, &impl_->common);
  if (!impl_->b)
    throw SolverError("sparse Cholesky: no memory for a solve of " + std::to_string(rows_) +
                      " rows (CHOLMOD)");
  std::memcpy(impl_->b->x, in, sizeof(double) * rows_);
  if (!cholmod_solve2(CHOLMOD_A, impl_->factor, impl_->b, nullptr, &impl_->x, nullptr, &impl_->y,
                      &impl_->e, &impl_->common) ||
      !impl_->x)
    throw SolverError("sparse Cholesky: solve failed (CHOLMOD)");
  std::memcpy(out, impl_->x->x, sizeof(double) * rows_);
}

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
