// Fixed-step time simulation of a linear model with an exact discretisation (paper §4.2: the
// state-space approach on the reduced model).
//
// Time convention: the simulator sits at a sample t_k with state z_k and input w_k (w = [u; u']).
// step(w_{k+1}) advances to t_{k+1}:
//   zero-order hold:  z_{k+1} = Phi z_k + Gamma w_k + f_d            (w_k held over the step)
//   first-order hold: z_{k+1} = Phi z_k + Gamma0 w_k + Gamma1 w_{k+1} + f_d
// and then evaluates the outputs at t_{k+1}: y_{k+1} = C z_{k+1} + D w_{k+1} + y0.
// So a fixed-rate loop passes the input sampled at the new time, for both holds.
//
// Two interchangeable engines (DiscretizationMethod):
//   AugmentedExponential: dense Phi [2n x 2n] from discretize(); O(n^2) per step; any C.
//   ModalDecoupled: q = Phi eta with mass-normalised modes; each mode an exact 2x2 discrete
//     system (discrete_modes.h), modal forces p = Phi^T (K_u u + C_u u' + f_g) and outputs
//     H Phi eta; O(n (n_w + n_y)) per step, less where few inputs change from one sample to the
//     next (road inputs on flat terrain): the input terms are then updated by the changed inputs'
//     columns only, exactly (modal_engine.cpp). Exact for proportional damping. Damping that
//     couples the modes (discrete dampers) is kept whole among the dynamic modes, which are then
//     stepped together by the exact discretisation of their coupled block, O(n^2) per step
//     (modal_engine.cpp); given modal_damping_ratios, each mode keeps its own
//     (maxOffDiagonalDampingRatio() reports the coupling that drops).
//     Optionally truncated (max_mode_frequency_hz): modes above the cut-off respond
//     quasi-statically (the mode-acceleration method),
//       q = Phi_k eta_k + Phi_t Omega_t^-2 Phi_t^T f(t),   f = K_u u + C_u u' + f_g,
//     so statics stay exact and only their inertia is dropped. A step of h cannot represent
//     motion above the Nyquist frequency 1/(2h) anyway; the stiff contact modes of a vehicle
//     (k_w = 2e10 N/m: kHz) are most of the modes, so this divides the per-step work.
// step() allocates no memory.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/dynamics/held_input_series.h"
#include "tracked_vehicle_dynamics/dynamics/modal_system.h"
#include "tracked_vehicle_dynamics/dynamics/output_layout.h"
#include "tracked_vehicle_dynamics/dynamics/second_order_system.h"
#include "tracked_vehicle_dynamics/dynamics/state_space.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// How a SecondOrderSystem is turned into a discrete-time stepper.
enum class DiscretizationMethod {
  /// exp([A B; 0 0] h) on the full first-order system (Van Loan); exact for any damping.
  AugmentedExponential,
  /// Exact 2x2 discretisation per mode; exact for proportional/modal damping, approximate
  /// (modal damping zeta_r = phi_r^T C phi_r / (2 omega_r)) otherwise. Much faster per step.
  ModalDecoupled,
};

/// "exact" (AugmentedExponential) or "modal" (ModalDecoupled): the method's name in command-line
/// options, node parameters and reports.
const char* methodName(DiscretizationMethod method);
/// The method named by methodName()'s text; nullopt for any other text.
std::optional<DiscretizationMethod> methodFromName(const std::string& name);

struct SimulatorOptions {
  double time_step = 1e-3;  ///< h [s]
  InputHold hold = InputHold::ZeroOrder;
  DiscretizationMethod method = DiscretizationMethod::AugmentedExponential;
  /// Output blocks, in row order (see OutputLayout).
  std::vector<OutputQuantity> quantities = {OutputQuantity::Displacement};
  /// Constant generalised force f_g [n] [N, N m] added to the right-hand side (e.g. gravity);
  /// empty means none.
  Vector generalized_force;
  /// ModalDecoupled only: zeta_r per mode (ascending frequency); empty means from C.
  Vector modal_damping_ratios;
  /// ModalDecoupled only: modes above this frequency [Hz] are quasi-static (see above): their
  /// displacement and velocity follow the input, their acceleration is not reported.
  /// 0 keeps every mode dynamic.
  double max_mode_frequency_hz = 0.0;
};

/// The cut-off tvd simulate, tvd ride and the node use unless told otherwise [Hz]: the Nyquist
/// frequency 1/(2 h) of the step h. A mode above it is not resolved at that step anyway; made
/// quasi-static, it keeps its exact static response and drops only its inertia.
inline double nyquistCutoff(double time_step) {
  return 0.5 / time_step;
}

/// The discrete system Simulator(system, options) steps with the augmented exponential method:
/// discretize(fromSecondOrder(system, options.quantities, options.generalized_force),
/// options.time_step, options.hold). Computed once, it can serve Simulator(discrete) and another
/// simulator on the same state with other outputs (GroundContactForces). Throws as they do.
StateSpace exactDiscretization(const SecondOrderSystem& system, const SimulatorOptions& options);

class SimulatorEngine;

class Simulator {
 public:
  /// From a discrete StateSpace (sample_time > 0, any hold): dense engine.
  /// Throws InputError when the system is invalid or continuous.
  explicit Simulator(const StateSpace& discrete);
  /// Discretises `system` as the options say. Throws InputError for inconsistent sizes or
  /// options, SolverError when M is not positive definite (or K indefinite, modal method).
  Simulator(const SecondOrderSystem& system, const SimulatorOptions& options);
  /// The modal engine on a decomposition already made, ModalSystem(system) or its withOutput():
  /// the same stepper as Simulator(system, options) without a second eigen-solve (e.g. the
  /// ground contact forces beside a run, on the same modes). The outputs (rows and names) are
  /// the ModalSystem's, not system.output's; that `modal` decomposes this very system is the
  /// caller's responsibility (only the mode and input counts are checked). Throws InputError
  /// unless options.method is ModalDecoupled and modal_damping_ratios empty (the ModalSystem's
  /// ratios apply), or when the counts differ from the system's.
  Simulator(const SecondOrderSystem& system, const ModalSystem& modal,
            const SimulatorOptions& options);
  ~Simulator();
  /// A moved-from simulator may only be destroyed or assigned to: every other call throws
  /// std::logic_error.
  Simulator(Simulator&&) noexcept;
  Simulator& operator=(Simulator&&) noexcept;

  /// t = 0, z = 0, w = 0.
  void reset();
  /// t = 0, state z0 = [q; q'] [2n] (e.g. staticEquilibrium()), current input w0 [n_w] (empty
  /// means zero). For the modal engine z0 is projected on the modes (exact: all modes kept).
  /// Throws InputError for wrong lengths or a non-finite entry.
  void reset(const Vector& state, const Vector& input = Vector());
  /// Advances one step to the input sample w_next [n_w] at the end of the step (see the time
  /// convention above). No allocation. Throws InputError for a wrong length or a NaN or infinite
  /// entry, before anything changes: such an input would poison the state for good.
  void step(const Vector& input_next);
  /// Same, first replacing the current input by `input_begin` (the value at the start of the
  /// step, for a first-order hold whose previous end value differs).
  void step(const Vector& input_begin, const Vector& input_end);
  /// Runs the whole input series W [n_samples x n_w], row k sampled at t + k h, from the current
  /// state: row 0 replaces the current input, then one step per further row. Returns the outputs
  /// Y [n_samples x n_y], row k at t + k h. The simulator ends at the last sample.
  /// Throws InputError for a wrong number of columns or a non-finite entry (naming its row),
  /// nothing changed; of a column its model does not use (zeros in its input map, e.g. u'
  /// without ground damping) the modal engine reads row 0 only, whatever the others hold.
  Matrix simulate(const Matrix& inputs);
  /// Same, from a series stored by its changes (held_input_series.h): equal to
  /// simulate(inputs.dense()) up to rounding, at a cost that grows with the events, not with
  /// samples x inputs (the modal engine; the dense engine runs the dense series). Throws
  /// InputError for a wrong number of inputs or an invalid series.
  Matrix simulate(const HeldInputSeries& inputs);

  /// Outputs y at the current sample [n_y], rows as outputNames().
  const Vector& outputs() const;
  /// Current state z = [q; q'] [2n] (O(n^2) for the modal engine: q = Phi eta).
  Vector state() const;
  /// Chooses the coordinates coordinates() returns, indices into q (checked: InputError naming
  /// the first outside [0, n)); replaces an earlier choice. The modal engine prepares their rows
  /// of the mode shapes and of the quasi-static modes' flexibility once, here.
  void watchCoordinates(const std::vector<DofIndex>& rows);
  /// [q(rows); q'(rows)] of the current state [2 n_rows] for the rows of watchCoordinates() (none
  /// chosen: empty), equal to state()'s up to rounding. For a caller reading a few coordinates
  /// often (the node's ground-contact check): the modal engine reads n_rows x (modes + inputs)
  /// coefficients instead of state()'s n x (n + 3 inputs), 5x fewer on the tracked model.
  /// Writes into *z, resized when its size differs (the modal engine allocates nothing else).
  void coordinates(Vector* z) const;
  /// Current input w [n_w].
  const Vector& input() const;
  /// Current time [s] since reset.
  double time() const;
  /// Steps taken since reset.
  long stepCount() const;

  DofIndex stateCount() const;
  DofIndex inputCount() const;
  DofIndex outputCount() const;
  const std::vector<std::string>& outputNames() const;
  double timeStep() const;
  InputHold hold() const;
  DiscretizationMethod method() const;
  /// ModalDecoupled: max_{r != s} |c_rs| / sqrt(c_rr c_ss) of Phi^T C Phi when each mode is
  /// stepped on its own (modal_damping_ratios given), 0 when the coupled dynamic modes are
  /// stepped together (the default: nothing of their damping is dropped);
  /// AugmentedExponential: 0.
  double maxOffDiagonalDampingRatio() const;
  /// ModalDecoupled: modes integrated dynamically / treated quasi-statically (above
  /// max_mode_frequency_hz). AugmentedExponential: stateCount() / 2 and 0.
  DofIndex dynamicModeCount() const;
  DofIndex quasiStaticModeCount() const;

 private:
  /// *engine_; throws std::logic_error when moved from (engine_ null).
  SimulatorEngine& engine() const;

  std::unique_ptr<SimulatorEngine> engine_;
};

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
