#include "tracked_vehicle_dynamics/fem/free_motion.h"

#include <algorithm>
#include <numeric>
#include <sstream>
#include <vector>

#include <Eigen/QR>
#include <Eigen/SVD>

#include "tracked_vehicle_dynamics/fem/modal_solver.h"

namespace tracked_vehicle_dynamics {
namespace fem {

Matrix rigidBodyModes(const System& system) {
  const DofMap& dofs = system.dofs;
  const DofIndex n = dofs.activeCount();
  Vector3 centroid = Vector3::Zero();
  for (DofIndex i = 0; i < n; ++i)
    centroid += dofs.positionOf(i);
  if (n > 0)
    centroid /= static_cast<double>(n);
  Matrix modes = Matrix::Zero(n, 6);
  for (DofIndex i = 0; i < n; ++i) {
    const DofRef d = dofs.dofOf(i);
    const Vector3 r = dofs.positionOf(i) - centroid;
    if (d.direction < 3) {
      modes(i, d.direction) = 1.0;
      // translation of the node under a unit rotation theta about axis a: (e_a x r)_d
      for (int a = 0; a < 3; ++a)
        modes(i, 3 + a) = Vector3::Unit(a).cross(r)(d.direction);
    } else {
      modes(i, d.direction) = 1.0;
    }
  }
  return modes;
}

std::string describeFreeMotions(const System& system) {
  const DofIndex n = system.size();
  // Zero-energy vectors: lowest eigenvectors of (K, I) — independent of how M looks.
  SparseMatrix identity(n, n);
  identity.setIdentity();
  // A stiffness with nothing in it (every DOF free) still needs a scale for the shift below.
  const double largest = system.stiffness.diagonal().cwiseAbs().maxCoeff();
  const double scale = largest > 0.0 ? largest : 1.0;
  ModalRequest request;
  // Up to six rigid-body motions and a few mechanisms (the message says when there may be more).
  request.count = static_cast<int>(std::min<DofIndex>(24, n));
  request.shift = -1e-8 * scale;
  std::ostringstream out;
  ModalBasis basis;
  try {
    basis = solveModes(system.stiffness, identity, request);
  } catch (const std::exception&) {
    return "could not isolate the free motion";
  }
  // The zero-energy vectors span the free motions, but any basis of that space is as good to the
  // eigen-solver: a free-free beam's six come out as mixtures. So each rigid-body motion r is
  // tested against the space (the part of r outside it, |r - N N^T r| / |r|, N orthonormal) and
  // named when it lies in it; what the space holds beyond the rigid motions named are mechanisms,
  // counted and described together below.
  std::vector<int> zero;
  for (int m = 0; m < basis.count(); ++m)
    if (basis.eigenvalues(m) <= 1e-9 * scale)
      zero.push_back(m);
  if (zero.empty())
    return "ill-conditioned stiffness (no exactly free motion found)";
  const Eigen::HouseholderQR<Matrix> qr(basis.shapes(Eigen::all, zero));
  const Matrix space = qr.householderQ() * Matrix::Identity(n, static_cast<DofIndex>(zero.size()));
  const Matrix rigid = rigidBodyModes(system);
  static const char* kRigidNames[6] = {
      "rigid-body translation along x", "rigid-body translation along y",
      "rigid-body translation along z", "rigid-body rotation about x",
      "rigid-body rotation about y",    "rigid-body rotation about z"};
  std::vector<int> free_rigid;
  for (int r = 0; r < 6; ++r) {
    const double norm = rigid.col(r).norm();
    if (norm == 0.0)
      continue;
    const Vector outside = rigid.col(r) - space * (space.transpose() * rigid.col(r));
    if (outside.norm() < 0.05 * norm)
      free_rigid.push_back(r);
  }
  // The free rigid motions' own span (on few DOFs some coincide, e.g. a single node's rotations).
  Matrix named(n, 0);
  if (!free_rigid.empty()) {
    const Eigen::ColPivHouseholderQR<Matrix> rq(rigid(Eigen::all, free_rigid));
    named = rq.householderQ() * Matrix::Identity(n, rq.rank());
  }
  int described = 0;
  for (const int r : free_rigid)
    out << (described++ ? "; " : "") << kRigidNames[r];
  // Mechanisms: the free space with the named rigid motions taken out. Its own basis is as
  // arbitrary as the eigen-solver's, so it is described as a whole: how many, and the DOFs that
  // move in it (row norms of its orthonormal basis, the larger ones).
  const Matrix rest = space - named * (named.transpose() * space);
  const Eigen::JacobiSVD<Matrix> svd(rest, Eigen::ComputeThinU);
  const Eigen::Index mechanisms = (svd.singularValues().array() > 0.5).count();  // ~1 when free
  if (mechanisms > 0) {
    const Vector moves = svd.matrixU().leftCols(mechanisms).rowwise().norm();
    std::vector<DofIndex> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](DofIndex a, DofIndex b) { return moves(a) > moves(b); });
    const double largest = moves(order[0]);
    std::size_t involved = 0;
    while (involved < order.size() && moves(order[involved]) >= 0.3 * largest)
      ++involved;
    const std::size_t shown = std::min<std::size_t>(involved, 8);
    out << (described++ ? "; " : "")
        << (mechanisms == 1 ? std::string("a mechanism")
                            : std::to_string(mechanisms) + " mechanisms")
        << " involving ";
    for (std::size_t i = 0; i < shown; ++i)
      out << (i ? ", " : "") << system.dofs.label(order[i]);
    if (involved > shown)
      out << " and " << involved - shown << " more DOFs";
  }
  // Every vector the solver returned was free: there may be more than it was asked for.
  if (static_cast<int>(zero.size()) == request.count && request.count < n)
    out << "; and perhaps more free motions (only the first " << request.count << " were sought)";
  return out.str();
}

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
