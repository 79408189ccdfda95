#include "tracked_vehicle_dynamics/vehicle/mode_classification.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <unordered_map>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/mass_element.h"
#include "tracked_vehicle_dynamics/fem/spring_element.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

namespace {

/// Sparse rows of the transformation for the six DOFs of a node [6 x n_active].
Matrix nodeRows(const fem::System& system, NodeId node) {
  const SparseMatrix& t = system.dofs.transformation();
  Matrix rows = Matrix::Zero(kDofsPerNode, t.cols());
  const DofIndex p0 = system.dofs.physical(node, 0);
  // Column-major T: gather the six rows by scanning columns once.
  for (Eigen::Index c = 0; c < t.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(t, c); it; ++it)
      if (it.row() >= p0 && it.row() < p0 + kDofsPerNode)
        rows(it.row() - p0, c) = it.value();
  return rows;
}

// The vehicle's bodies, by the node of their mass item: 0 the hull, 1 what is attached to it,
// 2 a road wheel. Everything else (the track) is not the vehicle's.
enum BodyGroup { kHullBody = 0, kAttachedBody = 1, kWheelBody = 2 };
std::unordered_map<NodeId, int> vehicleBodies(const VehicleModel& vehicle) {
  std::unordered_map<NodeId, int> group;
  group[vehicle.layout.hull] = kHullBody;
  for (NodeId id : vehicle.layout.hull_attached)
    group[id] = kAttachedBody;
  for (const WheelStation& w : vehicle.layout.wheels)
    group[w.centre] = kWheelBody;
  return group;
}

}  // namespace

const char* hullMotionName(HullMotion motion) {
  static const char* const names[] = {"longitudinal", "lateral", "bounce", "roll", "pitch", "yaw"};
  return names[static_cast<int>(motion)];
}

bool ModeClass::has(HullMotion m) const {
  return std::find(hull_motions.begin(), hull_motions.end(), m) != hull_motions.end();
}

bool ModeClass::matches(const std::string& paper_type) const {
  std::string t;
  for (char ch : paper_type)
    t += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  if (t.rfind("wheel bounce", 0) == 0) {
    // "wheel bounce" matches any wheel mode; "wheel bounce+roll" one that rolls the hull.
    const auto plus = t.find('+');
    if (kind != ModeKind::WheelBounce)
      return false;
    return plus == std::string::npos ||
           (!hull_motions.empty() && t.substr(plus + 1) == hullMotionName(hull_motions.front()));
  }
  if (kind != ModeKind::Hull || hull_motions.empty())
    return false;
  const auto plus = t.find('+');
  const std::string primary = t.substr(0, plus);
  const std::string secondary = plus == std::string::npos ? "" : t.substr(plus + 1);
  if (primary != hullMotionName(hull_motions.front()))
    return false;
  if (secondary.empty())
    return true;
  for (HullMotion m : hull_motions)
    if (secondary == hullMotionName(m))
      return true;
  return false;
}

std::vector<ModeClass> classifyModes(const VehicleModel& vehicle, const fem::System& system,
                                     const fem::ModalBasis& basis) {
  if (basis.shapes.rows() != system.size())
    throw InputError("classifyModes: mode shapes have " + std::to_string(basis.shapes.rows()) +
                     " rows, the system has " + std::to_string(system.size()) + " active DOFs");
  // Motion of each mass item's node for every mode [6 x modes] and its 6x6 mass matrix. For a
  // wheel, `relative` is its motion less the hull's rigid motion carried to its centre
  // (u_w = u_h + theta_h x r, theta_w = theta_h): the suspension travel.
  struct Body {
    Matrix motion;
    Matrix relative;
    Matrix6 mass;
    int group;  // BodyGroup
  };
  const std::unordered_map<NodeId, int> group = vehicleBodies(vehicle);
  std::unordered_map<NodeId, Vector3> position;
  for (const fem::Node& n : vehicle.model.nodes)
    position[n.id] = n.position;
  const Matrix hull_motion = nodeRows(system, vehicle.layout.hull) * basis.shapes;
  std::vector<Body> bodies;
  for (const fem::Mass& m : vehicle.model.masses) {
    const auto it = group.find(m.node);
    if (it == group.end())
      continue;
    Body b{nodeRows(system, m.node) * basis.shapes, Matrix(), fem::rigidBodyMass(m), it->second};
    if (b.group == kWheelBody)
      b.relative = b.motion -
                   fem::rigidOffset(position[m.node] - position[vehicle.layout.hull]) * hull_motion;
    bodies.push_back(std::move(b));
  }

  std::vector<ModeClass> out(basis.count());
  for (int j = 0; j < basis.count(); ++j) {
    ModeClass& c = out[j];
    const double total = basis.shapes.col(j).dot(system.mass * basis.shapes.col(j));
    double attached = 0.0;
    for (const Body& b : bodies) {
      const Vector6 v = b.motion.col(j);
      const double energy = v.dot(b.mass * v) / total;
      if (b.group == kHullBody) {
        // Per-component energies; the hull mass matrix is diagonal at its centre of gravity.
        const Vector6 mv = b.mass * v;
        for (int k = 0; k < 6; ++k)
          c.hull_energy[k] = v(k) * mv(k) / total;
      } else if (b.group == kAttachedBody) {
        attached += energy;
      } else {
        // Wheel bounce is the wheels' motion relative to the hull; the motion carried with the
        // hull counts as the hull's. The two parts are not M-orthogonal, so the wheel's energy
        // is shared between them in proportion to their own energies.
        const Vector6 r = b.relative.col(j);
        const Vector6 h = v - r;
        const double relative = r.dot(b.mass * r), carried = h.dot(b.mass * h);
        const double split = relative + carried > 0.0 ? relative / (relative + carried) : 0.0;
        c.wheel_share += split * energy;
        attached += (1.0 - split) * energy;
      }
    }
    double hull = 0.0;
    for (double e : c.hull_energy)
      hull += e;
    c.hull_share = hull + attached;
    c.track_share = std::max(0.0, 1.0 - c.hull_share - c.wheel_share);

    std::array<int, 6> order = {0, 1, 2, 3, 4, 5};
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return c.hull_energy[a] > c.hull_energy[b]; });
    if (c.hull_share >= c.wheel_share && c.hull_share >= c.track_share) {
      c.kind = ModeKind::Hull;
      for (int k : order)
        if (c.hull_energy[k] >= kComponentShare * hull)
          c.hull_motions.push_back(HullMotion(k));
      for (HullMotion m : c.hull_motions)
        c.label += (c.label.empty() ? "" : "+") + std::string(hullMotionName(m));
    } else if (c.wheel_share >= kWheelShare) {
      c.kind = ModeKind::WheelBounce;
      c.label = "wheel bounce";
      if (hull >= kCouplingShare) {
        c.hull_motions.push_back(HullMotion(order[0]));
        c.label += std::string("+") + hullMotionName(HullMotion(order[0]));
      }
    } else {
      c.kind = ModeKind::TrackLocal;
      c.label = "track chain local";
      // A chain mode that carries the hull along (e.g. rolls it) says so: its hull motion is what
      // a MAC with the un-tracked hull modes finds.
      if (hull >= kChainCouplingShare) {  // the hull's own energy, as for wheel modes
        c.hull_motions.push_back(HullMotion(order[0]));
        c.label += std::string("+") + hullMotionName(HullMotion(order[0]));
      }
    }
  }
  return out;
}

Matrix vehicleEnergy(const VehicleModel& vehicle, const fem::System& system,
                     const ModeShapes& shapes) {
  if (shapes.rows() != system.size())
    throw InputError("vehicleEnergy: mode shapes have " + std::to_string(shapes.rows()) +
                     " rows, the system has " + std::to_string(system.size()) + " active DOFs");
  // The bodies classifyModes() counts as the vehicle's, the road wheels with their whole motion
  // (relative and carried).
  const std::unordered_map<NodeId, int> vehicle_body = vehicleBodies(vehicle);
  const Eigen::Index k = shapes.cols();
  Matrix g = Matrix::Zero(k, k);
  for (const fem::Mass& m : vehicle.model.masses) {
    if (!vehicle_body.count(m.node))
      continue;
    const Matrix v = nodeRows(system, m.node) * shapes;  // 6 x k
    g.noalias() += v.transpose() * (fem::rigidBodyMass(m) * v);
  }
  // Shares of each mode's own kinetic energy: G_ij / sqrt(E_i E_j), E = diag(Phi^T M Phi).
  const Vector total = shapes.cwiseProduct(system.mass * shapes).colwise().sum().transpose();
  for (Eigen::Index i = 0; i < k; ++i)
    for (Eigen::Index j = 0; j < k; ++j)
      g(i, j) /= std::sqrt(total(i) * total(j));
  return 0.5 * (g + g.transpose());
}

std::vector<fem::DofRef> commonTranslationalDofs(const VehicleModel& a, const VehicleModel& b) {
  std::unordered_map<NodeId, Vector3> positions;
  for (const fem::Node& n : b.model.nodes)
    positions[n.id] = n.position;
  std::vector<NodeId> ids;
  for (const fem::Node& n : a.model.nodes) {
    const auto it = positions.find(n.id);
    if (it != positions.end() && (it->second - n.position).norm() <= 1e-9)
      ids.push_back(n.id);
  }
  std::sort(ids.begin(), ids.end());
  std::vector<fem::DofRef> dofs;
  for (NodeId id : ids)
    for (int d = 0; d < 3; ++d)
      dofs.push_back({id, d});
  return dofs;
}

Matrix physicalShapes(const fem::System& system, const std::vector<fem::DofRef>& dofs,
                      const ModeShapes& shapes) {
  if (shapes.rows() != system.size())
    throw InputError("physicalShapes: mode shapes have " + std::to_string(shapes.rows()) +
                     " rows, the system has " + std::to_string(system.size()) + " active DOFs");
  // Selection S (rows of T) then S * Phi.
  std::vector<DofIndex> rows;
  for (const fem::DofRef& d : dofs)
    rows.push_back(system.dofs.physical(d.node, d.direction));
  const SparseMatrix& t = system.dofs.transformation();
  std::unordered_map<DofIndex, std::vector<int>> wanted;
  for (std::size_t i = 0; i < rows.size(); ++i)
    wanted[rows[i]].push_back(static_cast<int>(i));
  std::vector<Triplet> trip;
  for (Eigen::Index c = 0; c < t.outerSize(); ++c)
    for (SparseMatrix::InnerIterator it(t, c); it; ++it) {
      const auto w = wanted.find(it.row());
      if (w == wanted.end())
        continue;
      for (int i : w->second)
        trip.emplace_back(i, c, it.value());
    }
  SparseMatrix s(static_cast<Eigen::Index>(dofs.size()), t.cols());
  s.setFromTriplets(trip.begin(), trip.end());
  return s * shapes;
}

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
