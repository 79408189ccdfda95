#include "tracked_vehicle_dynamics/fem/low_mode_refinement.h"

#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

namespace tracked_vehicle_dynamics {
namespace fem {

bool refineLowModes(const Matrix& stiffness, const Matrix& mass, Vector* lambda, Matrix* shapes) {
  const DofIndex n = lambda->size();
  if (n == 0)
    return false;
  const double lambda_max = lambda->cwiseAbs().maxCoeff();
  DofIndex p = 0;
  while (p < n && (*lambda)(p) <= kRefineBelow * lambda_max)
    ++p;
  if (p == 0 || p == n)
    return false;
  const Eigen::LLT<Matrix> k_factor(stiffness);
  if (k_factor.info() != Eigen::Success)
    return false;
  const Vector pivots = k_factor.matrixLLT().diagonal().cwiseAbs2();
  for (DofIndex i = 0; i < n; ++i)
    if (!(pivots(i) * kMaxPivotRatio >= stiffness(i, i)))
      return false;
  // One step: the solver's low subspace is accurate (its error is eps lambda_max over the gap
  // to the high modes, itself of the order of lambda_max); only the modes within it are not,
  // and the Rayleigh-Ritz step on K^-1 M X sorts them out.
  const Matrix y = mass * shapes->leftCols(p);
  const Matrix x1 = k_factor.solve(y);
  const Matrix m_x1 = mass * x1;
  Matrix k_p = x1.transpose() * y;
  Matrix m_p = x1.transpose() * m_x1;
  k_p = 0.5 * (k_p + k_p.transpose()).eval();
  m_p = 0.5 * (m_p + m_p.transpose()).eval();
  const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> ritz(
      k_p, m_p, Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
  if (ritz.info() != Eigen::Success)
    return false;
  const Matrix x = x1 * ritz.eigenvectors();  // M-normalised: Z^T M_p Z = I
  // The solver's high modes were M-orthogonal to its low ones; to the refined ones only to
  // ~1e-11, which a state projected on the modes and back (eta = Phi^T M q, q = Phi eta) would
  // lose. Make them M-orthogonal again, h -= X c with c = X^T M h, and unit again,
  // h^T M h = 1 - |c|^2: the change is of that order, the high modes' Rayleigh quotients move by
  // its square.
  Matrix high = shapes->rightCols(n - p);
  const Matrix c = (m_x1 * ritz.eigenvectors()).transpose() * high;
  high -= x * c;
  for (DofIndex j = 0; j < n - p; ++j)
    high.col(j) /= std::sqrt(1.0 - c.col(j).squaredNorm());
  lambda->head(p) = ritz.eigenvalues();
  shapes->leftCols(p) = x;
  shapes->rightCols(n - p) = high;
  return true;
}

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
