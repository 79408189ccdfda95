// Geometric (initial-stress) stiffness of members that carry a pre-load at rest: a tensioned
// member resists being turned (a taut string), a compressed one is destabilised by it (buckling).
// For a member of length L under axial force N (tension > 0) turned by a small angle theta about
// an axis across it, its end load does the work N L theta^2 / 2: the stiffness the matrices below
// add to the elastic K, K_total = K + K_G(N).
#pragma once

#include <vector>

#include "tracked_vehicle_dynamics/fem/model.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace fem {

/// Local geometric stiffness [12 x 12] of a beam of length L under axial force N, with the beam's
/// own shape functions (cubic Hermite bending, linear torsion), end moments neglected (McGuire,
/// Gallagher & Ziemian, Matrix Structural Analysis, 2nd ed., eq. 9.19):
///   bending  N / L [6/5, L/10, -6/5, L/10; L/10, 2L^2/15, -L/10, -L^2/30; ...] in each plane,
///   torsion  N I_p / (A L) [1, -1; -1, 1], I_p = I_y + I_z (the Wagner term),
/// and without McGuire's axial term N / L [1, -1; -1, 1] (beside EA / L it is round-off; the tie
/// has none either, so a rigid turn costs both the same N L).
Matrix12 beamLocalGeometricStiffness(const Section& section, double length, double axial_force);

/// The same in global coordinates, T^T k_G T (DOF order u1, theta1, u2, theta2).
Matrix12 beamGeometricStiffness(const Vector3& x1, const Vector3& x2, const Vector3& orientation,
                                const Section& section, double axial_force);

/// A tie's geometric stiffness (F / L) [P, -P; -P, P] on (u1, u2), P = I - e e^T, e = (x2 - x1) /
/// L; its rotations are zero (DOF order u1, theta1, u2, theta2).
Matrix12 tieGeometricStiffness(const Vector3& x1, const Vector3& x2, double force);

/// A rigid body's self-equilibrated pre-load (forces f_i at x_i) on its rotation about `centre`:
/// the second-order work of loads that turn with the body,
///   K = (sum f.r) I - (1/2) sum (f r^T + r f^T),  r = x_i - centre.
/// For a tensioned member held between two points of the body it is -N L (I - e e^T), the
/// opposite of the member's own stiffness to the same rigid rotation. Independent of `centre`
/// when the forces balance.
Matrix3 bodyPreloadStiffness(const Vector3& centre, const std::vector<Vector3>& points,
                             const std::vector<Vector3>& forces);

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
