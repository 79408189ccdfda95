// Linear statics K x = f on the active DOFs with a sparse Cholesky factorisation (CHOLMOD).
#pragma once

#include <string>

#include "tracked_vehicle_dynamics/fem/system.h"

namespace tracked_vehicle_dynamics {
namespace fem {

struct StaticResult {
  Vector displacement;    ///< x over the active DOFs
  double residual = 0.0;  ///< ||K x - f|| / ||f||
};

/// Solves K x = f. A singular K (a free rigid-body motion or a mechanism) throws SolverError
/// naming the motion, e.g. "stiffness matrix is singular: free motion: a mechanism involving
/// node 3 ux, node 4 ux (add supports or springs that restrain it)" or "...: free motion:
/// rigid-body translation along x (...)".
StaticResult solveStatic(const System& system, const Vector& load);

/// Nodal displacement of a physical DOF from an active-DOF vector (through the constraint
/// transformation, so fixed DOFs give 0 and rigid-joint slaves follow their master).
double physicalDisplacement(const System& system, const Vector& active, NodeId node, int direction);

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
