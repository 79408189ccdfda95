// Vehicle description: every parameter of the tracked vehicle, with its default (the paper's
// vehicle, Dimauro et al. 2024, Table 1 plus estimated geometry), loaded from a YAML file in
// which each value carries its unit and its source (config/vehicles/paper_vehicle.yaml).
//
// Frames follow REP-103: x forward, y left, z up. The origin lies on the ground plane (the pad
// bottoms of the ground run) under the hull reference point, which is the centre of the road-wheel
// wheelbase on the vehicle centre line. All values are SI (angles in rad) once loaded.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

/// Sprung mass: a rigid body at its centre of gravity.
struct HullDescription {
  double mass = 30300.0;         ///< m_s [kg]
  double roll_inertia = 3.9e4;   ///< I_x about the CoG [kg m^2]
  double pitch_inertia = 1.4e5;  ///< I_y about the CoG [kg m^2]
  double yaw_inertia = 1.6e5;    ///< I_z about the CoG [kg m^2]
  double cog_height = 1.57;      ///< h_G above the ground plane [m]
  double cog_x = 0.12;           ///< CoG ahead of the wheelbase centre [m]
  double length = 7.6;           ///< envelope L [m]
  double width = 3.42;           ///< envelope B [m]
  double height = 2.2;           ///< envelope H [m]
};

/// Road-wheel stations: `axle_count` per side, front to rear, centred on x = 0.
struct RunningGearDescription {
  int axle_count = 7;
  double axle_spacing = 0.78;          ///< l [m]
  double track_centre_distance = 2.8;  ///< b, between the track centre lines [m]
};

/// One road-wheel station's unsprung mass (wheel pair, hub and arm), rigid with its arm.
struct RoadWheelDescription {
  double mass = 1200.0;        ///< m_u [kg]
  double radius = 0.34;        ///< rolling radius on the link's upper surface [m]
  double spin_inertia = 69.0;  ///< about the wheel axle (y) [kg m^2]
  double tilt_inertia = 45.0;  ///< about x and z through the wheel centre [kg m^2]
};

/// Torsion-bar suspension: a trailing arm pivoting about a lateral axis ahead of and above the
/// wheel centre, x_p = x_w + a cos(beta), z_p = z_w + a sin(beta). The wheel is rigid with its arm
/// and stands on its track assembly through a contact patch on the link's upper surface (normal
/// and longitudinal force) and the guide horn (lateral force).
struct SuspensionDescription {
  double torsion_bar_stiffness = 5.2e5;  ///< k_t [N m/rad]
  double arm_length = 0.58;              ///< a, pivot to wheel centre [m]
  /// beta, static arm angle, pivot above the wheel centre [rad]
  double arm_angle = 9.0 * (kPi / 180.0);
  double pivot_y = 0.98;            ///< |y| of the pivots (hull side walls) [m]
  double contact_stiffness = 2e10;  ///< k_w, normal to the track [N/m]
  /// Along the chain at each road wheel's contact patch [N/m]: the wheel has no spin DOF, so
  /// this is a locked wheel when high, a rolling one when low.
  double contact_shear_stiffness = 2e10;
  /// Across the chain [N/m]: the guide horns against the road wheels' rims, and the sprockets',
  /// idlers' and rollers' lateral hold on the links. Optional in a description file
  /// (suspension.guide_stiffness); unset, it is contact_shear_stiffness (guideStiffness()), so a
  /// rolling wheel (low contact_shear_stiffness) can keep its lateral guidance.
  std::optional<double> guide_stiffness;
  double guide_contact_height = 0.09;  ///< guide horn-rim contact above the link surface [m]
  double arm_damping = 0.0;            ///< rotary damper at each damped station [N m s/rad]
};

/// The lateral stiffness the model uses: guide_stiffness when given, else contact_shear_stiffness.
inline double guideStiffness(const SuspensionDescription& s) {
  return s.guide_stiffness.value_or(s.contact_shear_stiffness);
}

/// The track assembly (link, two pins, two pads) and the chain it forms.
struct TrackAssemblyDescription {
  int count = 92;                          ///< assemblies per side
  int ground_count = 30;                   ///< assemblies per side on the ground
  double chain_length = 14.858;            ///< per side [m]
  double ground_length = 4.845;            ///< ground-contact length per side [m]
  double pitch = 0.1615;                   ///< assembly pitch [m]
  double pin_joint_distance = 0.065;       ///< between pins of adjacent assemblies [m]
  double mass = 27.0;                      ///< m_t [kg]
  double shear_stiffness_x = 1.4e6;        ///< k_x [N/m]
  double shear_stiffness_y = 3.4e6;        ///< k_y [N/m]
  double compression_stiffness = 1.895e7;  ///< k_z [N/m]
  double torsional_stiffness_y = 6.3e4;    ///< k_ry [N m/rad]
  double width = 0.62;                     ///< across the track [m]
  double pitch_line_height = 0.063;        ///< pin axes above the pad bottom [m]
  double upper_surface_height = 0.093;     ///< wheel path above the pad bottom [m]
  double pad_lateral_offset = 0.155;       ///< |y| of each pad's centre from the track centre [m]
  double pad_column_offset = 0.070;        ///< fore/aft spring columns from the pad centre [m]
  double pad_rubber_below_core = 0.015;    ///< [m]
  double pad_rubber_above_core = 0.015;    ///< [m]
  double pad_core_thickness = 0.003;       ///< steel core plate [m]
  double pad_mass = 1.5;                   ///< each pad, rubber and core [kg]
  double pad_sole_mass_fraction = 0.3;     ///< share of a pad's mass lumped at its ground nodes
  double pin_diameter = 0.030;             ///< [m]
  double steel_young_modulus = 205e9;      ///< [Pa]
  double steel_poisson_ratio = 0.29;       ///< [-]
  double steel_density = 7850.0;           ///< [kg/m^3]
  /// Fore/aft link members (pins to link centre), one of three across the width: they give the
  /// chain its bending stiffness about y (rigid pin joints, paper §2.2).
  double link_member_area = 1.2e-3;              ///< [m^2]
  double link_member_bending_inertia = 1.1e-8;   ///< about the lateral axis, chain bending [m^4]
  double link_member_lateral_inertia = 1.0e-6;   ///< about the normal axis [m^4]
  double link_member_torsion_constant = 2.0e-8;  ///< [m^4]
  /// Transverse link beam (across the track).
  double link_beam_area = 2.0e-3;              ///< [m^2]
  double link_beam_bending_inertia = 4.0e-7;   ///< about the tangential axis (pads' load) [m^4]
  double link_beam_inplane_inertia = 4.0e-6;   ///< about the normal axis [m^4]
  double link_beam_torsion_constant = 3.0e-7;  ///< [m^4]
  /// Static track tension, the tensioner's pre-load in each chain [N]. Optional in a description
  /// file (track_assembly.static_tension); unset or 0, the chain is a free-length beam loop (the
  /// paper's model). The tracked variant carries it as a pre-stress (vehicle/track_tension.h).
  std::optional<double> static_tension;
};

/// The rear drive sprocket; rigid with the hull (held by the final drive and brakes).
struct SprocketDescription {
  double radius = 0.334;    ///< pitch-line radius: the chain's pin axes wrap this circle [m]
  double centre_x = -3.05;  ///< [m]
  double centre_z = 0.78;   ///< [m]
  double mass = 1100.0;     ///< [kg]
  double inertia = 55.0;    ///< about each axis through its centre [kg m^2]
};

/// The front idler; rigid with the hull. Its x is not an input: the track tensioner sets it so
/// that the chain loop closes (chainPath() solves it).
struct IdlerDescription {
  double radius = 0.33;    ///< pitch-line radius [m]
  double centre_z = 0.62;  ///< [m]
  double mass = 700.0;     ///< [kg]
  double inertia = 35.0;   ///< about each axis through its centre [kg m^2]
};

/// Return rollers carrying the top run.
struct ReturnRollerDescription {
  std::vector<double> x;  ///< stations [m]; empty = no rollers
  double radius = 0.15;   ///< pitch-line radius [m]
  double mass = 0.0;      ///< each [kg]
};

/// Where along the path a pad ground node reads the road, u_q = h(s + x_q, y_q)
/// (road_excitation.h).
enum class RoadInputStation {
  /// At its pad's centre: the three sole columns of a pad share one height, so a pad transmits
  /// every wavelength (no contact-length filter inside a pad). The paper's reading: its
  /// un-tracked road wheels, each on one assembly, respond the same at every speed (§4.1.3).
  PadCentre,
  /// At the sole column's own station (0.14 m apart along a pad): the pad averages wavelengths
  /// of the order of its length, as a tyre's contact patch does.
  Sole,
};

/// How the chain is tied to the running gear and the ground.
struct ChainTieDescription {
  double ground_stiffness = 2e10;  ///< each pad ground node, x y z (rigid road) [N/m]
  RoadInputStation road_input_station = RoadInputStation::PadCentre;
};

/// Damping model for the dynamics stage (paper eq. 20 uses modal damping ratios).
enum class DampingModel { Modal, Rayleigh };

struct DampingDescription {
  DampingModel model = DampingModel::Modal;
  double modal_ratio = 0.05;         ///< zeta of every mode [-]
  double rayleigh_alpha = 0.0;       ///< C = alpha M + beta K [1/s]
  double rayleigh_beta = 0.0;        ///< [s]
  std::vector<int> damped_stations;  ///< axle numbers 1..axle_count with a rotary arm damper
};

/// A named point of the hull (crew seat, sensor mount), rigid with the hull.
struct NamedPoint {
  std::string name;
  Vector3 position = Vector3::Zero();  ///< [m]
};

/// How far the sprocket and idler wheels may reach beyond the hull's ends [m] (validation).
constexpr double kWheelOverhang = 0.5;

/// Every parameter of the vehicle. Defaults are the paper vehicle (config/vehicles/
/// paper_vehicle.yaml holds the same values with units and sources).
struct VehicleDescription {
  std::string name = "paper_vehicle";
  HullDescription hull;
  RunningGearDescription running_gear;
  RoadWheelDescription road_wheel;
  SuspensionDescription suspension;
  TrackAssemblyDescription track_assembly;
  SprocketDescription sprocket;
  IdlerDescription idler;
  ReturnRollerDescription return_rollers;
  ChainTieDescription ties;
  DampingDescription damping;
  std::vector<NamedPoint> named_points{{"crew_seat", Vector3(2.4, 0.55, 1.15)},
                                       {"sensor_mount", Vector3(0.3, 0.0, 2.2)}};
  /// Key path -> source text, as read from the file (not part of the hash).
  std::map<std::string, std::string> sources;
  /// Where it was read from, for messages (not part of the hash).
  std::string origin = "vehicle description";
  /// Key path (e.g. "sprocket.centre_z") -> its line in `origin`, for messages raised after
  /// loading (the model builder's geometric checks); empty for a description made in code (not
  /// part of the hash).
  std::map<std::string, int> key_lines;
};

/// `message` with " (line N)" appended when it reads "<origin>: <key path>: ..." and the key's
/// line is known (VehicleDescription::key_lines); otherwise unchanged.
std::string withKeyLine(const VehicleDescription& description, const std::string& message);

/// Reads a description file. Every key is required except suspension.guide_stiffness and
/// track_assembly.static_tension; each value is a map
/// {value: <number or list>, unit: <string>, source: <string>} (damping.model and
/// ties.road_input_station, names: {value, source}) and the unit must be the one the key expects
/// (e.g. "m", not "mm"). Another of the package's files (a model, a terrain) is named as such.
/// Throws InputError "<file>: <key path>: <what> (line N)" for a missing or unknown key, a wrong
/// unit, a non-finite or out-of-range value, and, through validateDescription(), for inconsistent
/// values.
VehicleDescription loadVehicleDescription(const std::string& path);

/// Same from YAML text; `file` names the source in messages.
VehicleDescription parseVehicleDescription(const std::string& text, const std::string& file);

/// Whether the sprocket is the front wheel of the chain loop (sprocket.centre_x > 0, a front
/// drive), the idler then standing behind the ground run.
bool frontDrive(const VehicleDescription& d);

/// Height of the road-wheel centres above the ground at static equilibrium [m]: the wheels rest
/// on the links' upper surface.
double wheelCentreZ(const VehicleDescription& d);

/// What a valid description may still get physically wrong, one sentence each, starting with the
/// key (the tools print them as warnings; nothing is changed): no damping at all (resonances
/// without bound, vibrations that never decay); a hull centre of gravity far enough off the
/// wheelbase centre to unload the far suspensions (sum x_i^2 / (n x_N)) or lift the far wheels
/// (the linear model's ground then pulls the vehicle down); a CoG below the arm pivots; a hull
/// mass or inertia that reads as another unit (a mass below the road wheels', a radius of
/// gyration beyond the hull's diagonal or below 5 % of its smallest dimension); a static
/// tension above half the weight.
std::vector<std::string> descriptionWarnings(const VehicleDescription& d);

/// Checks ranges and consistency (chain length = pitch x count, ground-contact assemblies not
/// more than the chain has, the wheelbase fits on the ground run, ...). Throws InputError
/// "<where>: <key path>: <what>".
void validateDescription(const VehicleDescription& description,
                         const std::string& where = "vehicle");

/// Canonical text of every value (key path = value in SI, fixed order, 17 significant digits);
/// sources and comments are excluded.
std::string canonicalDescription(const VehicleDescription& description);

/// FNV-1a 64 hash of canonicalDescription(): identifies a description in the reduced-model cache.
std::uint64_t descriptionHash(const VehicleDescription& description);

/// The hash as 16 lowercase hex digits.
std::string descriptionHashHex(const VehicleDescription& description);

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
