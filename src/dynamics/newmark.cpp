#include "tracked_vehicle_dynamics/dynamics/newmark.h"

#include "checks.h"
#include "tracked_vehicle_dynamics/dynamics/validation.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

namespace {

std::vector<std::string> baseNames(const SparseSecondOrderSystem& system) {
  validateSystem(system);
  std::vector<std::string> names = system.output_names;
  if (names.empty())
    for (DofIndex i = 0; i < system.outputCount(); ++i)
      names.push_back("output " + std::to_string(i));
  return names;
}

}  // namespace

NewmarkIntegrator::NewmarkIntegrator(const SparseSecondOrderSystem& system, double time_step,
                                     const std::vector<OutputQuantity>& quantities,
                                     const Vector& generalized_force)
    : dt_(time_step), layout_(baseNames(system), quantities) {
  detail::requireTimeStep("NewmarkIntegrator", time_step);
  const DofIndex n = system.size();
  mass_ = system.mass;
  damping_ = system.damping;
  stiffness_ = system.stiffness;
  // F = [K_u C_u] w
  input_matrix_.resize(n, 2 * system.inputCount());
  {
    std::vector<Triplet> triplets;
    for (int j = 0; j < system.input_stiffness.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(system.input_stiffness, j); it; ++it)
        triplets.emplace_back(it.row(), j, it.value());
    for (int j = 0; j < system.input_damping.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(system.input_damping, j); it; ++it)
        triplets.emplace_back(it.row(), system.inputCount() + j, it.value());
    input_matrix_.setFromTriplets(triplets.begin(), triplets.end());
  }
  output_ = system.output;
  generalized_force_ = Vector::Zero(n);
  if (generalized_force.size() != 0) {
    detail::requireLength("NewmarkIntegrator", "generalized force f_g", generalized_force, n);
    generalized_force_ = generalized_force;
  }
  const double h = time_step;
  const SparseMatrix effective =
      stiffness_ + (kGamma / (kBeta * h)) * damping_ + (1.0 / (kBeta * h * h)) * mass_;
  effective_stiffness_.compute(effective);
  if (effective_stiffness_.info() != Eigen::Success ||
      (effective_stiffness_.vectorD().array() <= 0.0).any())
    throw SolverError("NewmarkIntegrator: effective stiffness K + C/(beta h) + M/(beta h^2) (" +
                      detail::sizeText(n, n) + ") is not positive definite");
  q_.setZero(n);
  v_.setZero(n);
  a_.setZero(n);
  rhs_.setZero(n);
  w_.setZero(input_matrix_.cols());
  y_.setZero(layout_.size());
  reset();
}

Vector NewmarkIntegrator::force(const Vector& input) const {
  return input_matrix_ * input + generalized_force_;
}

void NewmarkIntegrator::reset() {
  const DofIndex n = stiffness_.rows();
  reset(Vector::Zero(n), Vector::Zero(n), Vector::Zero(input_matrix_.cols()));
}

void NewmarkIntegrator::reset(const Vector& displacement, const Vector& velocity,
                              const Vector& input) {
  const DofIndex n = stiffness_.rows();
  detail::requireLength("NewmarkIntegrator::reset", "displacement", displacement, n);
  detail::requireLength("NewmarkIntegrator::reset", "velocity", velocity, n);
  detail::requireLength("NewmarkIntegrator::reset", "input w", input, input_matrix_.cols());
  reset(displacement, velocity, initialAcceleration(displacement, velocity, input), input);
}

Vector NewmarkIntegrator::initialAcceleration(const Vector& displacement, const Vector& velocity,
                                              const Vector& input) const {
  // M a0 = F(w0) - C v0 - K q0; at rest in equilibrium this is 0 and M need not be factorised.
  const Vector residual = force(input) - damping_ * velocity - stiffness_ * displacement;
  if (residual.isZero(0.0))
    return Vector::Zero(residual.size());
  const Eigen::SimplicialLDLT<SparseMatrix> mass_factor(mass_);
  if (mass_factor.info() != Eigen::Success || (mass_factor.vectorD().array() <= 0.0).any())
    throw SolverError(
        "NewmarkIntegrator: mass matrix M is singular; pass the initial acceleration explicitly");
  return mass_factor.solve(residual);
}

void NewmarkIntegrator::reset(const Vector& displacement, const Vector& velocity,
                              const Vector& acceleration, const Vector& input) {
  const DofIndex n = stiffness_.rows();
  detail::requireLength("NewmarkIntegrator::reset", "displacement", displacement, n);
  detail::requireLength("NewmarkIntegrator::reset", "velocity", velocity, n);
  detail::requireLength("NewmarkIntegrator::reset", "acceleration", acceleration, n);
  detail::requireLength("NewmarkIntegrator::reset", "input w", input, input_matrix_.cols());
  q_ = displacement;
  v_ = velocity;
  a_ = acceleration;
  w_ = input;
  steps_ = 0;
  updateOutputs();
}

void NewmarkIntegrator::step(const Vector& input_next) {
  detail::requireLength("NewmarkIntegrator::step", "input w", input_next, input_matrix_.cols());
  const double h = dt_;
  const double c0 = 1.0 / (kBeta * h * h);
  const double c1 = kGamma / (kBeta * h);
  const double c2 = 1.0 / (kBeta * h);
  const double c3 = 1.0 / (2.0 * kBeta) - 1.0;
  const double c4 = kGamma / kBeta - 1.0;
  const double c5 = h * (kGamma / (2.0 * kBeta) - 1.0);
  rhs_ = force(input_next);
  rhs_ += mass_ * (c0 * q_ + c2 * v_ + c3 * a_);
  rhs_ += damping_ * (c1 * q_ + c4 * v_ + c5 * a_);
  const Vector q_next = effective_stiffness_.solve(rhs_);
  const Vector a_next = c0 * (q_next - q_) - c2 * v_ - c3 * a_;
  v_ += h * ((1.0 - kGamma) * a_ + kGamma * a_next);
  q_ = q_next;
  a_ = a_next;
  w_ = input_next;
  ++steps_;
  updateOutputs();
}

Matrix NewmarkIntegrator::simulate(const Matrix& inputs) {
  detail::requireSize("NewmarkIntegrator::simulate", "input series", inputs, inputs.rows(),
                      input_matrix_.cols());
  Matrix outputs(inputs.rows(), y_.size());
  if (inputs.rows() == 0)
    return outputs;
  const Vector first = inputs.row(0).transpose();
  if (first != w_)
    a_ = initialAcceleration(q_, v_, first);
  w_ = first;
  updateOutputs();
  outputs.row(0) = y_.transpose();
  for (DofIndex k = 1; k < inputs.rows(); ++k) {
    step(inputs.row(k).transpose());
    outputs.row(k) = y_.transpose();
  }
  return outputs;
}

void NewmarkIntegrator::updateOutputs() {
  const DofIndex n_y = output_.rows();
  for (OutputQuantity quantity : layout_.quantities()) {
    const DofIndex r = layout_.offset(quantity);
    const Vector& x = quantity == OutputQuantity::Displacement ? q_
                      : quantity == OutputQuantity::Velocity   ? v_
                                                               : a_;
    y_.segment(r, n_y) = output_ * x;
  }
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
