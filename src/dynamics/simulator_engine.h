// Private to the dynamics module: the two stepping strategies behind dynamics::Simulator.
//   DenseEngine (dense_engine.cpp): a discretised StateSpace, z_{k+1} = Phi z_k + Gamma0 w_k
//     (+ Gamma1 w_{k+1}) + f_d, for DiscretizationMethod::AugmentedExponential;
//   ModalEngine (modal_engine.cpp): the decoupled modes of a SecondOrderSystem, each stepped by
//     its exact 2x2 transition, for DiscretizationMethod::ModalDecoupled.
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "checks.h"
#include "tracked_vehicle_dynamics/dynamics/simulator.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

// The stepping strategy behind Simulator. Holds what both engines share: the current input,
// the outputs, the clock. The engines set these members; Simulator reads them.
class SimulatorEngine {
 public:
  virtual ~SimulatorEngine() = default;

  /// z [n_states], w [n_w]: sizes already checked.
  virtual void reset(const Vector& state, const Vector& input) = 0;
  /// Replaces the current input (same sample) and refreshes the outputs.
  virtual void setInput(const Vector& input) = 0;
  /// One step to the sample whose input is w_next; refreshes the outputs. No allocation.
  virtual void advance(const Vector& input_next) = 0;
  virtual Vector state() const = 0;
  /// Simulator::watchCoordinates (rows checked) and coordinates(). Default: rows of state().
  virtual void watchCoordinates(const std::vector<DofIndex>& rows) { watch_rows_ = rows; }
  virtual void coordinates(Vector* z) const {
    const Vector full = state();
    const auto r = static_cast<DofIndex>(watch_rows_.size());
    const DofIndex n = full.size() / 2;
    if (z->size() != 2 * r)
      z->resize(2 * r);
    for (DofIndex i = 0; i < r; ++i) {
      (*z)(i) = full(watch_rows_[static_cast<std::size_t>(i)]);
      (*z)(r + i) = full(n + watch_rows_[static_cast<std::size_t>(i)]);
    }
  }

  /// Default: one advance() per row, the series checked first (O(n_w) a row against the step's
  /// O(n^2)). Throws InputError for a non-finite entry, nothing changed.
  virtual Matrix simulate(const Matrix& inputs) {
    Matrix outputs(inputs.rows(), y_.size());
    if (inputs.rows() == 0)
      return outputs;
    if (!inputs.allFinite()) {
      for (DofIndex k = 0; k < inputs.rows(); ++k)
        for (DofIndex j = 0; j < inputs.cols(); ++j)
          if (!std::isfinite(inputs(k, j)))
            detail::throwNonFiniteSeriesEntry(k, j, inputs(k, j));
    }
    Vector w = inputs.row(0).transpose();
    setInput(w);
    outputs.row(0) = y_.transpose();
    for (DofIndex k = 1; k < inputs.rows(); ++k) {
      w = inputs.row(k).transpose();
      advance(w);
      outputs.row(k) = y_.transpose();
    }
    return outputs;
  }

  /// Default: the dense series.
  virtual Matrix simulate(const HeldInputSeries& inputs) { return simulate(inputs.dense()); }

  Vector y_;
  Vector w_;
  long steps_ = 0;
  double dt_ = 0.0;
  InputHold hold_ = InputHold::ZeroOrder;
  DiscretizationMethod method_ = DiscretizationMethod::AugmentedExponential;
  DofIndex state_count_ = 0;
  std::vector<std::string> names_;
  double off_diagonal_ratio_ = 0.0;
  DofIndex dynamic_modes_ = -1, quasi_static_modes_ = 0;  // -1: state_count_ / 2
  std::vector<DofIndex> watch_rows_;                      // watchCoordinates()
};

/// Steps `discrete` (checked by the caller: valid, discrete, B1 present for a first-order hold).
std::unique_ptr<SimulatorEngine> makeDenseEngine(const StateSpace& discrete);

/// Decomposes `system` (ModalSystem with options.modal_damping_ratios) and steps its modes.
std::unique_ptr<SimulatorEngine> makeModalEngine(const SecondOrderSystem& system,
                                                 const SimulatorOptions& options);

/// Steps `modal`, the caller's decomposition of `system` (its outputs may be other rows than
/// system.output's; sizes checked by the caller).
std::unique_ptr<SimulatorEngine> makeModalEngine(const SecondOrderSystem& system,
                                                 const ModalSystem& modal,
                                                 const SimulatorOptions& options);

/// Throws InputError unless SimulatorOptions::max_mode_frequency_hz, the modal engine's cut-off,
/// is finite and >= 0; checked before its eigen-solve.
void checkTruncation(const SimulatorOptions& options);

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
