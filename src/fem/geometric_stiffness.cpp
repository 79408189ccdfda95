#include "tracked_vehicle_dynamics/fem/geometric_stiffness.h"

#include "tracked_vehicle_dynamics/fem/beam_element.h"

namespace tracked_vehicle_dynamics {
namespace fem {

namespace {

/// T^T k T with T = diag(R, R, R, R), R's rows the local axes.
Matrix12 toGlobal(const Matrix3& r, const Matrix12& local) {
  Matrix12 t = Matrix12::Zero();
  for (int b = 0; b < 4; ++b)
    t.block<3, 3>(3 * b, 3 * b) = r;
  return t.transpose() * local * t;
}

}  // namespace

Matrix12 beamLocalGeometricStiffness(const Section& section, double length, double axial_force) {
  const double l = length, n = axial_force / length;
  Matrix12 k = Matrix12::Zero();
  // DOF order: 0 u1, 1 v1, 2 w1, 3 rx1, 4 ry1, 5 rz1, 6 u2, 7 v2, 8 w2, 9 rx2, 10 ry2, 11 rz2.
  // Bending in the x-y plane (v, rz) and in the x-z plane (w, ry, whose rotation is -dw/dx).
  const int v[2] = {1, 7}, rz[2] = {5, 11}, w[2] = {2, 8}, ry[2] = {4, 10};
  auto plane = [&](const int(&d)[2], const int(&r)[2], double sign) {
    const double a = 6.0 / 5.0, b = sign * l / 10.0, c = 2.0 * l * l / 15.0, e = -l * l / 30.0;
    const int idx[4] = {d[0], r[0], d[1], r[1]};
    const double m[4][4] = {{a, b, -a, b}, {b, c, -b, e}, {-a, -b, a, -b}, {b, e, -b, c}};
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        k(idx[i], idx[j]) += n * m[i][j];
  };
  plane(v, rz, 1.0);
  plane(w, ry, -1.0);
  const double torsion = n * (section.iy + section.iz) / section.area;
  k(3, 3) += torsion;
  k(9, 9) += torsion;
  k(3, 9) -= torsion;
  k(9, 3) -= torsion;
  return k;
}

Matrix12 beamGeometricStiffness(const Vector3& x1, const Vector3& x2, const Vector3& orientation,
                                const Section& section, double axial_force) {
  return toGlobal(beamLocalAxes(x1, x2, orientation),
                  beamLocalGeometricStiffness(section, (x2 - x1).norm(), axial_force));
}

Matrix12 tieGeometricStiffness(const Vector3& x1, const Vector3& x2, double force) {
  const Vector3 d = x2 - x1;
  const double l = d.norm();
  const Vector3 e = d / l;
  const Matrix3 p = (force / l) * (Matrix3::Identity() - e * e.transpose());
  Matrix12 k = Matrix12::Zero();
  k.block<3, 3>(0, 0) = p;
  k.block<3, 3>(6, 6) = p;
  k.block<3, 3>(0, 6) = -p;
  k.block<3, 3>(6, 0) = -p;
  return k;
}

Matrix3 bodyPreloadStiffness(const Vector3& centre, const std::vector<Vector3>& points,
                             const std::vector<Vector3>& forces) {
  // The body carries its pre-load as an internal stress path between the points. Turned rigidly
  // by theta, a point moves u = theta x r + theta x (theta x r) / 2 to second order, and that
  // stress does the work of the loads held at their directions: the potential
  // -(1/2) sum f . (theta (theta . r) - r |theta|^2) = (1/2) theta^T K theta gives K.
  Matrix3 k = Matrix3::Zero();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vector3 r = points[i] - centre;
    const Vector3& f = forces[i];
    k += f.dot(r) * Matrix3::Identity() - 0.5 * (f * r.transpose() + r * f.transpose());
  }
  return k;
}

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
