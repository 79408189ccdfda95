#include "tracked_vehicle_dynamics/reduction/craig_bampton.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
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

// The rows where a sparse matrix has entries, ascending.
std::vector<DofIndex> rowsWithEntries(const SparseMatrix& a) {
  std::vector<char> used(static_cast<std::size_t>(a.rows()), 0);
  for (DofIndex j = 0; j < a.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(a, j); it; ++it)
      used[static_cast<std::size_t>(it.row())] = 1;
  std::vector<DofIndex> rows;
  for (DofIndex i = 0; i < a.rows(); ++i)
    if (used[static_cast<std::size_t>(i)])
      rows.push_back(i);
  return rows;
}

// T^T A T for a symmetric sparse A, exactly symmetric. Only the rows where A has entries
// contribute (the dampers touch few DOFs), and only the lower triangle is multiplied. The rows go
// in blocks: with R the block's rows, (A T)(R, :) = A(:, R)^T T (A symmetric) and
// T^T A T = sum over blocks of T(R, :)^T (A T)(R, :), so no n x k product A T is formed (50 MB on
// the tracked vehicle), only a block of it.
Matrix congruence(const SparseMatrix& a, const Matrix& t) {
  const DofIndex k = t.cols();
  Matrix out = Matrix::Zero(k, k);
  // (k = 0: Eigen's triangular product would bind a reference to the empty matrix's data.)
  if (a.nonZeros() == 0 || k == 0)
    return out;
  const std::vector<DofIndex> rows = rowsWithEntries(a);
  constexpr std::size_t kBlock = 1024;  // 1024 x 431 doubles: 3.5 MB per block product
  for (std::size_t first = 0; first < rows.size(); first += kBlock) {
    const std::vector<DofIndex> block(
        rows.begin() + static_cast<std::ptrdiff_t>(first),
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

void checkMatrices(const Inputs& in, const std::vector<DofIndex>& masters) {
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
}

void checkOptions(DofIndex n, DofIndex master_count, const CraigBamptonOptions& options) {
  const DofIndex slaves = n - master_count;
  const FixedInterfaceModes& r = options.fixed_interface;
  if (r.count < 0 || r.count > slaves)
    throw InputError("craigBampton: " + std::to_string(r.count) +
                     " fixed-interface modes requested; the " + std::to_string(slaves) +
                     " slave DOFs allow 0.." + std::to_string(slaves));
  if (r.max_frequency_hz < 0.0)
    throw InputError("craigBampton: fixed-interface max_frequency_hz is negative");
  if (master_count == 0 && r.count == 0)
    throw InputError("craigBampton: no master DOF and no fixed-interface mode: empty basis");
  for (std::size_t i = 0; i < options.recovery_dofs.size(); ++i)
    if (options.recovery_dofs[i] < 0 || options.recovery_dofs[i] >= n)
      throw InputError("craigBampton: recovery DOF [" + std::to_string(i) +
                       "] = " + std::to_string(options.recovery_dofs[i]) +
                       " is not an active DOF (0.." + std::to_string(n - 1) + ")");
}

// How many of the ascending `frequencies_hz` (at least r.count of them) the request keeps.
DofIndex leadingCount(const Vector& frequencies_hz, const FixedInterfaceModes& r) {
  DofIndex keep = r.count;
  if (r.max_frequency_hz > 0.0) {
    keep = 0;
    while (keep < r.count && frequencies_hz(keep) <= r.max_frequency_hz)
      ++keep;
  }
  return keep;
}

// The leading r.count of ascending modes, cut at r.max_frequency_hz when it is set (as
// fem::solveModes() cuts): what a solve for r gives, from a solve for at least as many.
fem::ModalBasis leadingModes(const fem::ModalBasis& modes, const FixedInterfaceModes& r) {
  const DofIndex keep = leadingCount(modes.frequencies_hz, r);
  fem::ModalBasis out;
  out.eigenvalues = modes.eigenvalues.head(keep);
  out.frequencies_hz = modes.frequencies_hz.head(keep);
  out.shapes = modes.shapes.leftCols(keep);
  return out;
}

// The lowest fixed-interface modes of (K_ss, M_ss) (eq. 6).
fem::ModalBasis solveFixedInterfaceModes(const SparseMatrix& k_ss, const SparseMatrix& m_ss,
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
  return leadingModes(fem::solveModesDense(Matrix(k_ss), Matrix(m_ss)), r);
}

// Phi_S^T b(slaves, :) for a sparse n x k matrix b (the fixed-interface rows of T^T b).
Matrix slaveRowsProduct(const Matrix& phi_s, const SparseMatrix& p_s, const SparseMatrix& b) {
  return phi_s.transpose() * SparseMatrix(p_s.transpose() * b);
}

}  // namespace

struct CraigBamptonReducer::State {
  // Partition, constraint modes and master blocks (throws as the reducer's constructors say).
  State(const Inputs& matrices, std::vector<DofIndex> master_dofs);

  Inputs in;
  std::unique_ptr<const std::array<SparseMatrix, 3>> owned;  // what `in` refers to, if copied
  std::vector<DofIndex> masters;
  std::vector<DofIndex> slaves;
  std::vector<DofIndex> slave_index;  // per DOF: its row of Phi_S, -1 for a master
  SparseMatrix p_s;                   // n x s selection of the slave DOFs
  SparseMatrix k_ss;
  SparseMatrix m_ss;
  bool has_dampers = false;     // C given (not 0 x 0): its blocks are projected, m = 0 included
  SparseMatrix c_ss;            // empty without dampers
  Matrix t_m;                   // T_m = [I; Phi_C] in the original DOF order [n x m]
  Matrix mass_mm;               // T_m^T M T_m
  Matrix stiffness_mm;          // K_mm + K_sm^T Phi_C (Guyan), exactly symmetric
  Matrix damping_mm;            // T_m^T C T_m (0 x 0 without dampers)
  Matrix input_stiffness_m;     // T_m^T K_u
  Matrix input_damping_m;       // T_m^T C_u
  Vector gravity_m;             // T_m^T f_g
  Vector travel_m;              // T_m^T f_a
  CraigBamptonTimings seconds;  // partition, factorisation, constraint modes, master projection
};

CraigBamptonReducer::State::State(const Inputs& matrices, std::vector<DofIndex> master_dofs)
    : in(matrices), masters(std::move(master_dofs)) {
  checkMatrices(in, masters);
  const auto start = Clock::now();
  const DofIndex n = in.k.rows();
  const auto m = static_cast<DofIndex>(masters.size());

  // Partition (eq. 3) with sparse selection matrices.
  auto stage = Clock::now();
  std::vector<char> is_master(static_cast<std::size_t>(n), 0);
  for (const DofIndex i : masters)
    is_master[static_cast<std::size_t>(i)] = 1;
  slaves.reserve(static_cast<std::size_t>(n - m));
  slave_index.assign(static_cast<std::size_t>(n), -1);
  for (DofIndex i = 0; i < n; ++i)
    if (!is_master[static_cast<std::size_t>(i)]) {
      slave_index[static_cast<std::size_t>(i)] = static_cast<DofIndex>(slaves.size());
      slaves.push_back(i);
    }
  const auto s = static_cast<DofIndex>(slaves.size());
  const SparseMatrix p_m = selection(n, masters);
  p_s = selection(n, slaves);
  k_ss = p_s.transpose() * in.k * p_s;
  m_ss = p_s.transpose() * in.m * p_s;
  k_ss.makeCompressed();
  m_ss.makeCompressed();
  const SparseMatrix k_sm_sparse = p_s.transpose() * in.k * p_m;
  seconds.partition = since(stage);

  // Constraint modes (eq. 4): one factorisation of K_ss, one solve for all m columns.
  // T_m = [I; Phi_C] in the original DOF order: the constraint modes are written into its slave
  // rows block by block as they are solved, so no separate s x m Phi_C exists.
  t_m = Matrix::Zero(n, m);
  for (DofIndex i = 0; i < m; ++i)
    t_m(masters[static_cast<std::size_t>(i)], i) = 1.0;
  if (s > 0 && m > 0) {
    stage = Clock::now();
    fem::SparseCholesky cholesky;
    // CHOLMOD refuses a zero or negative pivot only: a singular K_ss whose pivot rounds to a
    // tiny positive value factorised, and the constraint modes then carried an arbitrary free
    // motion (review 134: a free-free beam with its rotation about one master left free, T off
    // by 2.6). rcond = (min L_ii / max L_ii)^2 of the vehicles' K_ss is 1e-6 .. 1e-7.
    if (!cholesky.factorize(k_ss) || cholesky.rcond() < fem::kSingularRcond)
      throw SolverError("craigBampton: K_ss (" + std::to_string(s) +
                        " slave DOFs) is not positive "
                        "definite: the " +
                        std::to_string(m) +
                        " master DOFs leave a rigid-body "
                        "motion or a mechanism of the slave DOFs free");
    seconds.factorisation = since(stage);
    stage = Clock::now();
    // Solved from the sparse K_sm in blocks, each block negated into T_m's slave rows: no dense
    // K_sm and no s x m Phi_C beside T_m (43 MB each on the tracked vehicle; the copy once kept
    // set the reduction's peak memory).
    cholesky.solve(k_sm_sparse, [&](DofIndex first, const Eigen::Ref<const Matrix>& x) {
      for (DofIndex c = 0; c < x.cols(); ++c)
        for (DofIndex j = 0; j < s; ++j)
          t_m(slaves[static_cast<std::size_t>(j)], first + c) = -x(j, c);
    });
    seconds.constraint_modes = since(stage);
  }

  // T_m (eq. 8's master columns) in the original DOF order, and the master blocks of eq. 9.
  // K needs no projection: the master block is the Schur complement K_mm + K_sm^T Phi_C (Guyan),
  // and with the constraint modes (eq. 4) its coupling to the fixed-interface modes vanishes,
  // Phi_S^T (K_sm + K_ss Phi_C) = 0 (reduce()).
  stage = Clock::now();
  stiffness_mm = Matrix::Zero(m, m);
  if (m > 0) {
    // K_sm^T Phi_C from T_m's slave rows: K_sm scattered to the slave rows of T_m (same terms in
    // the same order as with a separate Phi_C).
    const SparseMatrix k_sm_rows = p_s * k_sm_sparse;  // n x m
    const Matrix schur =
        Matrix(SparseMatrix(p_m.transpose() * in.k * p_m)) + k_sm_rows.transpose() * t_m;
    stiffness_mm = 0.5 * (schur + schur.transpose());
  }
  mass_mm = congruence(in.m, t_m);
  has_dampers = in.c.size() != 0;
  if (has_dampers) {
    damping_mm = congruence(in.c, t_m);
    c_ss = p_s.transpose() * in.c * p_s;
  }
  const DofIndex inputs = in.ku ? in.ku->cols() : 0;
  input_stiffness_m = in.ku ? Matrix(t_m.transpose() * *in.ku) : Matrix(m, 0);
  input_damping_m = in.cu ? Matrix(t_m.transpose() * *in.cu) : Matrix(m, inputs);
  gravity_m = in.gravity ? Vector(t_m.transpose() * *in.gravity) : Vector::Zero(m);
  // A load reduces like gravity: its work on x = T x_R is x_R^T (T^T f).
  travel_m = in.travel ? Vector(t_m.transpose() * *in.travel) : Vector::Zero(m);
  seconds.projection = since(stage);
  seconds.total = since(start);
}

namespace {

// The blocks of T^T A T (eq. 9) that a symmetric sparse A [n x n] gives the fixed-interface
// modes, T_r = [0; Phi_S]: the coupling T_m^T (A T_r) [m x r], with A T_r = A(:, s) Phi_S, over
// the rows where A T_r has entries only when those are few (a damper's C), and the modal block
// Phi_S^T A_ss Phi_S [r x r], made exactly symmetric.
void projectModes(const SparseMatrix& a, const SparseMatrix& a_ss, const SparseMatrix& p_s,
                  const Matrix& t_m, const Matrix& phi_s, Matrix* coupling, Matrix* modal) {
  const SparseMatrix a_s = a * p_s;  // n x s
  const std::vector<DofIndex> rows = rowsWithEntries(a_s);
  if (2 * rows.size() > static_cast<std::size_t>(a.rows())) {
    *coupling = t_m.transpose() * (a_s * phi_s);
  } else {
    const SparseMatrix a_rows = selection(a.rows(), rows).transpose() * a_s;  // rows x s
    *coupling = t_m(rows, Eigen::all).transpose() * (a_rows * phi_s);
  }
  const Matrix block = phi_s.transpose() * (a_ss * phi_s);
  *modal = 0.5 * (block + block.transpose());
}

// The system's matrices after checking the sizes of its input columns and loads.
Inputs systemInputs(const fem::System& system) {
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
  return Inputs{system.stiffness,     system.mass,        system.damping, &ku, &cu,
                &system.gravity_load, &system.travel_load};
}

}  // namespace

CraigBamptonReducer::CraigBamptonReducer(const fem::System& system, std::vector<DofIndex> masters)
    : state_(std::make_unique<State>(systemInputs(system), std::move(masters))) {}

CraigBamptonReducer::CraigBamptonReducer(const SparseMatrix& stiffness, const SparseMatrix& mass,
                                         const SparseMatrix& damping,
                                         std::vector<DofIndex> masters) {
  // Bare matrices are copied (sparse: small beside the reduction's dense blocks), so a caller's
  // temporary, e.g. a SparseMatrix() for no damping, cannot dangle; a System is referenced.
  auto owned = std::make_unique<const std::array<SparseMatrix, 3>>(
      std::array<SparseMatrix, 3>{stiffness, mass, damping});
  state_ =
      std::make_unique<State>(Inputs{(*owned)[0], (*owned)[1], (*owned)[2]}, std::move(masters));
  state_->owned = std::move(owned);
}

CraigBamptonReducer::~CraigBamptonReducer() = default;
CraigBamptonReducer::CraigBamptonReducer(CraigBamptonReducer&&) noexcept = default;
CraigBamptonReducer& CraigBamptonReducer::operator=(CraigBamptonReducer&&) noexcept = default;

bool CraigBamptonReducer::builtOn(const fem::System& system) const {
  return &state_->in.k == &system.stiffness && &state_->in.m == &system.mass &&
         &state_->in.c == &system.damping;
}

const std::vector<DofIndex>& CraigBamptonReducer::masters() const {
  return state_->masters;
}

DofIndex CraigBamptonReducer::slaveCount() const {
  return static_cast<DofIndex>(state_->slaves.size());
}

fem::ModalBasis CraigBamptonReducer::fixedInterfaceModes(const CraigBamptonOptions& options) const {
  const State& st = *state_;
  checkOptions(st.in.k.rows(), static_cast<DofIndex>(st.masters.size()), options);
  return solveFixedInterfaceModes(st.k_ss, st.m_ss, options);
}

CraigBamptonResult CraigBamptonReducer::reduce(const CraigBamptonOptions& options) const {
  const auto start = Clock::now();
  const State& st = *state_;
  checkOptions(st.in.k.rows(), static_cast<DofIndex>(st.masters.size()), options);
  fem::ModalBasis phi_s = solveFixedInterfaceModes(st.k_ss, st.m_ss, options);
  const double solve_seconds = since(start);
  const FixedInterfaceProjection projection = project(std::move(phi_s));
  CraigBamptonResult result = reduceOn(options, projection, projection.count(), start);
  result.seconds.fixed_interface_modes = solve_seconds;
  return result;
}

CraigBamptonResult CraigBamptonReducer::reduce(const CraigBamptonOptions& options,
                                               const fem::ModalBasis& modes) const {
  const auto start = Clock::now();
  const State& st = *state_;
  checkOptions(st.in.k.rows(), static_cast<DofIndex>(st.masters.size()), options);
  const FixedInterfaceModes& r = options.fixed_interface;
  if (modes.count() < r.count)  // their rows are project()'s to check
    throw std::logic_error("CraigBamptonReducer::reduce: " + std::to_string(modes.count()) +
                           " solved fixed-interface modes for " + std::to_string(r.count));
  const FixedInterfaceProjection projection = project(leadingModes(modes, r));
  return reduceOn(options, projection, projection.count(), start);
}

CraigBamptonResult CraigBamptonReducer::reduce(const CraigBamptonOptions& options,
                                               const FixedInterfaceProjection& projection) const {
  const auto start = Clock::now();
  const State& st = *state_;
  checkOptions(st.in.k.rows(), static_cast<DofIndex>(st.masters.size()), options);
  const FixedInterfaceModes& r = options.fixed_interface;
  if (projection.reducer != state_.get() || projection.count() < r.count)
    throw std::logic_error("CraigBamptonReducer::reduce: a projection of " +
                           std::to_string(projection.count()) + " fixed-interface modes " +
                           (projection.reducer != state_.get() ? "made by another reducer"
                                                               : "for " + std::to_string(r.count)));
  CraigBamptonResult result =
      reduceOn(options, projection, leadingCount(projection.modes.frequencies_hz, r), start);
  result.seconds.total += projection.seconds;  // done before the call, as from scratch
  return result;
}

FixedInterfaceProjection CraigBamptonReducer::project(fem::ModalBasis modes) const {
  const auto start = Clock::now();
  const State& st = *state_;
  const Inputs& in = st.in;
  if (modes.count() > 0 && modes.shapes.rows() != st.k_ss.rows())
    throw std::logic_error("CraigBamptonReducer::project: " + std::to_string(modes.count()) +
                           " fixed-interface modes of " + std::to_string(modes.shapes.rows()) +
                           " DOFs for " + std::to_string(st.k_ss.rows()) + " slave DOFs");
  FixedInterfaceProjection p;
  p.reducer = state_.get();
  const DofIndex r = modes.count();
  const DofIndex inputs = in.ku ? in.ku->cols() : 0;
  p.mass_coupling = Matrix::Zero(static_cast<DofIndex>(st.masters.size()), r);
  p.mass_modal = Matrix::Zero(r, r);
  p.input_stiffness = Matrix::Zero(r, inputs);
  p.input_damping = Matrix::Zero(r, inputs);
  p.gravity_load = Vector::Zero(r);
  p.travel_load = Vector::Zero(r);
  if (r > 0) {
    const Matrix& phi_s = modes.shapes;
    projectModes(in.m, st.m_ss, st.p_s, st.t_m, phi_s, &p.mass_coupling, &p.mass_modal);
    if (st.has_dampers)
      projectModes(in.c, st.c_ss, st.p_s, st.t_m, phi_s, &p.damping_coupling, &p.damping_modal);
    if (in.ku)
      p.input_stiffness = slaveRowsProduct(phi_s, st.p_s, *in.ku);
    if (in.cu)
      p.input_damping = slaveRowsProduct(phi_s, st.p_s, *in.cu);
    const SparseMatrix p_s_t = st.p_s.transpose();
    if (in.gravity)
      p.gravity_load = phi_s.transpose() * (p_s_t * *in.gravity);
    if (in.travel)
      p.travel_load = phi_s.transpose() * (p_s_t * *in.travel);
  }
  p.modes = std::move(modes);
  p.seconds = since(start);
  return p;
}

CraigBamptonResult CraigBamptonReducer::reduceOn(
    const CraigBamptonOptions& options, const FixedInterfaceProjection& projection, DofIndex r,
    std::chrono::steady_clock::time_point start) const {
  const State& st = *state_;
  const Inputs& in = st.in;
  const DofIndex n = in.k.rows();
  const auto m = static_cast<DofIndex>(st.masters.size());
  const fem::ModalBasis& modes = projection.modes;
  CraigBamptonResult result;
  result.seconds = st.seconds;
  result.seconds.fixed_interface_modes = 0.0;
  result.fixed_interface_eigenvalues = modes.eigenvalues.head(r);
  result.fixed_interface_frequencies_hz = modes.frequencies_hz.head(r);

  // Eq. 9 by blocks (class comment): the master blocks from the reducer, those of the leading r
  // fixed-interface modes from the projection. K_R = diag(K_Guyan, Omega^2): the mass-normalised
  // modes (eq. 6) give Phi_S^T K_ss Phi_S = diag(omega_i^2), and the coupling vanishes by eq. 4;
  // exact zeros that a projection only reproduces to rounding.
  const auto stage = Clock::now();
  const DofIndex k = m + r;
  result.mass = Matrix::Zero(k, k);
  result.mass.topLeftCorner(m, m) = st.mass_mm;
  result.stiffness = Matrix::Zero(k, k);
  result.stiffness.topLeftCorner(m, m) = st.stiffness_mm;
  Matrix c_discrete = Matrix::Zero(k, k);
  if (st.has_dampers)
    c_discrete.topLeftCorner(m, m) = st.damping_mm;
  const DofIndex inputs = in.ku ? in.ku->cols() : 0;
  result.input_stiffness = Matrix::Zero(k, inputs);
  result.input_stiffness.topRows(m) = st.input_stiffness_m;
  result.input_damping = Matrix::Zero(k, inputs);
  result.input_damping.topRows(m) = st.input_damping_m;
  result.gravity_load = Vector::Zero(k);
  result.gravity_load.head(m) = st.gravity_m;
  result.travel_load = Vector::Zero(k);
  result.travel_load.head(m) = st.travel_m;
  if (r > 0) {
    const FixedInterfaceProjection& p = projection;
    result.mass.topRightCorner(m, r) = p.mass_coupling.leftCols(r);
    result.mass.bottomLeftCorner(r, m) = p.mass_coupling.leftCols(r).transpose();
    result.mass.bottomRightCorner(r, r) = p.mass_modal.topLeftCorner(r, r);
    result.stiffness.bottomRightCorner(r, r).diagonal() = modes.eigenvalues.head(r);
    if (st.has_dampers) {
      c_discrete.topRightCorner(m, r) = p.damping_coupling.leftCols(r);
      c_discrete.bottomLeftCorner(r, m) = p.damping_coupling.leftCols(r).transpose();
      c_discrete.bottomRightCorner(r, r) = p.damping_modal.topLeftCorner(r, r);
    }
    result.input_stiffness.bottomRows(r) = p.input_stiffness.topRows(r);
    result.input_damping.bottomRows(r) = p.input_damping.topRows(r);
    result.gravity_load.tail(r) = p.gravity_load.head(r);
    result.travel_load.tail(r) = p.travel_load.head(r);
  }
  result.damping = reducedDamping(result.mass, result.stiffness, c_discrete, options.damping);
  result.masters = st.masters;

  // Rows of T_CMS (eq. 8): [T_m row | Phi_S row of a slave, 0 for a master].
  auto transformationRow = [&](DofIndex dof, auto row) {  // row: a block view, written through
    row.head(m) = st.t_m.row(dof);
    if (r == 0)
      return;
    const DofIndex j = st.slave_index[static_cast<std::size_t>(dof)];
    if (j >= 0)
      row.tail(r) = modes.shapes.row(j).head(r);
    else
      row.tail(r).setZero();
  };
  result.recovery.resize(static_cast<DofIndex>(options.recovery_dofs.size()), k);
  for (std::size_t i = 0; i < options.recovery_dofs.size(); ++i)
    transformationRow(options.recovery_dofs[i], result.recovery.row(static_cast<DofIndex>(i)));
  if (options.keep_transformation) {
    result.transformation.resize(n, k);
    for (DofIndex i = 0; i < n; ++i)
      transformationRow(i, result.transformation.row(i));
  }
  // The projection counts in each result that uses it, as the reducer's shared stages do.
  result.seconds.projection = st.seconds.projection + projection.seconds + since(stage);
  result.seconds.total = st.seconds.total + since(start);
  return result;
}

// Every check before the factorisation: the matrices and masters, then the options (which
// reduce() checks again after it).
CraigBamptonResult craigBampton(const fem::System& system, const std::vector<DofIndex>& masters,
                                const CraigBamptonOptions& options) {
  checkMatrices(systemInputs(system), masters);
  checkOptions(system.size(), static_cast<DofIndex>(masters.size()), options);
  return CraigBamptonReducer(system, masters).reduce(options);
}

CraigBamptonResult craigBampton(const SparseMatrix& stiffness, const SparseMatrix& mass,
                                const SparseMatrix& damping, const std::vector<DofIndex>& masters,
                                const CraigBamptonOptions& options) {
  checkMatrices(Inputs{stiffness, mass, damping}, masters);
  checkOptions(stiffness.rows(), static_cast<DofIndex>(masters.size()), options);
  return CraigBamptonReducer(stiffness, mass, damping, masters).reduce(options);
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
