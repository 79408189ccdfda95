#include "drive_over.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "tracked_vehicle_dynamics/dynamics/static_equilibrium.h"
#include "tracked_vehicle_dynamics/dynamics/travel_inertia.h"

namespace tracked_vehicle_dynamics {
namespace tools {

void driveOver(dynamics::Simulator& sim, const dynamics::SecondOrderSystem& system,
               const Vector& gravity, const Drive& drive, const dynamics::RoadExcitation& road,
               const terrain::TerrainLines& lines, const reduction::FullModelReference* full,
               const SampleSink& sink, dynamics::GroundContactForces* contact,
               const ForceSink& force_sink) {
  // The travel acceleration rides as one more input after the road's (travel_inertia.h).
  const bool travel = system.inputCount() == road.inputCount() + 1;
  if (!travel && system.inputCount() != road.inputCount())
    throw std::logic_error("driveOver: the system has " + std::to_string(system.inputCount()) +
                           " inputs for " + std::to_string(road.inputCount()) + " road inputs");
  auto inputs = [&](long first, long count) {
    Matrix w = drive.denseInputs(road, lines, first, count);
    if (!travel)
      return w;
    Vector a(count);
    for (long j = 0; j < count; ++j)
      a(j) = drive.acceleration(first + j);
    return dynamics::withTravelInput(w, a);
  };
  // Start from static equilibrium on the entry of the track, at rest relative to it, under gravity
  // alone: a travel acceleration a(0) != 0 acts from t = 0 on as a step (drive_over.h).
  const Vector w0 = inputs(0, 1).row(0).transpose();
  Vector u0 = w0.head(system.inputCount());
  if (travel)
    u0(road.inputCount()) = 0.0;
  const Vector z0 = dynamics::staticEquilibrium(system, u0, gravity);
  sim.reset(z0, w0);
  if (contact)
    contact->reset(z0, w0);
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
    // The contact forces of the block's samples, less its row 0 after the first block (as y).
    const auto forces = [&](long j, const Eigen::Ref<const Matrix>& f) {
      const long drop = first > 0 && j == 0 ? 1 : 0;
      if (force_sink && f.rows() > drop)
        force_sink(first + j + drop, f.bottomRows(f.rows() - drop));
    };
    Matrix y;
    if (full || drive.varyingSpeed() || travel) {
      const Matrix w = inputs(first, count);
      y = sim.simulate(w);
      // The full model adds its static residual to the displacements (rows 0..n_y-1).
      if (full)
        full->addResidual(w, dynamics::OutputQuantity::Displacement,
                          y.leftCols(system.outputCount()));
      if (contact)
        contact->simulate(w, forces);
    } else {
      const dynamics::HeldInputSeries w = drive.heldInputs(road, lines, first, count);
      y = sim.simulate(w);
      if (contact)
        contact->simulate(w, forces);
    }
    for (long j = first == 0 ? 0 : 1; j < y.rows(); ++j)
      sink(first + j, y.row(j));
  }
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
