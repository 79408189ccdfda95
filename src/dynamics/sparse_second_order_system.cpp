#include "tracked_vehicle_dynamics/dynamics/sparse_second_order_system.h"

#include "tracked_vehicle_dynamics/dynamics/validation.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

SparseSecondOrderSystem toSparse(const SecondOrderSystem& system) {
  validateSystem(system);
  SparseSecondOrderSystem s;
  s.mass = system.mass.sparseView();
  s.damping = system.damping.sparseView();
  s.stiffness = system.stiffness.sparseView();
  s.input_stiffness = system.input_stiffness.sparseView();
  s.input_damping = system.input_damping.sparseView();
  s.output = system.output.sparseView();
  s.output_names = system.output_names;
  s.input_stations = system.input_stations;
  return s;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
