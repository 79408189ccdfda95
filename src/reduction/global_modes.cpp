#include "tracked_vehicle_dynamics/reduction/global_modes.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <stdexcept>
#include <string>

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

Matrix globalPairs(Matrix mac, const std::vector<bool>& row_global,
                   const std::vector<bool>& column_global) {
  if (static_cast<Eigen::Index>(row_global.size()) != mac.rows() ||
      static_cast<Eigen::Index>(column_global.size()) != mac.cols())
    throw std::logic_error("globalPairs: " + std::to_string(row_global.size()) + " x " +
                           std::to_string(column_global.size()) + " flags for a " +
                           std::to_string(mac.rows()) + " x " + std::to_string(mac.cols()) +
                           " MAC");
  for (Eigen::Index j = 0; j < mac.rows(); ++j)
    if (!row_global[static_cast<std::size_t>(j)])
      mac.row(j).setZero();
  for (Eigen::Index k = 0; k < mac.cols(); ++k)
    if (!column_global[static_cast<std::size_t>(k)])
      mac.col(k).setZero();
  return mac;
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
