// What moves in each mode, from its kinetic-energy distribution (mass-normalised shapes, so the
// energies of a mode sum to 1): the hull's six rigid-body components about its centre of gravity,
// the road wheels, and the rest (the track assemblies).
//
//   hull mode         hull share is the largest; labelled by its components that hold at least
//                     kComponentShare of the hull energy, strongest first:
//                     "longitudinal", "lateral", "bounce", "roll", "pitch", "yaw",
//                     e.g. "longitudinal+pitch"
//   wheel bounce      otherwise, when the wheels' motion relative to the hull (suspension travel)
//                     holds at least kWheelShare of the energy (in the tracked vehicle the chain
//                     under the wheels moves with them); "+<hull component>" is appended when the
//                     hull holds at least kCouplingShare of the energy, e.g. "wheel bounce+roll"
//   track chain local otherwise; "+<hull component>" is appended when the hull holds at least
//                     kChainCouplingShare of the energy, e.g. "track chain local+roll"
// The wheels' energy from riding along with the hull (rigid transport of the hull's motion to the
// wheel centre) counts as the hull's, so hull modes with heavy wheels stay hull modes.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

/// A hull component holding at least this share of the hull's kinetic energy names the mode.
constexpr double kComponentShare = 0.25;
/// Share of the energy in the wheels' relative motion that makes a non-hull mode a wheel mode.
constexpr double kWheelShare = 0.25;
/// A wheel mode names the hull's main component when the hull holds this share of the energy.
constexpr double kCouplingShare = 0.002;
/// A chain mode names the hull's main component when the hull holds this share of the energy.
constexpr double kChainCouplingShare = 0.1;

enum class ModeKind { Hull, WheelBounce, TrackLocal };

/// Hull rigid-body components, in the order of the hull node's DOFs (ux uy uz rx ry rz).
enum class HullMotion { Longitudinal = 0, Lateral, Bounce, Roll, Pitch, Yaw };

/// "longitudinal", "lateral", "bounce", "roll", "pitch", "yaw".
const char* hullMotionName(HullMotion motion);

struct ModeClass {
  ModeKind kind = ModeKind::TrackLocal;
  std::vector<HullMotion> hull_motions;  ///< components that name the mode, strongest first
  std::string label;                     ///< e.g. "longitudinal+pitch", "wheel bounce+roll"
  std::array<double, 6> hull_energy{};   ///< share of the mode's kinetic energy per component
  double hull_share = 0.0;               ///< hull and hull-attached bodies
  double wheel_share = 0.0;              ///< road wheels (and their arms)
  double track_share = 0.0;              ///< everything else: the track assemblies

  bool has(HullMotion m) const;
  /// Whether the mode is of a paper type (Table 4): "<primary>[+<secondary>]", e.g. "pitch",
  /// "lateral+roll", "wheel bounce" (case-insensitive). A hull type matches when its primary
  /// motion is the mode's strongest component and its secondary, if any, is among the mode's
  /// named components; "wheel bounce" matches any wheel-bounce mode, "wheel bounce+<motion>" one
  /// whose hull suffix is <motion>.
  bool matches(const std::string& paper_type) const;
};

/// Classifies each mode of `basis` (computed on `system`, the assembled vehicle model).
std::vector<ModeClass> classifyModes(const VehicleModel& vehicle, const fem::System& system,
                                     const fem::ModalBasis& basis);

/// The vehicle's share of the kinetic energy, between modes: G = sum_b (S_b Phi)^T M_b (S_b Phi)
/// over the hull, the bodies attached to it and the road wheels, for the columns of `shapes`,
/// each scaled by its own kinetic energy (G_jj = hull_share + wheel_share of classifyModes();
/// symmetric, k x k). For M-orthonormal modes of one repeated eigenvalue its largest eigenvalue is
/// the largest share any mode of that eigenspace holds, whichever basis the solver returned.
Matrix vehicleEnergy(const VehicleModel& vehicle, const fem::System& system,
                     const ModeShapes& shapes);

/// Translational DOFs (ux, uy, uz) of the nodes both models have, with the same id and position
/// (to 1e-9 m): hull, named points, spider and arm nodes, wheel centres. Sorted by node id.
std::vector<fem::DofRef> commonTranslationalDofs(const VehicleModel& a, const VehicleModel& b);

/// Physical displacements of `dofs` for every column of `shapes` (active-DOF vectors of
/// `system`), through the constraint transformation, so rigid-joint slaves and fixed DOFs are
/// included [dofs.size() x shapes.cols()]. Throws InputError for an unknown node.
Matrix physicalShapes(const fem::System& system, const std::vector<fem::DofRef>& dofs,
                      const ModeShapes& shapes);

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
