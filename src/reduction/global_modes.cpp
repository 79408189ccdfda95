#include "tracked_vehicle_dynamics/reduction/global_modes.h"

#include <Eigen/Eigenvalues>

#include <algorithm>

#include "tracked_vehicle_dynamics/reduction/mac.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

std::vector<bool> globalModes(const vehicle::VehicleModel& vehicle, const fem::System& system,
                              const fem::ModalBasis& modes) {
  std::vector<bool> global(static_cast<std::size_t>(modes.count()), false);
  for (const auto& [first, end] : degenerateGroups(modes.frequencies_hz)) {
    // max over unit x of x^T G x = the largest eigenvalue of the group's G (for one mode, G_jj).
    const Matrix g =
        vehicle::vehicleEnergy(vehicle, system, modes.shapes.middleCols(first, end - first));
    const double largest = g.rows() == 1
                               ? g(0, 0)
                               : Eigen::SelfAdjointEigenSolver<Matrix>(g, Eigen::EigenvaluesOnly)
                                     .eigenvalues()
                                     .maxCoeff();
    std::fill(global.begin() + first, global.begin() + end, largest >= kGlobalEnergyShare);
  }
  return global;
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
