#include "tracked_vehicle_dynamics/dynamics/simulator.h"

#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "checks.h"
#include "simulator_engine.h"
#include "tracked_vehicle_dynamics/dynamics/discretization.h"
#include "tracked_vehicle_dynamics/dynamics/modal_system.h"
#include "tracked_vehicle_dynamics/dynamics/validation.h"
#include "tracked_vehicle_dynamics/enum_names.h"
#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

const char* methodName(DiscretizationMethod method) {
  switch (method) {  // no default: a new method without a name is a compiler warning
    case DiscretizationMethod::AugmentedExponential:
      return "exact";
    case DiscretizationMethod::ModalDecoupled:
      return "modal";
  }
  return "?";
}

std::optional<DiscretizationMethod> methodFromName(const std::string& name) {
  return enumFromName(
      name, {DiscretizationMethod::AugmentedExponential, DiscretizationMethod::ModalDecoupled},
      methodName);
}

namespace {

void checkOptions(const SecondOrderSystem& system, const SimulatorOptions& options) {
  validateSystem(system);
  detail::requireTimeStep("Simulator", options.time_step);
  if (options.generalized_force.size() != 0)
    detail::requireLength("Simulator", "generalized force f_g", options.generalized_force,
                          system.size());
}

std::unique_ptr<SimulatorEngine> makeEngine(const SecondOrderSystem& system,
                                            const SimulatorOptions& options) {
  checkOptions(system, options);
  if (options.method == DiscretizationMethod::ModalDecoupled) {
    checkTruncation(options);  // before the eigen-solve
    return makeModalEngine(system, options);
  }
  if (options.modal_damping_ratios.size() != 0)
    throw InputError(
        "Simulator: modal_damping_ratios apply to DiscretizationMethod::ModalDecoupled only");
  if (options.max_mode_frequency_hz != 0.0)
    throw InputError(
        "Simulator: max_mode_frequency_hz applies to DiscretizationMethod::ModalDecoupled only");
  return makeDenseEngine(exactDiscretization(system, options));
}

}  // namespace

StateSpace exactDiscretization(const SecondOrderSystem& system, const SimulatorOptions& options) {
  return discretize(fromSecondOrder(system, options.quantities, options.generalized_force),
                    options.time_step, options.hold);
}

Simulator::Simulator(const StateSpace& discrete) {
  validateStateSpace(discrete);
  if (discrete.isContinuous())
    throw InputError("Simulator: the StateSpace is continuous; discretize() it first");
  if (discrete.hold == InputHold::FirstOrder && discrete.next_input_matrix.size() == 0)
    throw InputError("Simulator: first-order-hold StateSpace without next input matrix B1");
  engine_ = makeDenseEngine(discrete);
}

Simulator::Simulator(const SecondOrderSystem& system, const SimulatorOptions& options)
    : engine_(makeEngine(system, options)) {}

Simulator::Simulator(const SecondOrderSystem& system, const ModalSystem& modal,
                     const SimulatorOptions& options) {
  checkOptions(system, options);
  if (options.method != DiscretizationMethod::ModalDecoupled)
    throw InputError(
        "Simulator: a ModalSystem is stepped by DiscretizationMethod::ModalDecoupled only");
  if (options.modal_damping_ratios.size() != 0)
    throw InputError(
        "Simulator: with a ModalSystem the damping ratios are its own; "
        "modal_damping_ratios must be empty");
  // Its outputs are its own (withOutput()); that it decomposes this system is the caller's word,
  // checked here only by the sizes (a full check would cost the eigen-solve it saves).
  if (modal.modeCount() != system.size() || modal.inputCount() != system.inputCount())
    throw InputError("Simulator: the ModalSystem (" + std::to_string(modal.modeCount()) +
                     " modes, " + std::to_string(modal.inputCount()) +
                     " inputs) is not of the system (" + std::to_string(system.size()) + " DOFs, " +
                     std::to_string(system.inputCount()) + " inputs)");
  engine_ = makeModalEngine(system, modal, options);
}

Simulator::~Simulator() = default;
Simulator::Simulator(Simulator&&) noexcept = default;
Simulator& Simulator::operator=(Simulator&&) noexcept = default;

namespace {

// Out of line, so the check in engine() stays a compare and a branch on the step path.
[[noreturn, gnu::cold, gnu::noinline]] void throwMovedFrom() {
  throw std::logic_error(
      "Simulator: used after being moved from (it has no engine); assign it another Simulator "
      "before calling it again");
}

}  // namespace

SimulatorEngine& Simulator::engine() const {
  if (!engine_)
    throwMovedFrom();
  return *engine_;
}

void Simulator::reset() {
  engine().reset(Vector::Zero(stateCount()), Vector::Zero(inputCount()));
}

void Simulator::reset(const Vector& state, const Vector& input) {
  detail::requireLength("Simulator::reset", "state z0", state, stateCount());
  detail::requireFinite("Simulator::reset", "state z0", state);
  if (input.size() == 0) {
    engine().reset(state, Vector::Zero(inputCount()));
    return;
  }
  detail::requireLength("Simulator::reset", "input w0", input, inputCount());
  detail::requireFinite("Simulator::reset", "input w0", input);
  engine().reset(state, input);
}

void Simulator::step(const Vector& input_next) {
  SimulatorEngine& engine = this->engine();  // one check per step
  if (input_next.size() != engine.w_.size())
    detail::requireLength("Simulator::step", "input w", input_next, engine.w_.size());
  detail::requireFinite("Simulator::step", "input w", input_next);
  engine.advance(input_next);
}

void Simulator::step(const Vector& input_begin, const Vector& input_end) {
  detail::requireLength("Simulator::step", "input w_begin", input_begin, inputCount());
  detail::requireLength("Simulator::step", "input w_end", input_end, inputCount());
  detail::requireFinite("Simulator::step", "input w_begin", input_begin);
  detail::requireFinite("Simulator::step", "input w_end", input_end);
  engine().setInput(input_begin);
  engine().advance(input_end);
}

Matrix Simulator::simulate(const Matrix& inputs) {
  detail::requireSize("Simulator::simulate", "input series", inputs, inputs.rows(), inputCount());
  // The engines refuse a non-finite entry (detail::throwNonFiniteSeriesEntry) before they change
  // anything: the modal one while it scans the series for changes anyway (a pass of its own
  // over a 21,601 x 720 series took 6 ms, its whole simulation 14).
  return engine().simulate(inputs);
}

Matrix Simulator::simulate(const HeldInputSeries& inputs) {
  if (inputs.inputCount() != inputCount())
    throw InputError("Simulator::simulate: the held input series has " +
                     std::to_string(inputs.inputCount()) + " inputs, the system " +
                     std::to_string(inputCount()));
  inputs.validate();
  return engine().simulate(inputs);
}

const Vector& Simulator::outputs() const {
  return engine().y_;
}
Vector Simulator::state() const {
  return engine().state();
}
void Simulator::watchCoordinates(const std::vector<DofIndex>& rows) {
  const DofIndex n = engine().state_count_ / 2;
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (rows[i] < 0 || rows[i] >= n)
      throw InputError("Simulator::watchCoordinates: coordinate " + std::to_string(rows[i]) +
                       " (entry " + std::to_string(i) + ") is outside the " + std::to_string(n) +
                       " coordinates of q");
  engine().watchCoordinates(rows);
}
void Simulator::coordinates(Vector* z) const {
  engine().coordinates(z);
}
const Vector& Simulator::input() const {
  return engine().w_;
}
double Simulator::time() const {
  const SimulatorEngine& engine = this->engine();
  return static_cast<double>(engine.steps_) * engine.dt_;
}
long Simulator::stepCount() const {
  return engine().steps_;
}
DofIndex Simulator::stateCount() const {
  return engine().state_count_;
}
DofIndex Simulator::inputCount() const {
  return engine().w_.size();
}
DofIndex Simulator::outputCount() const {
  return engine().y_.size();
}
const std::vector<std::string>& Simulator::outputNames() const {
  return engine().names_;
}
double Simulator::timeStep() const {
  return engine().dt_;
}
InputHold Simulator::hold() const {
  return engine().hold_;
}
DiscretizationMethod Simulator::method() const {
  return engine().method_;
}
double Simulator::maxOffDiagonalDampingRatio() const {
  return engine().off_diagonal_ratio_;
}
DofIndex Simulator::dynamicModeCount() const {
  const SimulatorEngine& engine = this->engine();
  return engine.dynamic_modes_ >= 0 ? engine.dynamic_modes_ : engine.state_count_ / 2;
}
DofIndex Simulator::quasiStaticModeCount() const {
  return engine().quasi_static_modes_;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
