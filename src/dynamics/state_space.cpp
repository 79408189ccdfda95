#include "tracked_vehicle_dynamics/dynamics/state_space.h"

#include <cmath>

#include "checks.h"
#include "tracked_vehicle_dynamics/dynamics/validation.h"
#include "tracked_vehicle_dynamics/enum_names.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

const char* holdName(InputHold hold) {
  switch (hold) {  // no default: a new hold without a name is a compiler warning
    case InputHold::ZeroOrder:
      return "zero_order";
    case InputHold::FirstOrder:
      return "first_order";
  }
  return "?";
}

std::optional<InputHold> holdFromName(const std::string& name) {
  return enumFromName(name, {InputHold::ZeroOrder, InputHold::FirstOrder}, holdName);
}

void validateStateSpace(const StateSpace& s) {
  const std::string where = "StateSpace";
  const DofIndex n = s.stateCount();
  const DofIndex m = s.inputCount();
  const DofIndex p = s.outputCount();
  detail::requireSize(where, "state matrix A", s.state_matrix, n, n);
  detail::requireSize(where, "input matrix B", s.input_matrix, n, m);
  detail::requireSize(where, "output matrix C", s.output_matrix, p, n);
  detail::requireSize(where, "feedthrough matrix D", s.feedthrough_matrix, p, m);
  if (s.next_input_matrix.size() != 0)
    detail::requireSize(where, "next input matrix B1", s.next_input_matrix, n, m);
  if (s.state_offset.size() != 0)
    detail::requireLength(where, "state offset f0", s.state_offset, n);
  if (s.output_offset.size() != 0)
    detail::requireLength(where, "output offset y0", s.output_offset, p);
  if (!s.output_names.empty())
    detail::requireLength(where, "output_names", s.output_names, p);
  if (!(s.sample_time >= 0.0) || !std::isfinite(s.sample_time))
    throw InputError(where + ": sample time must be >= 0 and finite, got " +
                     std::to_string(s.sample_time) + " s");
  if (s.isContinuous() && s.next_input_matrix.size() != 0)
    throw InputError(where + ": a continuous system has no next input matrix B1");
}

StateSpace fromSecondOrder(const SecondOrderSystem& system,
                           const std::vector<OutputQuantity>& quantities,
                           const Vector& generalized_force) {
  validateSystem(system);
  const DofIndex n = system.size();
  const DofIndex n_u = system.inputCount();
  const DofIndex n_y = system.outputCount();
  if (generalized_force.size() != 0)
    detail::requireLength("fromSecondOrder", "generalized force f_g", generalized_force, n);
  std::vector<std::string> base_names = system.output_names;
  if (base_names.empty())
    for (DofIndex i = 0; i < n_y; ++i)
      base_names.push_back("output " + std::to_string(i));
  const OutputLayout layout(base_names, quantities);

  const Eigen::LLT<Matrix> mass_factor(system.mass);
  if (mass_factor.info() != Eigen::Success)
    throw SolverError("fromSecondOrder: mass matrix M (" + detail::sizeText(n, n) +
                      ") is not positive definite");
  const Matrix minv_k = mass_factor.solve(system.stiffness);
  const Matrix minv_c = mass_factor.solve(system.damping);
  const Matrix minv_ku = mass_factor.solve(system.input_stiffness);
  const Matrix minv_cu = mass_factor.solve(system.input_damping);

  StateSpace s;
  s.state_matrix = Matrix::Zero(2 * n, 2 * n);
  s.state_matrix.topRightCorner(n, n).setIdentity();
  s.state_matrix.bottomLeftCorner(n, n) = -minv_k;
  s.state_matrix.bottomRightCorner(n, n) = -minv_c;
  s.input_matrix = Matrix::Zero(2 * n, 2 * n_u);
  s.input_matrix.bottomLeftCorner(n, n_u) = minv_ku;
  s.input_matrix.bottomRightCorner(n, n_u) = minv_cu;

  Vector minv_f = Vector::Zero(n);
  if (generalized_force.size() != 0) {
    minv_f = mass_factor.solve(generalized_force);
    s.state_offset = Vector::Zero(2 * n);
    s.state_offset.tail(n) = minv_f;
  }

  const Matrix& h = system.output;
  s.output_matrix = Matrix::Zero(layout.size(), 2 * n);
  s.feedthrough_matrix = Matrix::Zero(layout.size(), 2 * n_u);
  s.output_offset = Vector::Zero(layout.size());
  for (OutputQuantity q : quantities) {
    const DofIndex r = layout.offset(q);
    switch (q) {
      case OutputQuantity::Displacement:
        s.output_matrix.block(r, 0, n_y, n) = h;
        break;
      case OutputQuantity::Velocity:
        s.output_matrix.block(r, n, n_y, n) = h;
        break;
      case OutputQuantity::Acceleration:
        // q'' = M^-1 (-K q - C q' + K_u u + C_u u' + f_g)
        s.output_matrix.block(r, 0, n_y, n).noalias() = -h * minv_k;
        s.output_matrix.block(r, n, n_y, n).noalias() = -h * minv_c;
        s.feedthrough_matrix.block(r, 0, n_y, n_u).noalias() = h * minv_ku;
        s.feedthrough_matrix.block(r, n_u, n_y, n_u).noalias() = h * minv_cu;
        s.output_offset.segment(r, n_y).noalias() = h * minv_f;
        break;
    }
  }
  s.output_names = layout.names();
  return s;
}

Vector roadInput(const Vector& heights, const Vector& rates) {
  detail::requireLength("roadInput", "rates u'", rates, heights.size());
  Vector w(2 * heights.size());
  w << heights, rates;
  return w;
}

Matrix roadInputSeries(const Matrix& heights, double dt) {
  detail::requireTimeStep("roadInputSeries", dt);
  const DofIndex n_t = heights.rows();
  const DofIndex n_u = heights.cols();
  if (n_t < 2)
    throw InputError("roadInputSeries: need at least 2 samples, got " + std::to_string(n_t));
  Matrix w(n_t, 2 * n_u);
  w.leftCols(n_u) = heights;
  auto rates = w.rightCols(n_u);
  rates.row(0) = (heights.row(1) - heights.row(0)) / dt;
  rates.row(n_t - 1) = (heights.row(n_t - 1) - heights.row(n_t - 2)) / dt;
  if (n_t > 2)
    rates.middleRows(1, n_t - 2) =
        (heights.bottomRows(n_t - 2) - heights.topRows(n_t - 2)) / (2.0 * dt);
  return w;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
