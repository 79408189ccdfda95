// The vehicle's FE model (paper Fig. 2): a rigid hull with its Table 1 mass and inertia at the
// centre of gravity, a rigid "spider" of rigid joints from the hull node to the suspension pivots
// (and the sprockets, idlers, rollers and named points), torsion-bar trailing arms (an exact
// revolute joint about y plus a k_t spring), road wheels rigid with their arms, and track
// assemblies standing on ground springs (the road inputs).
//
//   Variant::Untracked  one assembly under each road wheel (the "minimal track chain", Fig. 2a)
//   Variant::Tracked    both closed chains of assemblies joined pin to pin by rigid joints,
//                       wrapping sprocket, idler and road wheels (Fig. 2b)
//
// Node ids are shared by both variants for the parts they have in common (hull, spider, arms,
// wheels, the assemblies under the wheels), so mode shapes can be compared node by node (MAC):
//   1                      hull centre of gravity
//   10 + i                 named point i
//   1000 + 100 s + 10 j    station j (0 = front) of side s (0 = left, +y; 1 = right):
//                          + 0 pivot on the hull, + 1 arm at the pivot, + 2 wheel centre,
//                          + 3 / + 4 contact patch on the wheel / on the link,
//                          + 5 / + 6 guide-horn contact on the wheel / on the link
//   2000 + 100 s           sprocket centre; + 1 idler centre; + 10 + r return roller r
//   100000 (s + 1) + 100 k track assembly k of side s (k = 0 at the rear end of the ground run,
//                          counting forward along the ground, then around the loop); + 60 / + 61
//                          its contact pair with a sprocket, idler or roller (tracked only)
//   500000 + 10000 s + 100 j  the assembly under station j (untracked only: centred under the
//                          wheel, while the chain's pitch does not fit the axle spacing)
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/fem/model.h"
#include "tracked_vehicle_dynamics/types.h"
#include "tracked_vehicle_dynamics/vehicle/track_assembly.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

/// Which vehicle model to build (see the file comment).
enum class Variant { Untracked, Tracked };

/// "untracked" / "tracked".
const char* variantName(Variant variant);
/// Parses "untracked" / "tracked"; throws InputError naming the text otherwise.
Variant parseVariant(const std::string& text);

/// "left" (side 0) / "right" (side 1).
const char* sideName(int side);
/// The name of a side's track assembly `index` (AssemblyRecord::index, its place in the chain
/// loop), e.g. "track_left_0"; the names of its springs start with it.
std::string assemblyName(int side, int index);
/// The name of a side's road wheel on axle `axle` (1 = front), e.g. "road_wheel_left_1": its
/// WheelStation's, and with " uz" its centre's output in a reduced model.
std::string roadWheelName(int side, int axle);

constexpr NodeId kHullNode = 1;

/// One road-wheel station.
struct WheelStation {
  std::string name;   ///< "road_wheel_<left|right>_<k>", k = 1 (front) ... N (rear),
                      ///< N = running_gear.axle_count (7 for the paper vehicle)
  int side = 0;       ///< 0 left (+y), 1 right (-y)
  int axle = 0;       ///< 0 front ... axle_count - 1 rear
  NodeId pivot = 0;   ///< on the hull (rigid-joint slave of the hull node)
  NodeId arm = 0;     ///< arm side of the revolute joint; its ry is the station's DOF
  NodeId centre = 0;  ///< wheel centre (slave of the arm)
  int assembly = -1;  ///< index into VehicleLayout::assemblies of the assembly it stands on
  std::size_t contact_spring = 0;  ///< index into Model::springs of its normal contact
};

/// One track assembly of the model.
struct AssemblyRecord {
  int side = 0;
  int index = 0;  ///< position k in the chain loop
  bool on_ground = false;
  TrackAssemblyNodes nodes;
};

/// A ground spring (road input): the pad sole node and where it stands.
struct RoadInput {
  NodeId node = 0;
  int side = 0;
  int assembly = 0;  ///< index into VehicleLayout::assemblies
  double x = 0.0;    ///< [m]
  double y = 0.0;    ///< [m]
  /// Where it reads the road [m]: x, or its pad's centre (ChainTieDescription::road_input_station).
  double road_x = 0.0;
  std::size_t spring = 0;  ///< index into Model::springs of its ground spring
};

/// The chain wheels a link can touch besides the road wheels (tracked only).
enum class ChainWheel { Sprocket, Idler, ReturnRoller };

/// "sprocket" / "idler" / "return_roller".
const char* chainWheelName(ChainWheel wheel);

/// A contact of a chain link with the sprocket, the idler or a return roller: a bushing from the
/// wheel's contact node (n1) to the link's (n2), both at the link's upper (inner) surface, in the
/// link's frame: x along the chain (travel direction), y lateral, z the loop's inward normal
/// (ChainPoint), which points from the link towards the wheel's centre. Its normal force
/// N = k_z z . (u_link - u_wheel) is compressive when positive: the link pushes the wheel along
/// +z, as a road wheel's patch (identity frame, z up) is pushed by its link.
struct ChainWheelContact {
  ChainWheel wheel = ChainWheel::Sprocket;
  int side = 0;            ///< 0 left, 1 right
  int roller = 0;          ///< return roller r (0-based, return_rollers.x order); 0 otherwise
  int assembly = 0;        ///< index into VehicleLayout::assemblies of the link
  std::size_t spring = 0;  ///< index into Model::springs (its name: "<wheel>_<side>_<k or r>")
};

/// Masses by part [kg].
struct MassBreakdown {
  double hull = 0.0;
  double road_wheels = 0.0;
  double track_assemblies = 0.0;
  double sprockets = 0.0;
  double idlers = 0.0;
  double return_rollers = 0.0;
  double total = 0.0;
};

/// Where everything is in the model.
struct VehicleLayout {
  Variant variant = Variant::Untracked;
  NodeId hull = kHullNode;
  std::vector<WheelStation> wheels;  ///< left 1..n then right 1..n
  std::vector<AssemblyRecord> assemblies;
  std::vector<RoadInput> road_inputs;  ///< in the order of the model's ground springs
  std::map<std::string, NodeId> named_points;
  std::vector<NodeId> sprockets, idlers, return_rollers;  ///< per side (tracked only)
  /// Per side (left first): the sprocket's and the idler's contacts in the chain order of their
  /// links (k ascending from the rear end of the ground run: on the paper's rear-drive vehicle
  /// the idler's come first), then one per return roller (tracked only; the same sequence on
  /// both sides).
  std::vector<ChainWheelContact> chain_wheel_contacts;
  double idler_x = 0.0;    ///< idler centre x set by the tensioner [m]
  PadSprings pad_springs;  ///< calibrated pad springs
  MassBreakdown mass;
  /// Node ids of the hull-attached bodies whose kinetic energy counts as "hull" in the mode
  /// classification besides the hull node (sprockets, idlers, rollers).
  std::vector<NodeId> hull_attached;
};

struct VehicleModel {
  fem::Model model;
  VehicleLayout layout;
};

/// The road station of every ground input, in the order of the assembled system's inputs
/// (fem::System::ground_inputs, which follow the model's ground springs). Throws std::logic_error
/// when the two lists disagree.
Vector roadInputStations(const VehicleLayout& layout,
                         const std::vector<fem::DofRef>& ground_inputs);

/// What a node of the model belongs to, for reports: "hull", "road_wheel_left_3 arm",
/// "track assembly left 17 sole", "sprocket right", a named point's name, ... ("node N" when
/// none of these).
std::string nodePart(const VehicleLayout& layout, NodeId node);

/// Builds the vehicle model of a description. Throws InputError (naming the description key)
/// when the description is inconsistent.
VehicleModel buildVehicleModel(const VehicleDescription& description, Variant variant);

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
