// How many eigenvalues of K phi = lambda M phi lie below a value, without computing any: the
// check that a Lanczos run (which holds one vector per distinct eigenvalue in exact arithmetic)
// did not skip a copy of a repeated eigenvalue.
#pragma once

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace fem {

/// The eigenvalues of K phi = lambda M phi below `lambda` [rad^2/s^2], by Sylvester's law of
/// inertia: the negative pivots of the LDL^T factorisation of the congruent K - lambda M (M
/// positive definite). No eigenvector is computed, so the solve that produced the modes is not
/// touched. Throws SolverError when the factorisation fails (lambda an eigenvalue to working
/// precision) and InputError when the sizes differ.
int eigenvaluesBelow(const SparseMatrix& stiffness, const SparseMatrix& mass, double lambda);

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
