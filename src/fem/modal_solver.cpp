#include "tracked_vehicle_dynamics/fem/modal_solver.h"

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/SymGEigsShiftSolver.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/sparse_cholesky.h"

namespace tracked_vehicle_dynamics {
namespace fem {

namespace {

constexpr double kTwoPi = 6.283185307179586;

// y = (K - sigma M)^-1 x for Spectra's shift-invert mode, with one CHOLMOD factorisation
// (K - sigma M is positive definite for sigma < 0 when M is positive semi-definite and K + |sigma|M
// has no null space).
class ShiftInvertOp {
 public:
  using Scalar = double;
  ShiftInvertOp(const SparseMatrix& k, const SparseMatrix& m) : k_(k), m_(m) {}
  Eigen::Index rows() const { return k_.rows(); }
  Eigen::Index cols() const { return k_.cols(); }
  void set_shift(double sigma) {
    SparseMatrix a = k_ - sigma * m_;
    a.makeCompressed();
    if (!chol_.factorize(a))
      throw SolverError("modal solver: K - sigma M is not positive definite for sigma = " +
                        std::to_string(sigma) +
                        " (a DOF without stiffness and mass, or a negative stiffness)");
  }
  void perform_op(const double* x, double* y) const { chol_.solveInPlace(x, y); }

 private:
  const SparseMatrix& k_;
  const SparseMatrix& m_;
  SparseCholesky chol_;
};

void checkInputs(const SparseMatrix& k, const SparseMatrix& m, int count) {
  if (k.rows() != k.cols() || m.rows() != m.cols() || k.rows() != m.rows())
    throw InputError("modal solver: K is " + std::to_string(k.rows()) + "x" +
                     std::to_string(k.cols()) + " and M is " + std::to_string(m.rows()) + "x" +
                     std::to_string(m.cols()) + "; both must be square and of the same size");
  if (count <= 0) throw InputError("modal solver: the number of modes must be positive");
  if (k.rows() == 0) throw InputError("modal solver: the model has no active DOF");
}

// Automatic shift: a small negative fraction of the mean K/M diagonal ratio keeps K - sigma M
// well conditioned while leaving the lowest (and the rigid-body) eigenvalues closest to sigma.
double automaticShift(const SparseMatrix& k, const SparseMatrix& m) {
  double ratio_sum = 0.0;
  int terms = 0;
  for (Eigen::Index i = 0; i < k.rows(); ++i) {
    const double kd = k.coeff(i, i), md = m.coeff(i, i);
    if (kd > 0 && md > 0) {
      ratio_sum += std::log(kd / md);
      ++terms;
    }
  }
  const double typical = terms ? std::exp(ratio_sum / terms) : 1.0;
  return -std::max(1e-6 * typical, 1e-3);
}

ModalBasis sortAndNormalise(const Vector& values, const Matrix& vectors, const SparseMatrix* m,
                            const Matrix* m_dense) {
  const int n = static_cast<int>(values.size());
  std::vector<int> order(n);
  for (int i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](int a, int b) { return values(a) < values(b); });
  ModalBasis basis;
  basis.eigenvalues.resize(n);
  basis.frequencies_hz.resize(n);
  basis.shapes.resize(vectors.rows(), n);
  for (int i = 0; i < n; ++i) {
    Vector phi = vectors.col(order[i]);
    const double modal_mass = m ? phi.dot(*m * phi) : phi.dot(*m_dense * phi);
    phi /= std::sqrt(modal_mass);
    // Sign convention: the largest component is positive, so results are reproducible.
    Eigen::Index imax;
    phi.cwiseAbs().maxCoeff(&imax);
    if (phi(imax) < 0) phi = -phi;
    basis.shapes.col(i) = phi;
    basis.eigenvalues(i) = values(order[i]);
    basis.frequencies_hz(i) = std::sqrt(std::max(0.0, values(order[i]))) / kTwoPi;
  }
  return basis;
}

}  // namespace

ModalBasis solveModes(const SparseMatrix& stiffness, const SparseMatrix& mass,
                      const ModalRequest& request) {
  checkInputs(stiffness, mass, request.count);
  const auto start = std::chrono::steady_clock::now();
  const Eigen::Index n = stiffness.rows();
  const double sigma = request.shift != 0.0 ? request.shift : automaticShift(stiffness, mass);

  // Small problems: the dense solver is exact and faster than Lanczos.
  if (n <= 200) {
    ModalBasis all = solveModesDense(Matrix(stiffness), Matrix(mass));
    int keep = std::min<int>(request.count, all.count());
    if (request.max_frequency_hz > 0) {
      keep = 0;
      while (keep < all.count() && keep < request.count &&
             all.frequencies_hz(keep) <= request.max_frequency_hz)
        ++keep;
    }
    all.eigenvalues.conservativeResize(keep);
    all.frequencies_hz.conservativeResize(keep);
    all.shapes.conservativeResize(Eigen::NoChange, keep);
    all.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return all;
  }

  ShiftInvertOp op(stiffness, mass);
  Spectra::SparseSymMatProd<double> bop(mass);
  // With a frequency limit, grow the number of requested modes until the highest one found lies
  // above the limit (or the count bound is reached); the factorisation is redone per attempt but
  // is cheap compared with the Lanczos iterations.
  int nev = request.max_frequency_hz > 0 ? std::min(request.count, 20) : request.count;
  while (true) {
    nev = static_cast<int>(std::min<Eigen::Index>(nev, n - 1));
    const int ncv = static_cast<int>(std::min<Eigen::Index>(std::max(2 * nev + 1, 20), n));
    Spectra::SymGEigsShiftSolver<ShiftInvertOp, Spectra::SparseSymMatProd<double>,
                                 Spectra::GEigsMode::ShiftInvert>
        solver(op, bop, nev, ncv, sigma);
    solver.init();
    const int converged = static_cast<int>(
        solver.compute(Spectra::SortRule::LargestMagn, request.max_iterations, request.tolerance,
                       Spectra::SortRule::SmallestAlge));
    if (solver.info() != Spectra::CompInfo::Successful) {
      const bool not_converging = solver.info() == Spectra::CompInfo::NotConverging;
      throw SolverError(std::string("modal solver (shift-invert Lanczos): ") +
                        (not_converging ? "did not converge" : "numerical issue") + ": " +
                        std::to_string(converged) + " of " + std::to_string(nev) +
                        " modes converged after " + std::to_string(solver.num_iterations()) +
                        " iterations (tolerance " + std::to_string(request.tolerance) + ")");
    }
    ModalBasis basis = sortAndNormalise(solver.eigenvalues(), solver.eigenvectors(), &mass, nullptr);
    basis.converged = converged;
    basis.iterations = static_cast<int>(solver.num_iterations());
    const bool limit_reached = request.max_frequency_hz > 0 &&
                               basis.frequencies_hz(basis.count() - 1) > request.max_frequency_hz;
    if (request.max_frequency_hz <= 0 || limit_reached || nev >= request.count || nev >= n - 1) {
      if (request.max_frequency_hz > 0) {
        int keep = 0;
        while (keep < basis.count() && basis.frequencies_hz(keep) <= request.max_frequency_hz) ++keep;
        basis.eigenvalues.conservativeResize(keep);
        basis.frequencies_hz.conservativeResize(keep);
        basis.shapes.conservativeResize(Eigen::NoChange, keep);
      }
      basis.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      return basis;
    }
    nev = std::min(request.count, 2 * nev);
  }
}

ModalBasis solveModesDense(const Matrix& stiffness, const Matrix& mass) {
  if (stiffness.rows() != stiffness.cols() || mass.rows() != mass.cols() ||
      stiffness.rows() != mass.rows())
    throw InputError("dense modal solver: K and M must be square and of the same size");
  const auto start = std::chrono::steady_clock::now();
  Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> es(stiffness, mass);
  if (es.info() != Eigen::Success)
    throw SolverError("dense modal solver: M is not positive definite or the solve failed");
  ModalBasis basis = sortAndNormalise(es.eigenvalues(), es.eigenvectors(), nullptr, &mass);
  basis.converged = basis.count();
  basis.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return basis;
}

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
