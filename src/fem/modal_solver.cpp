#include "tracked_vehicle_dynamics/fem/modal_solver.h"

#include <Spectra/SymGEigsShiftSolver.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/eigenvalue_count.h"
#include "tracked_vehicle_dynamics/fem/sparse_cholesky.h"

namespace tracked_vehicle_dynamics {
namespace fem {

namespace {

// Deflated verification runs for repeated eigenvalues: how many, how many modes each, and the
// relative gap (to the distance from the shift) under which an eigenvalue counts as new.
constexpr int kMaxDeflationPasses = 6;
constexpr int kVerificationModes = 6;
constexpr double kRepeatedTolerance = 1e-6;
// A verification Ritz pair is accepted as an eigenpair below this relative residual.
constexpr double kRitzResidual = 1e-8;

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
    // Spectra sets the shift on every solver construction; factorise once per distinct shift.
    if (factorised_ && sigma == sigma_)
      return;
    SparseMatrix a = k_ - sigma * m_;
    a.makeCompressed();
    if (!chol_.factorize(a))
      throw SolverError(
          "modal solver: K - sigma M is not positive definite for sigma = " + brief(sigma) +
          " (a DOF without stiffness and mass, or a negative stiffness)");
    sigma_ = sigma;
    factorised_ = true;
  }
  void perform_op(const double* x, double* y) const {
    chol_.solveInPlace(x, y);
    if (!deflation_)
      return;
    // y <- P y with the M-orthogonal projector P = I - Phi Phi^T M onto the complement of the
    // modes already found: they get nu = 0 and the Lanczos run finds the next ones, including
    // further copies of a repeated eigenvalue (rigid-body modes) that one Krylov space misses.
    Eigen::Map<Vector> out(y, rows());
    coeffs_.noalias() = mass_deflation_.transpose() * out;
    out.noalias() -= *deflation_ * coeffs_;
  }
  /// Restricts the operator to the M-orthogonal complement of `shapes` (mass-normalised).
  /// `shapes` must outlive the deflation (the caller's basis; deflate(Matrix()) ends it).
  void deflate(const Matrix& shapes) {
    if (shapes.cols() == 0) {
      deflation_ = nullptr;
      mass_deflation_.resize(0, 0);  // n x k: not kept beyond the deflated runs
      return;
    }
    deflation_ = &shapes;
    mass_deflation_.resize(shapes.rows(), shapes.cols());
    mass_deflation_.noalias() = m_ * shapes;
    coeffs_.resize(shapes.cols());
  }

 private:
  const SparseMatrix& k_;
  const SparseMatrix& m_;
  SparseCholesky chol_;
  double sigma_ = 0.0;
  bool factorised_ = false;
  const Matrix* deflation_ = nullptr;
  Matrix mass_deflation_;
  mutable Vector coeffs_;
};

// y = M x with M stored in full (both triangles): cheaper than a self-adjoint-view product, and
// Spectra applies B several times per Lanczos step (B-inner products and norms).
class MassProduct {
 public:
  using Scalar = double;
  explicit MassProduct(const SparseMatrix& m) : m_(m) {}
  Eigen::Index rows() const { return m_.rows(); }
  Eigen::Index cols() const { return m_.cols(); }
  void perform_op(const double* x, double* y) const {
    Eigen::Map<Vector>(y, m_.rows()).noalias() = m_ * Eigen::Map<const Vector>(x, m_.cols());
  }

 private:
  const SparseMatrix& m_;
};

struct RitzBlock {
  Vector values;     // Ritz values (approximate omega^2)
  Matrix vectors;    // Ritz vectors
  Vector residuals;  // ||K z - theta M z|| / ||K z|| (or / ||M z|| for theta ~ 0)
};

// A few steps of block power iteration with the (deflated) shift-invert operator, then
// Rayleigh-Ritz on (K, M): cheap detection of eigenvalues that dominate the deflated operator.
RitzBlock blockVerification(const ShiftInvertOp& op, const SparseMatrix& k, const SparseMatrix& m,
                            int block_size) {
  constexpr int kPowerSteps = 4;
  const Eigen::Index n = k.rows();
  std::mt19937_64 rng(12345);  // fixed seed: results are reproducible
  std::normal_distribution<double> normal;
  Matrix x(n, block_size);
  for (Eigen::Index j = 0; j < x.cols(); ++j)
    for (Eigen::Index i = 0; i < n; ++i)
      x(i, j) = normal(rng);
  Vector mx(n);
  RitzBlock out;
  for (int step = 0; step < kPowerSteps; ++step) {
    Matrix y(n, block_size);
    for (int j = 0; j < block_size; ++j) {
      mx.noalias() = m * x.col(j);
      op.perform_op(mx.data(), y.col(j).data());
    }
    // Rayleigh-Ritz on span(y), which also re-orthonormalises the block.
    const Matrix ky = k * y;
    const Matrix my = m * y;
    Matrix kr = y.transpose() * ky;
    Matrix mr = y.transpose() * my;
    kr = 0.5 * (kr + kr.transpose()).eval();
    mr = 0.5 * (mr + mr.transpose()).eval();
    Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> es(kr, mr);
    if (es.info() != Eigen::Success)
      break;  // block lost rank: nothing left to find
    x = y * es.eigenvectors();
    out.values = es.eigenvalues();
    out.vectors = x;
    out.residuals.resize(block_size);
    const Matrix kz = ky * es.eigenvectors();
    const Matrix mz = my * es.eigenvectors();
    for (int j = 0; j < block_size; ++j) {
      const double scale = std::max(kz.col(j).norm(), mz.col(j).norm() * std::abs(out.values(j)));
      out.residuals(j) = (kz.col(j) - out.values(j) * mz.col(j)).norm() /
                         std::max(scale, std::numeric_limits<double>::min());
    }
  }
  return out;
}

void checkInputs(const SparseMatrix& k, const SparseMatrix& m, int count) {
  if (k.rows() != k.cols() || m.rows() != m.cols() || k.rows() != m.rows())
    throw InputError("modal solver: K is " + std::to_string(k.rows()) + "x" +
                     std::to_string(k.cols()) + " and M is " + std::to_string(m.rows()) + "x" +
                     std::to_string(m.cols()) + "; both must be square and of the same size");
  if (count <= 0)
    throw InputError("modal solver: the number of modes must be positive");
  if (k.rows() == 0)
    throw InputError("modal solver: the model has no active DOF");
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
  for (int i = 0; i < n; ++i)
    order[i] = i;
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
    if (phi(imax) < 0)
      phi = -phi;
    basis.shapes.col(i) = phi;
    basis.eigenvalues(i) = values(order[i]);
    basis.frequencies_hz(i) = std::sqrt(std::max(0.0, values(order[i]))) / kTwoPi;
  }
  return basis;
}

// Adds the `added` columns of the extra modes to `current`'s and keeps, in `values` and
// `vectors`, the lowest current.count() of the union (the added displace the highest), or all of
// it with `keep_all`.
void keepLowest(const ModalBasis& current, const Vector& extra_values, const Matrix& extra_vectors,
                const std::vector<Eigen::Index>& added, const SparseMatrix& mass, bool keep_all,
                Vector* values, Matrix* vectors) {
  const Eigen::Index found = current.count();
  Vector merged_values(found + static_cast<Eigen::Index>(added.size()));
  Matrix merged_vectors(current.shapes.rows(), merged_values.size());
  merged_values.head(found) = current.eigenvalues;
  merged_vectors.leftCols(found) = current.shapes;
  for (std::size_t j = 0; j < added.size(); ++j) {
    merged_values(found + static_cast<Eigen::Index>(j)) = extra_values(added[j]);
    merged_vectors.col(found + static_cast<Eigen::Index>(j)) = extra_vectors.col(added[j]);
  }
  const ModalBasis merged = sortAndNormalise(merged_values, merged_vectors, &mass, nullptr);
  const Eigen::Index keep = keep_all ? merged.count() : found;
  *values = merged.eigenvalues.head(keep);
  *vectors = merged.shapes.leftCols(keep);
}

}  // namespace

ModalBasis solveModes(const SparseMatrix& stiffness, const SparseMatrix& mass,
                      const ModalRequest& request) {
  checkInputs(stiffness, mass, request.count);
  const auto start = std::chrono::steady_clock::now();
  const Eigen::Index n = stiffness.rows();
  const double sigma = request.shift != 0.0 ? request.shift : automaticShift(stiffness, mass);

  // The dense solver, cut to the request: exact, and faster than Lanczos on small problems.
  const auto dense = [&] {
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
  };
  // Every mode asked for: Lanczos finds at most n - 1 (its Krylov space is at most n wide and
  // one vector short of the last), and the shapes are a dense n x n matrix anyway.
  if (n <= 200 || (request.count >= n && request.max_frequency_hz <= 0))
    return dense();

  ShiftInvertOp op(stiffness, mass);
  MassProduct bop(mass);
  int iterations = 0;

  // One implicitly restarted Lanczos run for the `nev` eigenvalues closest to sigma.
  auto lanczos = [&](int nev) {
    nev = static_cast<int>(std::min<Eigen::Index>(nev, n - 1));
    // Krylov dimension: ARPACK's (and SciPy eigsh's) 2 nev + 1. A tighter nev + 30 saved nothing
    // at 40 modes and lost much more with many: on a spectrum crowded with near copies (a chain's
    // local modes above 100 Hz) each restart gains little, so 300 modes of the bundled tracked
    // vehicle took 295 restarts (66 s) against 10 (18 s), and 400 of a six-axle one did not
    // converge in 1000 (575 s) against 7 (27 s).
    const int ncv = static_cast<int>(std::min<Eigen::Index>(std::max(2 * nev + 1, 20), n));
    Spectra::SymGEigsShiftSolver<ShiftInvertOp, MassProduct, Spectra::GEigsMode::ShiftInvert>
        solver(op, bop, nev, ncv, sigma);
    solver.init();
    int converged = 0;
    try {
      converged =
          static_cast<int>(solver.compute(Spectra::SortRule::LargestMagn, request.max_iterations,
                                          request.tolerance, Spectra::SortRule::SmallestAlge));
    } catch (const std::runtime_error& e) {
      // Spectra's dense steps fail on non-finite Ritz values: eigenvalues beyond double range,
      // from a mass or stiffness orders of magnitude away from the rest (a pad mass of 1e-300 kg).
      throw SolverError(std::string("modal solver (shift-invert Lanczos): ") + e.what() +
                        ": the eigenvalues overflow; is a mass or stiffness of the model many "
                        "orders of magnitude away from the others?");
    }
    iterations += static_cast<int>(solver.num_iterations());
    if (solver.info() != Spectra::CompInfo::Successful) {
      const bool not_converging = solver.info() == Spectra::CompInfo::NotConverging;
      throw SolverError(std::string("modal solver (shift-invert Lanczos): ") +
                        (not_converging ? "did not converge" : "numerical issue") + ": " +
                        std::to_string(converged) + " of " + std::to_string(nev) +
                        " modes converged after " + std::to_string(solver.num_iterations()) +
                        " iterations (tolerance " + brief(request.tolerance) + ")");
    }
    return std::make_pair(Vector(solver.eigenvalues()), Matrix(solver.eigenvectors()));
  };

  // With a frequency limit, ask for the modes below it and one more, counted beforehand by
  // Sylvester's law (one LDL^T, eigenvalue_count.h), so that one run finds them all: growing the
  // request from 20 by doubling solved 266 modes of a six-axle tracked vehicle five times over.
  // The loop still grows the request should the highest mode found lie below the limit (copies
  // a run skipped), up to the count bound.
  const double limit = request.max_frequency_hz > 0 ? std::pow(kTwoPi * request.max_frequency_hz, 2)
                                                    : std::numeric_limits<double>::infinity();
  int nev = request.count;
  if (request.max_frequency_hz > 0) {
    nev = std::min(request.count, 20);
    try {
      nev = std::min(request.count, std::max(eigenvaluesBelow(stiffness, mass, limit) + 1, nev));
    } catch (const SolverError&) {
      // The limit is an eigenvalue to working precision: no count; grow the request instead.
    }
  }
  Vector values;
  Matrix vectors;
  while (true) {
    std::tie(values, vectors) = lanczos(nev);
    if (values.size() == 0 || values.maxCoeff() > limit || nev >= request.count || nev >= n - 1)
      break;
    nev = std::min(request.count, 2 * nev);
  }

  // With a frequency limit the union of found and recovered modes is kept (the limit and the
  // count cut it at the end): dropping the highest for a recovered copy could leave modes under
  // the limit out.
  const bool keep_union = request.max_frequency_hz > 0;

  // Verification of repeated eigenvalues: a Krylov space holds one vector per distinct
  // eigenvalue, so exact copies (the six rigid-body modes of a free structure, symmetric pairs)
  // may be missed. A missed copy has an eigenvalue below the highest one kept, i.e. it dominates
  // the deflated operator P (K - sigma M)^-1 M; a few block power steps with Rayleigh-Ritz find
  // it cheaply. A Ritz value that lies below but has not converged triggers a full deflated
  // Lanczos run instead.
  for (int pass = 0; pass < kMaxDeflationPasses; ++pass) {
    const Eigen::Index found = values.size();
    if (found == 0 || found + kVerificationModes >= n)
      break;
    ModalBasis current = sortAndNormalise(values, vectors, &mass, nullptr);
    op.deflate(current.shapes);
    const double highest = current.eigenvalues(found - 1);
    const double accept_below = highest - kRepeatedTolerance * std::abs(highest - sigma);
    const RitzBlock block = blockVerification(op, stiffness, mass, kVerificationModes);
    Vector extra_values = block.values;
    Matrix extra_vectors = block.vectors;
    std::vector<Eigen::Index> added;
    bool unconverged_candidate = false;
    for (Eigen::Index i = 0; i < extra_values.size(); ++i) {
      if (extra_values(i) >= accept_below)
        continue;
      if (block.residuals(i) < kRitzResidual)
        added.push_back(i);
      else
        unconverged_candidate = true;
    }
    if (added.empty() && unconverged_candidate) {
      std::tie(extra_values, extra_vectors) =
          lanczos(static_cast<int>(std::min<Eigen::Index>(kVerificationModes, n - found - 1)));
      for (Eigen::Index i = 0; i < extra_values.size(); ++i)
        if (extra_values(i) < accept_below)
          added.push_back(i);
    }
    op.deflate(Matrix());
    if (added.empty())
      break;
    keepLowest(current, extra_values, extra_vectors, added, mass, keep_union, &values, &vectors);
  }

  // The count check (Sylvester's law, eigenvalue_count.h). The verification above finds a missed
  // copy only when it dominates the deflated operator within a few power steps, which a copy
  // close to the next eigenvalues does not: on a six-axle vehicle, ten copies of 107.7208 Hz
  // beside 107.7306 Hz, the run returned nine and went on. The inertia of K - lambda M just below
  // the highest mode kept counts every mode below it; the missing ones are sought by deflated
  // Lanczos runs, each asked for them and a few more.
  int missed = 0;
  for (int pass = 0;; ++pass) {
    const Eigen::Index found = values.size();
    if (found == 0)
      break;
    ModalBasis current = sortAndNormalise(values, vectors, &mass, nullptr);
    const double highest = current.eigenvalues(found - 1);
    const double accept_below = highest - kRepeatedTolerance * std::abs(highest - sigma);
    const auto returned_below =
        static_cast<int>((current.eigenvalues.array() < accept_below).count());
    try {
      missed = std::max(eigenvaluesBelow(stiffness, mass, accept_below) - returned_below, 0);
    } catch (const SolverError&) {
      missed = 0;  // an eigenvalue at the limit to working precision: no count, no claim
      break;
    }
    // Counted after every recovery, so `missed` is the final set's; recovered up to
    // kMaxDeflationPasses times.
    if (missed == 0 || pass == kMaxDeflationPasses || found + missed + kVerificationModes >= n)
      break;
    op.deflate(current.shapes);
    Vector extra_values;
    Matrix extra_vectors;
    try {
      // No more than the count asked for: only the lowest request.count are kept in the end, and
      // an ill-conditioned K can leave thousands below (a link bending inertia typed 1e12 times
      // too large), for which one run would take hours and gigabytes.
      std::tie(extra_values, extra_vectors) =
          lanczos(std::min(missed, request.count) + kVerificationModes);
    } catch (const SolverError&) {
      op.deflate(Matrix());  // the modes found stand; the count says what they lack
      break;
    }
    op.deflate(Matrix());
    std::vector<Eigen::Index> added;
    for (Eigen::Index i = 0; i < extra_values.size(); ++i)
      if (extra_values(i) < accept_below)
        added.push_back(i);
    if (added.empty())
      break;
    keepLowest(current, extra_values, extra_vectors, added, mass, keep_union, &values, &vectors);
  }

  // A frequency limit at or above the highest mode with a count as large as the model: every
  // mode is asked for, and Lanczos stops one short (above).
  if (request.count >= n && values.size() == n - 1 && values.maxCoeff() <= limit)
    return dense();

  ModalBasis basis = sortAndNormalise(values, vectors, &mass, nullptr);
  // Shift-invert: the eigenvalues near 0 come out within ~1e-9 of |sigma| (3.6e-9 on the
  // free-free beam).
  constexpr double kShiftRoundOff = 1e-6;
  basis.zero_tolerance = kShiftRoundOff * std::abs(sigma);
  basis.missed = missed;
  basis.iterations = iterations;
  if (request.max_frequency_hz > 0) {
    int keep = 0;
    while (keep < basis.count() && keep < request.count &&
           basis.frequencies_hz(keep) <= request.max_frequency_hz)
      ++keep;
    basis.eigenvalues.conservativeResize(keep);
    basis.frequencies_hz.conservativeResize(keep);
    basis.shapes.conservativeResize(Eigen::NoChange, keep);
  }
  basis.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return basis;
}

std::string missedModesWarning(const ModalBasis& basis) {
  if (basis.missed <= 0 || basis.count() == 0)
    return "";
  return "the modal solver returned " + std::to_string(basis.count()) + " modes up to " +
         brief(basis.frequencies_hz(basis.count() - 1)) + " Hz but the system has " +
         std::to_string(basis.missed) +
         " more below that frequency (Sylvester count), copies of a repeated eigenvalue that "
         "deflated runs could not recover: these are not the lowest modes; ask for more modes";
}

std::string unstableModesWarning(const ModalBasis& basis) {
  if (basis.count() == 0)
    return "";
  // Rigid-body modes come out as +-1e-10 of the elastic eigenvalues; an unstable one is of
  // their order. Asked for the rigid-body modes alone, the largest returned is round-off itself:
  // the solve's own tolerance bounds it then (the free-free beam's four at -4e-5 .. -7e-7
  // rad^2/s^2 read as an instability against each other).
  constexpr double kRoundOff = 1e-8;
  const double threshold =
      -std::max(kRoundOff * basis.eigenvalues.cwiseAbs().maxCoeff(), basis.zero_tolerance);
  int negative = 0;
  for (Eigen::Index i = 0; i < basis.count(); ++i)
    negative += basis.eigenvalues(i) < threshold;
  if (negative == 0)
    return "";
  const double lowest = basis.eigenvalues.minCoeff();
  return std::to_string(negative) + (negative == 1 ? " mode has" : " modes have") +
         " omega^2 < 0 (the lowest " + brief(lowest) + " rad^2/s^2: a motion growing as exp(" +
         brief(std::sqrt(-lowest)) +
         " t), t in s), shown as 0 Hz: the structure is unstable, its stiffness indefinite; a "
         "compressive pre-load beyond buckling (a beam's axial_force or a tie's force below 0, "
         "a rigid body's pre-load)";
}

ModalBasis solveModesDense(const Matrix& stiffness, const Matrix& mass) {
  if (stiffness.rows() != stiffness.cols() || mass.rows() != mass.cols() ||
      stiffness.rows() != mass.rows())
    throw InputError("dense modal solver: K and M must be square and of the same size");
  // An infinite entry (a spring of 1e308 N/m summed with others) would surface as "M is not
  // positive definite" below: name the matrix that has it.
  for (const auto& [matrix, name] : {std::pair<const Matrix*, const char*>{&stiffness, "K"},
                                     std::pair<const Matrix*, const char*>{&mass, "M"}})
    if (!matrix->allFinite())
      throw InputError(std::string("dense modal solver: ") + name +
                       " has a non-finite entry (a stiffness or mass too large for a double?)");
  const auto start = std::chrono::steady_clock::now();
  Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> es(stiffness, mass);
  if (es.info() != Eigen::Success)
    throw SolverError("dense modal solver: M is not positive definite or the solve failed");
  ModalBasis basis = sortAndNormalise(es.eigenvalues(), es.eigenvectors(), nullptr, &mass);
  // Every eigenvalue carries a round-off of a few eps times the largest (the free-free beam's
  // rigid-body modes: up to 3.6e-5 against 5.6e12 rad^2/s^2, 29 eps); kept when the caller
  // truncates the basis.
  constexpr double kDenseRoundOff = 1e-12;
  if (basis.count() > 0)
    basis.zero_tolerance = kDenseRoundOff * basis.eigenvalues.cwiseAbs().maxCoeff();
  basis.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return basis;
}

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
