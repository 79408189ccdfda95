#include "tracked_vehicle_dynamics/dynamics/travel_inertia.h"

#include <string>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

namespace {

// Appends one entry to a per-input vector (station or lateral position), left empty when empty.
Vector appended(const Vector& v, double value) {
  if (v.size() == 0)
    return v;
  Vector out(v.size() + 1);
  out << v, value;
  return out;
}

}  // namespace

SecondOrderSystem withTravelInertia(const SecondOrderSystem& system, const Vector& travel_load) {
  const DofIndex n = system.size();
  if (travel_load.size() != n)
    throw InputError("travel inertia: the load has " + std::to_string(travel_load.size()) +
                     " entries, the system " + std::to_string(n) + " coordinates");
  if (!travel_load.allFinite())
    throw InputError("travel inertia: the load has a non-finite entry");
  SecondOrderSystem out = system;
  const DofIndex n_u = system.inputCount();
  out.input_stiffness.resize(n, n_u + 1);
  out.input_stiffness << system.input_stiffness, travel_load;
  out.input_damping.resize(n, n_u + 1);
  out.input_damping << system.input_damping, Vector::Zero(n);
  // The travel input reads no road; 0 only keeps one entry per input.
  out.input_stations = appended(system.input_stations, 0.0);
  out.input_lateral = appended(system.input_lateral, 0.0);
  return out;
}

Matrix withTravelInput(const Matrix& inputs, const Vector& acceleration) {
  if (inputs.cols() % 2 != 0 || acceleration.size() != inputs.rows())
    throw InputError("travel inertia: inputs [" + std::to_string(inputs.rows()) + " x " +
                     std::to_string(inputs.cols()) + "] are not rows [u, u'] with one of the " +
                     std::to_string(acceleration.size()) + " accelerations each");
  const DofIndex n_u = inputs.cols() / 2;
  Matrix out(inputs.rows(), 2 * (n_u + 1));
  out << inputs.leftCols(n_u), acceleration, inputs.rightCols(n_u), Vector::Zero(inputs.rows());
  return out;
}

void widenTravelInput(const Eigen::Ref<const Vector>& inputs, double acceleration,
                      Eigen::Ref<Vector> widened) {
  const DofIndex n_u = inputs.size() / 2;
  if (inputs.size() % 2 != 0 || widened.size() != 2 * (n_u + 1))
    throw InputError("travel inertia: an input vector of " + std::to_string(inputs.size()) +
                     " entries does not widen into " + std::to_string(widened.size()));
  widened.head(n_u) = inputs.head(n_u);
  widened(n_u) = acceleration;
  widened.segment(n_u + 1, n_u) = inputs.tail(n_u);
  widened(2 * n_u + 1) = 0.0;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
