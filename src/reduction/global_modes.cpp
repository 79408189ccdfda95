#include "tracked_vehicle_dynamics/reduction/global_modes.h"

#include <Eigen/Eigenvalues>

#include <algorithm>

#include "tracked_vehicle_dynamics/reduction/mac.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

std::vector<bool> globalModes(const vehicle::VehicleModel& vehicle, const fem::System& system,
                              const fem::ModalBasis& modes) {
  std::vector<bool> global(static_cast<std::size_t>(modes.count()), false);
  // One Gram matrix for all the modes (each body's rows of T are gathered once); a group's is its
  // diagonal block.
  const Matrix all = vehicle::vehicleEnergy(vehicle, system, modes.shapes);
  for (const auto& [first, end] : degenerateGroups(modes.frequencies_hz)) {
    // max over unit x of x^T G x = the largest eigenvalue of the group's G (for one mode, G_jj).
    const Eigen::Index n = end - first;
    const double largest = n == 1
                               ? all(first, first)
                               : Eigen::SelfAdjointEigenSolver<Matrix>(
                                     Matrix(all.block(first, first, n, n)), Eigen::EigenvaluesOnly)
                                     .eigenvalues()
                                     .maxCoeff();
    std::fill(global.begin() + first, global.begin() + end, largest >= kGlobalEnergyShare);
  }
  return global;
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
