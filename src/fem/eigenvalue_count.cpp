#include "tracked_vehicle_dynamics/fem/eigenvalue_count.h"

#include <Eigen/SparseCholesky>

#include <cmath>
#include <string>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace fem {

int eigenvaluesBelow(const SparseMatrix& stiffness, const SparseMatrix& mass, double lambda) {
  if (stiffness.rows() != stiffness.cols() || mass.rows() != stiffness.rows() ||
      mass.cols() != stiffness.cols())
    throw InputError("eigenvaluesBelow: K is " + std::to_string(stiffness.rows()) + " x " +
                     std::to_string(stiffness.cols()) + ", M " + std::to_string(mass.rows()) +
                     " x " + std::to_string(mass.cols()));
  // K - lambda M = L D L^T (with a fill-reducing permutation P, itself a congruence): by
  // Sylvester's law, K - lambda M, hence the pencil shifted by lambda, has as many negative
  // eigenvalues as D has negative entries.
  const SparseMatrix shifted = stiffness - lambda * mass;
  Eigen::SimplicialLDLT<SparseMatrix, Eigen::Lower> ldlt(shifted);
  if (ldlt.info() != Eigen::Success)
    throw SolverError("eigenvaluesBelow: LDL^T of K - " + brief(lambda) +
                      " M failed (an eigenvalue at the shift?)");
  const Vector d = ldlt.vectorD();
  int negative = 0;
  for (Eigen::Index i = 0; i < d.size(); ++i) {
    if (!std::isfinite(d(i)) || d(i) == 0.0)
      throw SolverError("eigenvaluesBelow: zero pivot in the LDL^T of K - " + brief(lambda) + " M");
    negative += d(i) < 0.0 ? 1 : 0;
  }
  return negative;
}

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
