#include "tracked_vehicle_dynamics/reduction/craig_bampton.h"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/sparse_cholesky.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

namespace {

// Above this share of the slave DOFs, the fixed-interface modes come from the dense solver (a
// Lanczos run for nearly all modes costs more and Spectra needs nev < s).
constexpr double kDenseModeShare = 0.5;
// The dense solver is only used up to this size [DOFs]; beyond it such a request is refused.
constexpr DofIndex kMaxDenseSlaves = 4000;

using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string size(const SparseMatrix& a) {
  return std::to_string(a.rows()) + "x" + std::to_string(a.cols());
}

// n x count selection matrix with a 1 at (rows[j], j).
SparseMatrix selection(DofIndex n, const std::vector<DofIndex>& rows) {
  std::vector<Triplet> t;
  t.reserve(rows.size());
  for (std::size_t j = 0; j < rows.size(); ++j)
    t.emplace_back(rows[j], static_cast<DofIndex>(j), 1.0);
  SparseMatrix p(n, static_cast<DofIndex>(rows.size()));
  p.setFromTriplets(t.begin(), t.end());
  p.makeCompressed();
  return p;
}

// T^T A T for a symmetric sparse A, exactly symmetric. Only the rows where A has entries
// contribute (the dampers touch few DOFs), and only the lower triangle is multiplied. The rows go
// in blocks: with R the block's rows, (A T)(R, :) = A(:, R)^T T (A symmetric) and
// T^T A T = sum over blocks of T(R, :)^T (A T)(R, :), so no n x k product A T is formed (50 MB on
// the tracked vehicle), only a block of it.
Matrix project(const SparseMatrix& a, const Matrix& t) {
  const DofIndex k = t.cols();
  Matrix out = Matrix::Zero(k, k);
  if (a.nonZeros() == 0)
    return out;
  std::vector<char> used(static_cast<std::size_t>(a.rows()), 0);
  for (DofIndex j = 0; j < a.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(a, j); it; ++it)
      used[static_cast<std::size_t>(it.row())] = 1;
  std::vector<DofIndex> rows;
  for (DofIndex i = 0; i < a.rows(); ++i)
    if (used[static_cast<std::size_t>(i)])
      rows.push_back(i);
  constexpr std::size_t kBlock = 1024;  // 1024 x 431 doubles: 3.5 MB per block product
  for (std::size_t first = 0; first < rows.size(); first += kBlock) {
    const std::vector<DofIndex> block(rows.begin() + static_cast<std::ptrdiff_t>(first),
                                      rows.begin() + static_cast<std::ptrdiff_t>(std::min(first + kBlock, rows.size())));
    const SparseMatrix a_cols = a * selection(a.rows(), block);
    const Matrix at_block = a_cols.transpose() * t;
    const Matrix t_block = t(block, Eigen::all);
    out.triangularView<Eigen::Lower>() += t_block.transpose() * at_block;
  }
  return out.selfadjointView<Eigen::Lower>();
}

struct Inputs {
  const SparseMatrix& k;
  const SparseMatrix& m;
  const SparseMatrix& c;
  const SparseMatrix* ku = nullptr;
  const SparseMatrix* cu = nullptr;
  const Vector* gravity = nullptr;
  const Vector* travel = nullptr;  // f_a, the travel inertia per unit forward acceleration
};

void checkInputs(const Inputs& in, const std::vector<DofIndex>& masters,
                 const CraigBamptonOptions& options) {
  const DofIndex n = in.k.rows();
  if (in.k.cols() != n || in.m.rows() != n || in.m.cols() != n)
    throw InputError("craigBampton: K is " + size(in.k) + " and M is " + size(in.m) +
                     "; both must be square of one size");
  if (in.c.size() != 0 && (in.c.rows() != n || in.c.cols() != n))
    throw InputError("craigBampton: C is " + size(in.c) + ", expected " + std::to_string(n) + "x" +
                     std::to_string(n) + " (or empty)");
  std::vector<char> seen(static_cast<std::size_t>(n), 0);
  for (std::size_t i = 0; i < masters.size(); ++i) {
    if (masters[i] < 0 || masters[i] >= n)
      throw InputError("craigBampton: master [" + std::to_string(i) +
                       "] = " + std::to_string(masters[i]) + " is not an active DOF (0.." +
                       std::to_string(n - 1) + ")");
    if (seen[static_cast<std::size_t>(masters[i])]++)
      throw InputError("craigBampton: master DOF " + std::to_string(masters[i]) +
                       " is listed twice");
  }
  const DofIndex slaves = n - static_cast<DofIndex>(masters.size());
  const FixedInterfaceModes& r = options.fixed_interface;
  if (r.count < 0 || r.count > slaves)
    throw InputError("craigBampton: " + std::to_string(r.count) +
                     " fixed-interface modes requested; the " + std::to_string(slaves) +
                     " slave DOFs allow 0.." + std::to_string(slaves));
  if (r.max_frequency_hz < 0.0)
    throw InputError("craigBampton: fixed-interface max_frequency_hz is negative");
  if (masters.empty() && r.count == 0)
    throw InputError("craigBampton: no master DOF and no fixed-interface mode: empty basis");
  for (std::size_t i = 0; i < options.recovery_dofs.size(); ++i)
    if (options.recovery_dofs[i] < 0 || options.recovery_dofs[i] >= n)
      throw InputError("craigBampton: recovery DOF [" + std::to_string(i) +
                       "] = " + std::to_string(options.recovery_dofs[i]) +
                       " is not an active DOF (0.." + std::to_string(n - 1) + ")");
}

// The lowest fixed-interface modes of (K_ss, M_ss) (eq. 6).
fem::ModalBasis fixedInterfaceModes(const SparseMatrix& k_ss, const SparseMatrix& m_ss,
                                    const CraigBamptonOptions& options) {
  const FixedInterfaceModes& r = options.fixed_interface;
  const DofIndex s = k_ss.rows();
  if (r.count == 0 || s == 0)
    return {};
  if (r.count < kDenseModeShare * static_cast<double>(s)) {
    fem::ModalRequest request = options.modal_solver;
    request.count = r.count;
    request.max_frequency_hz = r.max_frequency_hz;
    return fem::solveModes(k_ss, m_ss, request);
  }
  if (s > kMaxDenseSlaves)
    throw InputError("craigBampton: " + std::to_string(r.count) + " fixed-interface modes of " +
                     std::to_string(s) + " slave DOFs is too many for the dense solver (limit " +
                     std::to_string(kMaxDenseSlaves) + " DOFs); ask for fewer than half");
  fem::ModalBasis all = fem::solveModesDense(Matrix(k_ss), Matrix(m_ss));
  int keep = r.count;
  if (r.max_frequency_hz > 0.0) {
    keep = 0;
    while (keep < r.count && all.frequencies_hz(keep) <= r.max_frequency_hz)
      ++keep;
  }
  all.eigenvalues.conservativeResize(keep);
  all.frequencies_hz.conservativeResize(keep);
  all.shapes.conservativeResize(Eigen::NoChange, keep);
  return all;
}

CraigBamptonResult reduce(const Inputs& in, const std::vector<DofIndex>& masters,
                          const CraigBamptonOptions& options) {
  checkInputs(in, masters, options);
  const auto start = Clock::now();
  CraigBamptonResult result;
  const DofIndex n = in.k.rows();
  const auto m = static_cast<DofIndex>(masters.size());

  // Partition (eq. 3) with sparse selection matrices.
  auto stage = Clock::now();
  std::vector<DofIndex> slot(static_cast<std::size_t>(n), -1);  // master coordinate, or -1
  for (DofIndex i = 0; i < m; ++i)
    slot[static_cast<std::size_t>(masters[i])] = i;
  std::vector<DofIndex> slaves;
  slaves.reserve(static_cast<std::size_t>(n - m));
  for (DofIndex i = 0; i < n; ++i)
    if (slot[static_cast<std::size_t>(i)] < 0)
      slaves.push_back(i);
  const auto s = static_cast<DofIndex>(slaves.size());
  const SparseMatrix p_m = selection(n, masters);
  const SparseMatrix p_s = selection(n, slaves);
  SparseMatrix k_ss = p_s.transpose() * in.k * p_s;
  SparseMatrix m_ss = p_s.transpose() * in.m * p_s;
  k_ss.makeCompressed();
  m_ss.makeCompressed();
  const SparseMatrix k_sm_sparse = p_s.transpose() * in.k * p_m;
  result.seconds.partition = since(stage);

  // Constraint modes (eq. 4): one factorisation of K_ss, one solve for all m columns.
  Matrix phi_c(s, m);
  if (s > 0 && m > 0) {
    stage = Clock::now();
    fem::SparseCholesky cholesky;
    if (!cholesky.factorize(k_ss))
      throw SolverError("craigBampton: K_ss (" + std::to_string(s) +
                        " slave DOFs) is not positive "
                        "definite: the " +
                        std::to_string(m) +
                        " master DOFs leave a rigid-body "
                        "motion or a mechanism of the slave DOFs free");
    result.seconds.factorisation = since(stage);
    stage = Clock::now();
    // Solved from the sparse K_sm in blocks, negated in place: no dense K_sm and no second
    // s x m copy (43 MB each on the tracked vehicle).
    phi_c = cholesky.solve(k_sm_sparse);
    phi_c *= -1.0;
    result.seconds.constraint_modes = since(stage);
  }

  stage = Clock::now();
  const fem::ModalBasis phi_s = fixedInterfaceModes(k_ss, m_ss, options);
  result.fixed_interface_eigenvalues = phi_s.eigenvalues;
  result.fixed_interface_frequencies_hz = phi_s.frequencies_hz;
  result.seconds.fixed_interface_modes = since(stage);
  const DofIndex r = phi_s.count();

  // T_CMS (eq. 8) in the original DOF order.
  stage = Clock::now();
  Matrix t = Matrix::Zero(n, m + r);
  for (DofIndex i = 0; i < m; ++i)
    t(masters[static_cast<std::size_t>(i)], i) = 1.0;
  for (DofIndex j = 0; j < s; ++j) {
    const DofIndex row = slaves[static_cast<std::size_t>(j)];
    t.row(row).head(m) = phi_c.row(j);
    if (r > 0)
      t.row(row).tail(r) = phi_s.shapes.row(j);
  }

  // Eq. 9. K_R needs no projection: with the constraint modes (eq. 4) the coupling block
  // vanishes, Phi_S^T (K_sm + K_ss Phi_C) = 0, the mass-normalised fixed-interface modes (eq. 6)
  // give Phi_S^T K_ss Phi_S = diag(omega_i^2), and the master block is the Schur complement
  // K_mm + K_sm^T Phi_C (Guyan). One sparse-dense product instead of a dense n x k projection,
  // and the exact zeros the projection only reproduces to rounding.
  result.mass = project(in.m, t);
  result.stiffness = Matrix::Zero(m + r, m + r);
  if (m > 0) {
    const Matrix schur =
        Matrix(SparseMatrix(p_m.transpose() * in.k * p_m)) + k_sm_sparse.transpose() * phi_c;
    result.stiffness.topLeftCorner(m, m) = 0.5 * (schur + schur.transpose());
  }
  if (r > 0)
    result.stiffness.bottomRightCorner(r, r).diagonal() = phi_s.eigenvalues;
  const Matrix c_discrete = in.c.size() ? project(in.c, t) : Matrix::Zero(m + r, m + r);
  result.damping = reducedDamping(result.mass, result.stiffness, c_discrete, options.damping);
  const DofIndex inputs = in.ku ? in.ku->cols() : 0;
  result.input_stiffness = in.ku ? Matrix(t.transpose() * *in.ku) : Matrix(m + r, 0);
  result.input_damping = in.cu ? Matrix(t.transpose() * *in.cu) : Matrix(m + r, inputs);
  result.gravity_load = in.gravity ? Vector(t.transpose() * *in.gravity) : Vector::Zero(m + r);
  // A load reduces like gravity: its work on x = T x_R is x_R^T (T^T f).
  result.travel_load = in.travel ? Vector(t.transpose() * *in.travel) : Vector::Zero(m + r);
  result.masters = masters;
  result.recovery.resize(static_cast<DofIndex>(options.recovery_dofs.size()), m + r);
  for (std::size_t i = 0; i < options.recovery_dofs.size(); ++i)
    result.recovery.row(static_cast<DofIndex>(i)) = t.row(options.recovery_dofs[i]);
  if (options.keep_transformation)
    result.transformation = std::move(t);
  result.seconds.projection = since(stage);
  result.seconds.total = since(start);
  return result;
}

}  // namespace

CraigBamptonResult craigBampton(const fem::System& system, const std::vector<DofIndex>& masters,
                                const CraigBamptonOptions& options) {
  const DofIndex n = system.size();
  const SparseMatrix& ku = system.input_stiffness;
  const SparseMatrix& cu = system.input_damping;
  if (ku.rows() != n || cu.rows() != n || cu.cols() != ku.cols())
    throw InputError("craigBampton: K_u is " + size(ku) + " and C_u is " + size(cu) +
                     ", expected " + std::to_string(n) + " rows and one column per road input");
  if (system.gravity_load.size() != n)
    throw InputError("craigBampton: gravity load has " +
                     std::to_string(system.gravity_load.size()) + " entries, expected " +
                     std::to_string(n));
  if (system.travel_load.size() != n)
    throw InputError("craigBampton: travel inertia load has " +
                     std::to_string(system.travel_load.size()) + " entries, expected " +
                     std::to_string(n));
  Inputs in{system.stiffness, system.mass,         system.damping,
            &ku,              &cu,                 &system.gravity_load,
            &system.travel_load};
  return reduce(in, masters, options);
}

CraigBamptonResult craigBampton(const SparseMatrix& stiffness, const SparseMatrix& mass,
                                const SparseMatrix& damping, const std::vector<DofIndex>& masters,
                                const CraigBamptonOptions& options) {
  return reduce(Inputs{stiffness, mass, damping}, masters, options);
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
