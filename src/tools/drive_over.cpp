#include "drive_over.h"

#include <algorithm>

#include "tracked_vehicle_dynamics/dynamics/static_equilibrium.h"

namespace tracked_vehicle_dynamics {
namespace tools {

void driveOver(dynamics::Simulator& sim, const dynamics::SecondOrderSystem& system, const Vector& gravity,
               const Drive& drive, const dynamics::RoadExcitation& road, const terrain::TerrainLines& lines,
               const reduction::FullModelReference* full, const SampleSink& sink) {
  // Start from static equilibrium on the entry of the track, at rest relative to it.
  const Vector w0 = drive.denseInputs(road, lines, 0, 1).row(0).transpose();
  sim.reset(dynamics::staticEquilibrium(system, w0.head(road.inputCount()), gravity), w0);
  // Blocks of samples: the road inputs sampled ahead, then Simulator::simulate(), which turns
  // the per-step matrix-vector products into matrix products. Row 0 of a block is the last
  // sample of the previous one (the simulator's current input), so it is handed on only once.
  // At constant speed the reduced model takes the inputs stored by their changes (sampled only
  // where the terrain under a contact is not flat, shared by contacts on the same profile); the
  // full model's static residual and a varying speed take every sample.
  constexpr long kBlock = 16384;
  const long steps = drive.steps();
  for (long first = 0; first == 0 || first < steps; first += kBlock) {
    const long count = std::min(first + kBlock, steps) - first + 1;
    Matrix y;
    if (full || drive.varyingSpeed()) {
      const Matrix w = drive.denseInputs(road, lines, first, count);
      y = sim.simulate(w);
      // The full model adds its static residual to the displacements (rows 0..n_y-1).
      if (full) full->addResidual(w, dynamics::OutputQuantity::Displacement, y.leftCols(system.outputCount()));
    } else {
      y = sim.simulate(drive.heldInputs(road, lines, first, count));
    }
    for (long j = first == 0 ? 0 : 1; j < y.rows(); ++j) sink(first + j, y.row(j));
  }
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
