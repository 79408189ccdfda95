#include "tracked_vehicle_dynamics/vehicle/track_assembly.h"

#include <cmath>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/sparse_cholesky.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/io/number_text.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

namespace {

/// Calibration stops when every stiffness matches its target to this relative error.
constexpr double kCalibrationTolerance = 1e-9;
constexpr int kMaxCalibrationIterations = 100;
/// A pad spring the calibration has scaled this far (up or down) from the rigid-link start is
/// chasing a target the assembly cannot give. Well before the stiffness matrix loses definiteness
/// to round-off (springs ~1e16 times the link's, in the tests), and well beyond a slow but
/// converging run (about 1.14^100 = 5e5 when it stalls 14 % short).
constexpr double kRunawayFactor = 1e8;

// Local node numbers inside an assembly's id span.
constexpr NodeId kLink = 0, kFrontPin = 10, kRearPin = 20, kSole = 30, kCore = 40, kTop = 50;

const char* const kSteel = "track_steel";
const char* const kLinkSteel = "track_link_steel";
const char* const kPinSection = "track_pin";
const char* const kMemberSection = "track_link_member";
const char* const kBeamSection = "track_link_beam";

double pinDistance(const TrackAssemblyDescription& t) {
  return t.pitch - t.pin_joint_distance;
}

double pinMass(const TrackAssemblyDescription& t) {
  return 2.0 * t.steel_density * 0.25 * kPi * t.pin_diameter * t.pin_diameter * t.width;
}

// Total length x area of the link's beams (members and transverse beam), to spread the link mass.
double linkVolume(const TrackAssemblyDescription& t) {
  return 6.0 * 0.5 * pinDistance(t) * t.link_member_area + t.width * t.link_beam_area;
}

double linkMass(const TrackAssemblyDescription& t) {
  return t.mass - 2.0 * t.pad_mass - pinMass(t);
}

/// Each pad spans from its centre line to the track edge on both sides: w_p = w - 2 e_p.
double padWidth(const TrackAssemblyDescription& t) {
  return t.width - 2.0 * t.pad_lateral_offset;
}

double padHeight(const TrackAssemblyDescription& t) {
  return t.pad_rubber_below_core + t.pad_core_thickness + t.pad_rubber_above_core;
}

}  // namespace

void addTrackAssemblyProperties(fem::Model& model, const TrackAssemblyDescription& t) {
  if (model.findMaterial(kSteel))
    return;
  if (!(linkMass(t) > 0.0))
    throw InputError("track_assembly.mass: " + brief(t.mass) +
                     " kg does not cover the two pads (2 x track_assembly.pad_mass " +
                     brief(t.pad_mass) + " kg) and the pins (" + brief(pinMass(t)) +
                     " kg, from track_assembly.pin_diameter and steel_density): " +
                     brief(2.0 * t.pad_mass + pinMass(t)) + " kg");
  const double g = t.steel_young_modulus / (2.0 * (1.0 + t.steel_poisson_ratio));
  model.materials.push_back({kSteel, t.steel_young_modulus, g, t.steel_density});
  // The link's beams carry the link's mass (cast body, guide horn, bushings): an equivalent
  // density over their volume.
  model.materials.push_back({kLinkSteel, t.steel_young_modulus, g, linkMass(t) / linkVolume(t)});
  const double d = t.pin_diameter;
  const double i_pin = kPi * std::pow(d, 4) / 64.0;
  model.sections.push_back({kPinSection, 0.25 * kPi * d * d, i_pin, i_pin, 2.0 * i_pin, 0.0, 0.0});
  // Members run along e1 with orientation e3: local y = e2 (chain bending), local z = e3.
  model.sections.push_back({kMemberSection, t.link_member_area, t.link_member_bending_inertia,
                            t.link_member_lateral_inertia, t.link_member_torsion_constant, 0.0,
                            0.0});
  // The transverse beam runs along e2 with orientation e3: local y = -e1, bending under the pad
  // loads is about local y.
  model.sections.push_back({kBeamSection, t.link_beam_area, t.link_beam_bending_inertia,
                            t.link_beam_inplane_inertia, t.link_beam_torsion_constant, 0.0, 0.0});
}

TrackAssemblyNodes addTrackAssembly(fem::Model& model, const TrackAssemblyDescription& t,
                                    const PadSprings& springs, const AssemblyFrame& frame,
                                    NodeId base, const std::string& name) {
  const Matrix3& r = frame.axes;
  auto at = [&](double xi, double eta, double zeta) {
    return Vector3(frame.origin + r * Vector3(xi, eta, zeta));
  };
  const double w = t.width, ep = t.pad_lateral_offset, c = t.pad_column_offset;
  const double hp = t.pitch_line_height, half_d = 0.5 * pinDistance(t);
  const double z_core = t.pad_rubber_below_core + 0.5 * t.pad_core_thickness;
  const double z_top = padHeight(t);
  const Vector3 e3 = r.col(2);

  TrackAssemblyNodes n;
  n.base = base;
  const double link_eta[5] = {-0.5 * w, -ep, 0.0, ep, 0.5 * w};
  const double pin_eta[3] = {-0.5 * w, 0.0, 0.5 * w};
  const double column_xi[3] = {-c, 0.0, c};
  for (int i = 0; i < 5; ++i)
    n.link[i] = model.addNode(base + kLink + i, at(0, link_eta[i], hp));
  for (int i = 0; i < 3; ++i) {
    n.front_pin[i] = model.addNode(base + kFrontPin + i, at(half_d, pin_eta[i], hp));
    n.rear_pin[i] = model.addNode(base + kRearPin + i, at(-half_d, pin_eta[i], hp));
  }
  for (int p = 0; p < 2; ++p)
    for (int k = 0; k < 3; ++k) {
      const int j = 3 * p + k;
      const double eta = p == 0 ? -ep : ep;
      n.soles[j] = model.addNode(base + kSole + j, at(column_xi[k], eta, 0.0));
      n.cores[j] = model.addNode(base + kCore + j, at(column_xi[k], eta, z_core));
      n.tops[j] = model.addNode(base + kTop + j, at(column_xi[k], eta, z_top));
    }

  // Link: transverse beam and the fore/aft members to the pins; pins across the track.
  for (int i = 0; i < 4; ++i)
    model.beams.push_back({n.link[i], n.link[i + 1], kLinkSteel, kBeamSection, e3});
  for (int i = 0; i < 3; ++i) {
    model.beams.push_back({n.rear_pin[i], n.laneLink(i), kLinkSteel, kMemberSection, e3});
    model.beams.push_back({n.laneLink(i), n.front_pin[i], kLinkSteel, kMemberSection, e3});
  }
  for (int i = 0; i < 2; ++i) {
    model.beams.push_back({n.front_pin[i], n.front_pin[i + 1], kSteel, kPinSection, e3});
    model.beams.push_back({n.rear_pin[i], n.rear_pin[i + 1], kSteel, kPinSection, e3});
  }

  // Pads: per column a lower layer (sole -> core) and an upper layer (core -> top), whose series
  // stiffness is the column's; each layer's share follows its rubber thickness (k ~ 1/h).
  // The columns of a pad lie on one line along e1, so a column also carries the rubber block's
  // rotational stiffness about e1 (k_n w_p^2 / 12 for a block of width w_p); without it the core
  // could roll about that line freely.
  const double h_total = t.pad_rubber_below_core + t.pad_rubber_above_core;
  const double lower_factor = h_total / t.pad_rubber_below_core;
  const double upper_factor = h_total / t.pad_rubber_above_core;
  const double pad_width = padWidth(t);
  for (int j = 0; j < 6; ++j) {
    const double kn = (j % 3 == 1) ? springs.normal_middle : springs.normal_end;
    Vector6 k = Vector6::Zero();
    k << springs.shear_x, springs.shear_y, kn, kn * pad_width * pad_width / 12.0, 0.0, 0.0;
    fem::Spring lower;
    lower.n1 = n.soles[j];
    lower.n2 = n.cores[j];
    lower.stiffness = lower_factor * k;
    lower.frame = r;
    lower.name = name + "/pad_lower_" + std::to_string(j);
    model.springs.push_back(lower);
    fem::Spring upper = lower;
    upper.n1 = n.cores[j];
    upper.n2 = n.tops[j];
    upper.stiffness = upper_factor * k;
    upper.name = name + "/pad_upper_" + std::to_string(j);
    model.springs.push_back(upper);
  }

  // Rigid joints: each pad's steel core is rigid; the pad tops sit in the link's cavities; the
  // soles' rotations follow the core (the pad bottom stays parallel to the core plate).
  for (int p = 0; p < 2; ++p) {
    const NodeId core_master = n.cores[3 * p + 1];
    fem::RigidJoint core;
    core.master = core_master;
    core.slaves = {n.cores[3 * p], n.cores[3 * p + 2]};
    core.name = name + "/pad_core_" + std::to_string(p);
    model.rigid_joints.push_back(core);
    fem::RigidJoint top;
    top.master = n.link[p == 0 ? 1 : 3];
    top.slaves = {n.tops[3 * p], n.tops[3 * p + 1], n.tops[3 * p + 2]};
    top.name = name + "/pad_top_" + std::to_string(p);
    model.rigid_joints.push_back(top);
    fem::RigidJoint sole;
    sole.master = core_master;
    sole.slaves = {n.soles[3 * p], n.soles[3 * p + 1], n.soles[3 * p + 2]};
    sole.dofs = {{false, false, false, true, true, true}};
    sole.name = name + "/pad_sole_" + std::to_string(p);
    model.rigid_joints.push_back(sole);
  }

  // Pad masses: a share at the soles (so every translational DOF has mass), the rest on the core
  // as a rigid plate spanning the columns and half the track width.
  const double sole_mass = t.pad_sole_mass_fraction * t.pad_mass / 3.0;
  const double core_mass = (1.0 - t.pad_sole_mass_fraction) * t.pad_mass;
  const double len = 2.0 * c, wid = padWidth(t), hgt = padHeight(t);
  const Vector3 local_inertia(core_mass * (wid * wid + hgt * hgt) / 12.0,
                              core_mass * (len * len + hgt * hgt) / 12.0,
                              core_mass * (len * len + wid * wid) / 12.0);
  for (int p = 0; p < 2; ++p) {
    fem::Mass core;
    core.node = n.cores[3 * p + 1];
    core.mass = core_mass;
    core.inertia = r * local_inertia.asDiagonal() * r.transpose();
    core.name = name + "/pad_" + std::to_string(p);
    model.masses.push_back(core);
    for (int k = 0; k < 3; ++k) {
      fem::Mass sole;
      sole.node = n.soles[3 * p + k];
      sole.mass = sole_mass;
      sole.name = name + "/pad_sole_" + std::to_string(3 * p + k);
      model.masses.push_back(sole);
    }
  }
  return n;
}

namespace {

fem::Model standaloneModel(const TrackAssemblyDescription& t, const PadSprings& springs,
                           TrackAssemblyNodes& nodes) {
  fem::Model model;
  model.name = "track_assembly";
  addTrackAssemblyProperties(model, t);
  nodes = addTrackAssembly(model, t, springs, AssemblyFrame{}, 0, "track_assembly");
  for (NodeId sole : nodes.soles)
    model.fixed.push_back({sole, {{true, true, true, false, false, false}}});
  return model;
}

}  // namespace

TrackAssemblyStiffness measureTrackAssembly(const fem::Model& model,
                                            const TrackAssemblyNodes& nodes) {
  const fem::System sys = fem::assemble(model);
  fem::SparseCholesky chol;
  if (!chol.factorize(sys.stiffness))
    throw SolverError(
        "track assembly: the stiffness matrix is not positive definite: a track_assembly "
        "stiffness, link section property or steel_young_modulus many orders of magnitude too "
        "small (or away from the others)?");
  // Unit total load shared over the link nodes, in x, y, z and as a moment about y.
  const int directions[4] = {0, 1, 2, 4};
  Matrix loads = Matrix::Zero(sys.size(), 4);
  for (int c = 0; c < 4; ++c)
    for (NodeId id : nodes.link)
      loads(sys.dofs.requireActive(id, directions[c]), c) = 1.0 / nodes.link.size();
  const Matrix x = chol.solve(loads);
  double mean[4] = {0, 0, 0, 0};
  for (int c = 0; c < 4; ++c)
    for (NodeId id : nodes.link)
      mean[c] += x(sys.dofs.active(id, directions[c]), c) / nodes.link.size();
  return TrackAssemblyStiffness{1.0 / mean[0], 1.0 / mean[1], 1.0 / mean[2], 1.0 / mean[3]};
}

PadSprings calibrateTrackAssembly(const TrackAssemblyDescription& t) {
  // Start from the rigid-link estimate: 6 columns share k_z and the shears; the fore/aft columns
  // carry the share f of the normal stiffness that gives k_ry = f k_z c^2.
  const double c2 = t.pad_column_offset * t.pad_column_offset;
  double normal_sum = t.compression_stiffness;  // sum over the 6 columns
  double end_share = std::min(1.0, t.torsional_stiffness_y / (t.compression_stiffness * c2));
  PadSprings s;
  // The target furthest from what the last iteration measured, for the message if it fails.
  int worst = 0;  // the group farthest off its target at the last step, for the message
  double worst_error = -1.0;
  s.shear_x = t.shear_stiffness_x / 6.0;
  s.shear_y = t.shear_stiffness_y / 6.0;
  // Each spring group against the stiffness it mainly sets: the end columns carry k_ry, the
  // middle ones the rest of k_z. `measured` is the last measurement, for the message.
  struct Group {
    const char* key;
    const char* unit;
    double target, start, measured;
  };
  Group groups[4] = {{"shear_stiffness_x", "N/m", t.shear_stiffness_x, s.shear_x, 0.0},
                     {"shear_stiffness_y", "N/m", t.shear_stiffness_y, s.shear_y, 0.0},
                     {"compression_stiffness", "N/m", t.compression_stiffness,
                      (1.0 - end_share) * normal_sum / 2.0, 0.0},
                     {"torsional_stiffness_y", "N*m/rad", t.torsional_stiffness_y,
                      end_share * normal_sum / 4.0, 0.0}};
  // A target the steel link in series with the pads (or the pads' other springs in parallel)
  // cannot give sends its springs towards infinity (or zero) until the stiffness matrix is no
  // longer positive definite: name that target, not the matrix.
  const auto unreachable = [&](int group, double factor) {
    const Group& g = groups[group];
    const bool up = factor > 1.0;
    return InputError(
        std::string("track_assembly.") + g.key + ": " + brief(g.target) + " " + g.unit +
        (up ? " may be stiffer than the steel link in series with the pad springs allows"
            : " may be softer than the pad springs in parallel with these allow") +
        ": calibrating the pad springs to it scaled them " + brief(up ? factor : 1.0 / factor) +
        " times " + (up ? "up" : "down") + " and the assembly still gives " + brief(g.measured) +
        " " + g.unit + " (they would have to be " + (up ? "infinite" : "negative") + "); " +
        (up ? "lower " : "raise ") + g.key +
        (group == 0 ? " (an x load on the link also tilts the pads, so a low torsional_stiffness_y "
                      "caps it)"
                    : "") +
        ", or check the other track_assembly stiffnesses, the link sections and "
        "steel_young_modulus");
  };
  for (int it = 1; it <= kMaxCalibrationIterations; ++it) {
    s.normal_end = end_share * normal_sum / 4.0;
    s.normal_middle = (1.0 - end_share) * normal_sum / 2.0;
    s.iterations = it;
    // The group scaled farthest from its start (either way), and by how much.
    const double current[4] = {s.shear_x, s.shear_y, s.normal_middle, s.normal_end};
    int runaway = 0;
    double runaway_factor = 1.0;
    for (int i = 0; i < 4; ++i) {
      const double factor = current[i] / groups[i].start;
      if (std::abs(std::log(factor)) > std::abs(std::log(runaway_factor))) {
        runaway = i;
        runaway_factor = factor;
      }
    }
    if (std::abs(std::log(runaway_factor)) > std::log(kRunawayFactor))
      throw unreachable(runaway, runaway_factor);
    TrackAssemblyNodes nodes;
    TrackAssemblyStiffness k;
    try {
      k = measureTrackAssembly(standaloneModel(t, s, nodes), nodes);
    } catch (const SolverError&) {
      // The start estimate failing is the description's own doing (a stiffness or section many
      // orders of magnitude off): the measurement's message says so.
      if (it == 1)
        throw;
      throw unreachable(runaway, runaway_factor);
    }
    groups[0].measured = k.kx;
    groups[1].measured = k.ky;
    groups[2].measured = k.kz;
    groups[3].measured = k.kry;
    const double rx = t.shear_stiffness_x / k.kx, ry = t.shear_stiffness_y / k.ky;
    const double rz = t.compression_stiffness / k.kz, rr = t.torsional_stiffness_y / k.kry;
    if (std::max({std::abs(rx - 1), std::abs(ry - 1), std::abs(rz - 1), std::abs(rr - 1)}) <
        kCalibrationTolerance)
      return s;
    worst_error = -1.0;
    for (int i = 0; i < 4; ++i) {
      const double error = std::abs(groups[i].target / groups[i].measured - 1.0);
      if (error > worst_error) {
        worst_error = error;
        worst = i;
      }
    }
    // Each stiffness is governed mainly by its own spring group (series with the nearly rigid
    // link): scale the group by target / measured.
    s.shear_x *= rx;
    s.shear_y *= ry;
    normal_sum *= rz;
    end_share *= rr;
    // k_ry grows about as the end columns' share f (k_ry ~ f k_z c^2): with all of k_z in them
    // (f = 1) these columns give about k_ry / f, and columns sqrt(f) c from the centre would
    // give the target, if that fits in a pitch (2 c < pitch: validateDescription()).
    if (end_share > 1.0) {
      const double offset = t.pad_column_offset * std::sqrt(end_share);
      throw InputError(
          "track_assembly.pad_column_offset: the spring columns (" + brief(t.pad_column_offset) +
          " m from the pad centre) are too close together to give torsional_stiffness_y = " +
          brief(t.torsional_stiffness_y) + " N*m/rad: they give at most about " +
          brief(t.torsional_stiffness_y / end_share) +
          " N*m/rad (all of compression_stiffness in the fore and aft columns); " +
          (2.0 * offset < t.pitch
               ? "columns about " + brief(offset) + " m from the centre would give it"
               : "columns far enough apart for it (about " + brief(offset) +
                     " m from the centre) would not fit in the pitch (" + brief(t.pitch) +
                     " m): lower torsional_stiffness_y or raise compression_stiffness"));
    }
  }
  // Ten digits: the two differ in the seventh when the calibration stalls on round-off.
  const std::string reached =
      io::formatC("%.10g (the assembly gives %.10g", groups[worst].target, groups[worst].measured);
  throw InputError(std::string("track_assembly.") + groups[worst].key +
                   ": the pad springs' calibration does not reach " + reached + ", off by " +
                   brief(worst_error) + " relative after " +
                   std::to_string(kMaxCalibrationIterations) + " steps; tolerance " +
                   brief(kCalibrationTolerance) +
                   "): a value in another unit (N/mm for N/m), or many orders of magnitude from "
                   "the other stiffnesses?");
}

TrackAssemblyModel buildTrackAssemblyModel(const TrackAssemblyDescription& t) {
  TrackAssemblyModel out;
  out.springs = calibrateTrackAssembly(t);
  out.model = standaloneModel(t, out.springs, out.nodes);
  return out;
}

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
