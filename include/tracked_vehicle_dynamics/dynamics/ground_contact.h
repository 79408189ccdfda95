// The road inputs of a bonded linear model read as ground contacts: which coordinate each road
// input pushes on, through which spring and damper, so that the contact force can be recovered
// from a simulated response and checked for sign (the linear model ties every contact to the
// road; a real contact can only push).
//
// In a Craig-Bampton model the ground DOFs are masters (physical coordinates of x_R), and a
// ground spring k_i (damper c_i) between road input u_i and master m(i) enters as
//   K_u(:, i) = k_i e_m(i),   C_u(:, i) = c_i e_m(i)
// (the spring's other half, k_i e_m e_m^T, sits in K). The force the road exerts on the vehicle
// through contact i, compression positive (the ground pushes up), is then
//   F_i = k_i (u_i - q_m(i)) + c_i (u_i' - q_m(i)')                                       [N]
// in total displacements: a simulation started from static equilibrium under gravity
// (static_equilibrium.h) carries the static load in F_i, and at rest sum_i F_i = m g.
// F_i < 0 means the road pulls the vehicle down: beyond the bonded model's range, a real
// vehicle would lift off there.
#pragma once

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/dynamics/second_order_system.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// Which side of the vehicle a contact is on, from its lateral position (y left).
enum class ContactSide {
  Left,    ///< y > 0
  Right,   ///< y < 0
  Centre,  ///< y = 0 (counted on neither side)
};

/// "left", "right" or "centre".
const char* contactSideName(ContactSide side);

/// One road input acting on one coordinate through a spring (and damper) to the road.
struct GroundContact {
  DofIndex input = 0;       ///< road input i (column of K_u, C_u)
  DofIndex coordinate = 0;  ///< m(i): the coordinate of q the spring acts on
  double stiffness = 0.0;   ///< k_i [N/m], > 0
  double damping = 0.0;     ///< c_i [N s/m], >= 0 (0 when C_u(:, i) is zero)
  double lateral = 0.0;     ///< y of the input [m] (SecondOrderSystem::input_lateral; 0 if absent)
  ContactSide side = ContactSide::Centre;
  /// The rigid part the contact belongs to (a vehicle's pad, i.e. track assembly, whose soles
  /// are its contacts), -1 for none: groundContacts() leaves it to the caller. A pad's soles
  /// also carry its moments as opposite forces, so a sole can pull while its pad as a whole
  /// still presses (the pad would rock onto an edge); the pad's total pulling means the whole
  /// pad would leave the road.
  int group = -1;
};

/// The contacts of the first `road_inputs` inputs of `system` (all when < 0; a travel-inertia
/// system's extra input is not a contact), one per input, in input order. Verifies the structure
/// above rather than assuming it. Throws InputError naming the input when a column of K_u has
/// no non-zero or more than one, or a non-positive one; when C_u's column has a non-zero off
/// the coordinate of K_u's, or a negative one; or when road_inputs exceeds the inputs.
std::vector<GroundContact> groundContacts(const SecondOrderSystem& system,
                                          DofIndex road_inputs = -1);

/// F_i = k_i (u_i - q_m(i)) + c_i (u_i' - q_m(i)') of every contact into `forces` [n_contacts]
/// [N], for a state z = [q; q'] [2n] and input w = [u; u'] [2 input_count] (u_i at w(i), u_i'
/// at w(input_count + i)). No allocation. Throws InputError, naming `where`, when z or w is too
/// short for a contact or `forces` has the wrong length.
void contactForces(const std::vector<GroundContact>& contacts,
                   const Eigen::Ref<const Vector>& state, const Eigen::Ref<const Vector>& input,
                   DofIndex input_count, Eigen::Ref<Vector> forces, const char* where);

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
