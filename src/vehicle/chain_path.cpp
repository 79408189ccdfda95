#include "tracked_vehicle_dynamics/vehicle/chain_path.h"

#include <algorithm>
#include <cmath>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

namespace {

/// Bisection stops when the idler's position is bracketed to this width [m].
constexpr double kClosureTolerance = 1e-10;

Vector2 rotate(const Vector2& v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return Vector2(c * v.x() - s * v.y(), s * v.x() + c * v.y());
}

Vector2 normalOf(const Vector2& t) {
  return Vector2(-t.y(), t.x());
}

// Tangent from an external point P to circle (C, r) that then wraps the circle with the centre
// on the inward side: d = C - P = L t + r n, hence t = rot(-phi) d/|d|, tan(phi) = r / L.
Vector2 tangentPointFrom(const Vector2& p, const Vector2& c, double r, const std::string& key) {
  const Vector2 d = c - p;
  const double dist = d.norm();
  if (dist <= r)
    throw InputError(key + ": the wheel circle reaches the end of the ground run");
  const double l = std::sqrt(dist * dist - r * r);
  const Vector2 t = rotate(d / dist, -std::atan2(r, l));
  return p + l * t;
}

// Tangent leaving circle (C, r) towards an external point P: P - C = L t - r n.
Vector2 tangentPointTo(const Vector2& c, double r, const Vector2& p, const std::string& key) {
  const Vector2 d = p - c;
  const double dist = d.norm();
  if (dist <= r)
    throw InputError(key + ": the wheel circle reaches the end of the ground run");
  const double l = std::sqrt(dist * dist - r * r);
  const Vector2 t = rotate(d / dist, std::atan2(r, l));
  return c - r * normalOf(t);
}

double angleOf(const Vector2& v) {
  return std::atan2(v.y(), v.x());
}

}  // namespace

ChainPath::ChainPath(const VehicleDescription& d, double idler_x) {
  const auto& t = d.track_assembly;
  const double z = t.pitch_line_height;
  const double half = 0.5 * t.ground_count * t.pitch;
  const Vector2 rear(-half, z), front(half, z);
  sprocket_centre_ = Vector2(d.sprocket.centre_x, d.sprocket.centre_z);
  idler_centre_ = Vector2(idler_x, d.idler.centre_z);
  const double rs = d.sprocket.radius, ri = d.idler.radius;
  if (sprocket_centre_.y() - rs <= z)
    throw InputError("sprocket.centre_z: the sprocket reaches down to the ground run");
  if (idler_centre_.y() - ri <= z)
    throw InputError("idler.centre_z: the idler reaches down to the ground run");
  if (std::abs(sprocket_centre_.x()) <= half)
    throw InputError(
        "sprocket.centre_x: the sprocket must lie beyond an end of the ground run "
        "(|x| > " +
        brief(half) + " m)");
  // The wheel at each end of the loop: a rear drive sprocket with the idler in front, or a front
  // drive sprocket with the idler behind.
  const bool drive_front = frontDrive(d);
  const Vector2 front_centre = drive_front ? sprocket_centre_ : idler_centre_;
  const Vector2 rear_centre = drive_front ? idler_centre_ : sprocket_centre_;
  const double r_front = drive_front ? rs : ri, r_rear = drive_front ? ri : rs;
  const char* front_key = drive_front ? "sprocket.centre_z" : "idler.centre_z";
  const char* rear_key = drive_front ? "idler.centre_z" : "sprocket.centre_z";
  const ChainSegment front_arc = drive_front ? ChainSegment::Sprocket : ChainSegment::Idler;
  const ChainSegment rear_arc = drive_front ? ChainSegment::Idler : ChainSegment::Sprocket;

  const Vector2 t1 = tangentPointFrom(front, front_centre, r_front, front_key);
  // Top run: external tangent from the front wheel to the rear one, both circles on the inward
  // side: d = C2 - C1 = D (cos a t + sin a n), sin a = (r2 - r1) / D.
  const Vector2 dc = rear_centre - front_centre;
  const double dist = dc.norm();
  const Vector2 top_t = rotate(dc / dist, -std::asin((r_rear - r_front) / dist));
  const Vector2 t2 = front_centre - r_front * normalOf(top_t);
  const Vector2 t3 = rear_centre - r_rear * normalOf(top_t);
  const Vector2 t4 = tangentPointTo(rear_centre, r_rear, rear, rear_key);

  auto line = [&](ChainSegment seg, const Vector2& a, const Vector2& b) {
    Piece p;
    p.segment = seg;
    p.arc = false;
    p.a = a;
    p.b = b;
    p.len = (b - a).norm();
    pieces_.push_back(p);
  };
  auto arc = [&](ChainSegment seg, const Vector2& c, double r, const Vector2& from,
                 const Vector2& to) {
    Piece p;
    p.segment = seg;
    p.arc = true;
    p.centre = c;
    p.radius = r;
    p.start_angle = angleOf(from - c);
    p.sweep = std::fmod(angleOf(to - c) - p.start_angle + 2 * kTwoPi, kTwoPi);
    p.len = r * p.sweep;
    pieces_.push_back(p);
  };
  line(ChainSegment::Ground, rear, front);
  line(ChainSegment::FrontIncline, front, t1);
  arc(front_arc, front_centre, r_front, t1, t2);
  line(ChainSegment::TopRun, t2, t3);
  arc(rear_arc, rear_centre, r_rear, t3, t4);
  line(ChainSegment::RearIncline, t4, rear);
  if (top_t.x() >= 0.0)
    throw InputError(
        "idler: the top run must run rearwards (the front wheel ahead of the rear one)");
  for (Piece& p : pieces_) {
    p.s0 = length_;
    length_ += p.len;
  }
}

ChainPoint ChainPath::at(double s) const {
  s = std::fmod(s, length_);
  if (s < 0)
    s += length_;
  const Piece* piece = &pieces_.back();
  for (const Piece& p : pieces_)
    if (s < p.s0 + p.len) {
      piece = &p;
      break;
    }
  const double u = s - piece->s0;
  ChainPoint out;
  out.segment = piece->segment;
  if (piece->arc) {
    const double angle = piece->start_angle + u / piece->radius;
    const Vector2 radial(std::cos(angle), std::sin(angle));
    out.position = piece->centre + piece->radius * radial;
    out.tangent = Vector2(-radial.y(), radial.x());  // counter-clockwise in (x, z)
  } else {
    out.tangent = (piece->b - piece->a) / piece->len;
    out.position = piece->a + u * out.tangent;
  }
  return out;
}

std::pair<double, double> ChainPath::interval(ChainSegment segment) const {
  for (const Piece& p : pieces_)
    if (p.segment == segment)
      return {p.s0, p.s0 + p.len};
  return {0.0, 0.0};
}

double ChainPath::topRunHeight(double x) const {
  for (const Piece& p : pieces_)
    if (p.segment == ChainSegment::TopRun) {
      const double u = (x - p.a.x()) / (p.b.x() - p.a.x());
      return p.a.y() + u * (p.b.y() - p.a.y());
    }
  return 0.0;
}

double solveIdlerX(const VehicleDescription& d) {
  const auto& t = d.track_assembly;
  const double target = t.count * t.pitch;
  const double half = 0.5 * t.ground_count * t.pitch;
  // The idler stands at the end of the ground run opposite the sprocket, at distance u beyond it;
  // the loop grows monotonically with u. Its wheel may reach at most kWheelOverhang beyond the
  // hull's end.
  const double side = frontDrive(d) ? -1.0 : 1.0;  // +1: idler in front
  const double hull_end = 0.5 * d.hull.length;
  const double farthest = hull_end + kWheelOverhang - d.idler.radius - half;
  const auto idlerX = [&](double u) { return side * (half + u); };
  double lo = 1e-3, hi = std::max(farthest, lo + 1e-3);
  const std::string chain = "track_assembly.count: a chain of " + std::to_string(t.count) +
                            " assemblies (" + brief(target) + " m)";
  if (ChainPath(d, idlerX(lo)).length() > target)
    throw InputError(chain + " is too short to wrap the sprocket and the idler");
  if (ChainPath(d, idlerX(hi)).length() < target)
    throw InputError(chain + " is too long: it closes only with the idler's centre beyond x = " +
                     brief(idlerX(hi)) + " m, where its wheel (idler.radius " +
                     brief(d.idler.radius) + " m) reaches more than " + brief(kWheelOverhang) +
                     " m " + (side > 0 ? "ahead of the hull's front" : "behind the hull's rear") +
                     " end (x = " + brief(side * hull_end) + " m, half of hull.length " +
                     brief(d.hull.length) + " m from the middle of the wheelbase)");
  while (hi - lo > kClosureTolerance) {
    const double mid = 0.5 * (lo + hi);
    if (ChainPath(d, idlerX(mid)).length() < target)
      lo = mid;
    else
      hi = mid;
  }
  return idlerX(0.5 * (lo + hi));
}

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
