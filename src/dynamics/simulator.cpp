#include "tracked_vehicle_dynamics/dynamics/simulator.h"

#include <algorithm>
#include <cmath>

#include "checks.h"
#include "tracked_vehicle_dynamics/dynamics/discrete_modes.h"
#include "tracked_vehicle_dynamics/dynamics/discretization.h"
#include "tracked_vehicle_dynamics/dynamics/modal_system.h"
#include "tracked_vehicle_dynamics/dynamics/validation.h"
#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

// The stepping strategy behind Simulator. Holds what both engines share: the current input,
// the outputs, the clock.
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

  /// Default: one advance() per row.
  virtual Matrix simulate(const Matrix& inputs) {
    Matrix outputs(inputs.rows(), y_.size());
    if (inputs.rows() == 0)
      return outputs;
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
};

namespace {

constexpr double kPi = 3.14159265358979323846;

// z_{k+1} = Phi z_k + Gamma0 w_k (+ Gamma1 w_{k+1}) + f_d;  y = C z + D w + y0.
class DenseEngine : public SimulatorEngine {
 public:
  explicit DenseEngine(const StateSpace& d) {
    phi_ = d.state_matrix;
    gamma0_ = d.input_matrix;
    first_order_ = d.next_input_matrix.size() != 0;
    if (first_order_)
      gamma1_ = d.next_input_matrix;
    c_ = d.output_matrix;
    d_ = d.feedthrough_matrix;
    f_ = d.state_offset.size() != 0 ? d.state_offset : Vector::Zero(d.stateCount());
    y0_ = d.output_offset.size() != 0 ? d.output_offset : Vector::Zero(d.outputCount());
    has_offset_ = !f_.isZero(0.0);
    z_.setZero(d.stateCount());
    z_next_.setZero(d.stateCount());
    w_.setZero(d.inputCount());
    y_.setZero(d.outputCount());
    dt_ = d.sample_time;
    hold_ = d.hold;
    state_count_ = d.stateCount();
    names_ = d.output_names;
    if (names_.empty())
      for (DofIndex i = 0; i < d.outputCount(); ++i)
        names_.push_back("output " + std::to_string(i));
    updateOutputs();
  }

  void reset(const Vector& state, const Vector& input) override {
    z_ = state;
    w_ = input;
    steps_ = 0;
    updateOutputs();
  }

  void setInput(const Vector& input) override {
    w_ = input;
    updateOutputs();
  }

  void advance(const Vector& input_next) override {
    z_next_.noalias() = phi_ * z_;
    z_next_.noalias() += gamma0_ * w_;
    if (first_order_)
      z_next_.noalias() += gamma1_ * input_next;
    if (has_offset_)
      z_next_ += f_;
    z_.swap(z_next_);
    w_ = input_next;
    ++steps_;
    updateOutputs();
  }

  Vector state() const override { return z_; }

 private:
  void updateOutputs() {
    y_.noalias() = c_ * z_;
    y_.noalias() += d_ * w_;
    y_ += y0_;
  }

  Matrix phi_, gamma0_, gamma1_, c_, d_;
  Vector f_, y0_, z_, z_next_;
  bool first_order_ = false;
  bool has_offset_ = false;
};

// Per mode r: [eta; eta']_{k+1} = Phi_r [eta; eta']_k + g0_r p_k + g1_r p_{k+1} + (g0_r + g1_r) p_g
// with p = Psi w, Psi = [Phi^T K_u, Phi^T C_u], p_g = Phi^T f_g (constant: exact for both holds).
// Outputs: H Phi eta, H Phi eta', H Phi eta'' with eta'' = p + p_g - omega^2 eta - d eta'.
class ModalEngine : public SimulatorEngine {
 public:
  ModalEngine(const SecondOrderSystem& system, const SimulatorOptions& options) {
    if (!(options.max_mode_frequency_hz >= 0) || !std::isfinite(options.max_mode_frequency_hz))
      throw InputError("Simulator: max_mode_frequency_hz must be finite and >= 0 (0 keeps every mode)");
    const ModalSystem modal(system, options.modal_damping_ratios);
    const DofIndex n_all = modal.modeCount();
    const DofIndex n_u = system.inputCount();
    // Modes are in ascending frequency: the first n are dynamic, the rest quasi-static.
    DofIndex n = n_all;
    if (options.max_mode_frequency_hz > 0) {
      const double limit = 2.0 * kPi * options.max_mode_frequency_hz;
      n = 0;
      while (n < n_all && modal.naturalFrequencies()(n) <= limit) ++n;
    }
    const DofIndex n_t = n_all - n;
    const Vector omega = modal.naturalFrequencies().head(n);
    coefficients_ = discretizeModes(omega, modal.dampingCoefficients().head(n), options.time_step,
                                    options.hold);
    first_order_ = options.hold == InputHold::FirstOrder;
    // Psi = [Phi^T K_u, Phi^T C_u] without its zero columns (e.g. C_u = 0: no tyre damping),
    // which would only cost multiplications by zero in every step.
    Matrix psi_all(n_all, 2 * n_u);
    psi_all << modal.modalInputStiffness(), modal.modalInputDamping();
    for (DofIndex j = 0; j < psi_all.cols(); ++j)
      if (!psi_all.col(j).isZero(0.0))
        active_inputs_.push_back(j);
    psi_.resize(n, static_cast<DofIndex>(active_inputs_.size()));
    for (std::size_t j = 0; j < active_inputs_.size(); ++j)
      psi_.col(static_cast<DofIndex>(j)) = psi_all.col(active_inputs_[j]).head(n);
    active_input_.setZero(psi_.cols());
    omega_squared_ = omega.cwiseAbs2();
    damping_ = modal.dampingCoefficients().head(n);
    modal_output_ = modal.modalOutput().leftCols(n);
    shapes_ = modal.shapes().leftCols(n);
    mass_projection_ = modal.massProjection().topRows(n);
    const Vector modal_gravity = options.generalized_force.size() != 0
                                     ? Vector(modal.shapes().transpose() * options.generalized_force)
                                     : Vector(Vector::Zero(n_all));
    force_ = modal_gravity.head(n);
    const Vector gamma_disp = coefficients_.g0_disp + coefficients_.g1_disp;
    const Vector gamma_vel = coefficients_.g0_vel + coefficients_.g1_vel;
    offset_disp_ = gamma_disp.cwiseProduct(force_);
    offset_vel_ = gamma_vel.cwiseProduct(force_);

    // Quasi-static modes: eta_t = Omega_t^-2 (Phi_t^T f), so their outputs are
    //   y_t = H Phi_t Omega_t^-2 Phi_t^T (K_u u + C_u u' + f_g) = R_w w + r_g,
    //   y_t' = H Phi_t Omega_t^-2 Phi_t^T K_u u'   (the C_u u'' term is not available: dropped).
    residual_input_.setZero(modal.outputCount(), psi_.cols());
    residual_force_.setZero(modal.outputCount());
    residual_rate_.setZero(modal.outputCount(), n_u);
    if (n_t > 0) {
      const Vector inverse_omega2 = modal.naturalFrequencies().tail(n_t).cwiseAbs2().cwiseInverse();
      const Matrix output_flex =
          modal.modalOutput().rightCols(n_t) * inverse_omega2.asDiagonal();  // H Phi_t Omega^-2
      for (std::size_t j = 0; j < active_inputs_.size(); ++j)
        residual_input_.col(static_cast<DofIndex>(j)).noalias() =
            output_flex * psi_all.col(active_inputs_[j]).tail(n_t);
      residual_force_.noalias() = output_flex * modal_gravity.tail(n_t);
      residual_rate_.noalias() = output_flex * modal.modalInputStiffness().bottomRows(n_t);
      truncated_shapes_ = modal.shapes().rightCols(n_t) * inverse_omega2.asDiagonal();
      truncated_psi_ = psi_all.bottomRows(n_t);
      truncated_gravity_ = modal_gravity.tail(n_t);
    }

    const OutputLayout layout(modal.outputNames(), options.quantities);
    n_y_ = modal.outputCount();
    disp_offset_ =
        layout.has(OutputQuantity::Displacement) ? layout.offset(OutputQuantity::Displacement) : -1;
    vel_offset_ =
        layout.has(OutputQuantity::Velocity) ? layout.offset(OutputQuantity::Velocity) : -1;
    acc_offset_ =
        layout.has(OutputQuantity::Acceleration) ? layout.offset(OutputQuantity::Acceleration) : -1;
    names_ = layout.names();
    off_diagonal_ratio_ = modal.maxOffDiagonalDampingRatio();
    dt_ = options.time_step;
    hold_ = options.hold;
    method_ = DiscretizationMethod::ModalDecoupled;
    state_count_ = 2 * system.size();
    dynamic_modes_ = n;
    quasi_static_modes_ = n_t;
    n_u_ = n_u;

    for (Vector* v : {&eta_, &eta_dot_, &eta_next_, &eta_ddot_, &p_, &p_next_})
      v->setZero(n);
    w_.setZero(2 * n_u);
    y_.setZero(layout.size());
    updateOutputs();
  }

  void reset(const Vector& state, const Vector& input) override {
    const DofIndex n = shapes_.rows();
    eta_.noalias() = mass_projection_ * state.head(n);
    eta_dot_.noalias() = mass_projection_ * state.tail(n);
    steps_ = 0;
    setInput(input);
  }

  void setInput(const Vector& input) override {
    w_ = input;
    gatherActive(w_);
    p_.noalias() = psi_ * active_input_;
    updateOutputs();
  }

  void advance(const Vector& input_next) override {
    gatherActive(input_next);
    p_next_.noalias() = psi_ * active_input_;
    advanceModes(p_.data(), p_next_.data(), eta_.data(), eta_dot_.data(), eta_next_.data(),
                 eta_dot_.data());
    eta_.swap(eta_next_);
    p_.swap(p_next_);
    w_ = input_next;
    ++steps_;
    updateOutputs();
  }

  Vector state() const override {
    const DofIndex n = shapes_.rows();
    Vector z(2 * n);
    z.head(n).noalias() = shapes_ * eta_;
    z.tail(n).noalias() = shapes_ * eta_dot_;
    if (quasi_static_modes_ > 0) {
      // q_t = Phi_t Omega_t^-2 (Phi_t^T (K_u u + C_u u') + Phi_t^T f_g), q_t' from K_u u'.
      const Vector modal_force = truncated_psi_ * w_ + truncated_gravity_;
      z.head(n).noalias() += truncated_shapes_ * modal_force;
      z.tail(n).noalias() += truncated_shapes_ * (truncated_psi_.leftCols(n_u_) * w_.tail(n_u_));
    }
    return z;
  }

  // Blocked version: modal forces and outputs of kBlock samples at a time as matrix-matrix
  // products; only the O(n) per-mode recursion stays sequential.
  Matrix simulate(const Matrix& inputs) override {
    constexpr DofIndex kBlock = 256;
    const DofIndex n_t = inputs.rows();
    const DofIndex n = eta_.size();
    Matrix outputs(n_t, y_.size());
    if (n_t == 0)
      return outputs;
    setInput(inputs.row(0).transpose());
    outputs.row(0) = y_.transpose();
    Matrix forces(n, kBlock), disp(n, kBlock), vel(n, kBlock), acc(n, kBlock);
    for (DofIndex k0 = 1; k0 < n_t; k0 += kBlock) {
      const DofIndex b = std::min(kBlock, n_t - k0);
      forces.leftCols(b).noalias() =
          psi_ * inputs.middleRows(k0, b)(Eigen::all, active_inputs_).transpose();
      for (DofIndex j = 0; j < b; ++j) {
        const double* p_prev = j == 0 ? p_.data() : forces.col(j - 1).data();
        const double* eta_prev = j == 0 ? eta_.data() : disp.col(j - 1).data();
        const double* eta_dot_prev = j == 0 ? eta_dot_.data() : vel.col(j - 1).data();
        advanceModes(p_prev, forces.col(j).data(), eta_prev, eta_dot_prev, disp.col(j).data(),
                     vel.col(j).data());
      }
      if (acc_offset_ >= 0)
        acc.leftCols(b) = (forces.leftCols(b).colwise() + force_).array() -
                          disp.leftCols(b).array().colwise() * omega_squared_.array() -
                          vel.leftCols(b).array().colwise() * damping_.array();
      auto rows = outputs.middleRows(k0, b);
      if (disp_offset_ >= 0) {
        rows.middleCols(disp_offset_, n_y_).noalias() =
            disp.leftCols(b).transpose() * modal_output_.transpose();
        if (quasi_static_modes_ > 0) {
          rows.middleCols(disp_offset_, n_y_).noalias() +=
              inputs.middleRows(k0, b)(Eigen::all, active_inputs_) * residual_input_.transpose();
          rows.middleCols(disp_offset_, n_y_).rowwise() += residual_force_.transpose();
        }
      }
      if (vel_offset_ >= 0) {
        rows.middleCols(vel_offset_, n_y_).noalias() =
            vel.leftCols(b).transpose() * modal_output_.transpose();
        if (quasi_static_modes_ > 0)
          rows.middleCols(vel_offset_, n_y_).noalias() +=
              inputs.middleRows(k0, b).rightCols(n_u_) * residual_rate_.transpose();
      }
      if (acc_offset_ >= 0)
        rows.middleCols(acc_offset_, n_y_).noalias() =
            acc.leftCols(b).transpose() * modal_output_.transpose();
      eta_ = disp.col(b - 1);
      eta_dot_ = vel.col(b - 1);
      p_ = forces.col(b - 1);
      steps_ += b;
    }
    w_ = inputs.row(n_t - 1).transpose();
    updateOutputs();
    return outputs;
  }

 private:
  using ArrayMap = Eigen::Map<Eigen::ArrayXd>;
  using ConstArrayMap = Eigen::Map<const Eigen::ArrayXd>;

  void gatherActive(const Vector& input) {
    for (std::size_t j = 0; j < active_inputs_.size(); ++j)
      active_input_(static_cast<DofIndex>(j)) = input(active_inputs_[j]);
  }

  // One step of every mode; eta_dot_out may alias eta_dot (coefficient-wise).
  void advanceModes(const double* p, const double* p_next, const double* eta, const double* eta_dot,
                    double* eta_out, double* eta_dot_out) const {
    const DofIndex n = eta_.size();
    const ConstArrayMap p0(p, n), p1(p_next, n), x(eta, n), v(eta_dot, n);
    const DiscreteModes& c = coefficients_;
    ArrayMap x_out(eta_out, n), v_out(eta_dot_out, n);
    if (first_order_) {
      x_out = c.a11.array() * x + c.a12.array() * v + c.g0_disp.array() * p0 +
              c.g1_disp.array() * p1 + offset_disp_.array();
      v_out = c.a21.array() * x + c.a22.array() * v + c.g0_vel.array() * p0 +
              c.g1_vel.array() * p1 + offset_vel_.array();
    } else {
      x_out = c.a11.array() * x + c.a12.array() * v + c.g0_disp.array() * p0 + offset_disp_.array();
      v_out = c.a21.array() * x + c.a22.array() * v + c.g0_vel.array() * p0 + offset_vel_.array();
    }
  }

  // active_input_ holds the current w (gathered by setInput/advance).
  void updateOutputs() {
    if (disp_offset_ >= 0) {
      y_.segment(disp_offset_, n_y_).noalias() = modal_output_ * eta_;
      if (quasi_static_modes_ > 0) {
        y_.segment(disp_offset_, n_y_).noalias() += residual_input_ * active_input_;
        y_.segment(disp_offset_, n_y_) += residual_force_;
      }
    }
    if (vel_offset_ >= 0) {
      y_.segment(vel_offset_, n_y_).noalias() = modal_output_ * eta_dot_;
      if (quasi_static_modes_ > 0)
        y_.segment(vel_offset_, n_y_).noalias() += residual_rate_ * w_.tail(n_u_);
    }
    if (acc_offset_ >= 0) {
      eta_ddot_.array() = p_.array() + force_.array() - omega_squared_.array() * eta_.array() -
                          damping_.array() * eta_dot_.array();
      y_.segment(acc_offset_, n_y_).noalias() = modal_output_ * eta_ddot_;
    }
  }

  DiscreteModes coefficients_;
  bool first_order_ = false;
  Matrix psi_, modal_output_, shapes_, mass_projection_;
  Vector omega_squared_, damping_, force_, offset_disp_, offset_vel_;
  Vector eta_, eta_dot_, eta_next_, eta_ddot_, p_, p_next_;
  std::vector<DofIndex> active_inputs_;  // columns of w with a non-zero modal force
  Vector active_input_;                  // w restricted to active_inputs_
  DofIndex n_y_ = 0;
  DofIndex disp_offset_ = -1, vel_offset_ = -1, acc_offset_ = -1;
  // Quasi-static (truncated) modes, see the constructor.
  DofIndex n_u_ = 0;
  Matrix residual_input_, residual_rate_, truncated_shapes_, truncated_psi_;
  Vector residual_force_, truncated_gravity_;
};

std::unique_ptr<SimulatorEngine> makeEngine(const SecondOrderSystem& system,
                                            const SimulatorOptions& options) {
  validateSystem(system);
  detail::requireTimeStep("Simulator", options.time_step);
  if (options.generalized_force.size() != 0)
    detail::requireLength("Simulator", "generalized force f_g", options.generalized_force,
                          system.size());
  if (options.method == DiscretizationMethod::ModalDecoupled)
    return std::make_unique<ModalEngine>(system, options);
  if (options.modal_damping_ratios.size() != 0)
    throw InputError(
        "Simulator: modal_damping_ratios apply to DiscretizationMethod::ModalDecoupled only");
  if (options.max_mode_frequency_hz != 0.0)
    throw InputError(
        "Simulator: max_mode_frequency_hz applies to DiscretizationMethod::ModalDecoupled only");
  const StateSpace continuous =
      fromSecondOrder(system, options.quantities, options.generalized_force);
  return std::make_unique<DenseEngine>(discretize(continuous, options.time_step, options.hold));
}

}  // namespace

Simulator::Simulator(const StateSpace& discrete) {
  validateStateSpace(discrete);
  if (discrete.isContinuous())
    throw InputError("Simulator: the StateSpace is continuous; discretize() it first");
  if (discrete.hold == InputHold::FirstOrder && discrete.next_input_matrix.size() == 0)
    throw InputError("Simulator: first-order-hold StateSpace without next input matrix B1");
  engine_ = std::make_unique<DenseEngine>(discrete);
}

Simulator::Simulator(const SecondOrderSystem& system, const SimulatorOptions& options)
    : engine_(makeEngine(system, options)) {}

Simulator::~Simulator() = default;
Simulator::Simulator(Simulator&&) noexcept = default;
Simulator& Simulator::operator=(Simulator&&) noexcept = default;

void Simulator::reset() {
  engine_->reset(Vector::Zero(stateCount()), Vector::Zero(inputCount()));
}

void Simulator::reset(const Vector& state, const Vector& input) {
  detail::requireLength("Simulator::reset", "state z0", state, stateCount());
  if (input.size() == 0) {
    engine_->reset(state, Vector::Zero(inputCount()));
    return;
  }
  detail::requireLength("Simulator::reset", "input w0", input, inputCount());
  engine_->reset(state, input);
}

void Simulator::step(const Vector& input_next) {
  if (input_next.size() != inputCount())
    detail::requireLength("Simulator::step", "input w", input_next, inputCount());
  engine_->advance(input_next);
}

void Simulator::step(const Vector& input_begin, const Vector& input_end) {
  detail::requireLength("Simulator::step", "input w_begin", input_begin, inputCount());
  detail::requireLength("Simulator::step", "input w_end", input_end, inputCount());
  engine_->setInput(input_begin);
  engine_->advance(input_end);
}

Matrix Simulator::simulate(const Matrix& inputs) {
  detail::requireSize("Simulator::simulate", "input series", inputs, inputs.rows(), inputCount());
  return engine_->simulate(inputs);
}

const Vector& Simulator::outputs() const {
  return engine_->y_;
}
Vector Simulator::state() const {
  return engine_->state();
}
const Vector& Simulator::input() const {
  return engine_->w_;
}
double Simulator::time() const {
  return static_cast<double>(engine_->steps_) * engine_->dt_;
}
long Simulator::stepCount() const {
  return engine_->steps_;
}
DofIndex Simulator::stateCount() const {
  return engine_->state_count_;
}
DofIndex Simulator::inputCount() const {
  return engine_->w_.size();
}
DofIndex Simulator::outputCount() const {
  return engine_->y_.size();
}
const std::vector<std::string>& Simulator::outputNames() const {
  return engine_->names_;
}
double Simulator::timeStep() const {
  return engine_->dt_;
}
InputHold Simulator::hold() const {
  return engine_->hold_;
}
DiscretizationMethod Simulator::method() const {
  return engine_->method_;
}
double Simulator::maxOffDiagonalDampingRatio() const {
  return engine_->off_diagonal_ratio_;
}
DofIndex Simulator::dynamicModeCount() const {
  return engine_->dynamic_modes_ >= 0 ? engine_->dynamic_modes_ : engine_->state_count_ / 2;
}
DofIndex Simulator::quasiStaticModeCount() const {
  return engine_->quasi_static_modes_;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
