// The 1-D track assembly (paper §2.1.3, Fig. 6c, Table 3): a steel link of beams, two pins, and
// two rubber pads, each a rigid steel core between two layers of three spring columns (12
// springs in series and parallel). The pads' ground nodes ("soles") are the ground-contact points.
//
// Local frame of an assembly (columns of AssemblyFrame::axes): e1 along the chain in the travel
// direction, e2 = global y, e3 = e1 x e2 the inward normal (up on the ground run). The origin is
// the centre of the pad bottoms. Node layout, local coordinates (xi, eta, zeta):
//   link     5 nodes  (0, eta, h_p), eta in {-w/2, -e_p, 0, e_p, w/2}; beams across the track
//   pins     3 + 3    (+-d/2, eta, h_p), eta in {-w/2, 0, w/2}; d = pitch - pin_joint_distance
//   members  pins -> link node at eta in {-w/2, 0, w/2}: 6 beams, the chain's bending stiffness
//   pads     per pad (eta = +-e_p) and column (xi in {-c, 0, c}): sole (zeta = 0), core
//            (mid-core), top (pad top, rigid with the link node above it)
// with w the width, e_p the pad lateral offset, c the column offset and h_p the pitch line height.
#pragma once

#include <array>
#include <string>

#include "tracked_vehicle_dynamics/fem/model.h"
#include "tracked_vehicle_dynamics/types.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

/// Number of node ids an assembly reserves (ids base .. base + kAssemblyIdSpan - 1).
constexpr NodeId kAssemblyIdSpan = 100;

/// Spring constants of one pad spring column, lower and upper layer in series; calibrated so the
/// assembly reproduces the description's k_x, k_y, k_z and k_ry (calibrateTrackAssembly()).
struct PadSprings {
  double shear_x = 0.0;        ///< series stiffness of a column along e1 [N/m]
  double shear_y = 0.0;        ///< along e2 [N/m]
  double normal_end = 0.0;     ///< along e3, fore and aft columns [N/m]
  double normal_middle = 0.0;  ///< along e3, middle column [N/m]
  int iterations = 0;          ///< calibration iterations used
};

/// Position and orientation of an assembly: origin at the centre of the pad bottoms; columns of
/// `axes` are e1 (along the chain), e2 (= y), e3 (inward normal), in global coordinates.
struct AssemblyFrame {
  Vector3 origin = Vector3::Zero();
  Matrix3 axes = Matrix3::Identity();
};

/// Node ids of one assembly.
struct TrackAssemblyNodes {
  NodeId base = 0;
  std::array<NodeId, 5> link{};       ///< across the track, -y to +y; link[2] is the centre
  std::array<NodeId, 3> front_pin{};  ///< pin at +d/2 along e1, -y to +y
  std::array<NodeId, 3> rear_pin{};   ///< pin at -d/2 along e1
  std::array<NodeId, 6> soles{};      ///< pad ground nodes, 3 * pad + column
  std::array<NodeId, 6> cores{};      ///< pad core nodes (cores[1], cores[4] are the masters)
  std::array<NodeId, 6> tops{};       ///< pad top nodes (rigid with the link)

  NodeId linkCentre() const { return link[2]; }
  /// The link node each lane's fore/aft members meet at: lane i runs rear_pin[i] ->
  /// link[laneLink(i)] -> front_pin[i] (the chain's tension path).
  NodeId laneLink(int lane) const { return link[2 * lane]; }
};

/// Stiffness of an assembly measured on its FE model with the soles held (the paper's tests):
/// load on the link nodes, stiffness = total load / mean displacement of the loaded nodes.
struct TrackAssemblyStiffness {
  double kx = 0.0;   ///< [N/m]
  double ky = 0.0;   ///< [N/m]
  double kz = 0.0;   ///< [N/m]
  double kry = 0.0;  ///< moment about e2 shared over the link nodes / mean rotation [N m/rad]
};

/// Adds the materials and sections an assembly uses ("track_steel", "track_link_steel",
/// "track_pin", "track_link_member", "track_link_beam") unless the model already has them.
void addTrackAssemblyProperties(fem::Model& model, const TrackAssemblyDescription& description);

/// Adds one assembly (nodes base + 0..99, its beams, 12 pad springs, rigid joints, masses) and
/// returns its node ids. Needs addTrackAssemblyProperties() first. Ground contact is not added.
TrackAssemblyNodes addTrackAssembly(fem::Model& model, const TrackAssemblyDescription& description,
                                    const PadSprings& springs, const AssemblyFrame& frame,
                                    NodeId base, const std::string& name);

/// Finds pad spring constants that give the description's k_x, k_y, k_z and k_ry on the
/// assembly model (fixed-point iteration on the measured stiffnesses, converged to 1e-9).
/// Throws InputError "track_assembly.pad_column_offset" when the columns are too close together
/// for k_ry, InputError naming the stiffness key whose springs the iteration scales 1e8 times
/// away from the start (a target the steel link in series cannot give), and InputError naming
/// the stiffness key farthest off when the iteration does not converge in 100 steps;
/// SolverError when the assembly's stiffness matrix is not positive definite at the start
/// estimate (a stiffness or section many orders of magnitude too small).
PadSprings calibrateTrackAssembly(const TrackAssemblyDescription& description);

/// One assembly alone, soles held in translation (their rotations follow the pad core), as in the
/// paper's static analyses.
struct TrackAssemblyModel {
  fem::Model model;
  TrackAssemblyNodes nodes;
  PadSprings springs;
};

/// The calibrated stand-alone assembly model at the origin, e1 = x, e3 = z.
TrackAssemblyModel buildTrackAssemblyModel(const TrackAssemblyDescription& description);

/// Static stiffnesses of a stand-alone assembly model (four load cases on one factorisation).
TrackAssemblyStiffness measureTrackAssembly(const fem::Model& model,
                                            const TrackAssemblyNodes& nodes);

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
