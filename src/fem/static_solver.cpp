#include "tracked_vehicle_dynamics/fem/static_solver.h"

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/free_motion.h"
#include "tracked_vehicle_dynamics/fem/sparse_cholesky.h"

namespace tracked_vehicle_dynamics {
namespace fem {

StaticResult solveStatic(const System& system, const Vector& load) {
  const DofIndex n = system.size();
  if (load.size() != n)
    throw InputError("static load has " + std::to_string(load.size()) + " entries, expected " +
                     std::to_string(n) + " (active DOFs)");
  if (n == 0)
    throw InputError("static solve: the model has no active DOF");
  if (!load.allFinite())
    throw InputError("static load contains NaN or infinite entries");
  SparseCholesky chol;
  if (!chol.factorize(system.stiffness) || chol.rcond() < kSingularRcond)
    throw SolverError("stiffness matrix is singular: free motion: " + describeFreeMotions(system) +
                      " (add supports or springs that restrain it" +
                      (system.prestressed
                           ? std::string("; or the model's pre-loads make it unstable: a "
                                         "compression beyond buckling turns K indefinite")
                           : std::string()) +
                      ")");
  StaticResult result;
  result.displacement = chol.solve(load);
  const double fnorm = load.norm();
  result.residual =
      fnorm > 0 ? (system.stiffness * result.displacement - load).norm() / fnorm : 0.0;
  return result;
}

double physicalDisplacement(const System& system, const Vector& active, NodeId node,
                            int direction) {
  const DofIndex p = system.dofs.physical(node, direction);
  return (system.dofs.transformation() * active)(p);
}

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
