#include "tracked_vehicle_dynamics/fem/free_motion.h"

#include <algorithm>
#include <numeric>
#include <sstream>

#include "tracked_vehicle_dynamics/fem/modal_solver.h"

namespace tracked_vehicle_dynamics {
namespace fem {

Matrix rigidBodyModes(const System& system) {
  const DofMap& dofs = system.dofs;
  const DofIndex n = dofs.activeCount();
  Vector3 centroid = Vector3::Zero();
  for (DofIndex i = 0; i < n; ++i) centroid += dofs.positionOf(i);
  if (n > 0) centroid /= static_cast<double>(n);
  Matrix modes = Matrix::Zero(n, 6);
  for (DofIndex i = 0; i < n; ++i) {
    const DofRef d = dofs.dofOf(i);
    const Vector3 r = dofs.positionOf(i) - centroid;
    if (d.direction < 3) {
      modes(i, d.direction) = 1.0;
      // translation of the node under a unit rotation theta about axis a: (e_a x r)_d
      for (int a = 0; a < 3; ++a) modes(i, 3 + a) = Vector3::Unit(a).cross(r)(d.direction);
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
  const double scale = system.stiffness.diagonal().cwiseAbs().maxCoeff();
  ModalRequest request;
  request.count = static_cast<int>(std::min<DofIndex>(6, n));
  request.shift = -1e-8 * scale;
  std::ostringstream out;
  ModalBasis basis;
  try {
    basis = solveModes(system.stiffness, identity, request);
  } catch (const std::exception&) {
    return "could not isolate the free motion";
  }
  const Matrix rigid = rigidBodyModes(system);
  static const char* kRigidNames[6] = {"rigid-body translation along x",
                                       "rigid-body translation along y",
                                       "rigid-body translation along z",
                                       "rigid-body rotation about x",
                                       "rigid-body rotation about y",
                                       "rigid-body rotation about z"};
  int described = 0;
  for (int m = 0; m < basis.count(); ++m) {
    if (basis.eigenvalues(m) > 1e-9 * scale) continue;
    const Vector phi = basis.shapes.col(m);
    if (described++ > 0) out << "; ";
    // Name it a rigid-body motion when it is (almost) one of the six, by MAC.
    int best = -1;
    double best_mac = 0.0;
    for (int r = 0; r < 6; ++r) {
      const double norm = rigid.col(r).squaredNorm();
      if (norm == 0.0) continue;
      const double dot = rigid.col(r).dot(phi);
      const double mac = dot * dot / (norm * phi.squaredNorm());
      if (mac > best_mac) {
        best_mac = mac;
        best = r;
      }
    }
    if (best >= 0 && best_mac > 0.9) {
      out << kRigidNames[best];
    } else {
      std::vector<DofIndex> order(n);
      std::iota(order.begin(), order.end(), 0);
      const int shown = static_cast<int>(std::min<DofIndex>(4, n));
      std::partial_sort(order.begin(), order.begin() + shown, order.end(),
                        [&](DofIndex a, DofIndex b) { return std::abs(phi(a)) > std::abs(phi(b)); });
      out << "mechanism involving ";
      for (int i = 0; i < shown; ++i) out << (i ? ", " : "") << system.dofs.label(order[i]);
    }
  }
  if (described == 0) return "ill-conditioned stiffness (no exactly free motion found)";
  return out.str();
}

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
