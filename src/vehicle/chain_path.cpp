#include "tracked_vehicle_dynamics/vehicle/chain_path.h"

#include <algorithm>
#include <cmath>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

namespace {

constexpr double kTwoPi = 6.283185307179586;
/// Bisection stops when the loop length matches the chain to this length [m].
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
  if (sprocket_centre_.x() >= rear.x())
    throw InputError("sprocket.centre_x: the sprocket must lie behind the ground run");

  const Vector2 t1 = tangentPointFrom(front, idler_centre_, ri, "idler.centre_z");
  // Top run: external tangent from the idler to the sprocket, both circles on the inward side:
  // d = C2 - C1 = D (cos a t + sin a n), sin a = (r2 - r1) / D.
  const Vector2 dc = sprocket_centre_ - idler_centre_;
  const double dist = dc.norm();
  const Vector2 top_t = rotate(dc / dist, -std::asin((rs - ri) / dist));
  const Vector2 t2 = idler_centre_ - ri * normalOf(top_t);
  const Vector2 t3 = sprocket_centre_ - rs * normalOf(top_t);
  const Vector2 t4 = tangentPointTo(sprocket_centre_, rs, rear, "sprocket.centre_z");

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
  arc(ChainSegment::Idler, idler_centre_, ri, t1, t2);
  line(ChainSegment::TopRun, t2, t3);
  arc(ChainSegment::Sprocket, sprocket_centre_, rs, t3, t4);
  line(ChainSegment::RearIncline, t4, rear);
  if (top_t.x() >= 0.0)
    throw InputError("idler: the top run must run rearwards (idler ahead of sprocket)");
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
  const double front = 0.5 * t.ground_count * t.pitch;
  // The loop grows monotonically as the idler moves forward; the idler wheel may reach at most
  // kWheelOverhang beyond the hull's front end.
  const double hull_front = 0.5 * d.hull.length;
  const double farthest = hull_front + kWheelOverhang - d.idler.radius;
  double lo = front + 1e-3, hi = std::max(farthest, lo + 1e-3);
  const std::string chain = "track_assembly.count: a chain of " + std::to_string(t.count) +
                            " assemblies (" + brief(target) + " m)";
  if (ChainPath(d, lo).length() > target)
    throw InputError(chain + " is too short to wrap the sprocket and the idler");
  if (ChainPath(d, hi).length() < target)
    throw InputError(chain + " is too long: it closes only with the idler beyond x = " +
                     brief(farthest) + " m, i.e. more than " + brief(kWheelOverhang) +
                     " m ahead of the hull's front end (x = " + brief(hull_front) +
                     " m; hull.length " + brief(d.hull.length) + " m)");
  while (hi - lo > kClosureTolerance) {
    const double mid = 0.5 * (lo + hi);
    if (ChainPath(d, mid).length() < target)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
