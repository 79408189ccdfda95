// Static track tension as a pre-stress of the chain loop (track_assembly.static_tension).
//
// At rest the tensioner holds each chain at a tension T, the same all round the loop when
// nothing drives it (no drive torque, the chain's own weight neglected). The linear model keeps
// the static solution of gravity and adds what the tension changes about small motions: the
// geometric stiffness of every tensioned member (fem/geometric_stiffness.h), which makes a free
// span a taut string, f = sqrt(T / mu) / (2 L) for a span of length L and mass mu per metre.
#pragma once

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/fem/model.h"
#include "tracked_vehicle_dynamics/vehicle/track_assembly.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

/// One closed chain: its assemblies in loop order (each one's front pins are joined by rigid
/// joints to the next one's rear pins).
struct ChainLoop {
  std::vector<TrackAssemblyNodes> assemblies;
  const char* side = "";  ///< "left" / "right", for item names
};

/// Puts tension T [N] into a chain that is already in `model`:
///  - each lane's two fore/aft link members carry T / 3 (a straight chain under T stretches its
///    three identical lanes alike, so each takes a third);
///  - each rigid pin-to-pin joint (65 mm between the pins, paper §2.2) becomes a tie of T / 3:
///    the joint is rigid, but turning its length under load takes work like a member's;
///  - the tension's pull where the loop turns (wraps and the ground run's ends) is reacted by the
///    wheels, which hang on the hull: a BodyPreload on `hull` takes the loop's stiffness to
///    a rigid rotation back, so the vehicle as a whole turns freely as before. The end road
///    wheels' share goes to the hull too (their arms' own turning under it is left out).
/// Nothing is added for T = 0.
void addChainTension(fem::Model& model, const ChainLoop& chain, NodeId hull, double tension);

/// The tension the variant's model carries per chain [N]: the description's for the tracked
/// variant, 0 for the un-tracked one (no loop) or when not given.
double modelTrackTension(const VehicleDescription& description, Variant variant);

/// One line for reports: what the model does with track_assembly.static_tension ("" when it is
/// not given). Tracked: the tension and that its forces on the wheels are not in the static
/// loads; un-tracked: that it is not used.
std::string trackTensionText(const VehicleDescription& description, Variant variant);

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
