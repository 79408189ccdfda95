// Runs a simulator over a whole Drive (drive.h), from static equilibrium at the track's entry,
// handing every output sample to the caller: the loop `tvd simulate` and `tvd ride` share.
#pragma once

#include <functional>

#include "drive.h"
#include "output_row.h"
#include "tracked_vehicle_dynamics/dynamics/ground_contact_forces.h"
#include "tracked_vehicle_dynamics/dynamics/road_excitation.h"
#include "tracked_vehicle_dynamics/dynamics/simulator.h"
#include "tracked_vehicle_dynamics/reduction/full_model_reference.h"
#include "tracked_vehicle_dynamics/terrain/terrain_lines.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace tools {

/// Called once per sample k = 0 .. drive.steps() with the outputs at that sample.
using SampleSink = std::function<void(long k, const OutputRow& outputs)>;
/// Called once per chunk with the ground contact forces [rows x contacts] of samples first ..
/// first + rows - 1 (ground_contact_forces.h), in order.
using ForceSink = std::function<void(long first, const Eigen::Ref<const Matrix>& forces)>;

/// Resets `sim` (built from `system`) to static equilibrium under `gravity` on the road inputs of
/// sample 0, at rest relative to the track, then steps it through every sample of `drive`.
/// When `system` has one input more than `road` it is a travel-inertia system
/// (dynamics::withTravelInertia, travel_inertia.h) and that input carries the drive's forward
/// acceleration a(t) (drive.acceleration(k)). The static start is under gravity alone (a = 0): the
/// displacements are then reported from the vehicle's rest state whatever the profile does, and a
/// profile that brakes or accelerates from t = 0 applies a(0) as a step when the run starts.
/// `full`, when given, is the full model whose static residual is added to the displacements
/// (system = full->modal). At constant speed without `full` the inputs are sampled by their
/// changes (sampleHeldSeries), otherwise every input at every sample.
/// `contact`, when given (built on `system` with the options of `sim`), is reset and driven
/// alongside `sim` with the same inputs, and its forces go to `force_sink`.
void driveOver(dynamics::Simulator& sim, const dynamics::SecondOrderSystem& system,
               const Vector& gravity, const Drive& drive, const dynamics::RoadExcitation& road,
               const terrain::TerrainLines& lines, const reduction::FullModelReference* full,
               const SampleSink& sink, dynamics::GroundContactForces* contact = nullptr,
               const ForceSink& force_sink = {});

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
