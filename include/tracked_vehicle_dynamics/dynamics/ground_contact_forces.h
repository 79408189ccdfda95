// The ground contact forces of a simulated run (ground_contact.h):
//   F_i = k_i (u_i - q_m(i)) + c_i (u_i' - q_m(i)')                                       [N]
// from the same inputs and initial state as the run's own Simulator.
//
// Why a Simulator of its own: the forces need q_m, q_m' of every contact (the tracked vehicle:
// 360 of them), which are not among the physical outputs H. Rows added to H would get every
// quantity the run reports (displacement, velocity and acceleration: three times the rows) and
// would change the arithmetic of the run's own outputs (the blocked products depend on the
// number of rows), so its columns would no longer be bit-identical to a run without the monitor.
// A second Simulator on the same system and options, whose outputs are only the contacts'
// coordinates (displacements, and velocities where some c_i != 0), gives q_m exactly as the run
// computes them (the same modes, the same quasi-static treatment of truncated ones; with
// truncation, q' of the quasi-static part lacks the C_u u'' term, as the run's velocities do),
// at the cost of one more modal recursion and its own input terms (and, unless it is handed the
// run's ModalSystem, one more eigen-solve).
#pragma once

#include <functional>
#include <vector>

#include "tracked_vehicle_dynamics/dynamics/ground_contact.h"
#include "tracked_vehicle_dynamics/dynamics/held_input_series.h"
#include "tracked_vehicle_dynamics/dynamics/second_order_system.h"
#include "tracked_vehicle_dynamics/dynamics/simulator.h"
#include "tracked_vehicle_dynamics/dynamics/state_space.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

class GroundContactForces {
 public:
  /// Receives the forces of consecutive samples: rows [count x n_contacts] [N] for samples
  /// first .. first + count - 1 of the series.
  using Sink = std::function<void(long first, const Eigen::Ref<const Matrix>& forces)>;

  /// `system` is the run's (it may carry inputs that are no contacts, e.g. the travel input);
  /// `contacts` from groundContacts() (inputs and coordinates within `system`); `options` the
  /// run's Simulator options (its output quantities are replaced). Throws InputError for an
  /// empty contact list or a contact outside the system, and whatever Simulator throws.
  /// `modal`, when given, is the run's decomposition, ModalSystem(system, ratios), with
  /// options.method ModalDecoupled and options.modal_damping_ratios empty (ratios belong to the
  /// ModalSystem): the forces' Simulator then steps the same modes without decomposing the
  /// system again (the tracked vehicle: 431 DOFs, about a third of `tvd simulate`'s set-up).
  GroundContactForces(const SecondOrderSystem& system, std::vector<GroundContact> contacts,
                      SimulatorOptions options, const ModalSystem* modal = nullptr);
  /// The same on the run's exact discretisation, `discrete` = exactDiscretization(system,
  /// options) (method AugmentedExponential): the forces' Simulator steps its Phi and Gamma with the
  /// contacts' outputs (the state is the continuous one, so only the output equation differs)
  /// instead of computing the augmented exponential again (about 10 s on the tracked vehicle).
  /// Throws InputError as above, and when `discrete` is continuous or its sizes are not the
  /// system's.
  GroundContactForces(const SecondOrderSystem& system, std::vector<GroundContact> contacts,
                      SimulatorOptions options, const StateSpace& discrete);

  /// As Simulator::reset(state, input): z0 [2n], w0 [2 n_inputs].
  void reset(const Vector& state, const Vector& input);
  /// Runs the input series from the current state (as Simulator::simulate: row 0 replaces the
  /// current input) and hands the forces of every sample, row 0 included, to `sink`, in chunks
  /// of kChunk samples: the forces of a long run (the tracked vehicle: 360 per sample) then stay
  /// in cache instead of filling a fresh [samples x contacts] matrix. Throws InputError for a
  /// wrong input count or an invalid series.
  void simulate(const Matrix& inputs, const Sink& sink);
  void simulate(const HeldInputSeries& inputs, const Sink& sink);
  /// The same, all forces at once: F [n_samples x n_contacts] [N].
  Matrix simulate(const Matrix& inputs);
  Matrix simulate(const HeldInputSeries& inputs);
  /// F [n_contacts] [N] for a state z = [q; q'] [2n] and input w [2 n_inputs], e.g. a static
  /// equilibrium. Throws InputError for wrong lengths.
  Vector forces(const Vector& state, const Vector& input) const;

  const std::vector<GroundContact>& contacts() const { return contacts_; }
  DofIndex contactCount() const { return static_cast<DofIndex>(contacts_.size()); }

  /// Samples per chunk handed to a Sink.
  static constexpr long kChunk = 512;

 private:
  /// forces = K (u - q) + C (u' - q') in place: on entry forces(k, i) = u_i (and the next n_c
  /// columns u_i' when damped), `coordinates` the simulated q (then q').
  void subtractCoordinates(const Matrix& coordinates, Matrix& forces) const;

  std::vector<GroundContact> contacts_;
  Simulator sim_;
  DofIndex n_u_ = 0;
  bool damped_ = false;  ///< some c_i != 0: velocities are simulated too
  Matrix forces_;        ///< the chunk's forces (reused)
};

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
