// 3-D two-node beam element: Euler-Bernoulli or Timoshenko stiffness, consistent mass.
#pragma once

#include "tracked_vehicle_dynamics/fem/model.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace fem {

/// Element matrices in global coordinates, DOF order (u1, theta1, u2, theta2).
struct BeamMatrices {
  Matrix12 stiffness;
  Matrix12 mass;
};

/// Rotation whose rows are the beam's local axes in global coordinates: x along n1 -> n2, z in the
/// plane of x and `orientation`, y = z x x. Throws InputError if the axis and orientation are
/// parallel or the length is zero.
Matrix3 beamLocalAxes(const Vector3& x1, const Vector3& x2, const Vector3& orientation);

/// Local stiffness [12 x 12] of a beam of length L [m]. Bending uses the Timoshenko shear
/// parameter Phi = 12 E I / (kappa G A L^2) (Przemieniecki), which is 0 for Euler-Bernoulli.
Matrix12 beamLocalStiffness(const Material& material, const Section& section, double length);

/// Local consistent mass [12 x 12]: linear shape functions for axial and torsion (polar inertia
/// rho (Iy + Iz) L), cubic Hermite for bending (rho A L / 420 [156 22L 54 -13L ...]).
Matrix12 beamLocalMass(const Material& material, const Section& section, double length);

/// Global element matrices T^T k T with T = diag(R, R, R, R).
BeamMatrices beamMatrices(const Vector3& x1, const Vector3& x2, const Vector3& orientation,
                          const Material& material, const Section& section);

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
