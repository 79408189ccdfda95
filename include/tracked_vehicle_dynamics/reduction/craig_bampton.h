// Craig-Bampton component mode synthesis (paper §3.1, eqs. 3-10; Craig & Bampton 1968).
//
// The active DOFs x are split into masters x_m [m] and slaves x_s [s] (eq. 3) and approximated
// by x = T_CMS x_R, x_R = {x_m | x_r}:
//
//   T_CMS = [ I     0    ]  rows: masters      [n x (m + r)]                          (eq. 8)
//           [ Phi_C Phi_S]        slaves
//
//   Phi_C = -K_ss^-1 K_sm       constraint modes: the static slave response to a unit master
//                               displacement (eq. 4)
//   K_ss Phi_S = M_ss Phi_S W^2 the lowest r fixed-interface modes, masters clamped (eqs. 6-7),
//                               mass-normalised, Phi_S^T M_ss Phi_S = I
//
// and every matrix is projected, M_R = T^T M T, K_R = T^T K T, C_R = T^T C T (eq. 9), as are the
// road-input matrices (T^T K_u, T^T C_u) and the gravity load (T^T f_g). The rows are in the
// order of the given master list (not sorted), then the fixed-interface modes by frequency.
// Properties the tests check: T is the identity on the master rows; K_R is block diagonal
// diag(K_mm + K_ms Phi_C, W^2) (eq. 5, the Guyan stiffness, is exact for loads on the masters);
// with all s fixed-interface modes T is square and the reduced eigenvalues are the full ones.
#pragma once

#include <chrono>
#include <memory>
#include <vector>

#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/reduction/fixed_interface_modes.h"
#include "tracked_vehicle_dynamics/reduction/reduced_damping.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

struct CraigBamptonOptions {
  FixedInterfaceModes fixed_interface;  ///< r (see fixed_interface_modes.h)
  DampingOptions damping;               ///< damping model added to the projected dampers
  /// Shift, tolerance and iteration limit of the fixed-interface eigen-solve; its count and
  /// max_frequency_hz are taken from fixed_interface.
  fem::ModalRequest modal_solver;
  /// Return T_CMS itself (n x (m + r) dense: 54 MB for 17 000 x 400).
  bool keep_transformation = false;
  /// Active DOFs whose rows of T_CMS are returned in `recovery` (outputs y = T_row x_R).
  std::vector<DofIndex> recovery_dofs;
};

/// Wall time of each stage [s]. A result of CraigBamptonReducer::reduce() counts the stages the
/// reducer did once (partition, factorisation, constraint modes and its share of the projection)
/// in each result, so `total` is the time the result would take from scratch.
struct CraigBamptonTimings {
  double partition = 0.0;              ///< K_ss, K_sm, M_ss extraction
  double factorisation = 0.0;          ///< sparse Cholesky of K_ss
  double constraint_modes = 0.0;       ///< Phi_C: one solve with m right-hand sides
  double fixed_interface_modes = 0.0;  ///< Phi_S: shift-invert Lanczos (or dense) on (K_ss, M_ss)
  double projection = 0.0;  ///< T^T (.) T of M, K, C, K_u, C_u, f_g and the damping model
  double total = 0.0;
};

struct CraigBamptonResult {
  Matrix mass;             ///< M_R [(m + r) x (m + r)] [kg, ...]
  Matrix stiffness;        ///< K_R [(m + r) x (m + r)] [N/m, ...]
  Matrix damping;          ///< C_R: projected dampers + the damping model [(m + r) x (m + r)]
  Matrix input_stiffness;  ///< T^T K_u [(m + r) x n_inputs] (empty columns without a System)
  Matrix input_damping;    ///< T^T C_u [(m + r) x n_inputs]
  Vector gravity_load;     ///< T^T f_g [m + r] (zeros without a System)
  Vector travel_load;      ///< T^T f_a [m + r] per unit forward acceleration (zeros without one)
  std::vector<DofIndex> masters;          ///< active DOF of each master coordinate
  Vector fixed_interface_eigenvalues;     ///< omega_i^2 of Phi_S [rad^2/s^2], ascending
  Vector fixed_interface_frequencies_hz;  ///< [Hz]
  Matrix recovery;        ///< rows of T_CMS for options.recovery_dofs [n_recovery x (m + r)]
  Matrix transformation;  ///< T_CMS [n x (m + r)] when options.keep_transformation, else 0 x 0
  CraigBamptonTimings seconds;

  DofIndex size() const { return stiffness.rows(); }
  DofIndex masterCount() const { return static_cast<DofIndex>(masters.size()); }
  DofIndex modeCount() const { return fixed_interface_eigenvalues.size(); }
};

/// The blocks of eq. 9 that fixed-interface modes bring, T_r = [0; Phi_S]
/// (CraigBamptonReducer::project()). Each column, row or entry belongs to one mode (or a pair),
/// so the blocks of the leading r' modes are the leading columns, rows and corner of these: a
/// caller that tries r' and then r modes projects the r once.
struct FixedInterfaceProjection {
  fem::ModalBasis modes;    ///< Phi_S [s x r], mass-normalised, ascending
  Matrix mass_coupling;     ///< T_m^T M T_r [m x r]
  Matrix mass_modal;        ///< Phi_S^T M_ss Phi_S [r x r] (= I to rounding), exactly symmetric
  Matrix damping_coupling;  ///< T_m^T C T_r [m x r]; 0 x 0 without dampers
  Matrix damping_modal;     ///< Phi_S^T C_ss Phi_S [r x r]; 0 x 0 without dampers
  Matrix input_stiffness;   ///< Phi_S^T K_u(slaves, :) [r x n_inputs]
  Matrix input_damping;     ///< Phi_S^T C_u(slaves, :) [r x n_inputs]
  Vector gravity_load;      ///< Phi_S^T f_g(slaves) [r]
  Vector travel_load;       ///< Phi_S^T f_a(slaves) [r]
  double seconds = 0.0;     ///< wall time of the projection [s]
  const void* reducer = nullptr;  ///< the reducer's state that projected them (identity only)

  DofIndex count() const { return modes.count(); }
};

/// The stages of a reduction on one master set that do not depend on the fixed-interface modes:
/// the partition (eq. 3), the constraint modes Phi_C with one factorisation of K_ss (eq. 4),
/// T_m = [I; Phi_C] and the master blocks of eq. 9 (T_m^T M T_m, the Guyan K, T_m^T C T_m,
/// T_m^T K_u, T_m^T C_u, T_m^T f_g, T_m^T f_a). reduce() adds r fixed-interface modes: their
/// eigen-solve, and for the blocks they bring, with T_r = [0; Phi_S],
///   T_m^T M T_r = T_m^T (M T_r),  T_r^T M T_r = Phi_S^T M_ss Phi_S (= I, computed),
/// and the same for C, and Phi_S^T on the slave rows of K_u, C_u, f_g, f_a: products with r
/// columns, against the n m^2 of the master block. A caller that raises r until a check passes
/// (vehicle_reduction.cpp) pays for the shared stages once. Keeps references to the System it was
/// built from, which must outlive it (a temporary System is refused at compile time), and copies
/// bare matrices (a temporary is safe); reduce() is const and may run from several threads. A
/// moved-from reducer may only be assigned to or destroyed.
class CraigBamptonReducer {
 public:
  /// Throws InputError for a repeated or out-of-range master or inconsistent matrix sizes, and
  /// SolverError when K_ss is not positive definite (see craigBampton()).
  CraigBamptonReducer(const fem::System& system, std::vector<DofIndex> masters);
  CraigBamptonReducer(fem::System&& system, std::vector<DofIndex> masters) = delete;
  /// Bare matrices [n x n]; `damping` may be empty (0 x 0). No input columns, zero loads.
  CraigBamptonReducer(const SparseMatrix& stiffness, const SparseMatrix& mass,
                      const SparseMatrix& damping, std::vector<DofIndex> masters);
  ~CraigBamptonReducer();
  CraigBamptonReducer(CraigBamptonReducer&&) noexcept;
  CraigBamptonReducer& operator=(CraigBamptonReducer&&) noexcept;

  /// The reduction with options.fixed_interface modes. Throws InputError for more fixed-interface
  /// modes than slave DOFs, an out-of-range recovery DOF or an empty basis, SolverError when the
  /// fixed-interface eigen-solve fails.
  CraigBamptonResult reduce(const CraigBamptonOptions& options = {}) const;

  /// The fixed-interface modes options.fixed_interface asks for (eq. 6): the eigen-solve of
  /// reduce(), on its own, for a caller that will try several counts. Throws as reduce().
  fem::ModalBasis fixedInterfaceModes(const CraigBamptonOptions& options) const;
  /// reduce() on modes already solved by fixedInterfaceModes() for at least
  /// options.fixed_interface.count: it keeps their leading options.fixed_interface.count (those
  /// up to options.fixed_interface.max_frequency_hz when it is set), so raising the count
  /// solves once for the largest rather than once per count (on the tracked vehicle a Lanczos
  /// run for 28 modes costs 0.25 s, one for 42 0.30 s). Throws std::logic_error when `modes`
  /// hold fewer than the count, or are not of this reducer's slave DOFs.
  CraigBamptonResult reduce(const CraigBamptonOptions& options, const fem::ModalBasis& modes) const;
  /// The blocks `modes` (fixedInterfaceModes() of this reducer) bring, for reduce(options,
  /// projection). Throws std::logic_error when they are not of this reducer's slave DOFs.
  FixedInterfaceProjection project(fem::ModalBasis modes) const;
  /// reduce() on the leading options.fixed_interface.count modes of a projection (those up to
  /// options.fixed_interface.max_frequency_hz when it is set): neither solved nor projected again.
  /// With all its modes, bit for bit reduce(options, projection.modes). Throws std::logic_error
  /// when it holds fewer modes than the count or another reducer made it.
  CraigBamptonResult reduce(const CraigBamptonOptions& options,
                            const FixedInterfaceProjection& projection) const;

  const std::vector<DofIndex>& masters() const;
  /// Whether it was built on this very System (its matrices, not equal copies).
  bool builtOn(const fem::System& system) const;
  DofIndex slaveCount() const;

 private:
  struct State;
  // Every reduce() once its leading `r` modes are projected; `start` times the whole call.
  CraigBamptonResult reduceOn(const CraigBamptonOptions& options,
                              const FixedInterfaceProjection& projection, DofIndex r,
                              std::chrono::steady_clock::time_point start) const;
  std::unique_ptr<State> state_;
};

/// Reduces an assembled system (M, K, C, K_u, C_u, gravity and travel inertia loads) on the given
/// master DOFs (active indices, any order). Throws InputError for a repeated or out-of-range
/// master, more fixed-interface modes than slave DOFs, an out-of-range recovery DOF, or an empty
/// basis (m + r = 0); SolverError when K_ss is not positive definite (the masters leave a
/// rigid-body motion or mechanism of the slaves free) or the fixed-interface eigen-solve fails (for
/// the dense path used for many modes, M_ss must be positive definite).
CraigBamptonResult craigBampton(const fem::System& system, const std::vector<DofIndex>& masters,
                                const CraigBamptonOptions& options = {});

/// The same on bare matrices [n x n]; `damping` may be empty (0 x 0) for no dampers. The result
/// has no input columns and a zero gravity load.
CraigBamptonResult craigBampton(const SparseMatrix& stiffness, const SparseMatrix& mass,
                                const SparseMatrix& damping, const std::vector<DofIndex>& masters,
                                const CraigBamptonOptions& options = {});

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
