#include "tracked_vehicle_dynamics/fem/spring_element.h"

namespace tracked_vehicle_dynamics {
namespace fem {

namespace {
Matrix3 skew(const Vector3& r) {
  Matrix3 s;
  s << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
  return s;
}
}  // namespace

Matrix6 bushingMatrix(const Vector6& values, const Matrix3& frame) {
  Matrix6 k = Matrix6::Zero();
  k.topLeftCorner<3, 3>() = frame * values.head<3>().asDiagonal() * frame.transpose();
  k.bottomRightCorner<3, 3>() = frame * values.tail<3>().asDiagonal() * frame.transpose();
  return k;
}

Matrix6 rigidOffset(const Vector3& r) {
  Matrix6 g = Matrix6::Identity();
  g.topRightCorner<3, 3>() = -skew(r);
  return g;
}

SpringMatrices springMatrices(const Spring& spring, const Vector3& x1, const Vector3& x2) {
  const Vector3 p = 0.5 * (x1 + x2);
  Eigen::Matrix<double, 6, 12> b;
  b.leftCols<6>() = -rigidOffset(p - x1);
  b.rightCols<6>() = rigidOffset(p - x2);
  SpringMatrices out;
  out.stiffness = b.transpose() * bushingMatrix(spring.stiffness, spring.frame) * b;
  out.damping = b.transpose() * bushingMatrix(spring.damping, spring.frame) * b;
  return out;
}

GroundSpringMatrices groundSpringMatrices(const Spring& spring, const Vector3& /*x1*/) {
  // The grounded bushing acts at its node, so G_1 = I.
  const Matrix6 kp = bushingMatrix(spring.stiffness, spring.frame);
  const Matrix6 cp = bushingMatrix(spring.damping, spring.frame);
  Vector6 g = Vector6::Zero();
  g(2) = 1.0;  // the ground moves along global z
  GroundSpringMatrices out;
  out.stiffness = kp;
  out.damping = cp;
  out.input_stiffness = kp * g;
  out.input_damping = cp * g;
  return out;
}

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
