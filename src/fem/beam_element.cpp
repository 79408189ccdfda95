#include "tracked_vehicle_dynamics/fem/beam_element.h"

#include <cmath>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace fem {

namespace {
// Local DOF indices: node a at 0..5, node b at 6..11; (ux uy uz rx ry rz).
constexpr int kUx = 0, kUy = 1, kUz = 2, kRx = 3, kRy = 4, kRz = 5;

// Writes a 4x4 bending block onto DOFs (v1, t1, v2, t2).
void addBlock(Matrix12& m, const int (&dofs)[4], const Eigen::Matrix4d& block) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      m(dofs[i], dofs[j]) += block(i, j);
}

double shearParameter(double ei, double kappa, const Material& mat, const Section& sec,
                      double length) {
  if (kappa <= 0.0)
    return 0.0;  // Euler-Bernoulli
  return 12.0 * ei / (kappa * mat.shear_modulus * sec.area * length * length);
}
}  // namespace

Matrix3 beamLocalAxes(const Vector3& x1, const Vector3& x2, const Vector3& orientation) {
  const Vector3 axis = x2 - x1;
  const double length = axis.norm();
  if (!(length > 0.0))
    throw InputError("beam has zero length");
  const Vector3 ex = axis / length;
  const Vector3 z_raw = orientation - orientation.dot(ex) * ex;
  if (z_raw.norm() <= 1e-9 * orientation.norm() || orientation.norm() == 0.0)
    throw InputError("beam orientation vector is parallel to the beam axis");
  const Vector3 ez = z_raw.normalized();
  const Vector3 ey = ez.cross(ex);
  Matrix3 r;
  r.row(0) = ex;
  r.row(1) = ey;
  r.row(2) = ez;
  return r;
}

Matrix12 beamLocalStiffness(const Material& mat, const Section& sec, double length) {
  const double l = length, l2 = l * l, l3 = l2 * l;
  const double e = mat.young_modulus;
  Matrix12 k = Matrix12::Zero();

  const double ea = e * sec.area / l;
  k(kUx, kUx) = k(6 + kUx, 6 + kUx) = ea;
  k(kUx, 6 + kUx) = k(6 + kUx, kUx) = -ea;
  const double gj = mat.shear_modulus * sec.torsion / l;
  k(kRx, kRx) = k(6 + kRx, 6 + kRx) = gj;
  k(kRx, 6 + kRx) = k(6 + kRx, kRx) = -gj;

  // Bending in the local x-y plane (uy, rz) about z: EI_z; shear along y.
  {
    const double phi = shearParameter(e * sec.iz, sec.shear_factor_y, mat, sec, l);
    const double c = e * sec.iz / (l3 * (1.0 + phi));
    Eigen::Matrix4d b;
    b << 12, 6 * l, -12, 6 * l, 6 * l, (4 + phi) * l2, -6 * l, (2 - phi) * l2, -12, -6 * l, 12,
        -6 * l, 6 * l, (2 - phi) * l2, -6 * l, (4 + phi) * l2;
    const int dofs[4] = {kUy, kRz, 6 + kUy, 6 + kRz};
    addBlock(k, dofs, c * b);
  }
  // Bending in the local x-z plane (uz, ry) about y: EI_y; a positive ry lowers uz ahead.
  {
    const double phi = shearParameter(e * sec.iy, sec.shear_factor_z, mat, sec, l);
    const double c = e * sec.iy / (l3 * (1.0 + phi));
    Eigen::Matrix4d b;
    b << 12, -6 * l, -12, -6 * l, -6 * l, (4 + phi) * l2, 6 * l, (2 - phi) * l2, -12, 6 * l, 12,
        6 * l, -6 * l, (2 - phi) * l2, 6 * l, (4 + phi) * l2;
    const int dofs[4] = {kUz, kRy, 6 + kUz, 6 + kRy};
    addBlock(k, dofs, c * b);
  }
  return k;
}

Matrix12 beamLocalMass(const Material& mat, const Section& sec, double length) {
  const double l = length, l2 = l * l;
  const double m = mat.density * sec.area * l;
  Matrix12 mm = Matrix12::Zero();

  mm(kUx, kUx) = mm(6 + kUx, 6 + kUx) = m / 3.0;
  mm(kUx, 6 + kUx) = mm(6 + kUx, kUx) = m / 6.0;
  const double jp = mat.density * (sec.iy + sec.iz) * l;  // polar mass moment per element
  mm(kRx, kRx) = mm(6 + kRx, 6 + kRx) = jp / 3.0;
  mm(kRx, 6 + kRx) = mm(6 + kRx, kRx) = jp / 6.0;

  const double c = m / 420.0;
  {
    Eigen::Matrix4d b;
    b << 156, 22 * l, 54, -13 * l, 22 * l, 4 * l2, 13 * l, -3 * l2, 54, 13 * l, 156, -22 * l,
        -13 * l, -3 * l2, -22 * l, 4 * l2;
    const int dofs[4] = {kUy, kRz, 6 + kUy, 6 + kRz};
    addBlock(mm, dofs, c * b);
  }
  {
    Eigen::Matrix4d b;
    b << 156, -22 * l, 54, 13 * l, -22 * l, 4 * l2, -13 * l, -3 * l2, 54, -13 * l, 156, 22 * l,
        13 * l, -3 * l2, 22 * l, 4 * l2;
    const int dofs[4] = {kUz, kRy, 6 + kUz, 6 + kRy};
    addBlock(mm, dofs, c * b);
  }
  return mm;
}

BeamMatrices beamMatrices(const Vector3& x1, const Vector3& x2, const Vector3& orientation,
                          const Material& material, const Section& section) {
  const Matrix3 r = beamLocalAxes(x1, x2, orientation);
  const double length = (x2 - x1).norm();
  Matrix12 t = Matrix12::Zero();
  for (int b = 0; b < 4; ++b)
    t.block<3, 3>(3 * b, 3 * b) = r;
  BeamMatrices out;
  out.stiffness = t.transpose() * beamLocalStiffness(material, section, length) * t;
  out.mass = t.transpose() * beamLocalMass(material, section, length) * t;
  return out;
}

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
