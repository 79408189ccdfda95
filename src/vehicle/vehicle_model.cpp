#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/vehicle/chain_path.h"
#include "tracked_vehicle_dynamics/vehicle/track_tension.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

const char* sideName(int side) {
  return side == 0 ? "left" : "right";
}

std::string assemblyName(int side, int index) {
  return std::string("track_") + sideName(side) + "_" + std::to_string(index);
}

std::string roadWheelName(int side, int axle) {
  return std::string("road_wheel_") + sideName(side) + "_" + std::to_string(axle);
}

namespace {

/// Un-tracked assemblies sit centred under their wheel, apart from the chain's: own id block.
constexpr NodeId kUntrackedAssemblyBase = 500000;

double sideY(const VehicleDescription& d, int side) {
  return (side == 0 ? 0.5 : -0.5) * d.running_gear.track_centre_distance;
}

NodeId stationNode(int side, int axle, int part) {
  return 1000 + 100 * side + 10 * axle + part;
}
/// Return roller r (0-based) of a side; at most 50 per side (validateDescription).
NodeId rollerNode(int side, int r) {
  return 2010 + 100 * side + r;
}
NodeId chainAssemblyBase(int side, int k) {
  return 100000 * (side + 1) + 100 * k;
}

/// Axle j (0 = front) of n, spaced l, centred on x = 0.
double axleX(const VehicleDescription& d, int axle) {
  const auto& g = d.running_gear;
  return (0.5 * (g.axle_count - 1) - axle) * g.axle_spacing;
}

/// Frame of an assembly whose pitch-line point and tangent (x-z plane) are given, on side y.
AssemblyFrame frameAt(const Vector2& point, const Vector2& tangent, double y, double pitch_height) {
  AssemblyFrame f;
  const Vector3 e1(tangent.x(), 0.0, tangent.y());
  const Vector3 e2 = Vector3::UnitY();
  const Vector3 e3 = e1.cross(e2);  // inward normal (-t_z, 0, t_x)
  f.axes.col(0) = e1;
  f.axes.col(1) = e2;
  f.axes.col(2) = e3;
  f.origin = Vector3(point.x(), y, point.y()) - pitch_height * e3;
  return f;
}

/// Local ids, inside an assembly's id span, of the contact node pair a chain wheel uses.
constexpr NodeId kLinkContact = 60, kWheelContact = 61;

class Builder {
 public:
  Builder(const VehicleDescription& d, Variant variant) : d_(d) {
    out_.layout.variant = variant;
    out_.model.name = d.name + "_" + variantName(variant);
  }

  VehicleModel build() {
    validateDescription(d_, d_.origin);
    // One description is valid or not whichever variant is built from it: the un-tracked one has
    // no chain, but the same file makes the tracked one.
    const ChainPath path = checkedChainPath();
    out_.layout.pad_springs = calibrateTrackAssembly(d_.track_assembly);
    addTrackAssemblyProperties(out_.model, d_.track_assembly);
    addHull();
    for (int side = 0; side < 2; ++side)
      for (int axle = 0; axle < d_.running_gear.axle_count; ++axle)
        addStation(side, axle);
    if (out_.layout.variant == Variant::Untracked)
      addUntrackedAssemblies();
    else
      addChains(path);
    model().rigid_joints.insert(model().rigid_joints.begin(), spider_);
    addDofSets();
    summariseMass();
    return std::move(out_);
  }

 private:
  fem::Model& model() { return out_.model; }
  VehicleLayout& layout() { return out_.layout; }

  void attachToHull(NodeId node) { spider_.slaves.push_back(node); }

  void addHull() {
    const auto& h = d_.hull;
    model().addNode(kHullNode, Vector3(h.cog_x, 0.0, h.cog_height));
    fem::Mass m;
    m.node = kHullNode;
    m.mass = h.mass;
    m.inertia = Vector3(h.roll_inertia, h.pitch_inertia, h.yaw_inertia).asDiagonal();
    m.name = "hull";
    model().masses.push_back(m);
    spider_.master = kHullNode;
    spider_.name = "spider";
    for (std::size_t i = 0; i < d_.named_points.size(); ++i) {
      const NodeId id = 10 + static_cast<NodeId>(i);
      model().addNode(id, d_.named_points[i].position);
      attachToHull(id);
      layout().named_points[d_.named_points[i].name] = id;
    }
  }

  // The first road wheel centre [x, z] whose circle (radius R) overlaps the circle (x, z, r), or
  // -1: wheels of the running gear must not interpenetrate.
  int overlappedRoadWheel(double x, double z, double r) const {
    const double rw = d_.road_wheel.radius, zw = wheelCentreZ(d_);
    for (int axle = 0; axle < d_.running_gear.axle_count; ++axle)
      if (std::hypot(x - axleX(d_, axle), z - zw) < r + rw)
        return axle;
    return -1;
  }

  std::string roadWheelText(int axle) const {
    return "road wheel " + std::to_string(axle + 1) + " (centre x = " + brief(axleX(d_, axle)) +
           " m, z = " + brief(wheelCentreZ(d_)) + " m, radius " + brief(d_.road_wheel.radius) +
           " m)";
  }

  // The sprocket and the idler (whose x the chain length sets) clear the road wheels.
  void checkEndWheelClearance(const ChainPath& path) const {
    const Vector2 s = path.sprocketCentre(), i = path.idlerCentre();
    int axle = overlappedRoadWheel(s.x(), s.y(), d_.sprocket.radius);
    if (axle >= 0)
      throw InputError("sprocket.centre_x: the sprocket (centre x = " + brief(s.x()) +
                       " m, z = " + brief(s.y()) + " m, radius " + brief(d_.sprocket.radius) +
                       " m) overlaps " + roadWheelText(axle));
    axle = overlappedRoadWheel(i.x(), i.y(), d_.idler.radius);
    if (axle >= 0)
      throw InputError("idler.centre_z: the idler (centre x = " + brief(i.x()) +
                       " m, set by the chain length; z = " + brief(i.y()) + " m, radius " +
                       brief(d_.idler.radius) + " m) overlaps " + roadWheelText(axle) +
                       ": raise the idler or lengthen the chain (track_assembly.count)");
  }

  // The top run, a straight line tangent to the sprocket and the idler, passes over the road
  // wheels: its link's wheel path, (upper_surface_height - pitch_line_height) inside the pitch
  // line, must clear each wheel, the pitch line's distance from the wheel centre at least
  // R + that depth. A low sprocket or idler beside large wheels would otherwise lay the chain
  // through a wheel, which the model (no contact there) would carry without a word.
  void checkTopRunClearance(const ChainPath& path) const {
    const auto [s0, s1] = path.interval(ChainSegment::TopRun);
    const Vector2 a = path.at(s0).position, b = path.at(s1).position;
    const double depth =
        d_.track_assembly.upper_surface_height - d_.track_assembly.pitch_line_height;
    const double rw = d_.road_wheel.radius, zw = wheelCentreZ(d_);
    for (int axle = 0; axle < d_.running_gear.axle_count; ++axle) {
      const Vector2 c(axleX(d_, axle), zw);
      const double u = std::clamp((c - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      const double distance = (a + u * (b - a) - c).norm();
      if (distance < rw + depth - 1e-9)
        throw InputError(
            "sprocket.centre_z / idler.centre_z: the chain's top run (pitch line from x = " +
            brief(a.x()) + " m, z = " + brief(a.y()) + " m to x = " + brief(b.x()) +
            " m, z = " + brief(b.y()) + " m) passes " + brief(distance) + " m from the centre of " +
            roadWheelText(axle) + ", less than its radius plus the link's wheel path " +
            brief(depth) + " m inside the pitch line: the chain would run through the wheel by " +
            brief(rw + depth - distance) + " m; raise the sprocket or the idler");
    }
  }

  // The chain's path (the idler's x from the chain length), its sprocket and idler clear of the
  // road wheels, its top run over them, and its return rollers between them, clear of the
  // wheels and the ground run.
  ChainPath checkedChainPath() const {
    ChainPath path(d_, solveIdlerX(d_));
    checkEndWheelClearance(path);
    checkTopRunClearance(path);
    const bool idler_in_front = path.idlerCentre().x() > path.sprocketCentre().x();
    for (const double xr : d_.return_rollers.x) {
      if (idler_in_front ? xr >= path.idlerCentre().x() : xr <= path.idlerCentre().x())
        throw InputError("return_rollers.x: roller at x = " + brief(xr) + " m lies " +
                         (idler_in_front ? "ahead of" : "behind") +
                         " the idler (x = " + brief(path.idlerCentre().x()) + " m)");
      checkRollerClearance(path, xr, path.topRunHeight(xr) - d_.return_rollers.radius);
    }
    return path;
  }

  // A return roller hangs under the top run (centre z_r = top-run height - r); it must clear the
  // road wheels, the sprocket and the idler (centre distance >= R + r) and the ground run below
  // them. Next to a wheel the chain wraps, a roller under a level top run needs
  // |x_r - x_c| >= 2 sqrt(R r) to clear it; closer, it would sit inside that wheel and carry the
  // chain's wrap as a load of its own.
  void checkRollerClearance(const ChainPath& path, double xr, double zr) const {
    const double r = d_.return_rollers.radius;
    const std::string roller =
        "return_rollers.x: the roller at x = " + brief(xr) + " m (radius " + brief(r) +
        " m, its centre hanging under the top run at z = " + brief(zr) + " m)";
    if (zr - r <= d_.track_assembly.upper_surface_height)
      throw InputError(roller +
                       " reaches down to the ground run (return_rollers.radius, or the "
                       "top run is too low)");
    const int axle = overlappedRoadWheel(xr, zr, r);
    if (axle >= 0)
      throw InputError(roller + " overlaps " + roadWheelText(axle));
    const struct {
      const char* name;
      Vector2 centre;
      double radius;
    } ends[] = {{"sprocket", path.sprocketCentre(), d_.sprocket.radius},
                {"idler", path.idlerCentre(), d_.idler.radius}};
    for (const auto& end : ends)
      if (std::hypot(xr - end.centre.x(), zr - end.centre.y()) < r + end.radius)
        throw InputError(
            roller + " overlaps the " + end.name + " (centre x = " + brief(end.centre.x()) +
            " m, z = " + brief(end.centre.y()) + " m, radius " + brief(end.radius) + " m)");
  }

  // Trailing arm: pivot ahead of and above the wheel centre, x_p = x_w + a cos(beta),
  // z_p = z_w + a sin(beta). The revolute joint frees only ry; the torsion bar is a k_t spring
  // about y between the hull-side and arm-side pivot nodes.
  void addStation(int side, int axle) {
    const auto& s = d_.suspension;
    const double y = sideY(d_, side);
    const double x = axleX(d_, axle);
    const double zw = wheelCentreZ(d_);
    const Vector3 centre(x, y, zw);
    const Vector3 pivot(x + s.arm_length * std::cos(s.arm_angle), (side == 0 ? 1 : -1) * s.pivot_y,
                        zw + s.arm_length * std::sin(s.arm_angle));
    WheelStation st;
    st.name = roadWheelName(side, axle + 1);
    st.side = side;
    st.axle = axle;
    st.pivot = model().addNode(stationNode(side, axle, 0), pivot);
    st.arm = model().addNode(stationNode(side, axle, 1), pivot);
    st.centre = model().addNode(stationNode(side, axle, 2), centre);
    attachToHull(st.pivot);

    fem::RigidJoint revolute;
    revolute.master = st.pivot;
    revolute.slaves.assign(1, st.arm);
    revolute.dofs = {{true, true, true, true, false, true}};
    revolute.name = st.name + "/revolute";
    model().rigid_joints.push_back(revolute);
    fem::RigidJoint arm;
    arm.master = st.arm;
    arm.slaves.assign(1, st.centre);
    arm.name = st.name + "/arm";
    model().rigid_joints.push_back(arm);

    fem::Spring bar;
    bar.n1 = st.pivot;
    bar.n2 = st.arm;
    bar.stiffness(4) = s.torsion_bar_stiffness;
    const auto& damped = d_.damping.damped_stations;
    if (std::find(damped.begin(), damped.end(), axle + 1) != damped.end())
      bar.damping(4) = s.arm_damping;
    bar.name = st.name + "/torsion_bar";
    model().springs.push_back(bar);

    const auto& w = d_.road_wheel;
    fem::Mass m;
    m.node = st.centre;
    m.mass = w.mass;
    m.inertia = Vector3(w.tilt_inertia, w.spin_inertia, w.tilt_inertia).asDiagonal();
    m.name = st.name;
    model().masses.push_back(m);
    layout().wheels.push_back(st);
  }

  int addAssembly(int side, int k, bool on_ground, const AssemblyFrame& frame, NodeId base) {
    AssemblyRecord rec;
    rec.side = side;
    rec.index = k;
    rec.on_ground = on_ground;
    rec.nodes = addTrackAssembly(model(), d_.track_assembly, layout().pad_springs, frame, base,
                                 assemblyName(side, k));
    const int index = static_cast<int>(layout().assemblies.size());
    if (on_ground) {
      const double kg = d_.ties.ground_stiffness;
      for (NodeId sole : rec.nodes.soles) {
        fem::Spring g;
        g.n1 = sole;
        g.n2 = fem::kGround;
        g.stiffness << kg, kg, kg, 0.0, 0.0, 0.0;
        g.name = "ground_" + std::to_string(sole);
        model().springs.push_back(g);
        RoadInput in;
        in.spring = model().springs.size() - 1;
        in.node = sole;
        in.side = side;
        in.assembly = index;
        const Vector3 local = localSole(sole - base);
        const Vector3 pos = frame.origin + frame.axes * local;
        in.x = pos.x();
        in.y = pos.y();
        in.road_x = d_.ties.road_input_station == RoadInputStation::Sole
                        ? pos.x()
                        : (frame.origin + frame.axes * Vector3(0.0, local.y(), local.z())).x();
        layout().road_inputs.push_back(in);
      }
    }
    layout().assemblies.push_back(rec);
    return index;
  }

  Vector3 localSole(NodeId local) const {
    const auto& t = d_.track_assembly;
    const int j = static_cast<int>(local - 30);
    const double xi[3] = {-t.pad_column_offset, 0.0, t.pad_column_offset};
    return Vector3(xi[j % 3], j < 3 ? -t.pad_lateral_offset : t.pad_lateral_offset, 0.0);
  }

  // Wheel-track contact: a bushing between two coincident nodes at the contact point on the
  // link's upper (inner) surface, one rigid with the wheel body and one with the link centre, so
  // the contact force acts where the wheel touches the link. Stiffness in the assembly frame
  // (along the chain, across, normal); no moment is transmitted.
  void addContact(NodeId wheel_body, NodeId wheel_node, NodeId link_node, const AssemblyRecord& a,
                  const Vector3& point, const Matrix3& frame, double along, double across,
                  double normal, const std::string& name) {
    model().addNode(wheel_node, point);
    model().addNode(link_node, point);
    fem::RigidJoint on_wheel;
    on_wheel.master = wheel_body;
    on_wheel.slaves.assign(1, wheel_node);
    on_wheel.name = name + "/wheel_side";
    model().rigid_joints.push_back(on_wheel);
    fem::RigidJoint on_link;
    on_link.master = a.nodes.linkCentre();
    on_link.slaves.assign(1, link_node);
    on_link.name = name + "/link_side";
    model().rigid_joints.push_back(on_link);
    fem::Spring s;
    s.n1 = wheel_node;
    s.n2 = link_node;
    s.stiffness << along, across, normal, 0.0, 0.0, 0.0;
    s.frame = frame;
    s.name = name;
    model().springs.push_back(s);
  }

  void recordChainWheelContact(ChainWheel wheel, int side, int roller, int assembly) {
    ChainWheelContact c;
    c.wheel = wheel;
    c.side = side;
    c.roller = roller;
    c.assembly = assembly;
    c.spring = model().springs.size() - 1;
    layout().chain_wheel_contacts.push_back(c);
  }

  /// The point of the link's upper surface above the assembly's centre line at `along` from it.
  Vector3 upperSurface(const AssemblyRecord& a, const Matrix3& frame, double along) const {
    const fem::Node& centre = nodeById(a.nodes.linkCentre());
    const double up = d_.track_assembly.upper_surface_height - d_.track_assembly.pitch_line_height;
    return centre.position + along * frame.col(0) + up * frame.col(2);
  }

  const fem::Node& nodeById(NodeId id) const {
    for (auto it = out_.model.nodes.rbegin(); it != out_.model.nodes.rend(); ++it)
      if (it->id == id)
        return *it;
    throw InputError("internal: node " + std::to_string(id) + " missing");
  }

  // Road wheel on its assembly: the wheel is rigid with its arm (no spin DOF), so the contact
  // patch carries the normal force (k_w) and the longitudinal force (contact_shear_stiffness:
  // locked when high, rolling when low); the lateral force passes through the guide horn, which
  // touches the wheels' rims above the link's upper surface (guideStiffness()).
  void tieWheel(WheelStation& st, int assembly) {
    const auto& s = d_.suspension;
    st.assembly = assembly;
    const AssemblyRecord& a = layout().assemblies[assembly];
    const Matrix3 frame = Matrix3::Identity();
    const double along = axleX(d_, st.axle) - nodeById(a.nodes.linkCentre()).position.x();
    const Vector3 patch = upperSurface(a, frame, along);
    addContact(st.centre, stationNode(st.side, st.axle, 3), stationNode(st.side, st.axle, 4), a,
               patch, frame, s.contact_shear_stiffness, 0.0, s.contact_stiffness,
               st.name + "/contact");
    st.contact_spring = model().springs.size() - 1;
    addContact(st.centre, stationNode(st.side, st.axle, 5), stationNode(st.side, st.axle, 6), a,
               patch + s.guide_contact_height * Vector3::UnitZ(), frame, 0.0, guideStiffness(s),
               0.0, st.name + "/guide");
  }

  // Paper Fig. 2a: each road wheel stands on one assembly, centred under it.
  void addUntrackedAssemblies() {
    const double hp = d_.track_assembly.pitch_line_height;
    for (WheelStation& st : layout().wheels) {
      const double x = axleX(d_, st.axle);
      const AssemblyFrame f = frameAt(Vector2(x, hp), Vector2::UnitX(), sideY(d_, st.side), hp);
      const NodeId base = kUntrackedAssemblyBase + 10000 * st.side + kAssemblyIdSpan * st.axle;
      tieWheel(st, addAssembly(st.side, st.axle, true, f, base));
    }
  }

  // Paper Fig. 2b: closed chains, pin to pin rigid joints, ground run on ground springs.
  void addChains(const ChainPath& path) {
    const auto& t = d_.track_assembly;
    const auto& s = d_.suspension;
    layout().idler_x = path.idlerCentre().x();
    const auto sprocket_arc = path.interval(ChainSegment::Sprocket);
    const auto idler_arc = path.interval(ChainSegment::Idler);
    for (int side = 0; side < 2; ++side) {
      const double y = sideY(d_, side);
      std::vector<int> index(t.count);
      for (int k = 0; k < t.count; ++k) {
        const double sk = (k + 0.5) * t.pitch;
        const ChainPoint p = path.at(sk);
        index[k] = addAssembly(side, k, k < t.ground_count,
                               frameAt(p.position, p.tangent, y, t.pitch_line_height),
                               chainAssemblyBase(side, k));
      }
      for (int k = 0; k < t.count; ++k) {
        const auto& front = layout().assemblies[index[k]].nodes.front_pin;
        const auto& rear = layout().assemblies[index[(k + 1) % t.count]].nodes.rear_pin;
        for (int i = 0; i < 3; ++i) {
          fem::RigidJoint pin;
          pin.master = front[i];
          pin.slaves.assign(1, rear[i]);
          pin.name = std::string("chain_") + sideName(side) + "_joint_" + std::to_string(k);
          model().rigid_joints.push_back(pin);
        }
      }
      // The tensioner's pre-load (track_assembly.static_tension): a pre-stress of the loop.
      ChainLoop loop;
      loop.side = sideName(side);
      for (int k = 0; k < t.count; ++k)
        loop.assemblies.push_back(layout().assemblies[index[k]].nodes);
      addChainTension(model(), loop, layout().hull, t.static_tension.value_or(0.0));
      // Road wheels on the ground assembly nearest below them.
      for (WheelStation& st : layout().wheels) {
        if (st.side != side)
          continue;
        const double u = (axleX(d_, st.axle) + 0.5 * t.ground_count * t.pitch) / t.pitch - 0.5;
        const int k = std::clamp(static_cast<int>(std::lround(u)), 0, t.ground_count - 1);
        tieWheel(st, index[k]);
      }
      // Sprocket (teeth on the pins: radial, lateral and tangential), idler (rolling: radial and
      // lateral only) and rollers (as the idler), all rigid with the hull.
      const NodeId sprocket = model().addNode(
          2000 + 100 * side, Vector3(path.sprocketCentre().x(), y, path.sprocketCentre().y()));
      const NodeId idler = model().addNode(
          2001 + 100 * side, Vector3(path.idlerCentre().x(), y, path.idlerCentre().y()));
      addWheelMass(sprocket, d_.sprocket.mass, d_.sprocket.inertia, "sprocket");
      addWheelMass(idler, d_.idler.mass, d_.idler.inertia, "idler");
      layout().sprockets.push_back(sprocket);
      layout().idlers.push_back(idler);
      for (int k = 0; k < t.count; ++k) {
        const double sk = (k + 0.5) * t.pitch;
        const AssemblyRecord& a = layout().assemblies[index[k]];
        const Matrix3 frame = frameAt(path.at(sk).position, path.at(sk).tangent, y, 0).axes;
        // Across the chain: the guide stiffness (the teeth hold the pins along it with k_w).
        const double kc = s.contact_stiffness, ks = guideStiffness(s);
        const NodeId base = a.nodes.base;
        const std::string tag = std::string(sideName(side)) + "_" + std::to_string(k);
        if (sk >= sprocket_arc.first && sk < sprocket_arc.second) {
          addContact(sprocket, base + kWheelContact, base + kLinkContact, a,
                     upperSurface(a, frame, 0.0), frame, kc, ks, kc, "sprocket_" + tag);
          recordChainWheelContact(ChainWheel::Sprocket, side, 0, index[k]);
        }
        if (sk >= idler_arc.first && sk < idler_arc.second) {
          addContact(idler, base + kWheelContact, base + kLinkContact, a,
                     upperSurface(a, frame, 0.0), frame, 0.0, ks, kc, "idler_" + tag);
          recordChainWheelContact(ChainWheel::Idler, side, 0, index[k]);
        }
      }
      const auto top = path.interval(ChainSegment::TopRun);
      for (std::size_t r = 0; r < d_.return_rollers.x.size(); ++r) {
        const double xr = d_.return_rollers.x[r];  // checked: checkedChainPath()
        int best = -1;
        double best_dist = 1e300;
        for (int k = 0; k < t.count; ++k) {
          const double sk = (k + 0.5) * t.pitch;
          if (sk < top.first || sk >= top.second)
            continue;
          const double dist = std::abs(path.at(sk).position.x() - xr);
          if (dist < best_dist)
            best = k, best_dist = dist;
        }
        if (best < 0)
          throw InputError("return_rollers.x: the top run holds no assembly");
        const NodeId roller =
            model().addNode(rollerNode(side, static_cast<int>(r)),
                            Vector3(xr, y, path.topRunHeight(xr) - d_.return_rollers.radius));
        addWheelMass(roller, d_.return_rollers.mass, 0.0, "return_roller");
        layout().return_rollers.push_back(roller);
        const double sb = (best + 0.5) * t.pitch;
        const Matrix3 frame = frameAt(path.at(sb).position, path.at(sb).tangent, y, 0).axes;
        const AssemblyRecord& a = layout().assemblies[index[best]];
        addContact(roller, a.nodes.base + kWheelContact, a.nodes.base + kLinkContact, a,
                   upperSurface(a, frame, 0.0), frame, 0.0, guideStiffness(s), s.contact_stiffness,
                   std::string("return_roller_") + sideName(side) + "_" + std::to_string(r));
        recordChainWheelContact(ChainWheel::ReturnRoller, side, static_cast<int>(r), index[best]);
      }
    }
  }

  void addWheelMass(NodeId node, double mass, double inertia, const std::string& name) {
    attachToHull(node);
    layout().hull_attached.push_back(node);
    if (mass <= 0.0)
      return;
    fem::Mass m;
    m.node = node;
    m.mass = mass;
    m.inertia = inertia * Matrix3::Identity();
    m.name = name;
    model().masses.push_back(m);
  }

  void addDofSets() {
    auto& sets = model().dof_sets;
    for (int d = 0; d < kDofsPerNode; ++d)
      sets["hull"].push_back({kHullNode, d});
    for (const WheelStation& st : layout().wheels)
      sets["arms"].push_back({st.arm, 4});
    for (const RoadInput& in : layout().road_inputs)
      sets["ground_contact"].push_back({in.node, static_cast<int>(Direction::Uz)});
  }

  void summariseMass() {
    MassBreakdown& m = layout().mass;
    m.hull = d_.hull.mass;
    m.road_wheels = d_.road_wheel.mass * layout().wheels.size();
    m.track_assemblies = d_.track_assembly.mass * layout().assemblies.size();
    m.sprockets = d_.sprocket.mass * layout().sprockets.size();
    m.idlers = d_.idler.mass * layout().idlers.size();
    m.return_rollers = d_.return_rollers.mass * layout().return_rollers.size();
    m.total =
        m.hull + m.road_wheels + m.track_assemblies + m.sprockets + m.idlers + m.return_rollers;
  }

  const VehicleDescription& d_;
  VehicleModel out_;
  fem::RigidJoint spider_;
};

}  // namespace

const char* variantName(Variant variant) {
  return variant == Variant::Untracked ? "untracked" : "tracked";
}

const char* chainWheelName(ChainWheel wheel) {
  switch (wheel) {
    case ChainWheel::Sprocket:
      return "sprocket";
    case ChainWheel::Idler:
      return "idler";
    case ChainWheel::ReturnRoller:
      return "return_roller";
  }
  return "?";
}

Variant parseVariant(const std::string& text) {
  if (text == "untracked")
    return Variant::Untracked;
  if (text == "tracked")
    return Variant::Tracked;
  throw InputError("unknown vehicle variant '" + text + "' (untracked or tracked)");
}

Vector roadInputStations(const VehicleLayout& layout,
                         const std::vector<fem::DofRef>& ground_inputs) {
  if (ground_inputs.size() != layout.road_inputs.size())
    throw std::logic_error("roadInputStations: " + std::to_string(ground_inputs.size()) +
                           " ground inputs, " + std::to_string(layout.road_inputs.size()) +
                           " road inputs");
  Vector x(static_cast<Eigen::Index>(ground_inputs.size()));
  for (std::size_t q = 0; q < ground_inputs.size(); ++q) {
    if (ground_inputs[q].node != layout.road_inputs[q].node)
      throw std::logic_error("roadInputStations: input " + std::to_string(q) + " is node " +
                             std::to_string(ground_inputs[q].node) + " in the system, " +
                             std::to_string(layout.road_inputs[q].node) + " in the layout");
    x(static_cast<Eigen::Index>(q)) = layout.road_inputs[q].road_x;
  }
  return x;
}

std::string nodePart(const VehicleLayout& layout, NodeId node) {
  if (node == layout.hull)
    return "hull";
  for (const auto& [name, id] : layout.named_points)
    if (id == node)
      return name;
  // Station nodes: stationNode(side, axle, part), parts 0..6 as in vehicle_model.h.
  static const char* const kStationParts[] = {"pivot",
                                              "arm",
                                              "centre",
                                              "wheel contact",
                                              "link contact",
                                              "wheel guide contact",
                                              "link guide contact"};
  for (const WheelStation& wheel : layout.wheels) {
    const NodeId base = stationNode(wheel.side, wheel.axle, 0);
    if (node >= base && node < base + 7)
      return wheel.name + " " + kStationParts[node - base];
  }
  for (const AssemblyRecord& a : layout.assemblies) {
    const TrackAssemblyNodes& n = a.nodes;
    if (node < n.base || node >= n.base + 100)
      continue;
    auto in = [node](const auto& ids) {
      return std::find(ids.begin(), ids.end(), node) != ids.end();
    };
    const char* part = in(n.soles)                         ? "sole"
                       : in(n.cores)                       ? "pad core"
                       : in(n.tops)                        ? "pad top"
                       : in(n.front_pin) || in(n.rear_pin) ? "pin"
                                                           : "link";
    return std::string("track assembly ") + sideName(a.side) + " " + std::to_string(a.index + 1) +
           " " + part;
  }
  for (std::size_t side = 0; side < layout.sprockets.size(); ++side) {  // one per side, left first
    if (layout.sprockets[side] == node)
      return std::string("sprocket ") + sideName(static_cast<int>(side));
    if (layout.idlers[side] == node)
      return std::string("idler ") + sideName(static_cast<int>(side));
  }
  for (const NodeId roller : layout.return_rollers)
    if (roller == node)
      for (int side = 0; side < 2; ++side)
        if (node >= rollerNode(side, 0) && node < rollerNode(side, 50))
          return std::string("return roller ") + sideName(side) + " " +
                 std::to_string(node - rollerNode(side, 0) + 1);
  return "node " + std::to_string(node);
}

VehicleModel buildVehicleModel(const VehicleDescription& description, Variant variant) {
  // The builder's geometric checks (the chain path around sprocket and idler) name the key;
  // the file they came from is prefixed here, once, and the key's line appended.
  try {
    return Builder(description, variant).build();
  } catch (const InputError& e) {
    const std::string what = e.what();
    const bool prefixed = what.rfind(description.origin + ":", 0) == 0;
    throw InputError(withKeyLine(description, prefixed ? what : description.origin + ": " + what));
  }
}

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
