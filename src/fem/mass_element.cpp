#include "tracked_vehicle_dynamics/fem/mass_element.h"

namespace tracked_vehicle_dynamics {
namespace fem {

Matrix6 rigidBodyMass(const Mass& item) {
  const Vector3& r = item.offset;
  Matrix3 s;
  s << 0, -r.z(), r.y(), r.z(), 0, -r.x(), -r.y(), r.x(), 0;
  Eigen::Matrix<double, 3, 6> l;
  l.leftCols<3>() = Matrix3::Identity();
  l.rightCols<3>() = -s;
  Matrix6 m = item.mass * l.transpose() * l;
  m.bottomRightCorner<3, 3>() += item.inertia;
  return m;
}

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
