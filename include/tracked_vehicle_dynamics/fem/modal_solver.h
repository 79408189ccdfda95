// Generalised symmetric eigenproblem K phi = omega^2 M phi by shift-invert Lanczos (Spectra).
#pragma once

#include <string>

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace fem {

/// What to compute: the lowest `count` modes, or every mode below `max_frequency_hz` (when > 0).
struct ModalRequest {
  int count = 20;                 ///< number of modes (upper bound when max_frequency_hz > 0)
  double max_frequency_hz = 0.0;  ///< 0: use count only
  /// Shift sigma [rad^2/s^2]; negative so that rigid-body modes (omega = 0) are found and
  /// K - sigma M is positive definite. 0: chosen automatically from the matrix scales.
  double shift = 0.0;
  double tolerance = 1e-10;
  int max_iterations = 1000;
};

/// Modes sorted by increasing frequency; shapes are mass-normalised (Phi^T M Phi = I).
struct ModalBasis {
  Vector eigenvalues;     ///< omega^2 [rad^2/s^2]
  Vector frequencies_hz;  ///< omega / 2 pi [Hz]; rigid-body modes give ~0
  ModeShapes shapes;      ///< [n x modes]
  /// Modes below the highest one returned that the solver could not find (the count of
  /// eigenvalues below it by Sylvester's law, less the modes returned below it): 0 when none is
  /// missing. Not counted (0) when K - lambda M cannot be factorised there.
  int missed = 0;
  int iterations = 0;    ///< Arnoldi iterations summed over the solves (informational)
  double seconds = 0.0;  ///< wall time of the solve [s]
  /// |omega^2| [rad^2/s^2] within which the solve cannot tell an eigenvalue from 0 (a rigid-body
  /// mode's), from the whole problem, not the modes returned: 1e-6 of the shift-invert solve's
  /// |sigma|, or 1e-12 of the dense solve's largest |omega^2| (about 4500 eps).
  double zero_tolerance = 0.0;

  int count() const { return static_cast<int>(eigenvalues.size()); }
};

/// Solves the lowest modes of (K, M). Throws SolverError when the solver fails, naming the
/// reason (factorisation failure, no convergence after max_iterations, numerical issue) and
/// InputError for mismatched sizes or a non-positive count.
ModalBasis solveModes(const SparseMatrix& stiffness, const SparseMatrix& mass,
                      const ModalRequest& request);

/// "" when `basis` holds every mode below its highest one (ModalBasis::missed == 0), else a
/// sentence for the user saying how many are missing below which frequency.
std::string missedModesWarning(const ModalBasis& basis);

/// "" when every eigenvalue of `basis` is >= 0 (to round-off: -1e-8 of the largest |omega^2|, or
/// -ModalBasis::zero_tolerance when more),
/// else a sentence saying how many are negative and the lowest: the structure is unstable (a
/// compressive pre-load beyond buckling), and those modes' frequencies read 0 Hz.
std::string unstableModesWarning(const ModalBasis& basis);

/// Dense generalised eigenproblem of all modes (small systems, references in tests).
ModalBasis solveModesDense(const Matrix& stiffness, const Matrix& mass);

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
