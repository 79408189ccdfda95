// Lumped mass / rigid body attached to a node with its centre of gravity at node + r.
//
// The centre-of-gravity velocity is v_c = v - [r]x omega = L qdot with L = [I  -[r]x], so
//   M_e = m L^T L + diag(0, J_c)
// and the gravity load is f = M_e a_rigid = m L^T g = [m g ; r x m g].
#pragma once

#include "tracked_vehicle_dynamics/fem/model.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace fem {

/// 6x6 mass matrix of a rigid body about its reference node (global axes).
Matrix6 rigidBodyMass(const Mass& mass);

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
