// Six-component spring/damper (bushing) between two nodes, or between a node and the ground.
//
// The bushing acts at a point p (the midpoint of its nodes). Each node's motion is carried to p
// by a rigid offset, u_p = u_i + theta_i x (p - x_i), so a rigid-body motion of both nodes gives
// no relative displacement and no force, even when the nodes do not coincide:
//   d = G_2 q_2 - G_1 q_1,   G_i = [I  -[p - x_i]x ; 0  I]
//   K_e = B^T K_p B,  B = [-G_1  G_2],  K_p = diag(F diag(k_t) F^T, F diag(k_r) F^T)
// with F the local frame (columns = local axes).
#pragma once

#include "tracked_vehicle_dynamics/fem/model.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace fem {

/// Element matrices of a two-node bushing, DOF order (q_1, q_2).
struct SpringMatrices {
  Matrix12 stiffness;
  Matrix12 damping;
};

/// Element matrices of a grounded bushing (q_1 only) and its road-input columns: the ground point
/// moves vertically by u, and the force on the node is -K (q - g u), g the unit vertical motion
/// of the ground at p, hence K_u = G_1^T K_p g and C_u = G_1^T C_p g.
struct GroundSpringMatrices {
  Matrix6 stiffness;
  Matrix6 damping;
  Vector6 input_stiffness;
  Vector6 input_damping;
};

/// 6x6 bushing stiffness (or damping) at its point, in global axes.
Matrix6 bushingMatrix(const Vector6& values, const Matrix3& frame);

/// Rigid offset G = [I -[r]x ; 0 I] carrying node motion to a point at node + r.
Matrix6 rigidOffset(const Vector3& r);

SpringMatrices springMatrices(const Spring& spring, const Vector3& x1, const Vector3& x2);

GroundSpringMatrices groundSpringMatrices(const Spring& spring, const Vector3& x1);

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
