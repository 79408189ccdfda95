#include "tracked_vehicle_dynamics/dynamics/validation.h"

#include "checks.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

namespace {

template <typename System>
void validateCommon(const std::string& where, const System& s) {
  const DofIndex n = s.stiffness.rows();
  if (n == 0)
    throw InputError(where + ": the system has no degree of freedom");
  const DofIndex n_inputs = s.input_stiffness.cols();
  detail::requireSize(where, "stiffness K", s.stiffness, n, n);
  detail::requireSize(where, "mass M", s.mass, n, n);
  detail::requireSize(where, "damping C", s.damping, n, n);
  detail::requireSize(where, "input stiffness K_u", s.input_stiffness, n, n_inputs);
  detail::requireSize(where, "input damping C_u", s.input_damping, n, n_inputs);
  detail::requireSize(where, "output H", s.output, s.output.rows(), n);
  if (!s.output_names.empty())
    detail::requireLength(where, "output_names", s.output_names, s.output.rows());
  if (s.input_stations.size() != 0)
    detail::requireLength(where, "input_stations", s.input_stations, n_inputs);
}

}  // namespace

void validateSystem(const SecondOrderSystem& system) {
  const std::string where = "SecondOrderSystem";
  validateCommon(where, system);
  if (system.input_lateral.size() != 0)
    detail::requireLength(where, "input_lateral", system.input_lateral, system.inputCount());
}

void validateSystem(const SparseSecondOrderSystem& system) {
  validateCommon("SparseSecondOrderSystem", system);
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
