// The travel inertia of a vehicle whose speed changes, as one more input of its model.
//
// The model is written in the path frame, which translates with the station s(t). When the speed
// changes, the frame accelerates at a(t) = dv/dt and every mass feels the inertial load -m a along
// x (d'Alembert); assembled consistently, the load on the model is a(t) f_a with
// f_a = -T^T M e_x per unit a (fem::System::travel_load, reduced like gravity). Braking (a < 0)
// pushes the hull forward against the pads' shear springs and pitches it nose down (REP-103:
// positive rotation about +y, y left).
//
// Rather than a second kind of load in the simulator, a(t) rides as one more road-input entry:
//   M q'' + C q' + K q = [K_u, f_a] [u; a] + [C_u, 0] [u'; a']
// so every engine of the Simulator (modal, quasi-static, held input) and the static equilibrium
// take it unchanged. The input vector w = [u; u'] becomes [u; a; u'; 0] (the rate entry of the
// travel input carries no load: C_u' = [C_u, 0]). The road is still sampled with the ORIGINAL
// system's input_stations/input_lateral: the augmented ones hold one more entry (0) for the
// travel input, which reads no road.
#pragma once

#include "tracked_vehicle_dynamics/dynamics/second_order_system.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// `system` with the travel input appended: K_u' = [K_u, travel_load], C_u' = [C_u, 0],
/// input_stations/input_lateral with one more 0 (when they are given). travel_load [n] is the
/// generalized load per unit forward acceleration [N, N m per m/s^2]. Throws InputError when its
/// length is not the system's size or it has a non-finite entry.
SecondOrderSystem withTravelInertia(const SecondOrderSystem& system, const Vector& travel_load);

/// Input rows [u, u'] [n_samples x 2 n_u] widened to [u, a, u', 0] [n_samples x 2 (n_u + 1)] with
/// the travel acceleration a [n_samples] [m/s^2] of each row. Throws InputError for an odd
/// column count or a length mismatch.
Matrix withTravelInput(const Matrix& inputs, const Vector& acceleration);

/// One input vector w = [u; u'] [2 n_u] widened to [u; a; u'; 0] into `widened`, which must hold
/// 2 (n_u + 1) entries (no allocation: for a real-time loop). Throws InputError for a size
/// mismatch.
void widenTravelInput(const Eigen::Ref<const Vector>& inputs, double acceleration,
                      Eigen::Ref<Vector> widened);

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
