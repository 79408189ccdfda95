// Damping that holds the ground contacts to an inertial frame, and when it shows in their forces.
//
// A bonded model ties each contact coordinate m(i) to the road by a stiff spring k_i
// (ground_contact.h; the bundled vehicles: 2e10 N/m). Each tie makes one mode of its own, the
// contact mass on its spring (about 9 to 58 kHz on the bundled vehicles, far above the ride band).
// A damping that acts on absolute velocities (modal damping, eq. 20, or the mass-proportional part
// of Rayleigh damping) damps these modes too, i.e. it puts a damper between every contact and an
// inertial frame. When such a mode is integrated dynamically (the exact method, or a modal cut-off
// above it), the road has to drive that damper at the road's own vertical speed, so the contact
// force F_i = k_i (u_i - q_m(i)) carries a damping force, about 2 zeta sqrt(k_i m_i) u_i', that
// no road exerts, while the bodies' motions barely change. Kept quasi-static (the modal method's
// default cut-off, the Nyquist frequency of the step), the tie modes carry no damping force.
// Only stiff ties are judged: a ground spring at least kStiffTieRatio times stiffer than what
// the rest of the model puts on its coordinate, K_mm - k_m, is a penalty standing for a rigid
// contact (the bundled soles: 2e10 N/m against about 3e6 N/m of pad rubber), whose mode no
// vehicle has. A compliant tie (a tyre: a few times its suspension) makes a ride mode, the wheel
// hop, and its damping is the model's choice, whatever the step.
//
// The absolute damping of each contact: when the whole model and its road move together as a
// rigid body, vertically at unit speed, relative dampers (C proportional to K, the ground dampers
// C_u, the arm dampers) do nothing, and what remains on the contact's coordinate,
//   f = C r - C_u 1,   K r = K_u 1   (the static response to a uniform lift of the road: r is
//                                      the rigid motion, 1 on every coordinate that moves with it)
// is the damping to the inertial frame. As a ratio of the tie's critical damping:
//   zeta_abs,i = |f_m(i)| / (2 sqrt(k_m(i) M_m(i)m(i)))
// with k_m the ground stiffness on the coordinate (the sum of its contacts' k_i)
// (modal damping zeta gives about zeta, a mass-proportional alpha M gives alpha / (2 omega_tie),
// stiffness-proportional damping 0).
//
// A tie mode: a mode r (K phi_r = omega_r^2 M phi_r, phi_r^T M phi_r = 1) whose strain energy
// lies mostly in the ground springs, sum_i k_i phi_r(m(i))^2 > omega_r^2 / 2 (the bundled
// vehicles: one per contact, each with more than 99.99 % of its energy there, every other mode
// with less than 0.02 %).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "tracked_vehicle_dynamics/dynamics/ground_contact.h"
#include "tracked_vehicle_dynamics/dynamics/modal_system.h"
#include "tracked_vehicle_dynamics/dynamics/second_order_system.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// A stiff tie: k_m >= kStiffTieRatio (K_mm - k_m) (above).
constexpr double kStiffTieRatio = 100.0;

/// The absolute damping ratio zeta_abs,i of each contact (above), in contact order [-].
/// `contacts` from groundContacts(system). Throws InputError for an invalid system or a contact
/// outside it, SolverError when K is singular (a model not held by its ground springs alone:
/// then a uniform lift of the road is no rigid motion, and no ratio is defined).
Vector absoluteContactDamping(const SecondOrderSystem& system,
                              const std::vector<GroundContact>& contacts);

/// The contacts of `contacts` whose coordinate is tied stiffly (kStiffTieRatio) in `system`.
std::vector<GroundContact> stiffTies(const SecondOrderSystem& system,
                                     const std::vector<GroundContact>& contacts);

/// The frequencies [Hz] of the lowest and the highest tie mode among `modal`'s modes (above),
/// both +infinity when there is none. `modal` is the decomposition of the system `contacts`
/// belong to.
std::pair<double, double> groundTieModeRangeHz(const ModalSystem& modal,
                                               const std::vector<GroundContact>& contacts);

/// Absolute damping below this ratio of a tie's critical damping is not worth a word: its force
/// is under 0.1 % of what 2 sqrt(k m) u' would be.
constexpr double kNegligibleTieDamping = 1e-3;

/// The warning for a run whose stiff ties' modes are (some of them) dynamic and damped to an
/// inertial frame, "" when they are not. `modal`: the run's decomposition, whose modes up to
/// `max_dynamic_hz` are dynamic (<= 0: all of them, as SimulatorOptions'
/// max_mode_frequency_hz); nullptr for a method that integrates every mode (exact), whose tie
/// modes are then found by a decomposition made here, only when the damping holds a stiff tie
/// (a dense eigen-solve: 0.1-0.3 s on the tracked model, beside the exact method's seconds).
/// `how` names what makes them dynamic for the user ("--method exact", ...), `instead` what
/// keeps them quasi-static. Throws as absoluteContactDamping and ModalSystem.
std::string groundTieDampingWarning(const SecondOrderSystem& system,
                                    const std::vector<GroundContact>& contacts,
                                    const ModalSystem* modal, double max_dynamic_hz,
                                    const std::string& how, const std::string& instead);

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
