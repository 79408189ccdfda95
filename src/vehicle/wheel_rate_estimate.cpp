#include "tracked_vehicle_dynamics/vehicle/wheel_rate_estimate.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/number_text.h"
#include "tracked_vehicle_dynamics/vehicle/chain_path.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {
namespace {

std::string fixed(double value, int digits) {
  return io::formatC("%.*f", digits, value);
}

// "the hull (30300 kg) on its 14 road wheels' torsion bars and pads alone (wheel rate
// k_t / (a cos beta)^2 = 1.58456e+06 N/m, in series with track_assembly.compression_stiffness:
// 1.46228e+06 N/m per wheel)": the estimate, said once for both warnings.
std::string estimateText(const WheelRateEstimate& e, Variant variant) {
  return std::string("the hull") + (variant == Variant::Tracked ? " with its chain wheels" : "") +
         " (" + brief(e.sprung_mass) + " kg) on its " + std::to_string(e.wheels) +
         " road wheels' torsion bars and pads alone (wheel rate k_t / (a cos beta)^2 = " +
         brief(e.wheel_rate) +
         " N/m, in series with track_assembly.compression_stiffness: " + brief(e.series_rate) +
         " N/m per wheel)";
}

// What carries the hull besides its suspension, and where the docs say how to fit it.
std::string carriersText(const VehicleDescription& d, Variant variant) {
  const std::string ties =
      "the road wheels locked to their links fore and aft "
      "(suspension.contact_shear_stiffness " +
      brief(d.suspension.contact_shear_stiffness) +
      " N/m: each arm drags its contact patch against the pads' shear as "
      "it turns; a rolling wheel is free there, suspension.guide_stiffness "
      "keeping its lateral guidance)";
  if (variant == Variant::Untracked)
    return "it is stiffened by " + ties +
           "; doc/vehicle_model.md, \"The un-tracked bounce against a hand estimate\"";
  const std::string tension =
      d.track_assembly.static_tension && *d.track_assembly.static_tension > 0.0
          ? ", the chain's tension (track_assembly.static_tension " +
                brief(*d.track_assembly.static_tension) + " N: a taut loop holds the hull up)"
          : std::string();
  return "the chain's bending (track_assembly.link_member_bending_inertia " +
         brief(d.track_assembly.link_member_bending_inertia) + " m^4)" + tension + " or " + ties +
         " carry the hull; values fitted to the paper's 55 t vehicle rarely suit another: fit "
         "them to yours (doc/vehicle_model.md, \"Tuning\")";
}

}  // namespace

WheelRateEstimate wheelRateEstimate(const VehicleDescription& d, Variant variant) {
  WheelRateEstimate e;
  const SuspensionDescription& s = d.suspension;
  const double lever = s.arm_length * std::cos(s.arm_angle);
  e.wheel_rate = s.torsion_bar_stiffness / (lever * lever);
  const double kz = d.track_assembly.compression_stiffness;
  e.series_rate = e.wheel_rate * kz / (e.wheel_rate + kz);
  e.wheels = 2 * d.running_gear.axle_count;
  e.sprung_mass = d.hull.mass;
  if (variant == Variant::Tracked)
    e.sprung_mass += 2.0 * (d.sprocket.mass + d.idler.mass +
                            static_cast<double>(d.return_rollers.x.size()) * d.return_rollers.mass);
  const double n_k = e.wheels * e.series_rate;
  e.sag = e.sprung_mass * kStandardGravity / n_k;
  e.bounce_hz = std::sqrt(n_k / e.sprung_mass) / (2.0 * kPi);
  // The sprung mass's CoG: the hull's, and tracked the chain wheels rigid with it (the idler's
  // x is where the chain closes).
  double moment = d.hull.mass * d.hull.cog_x;
  if (variant == Variant::Tracked) {
    moment += 2.0 * (d.sprocket.mass * d.sprocket.centre_x + d.idler.mass * solveIdlerX(d));
    for (const double x : d.return_rollers.x)
      moment += 2.0 * d.return_rollers.mass * x;
  }
  e.cog_x = moment / e.sprung_mass;
  // Axles at x_j = ((N - 1) / 2 - j) l about the wheelbase's middle, one wheel a side.
  const int axles = d.running_gear.axle_count;
  double second_moment = 0.0;
  for (int j = 0; j < axles; ++j) {
    const double x = (0.5 * (axles - 1) - j) * d.running_gear.axle_spacing;
    second_moment += 2.0 * x * x;
  }
  e.end_station = 0.5 * (axles - 1) * d.running_gear.axle_spacing;
  e.pitch = second_moment > 0.0
                ? e.sprung_mass * kStandardGravity * e.cog_x / (e.series_rate * second_moment)
                : 0.0;
  return e;
}

std::string sagShareWarning(double hull_sag, const VehicleDescription& description,
                            Variant variant) {
  const WheelRateEstimate e = wheelRateEstimate(description, variant);
  // Positive down, as e.sag; 0 - x, not -x, so that a hull that does not move sags "0.00 mm"
  // and never "-0.00 mm" (IEEE 754: 0 - 0 is +0).
  const double sag = 0.0 - hull_sag;
  static_assert(kMinSagShare == 0.2, "the warning says \"less than a fifth\"");
  if (sag >= kMinSagShare * e.sag)
    return "";
  const std::string what =
      sag < 0.0
          ? "the hull rises " + fixed(-sag * 1e3, 2) + " mm under its own weight"
          : "the hull sags " + fixed(sag * 1e3, 2) + " mm under its weight, less than a fifth of";
  return what + (sag < 0.0 ? ", where " : " ") + "the " + fixed(e.sag * 1e3, 1) + " mm of " +
         estimateText(e, variant) + (sag < 0.0 ? " would sag" : "") + ": " +
         carriersText(description, variant);
}

std::string attitudeWarning(double hull_pitch, const VehicleDescription& description,
                            Variant variant) {
  const WheelRateEstimate e = wheelRateEstimate(description, variant);
  static_assert(kMaxPitchShare == 0.25, "the warning says \"more than a quarter\"");
  const double off = std::abs(hull_pitch - e.pitch) * e.end_station;
  if (!(off > kMaxPitchShare * e.sag))
    return "";
  const auto attitude = [](double pitch) {
    const double deg = pitch * kRadToDegree;
    return std::abs(deg) < 0.005
               ? std::string("level")
               : fixed(std::abs(deg), 2) + (deg > 0.0 ? " deg nose down" : " deg nose up");
  };
  return "the hull sits " + attitude(hull_pitch) + " at rest, where " + estimateText(e, variant) +
         " would sit " + attitude(e.pitch) + " (its CoG " + fixed(std::abs(e.cog_x), 3) +
         (e.cog_x < 0.0 ? " m behind" : " m ahead of") +
         " the wheelbase's middle): the end axles " + fixed(off * 1e3, 1) +
         " mm off the estimate's attitude, more than a quarter of its " + fixed(e.sag * 1e3, 1) +
         " mm sag, so the wheel loads do not follow the CoG; " +
         carriersText(description, variant) +
         (variant == Variant::Tracked
              ? " (compare tvd statics --contact bilateral, the linear model, with the default "
                "contacts that cannot pull)"
              : "");
}

std::vector<std::string> restWarnings(double hull_sag, double hull_pitch,
                                      const VehicleDescription& description, Variant variant) {
  std::vector<std::string> warnings;
  for (std::string w : {sagShareWarning(hull_sag, description, variant),
                        attitudeWarning(hull_pitch, description, variant)})
    if (!w.empty())
      warnings.push_back(std::move(w));
  return warnings;
}

std::string bounceWarning(const VehicleDescription& description, Variant variant,
                          const std::vector<ModeClass>& classes, const Vector& frequencies_hz) {
  const WheelRateEstimate e = wheelRateEstimate(description, variant);
  const double limit =
      variant == Variant::Tracked ? kMaxTrackedBounceRatio : kMaxUntrackedBounceRatio;
  // Un-tracked, the statics match the estimate (every arm turns alike under the CoG's load):
  // what stiffens is the bounce alone, not what carries the hull.
  const std::string beyond =
      "; beyond " + brief(limit) + " times (the paper's vehicle: " +
      (variant == Variant::Tracked ? "2.0) it is not the torsion bars that hold the hull: "
                                   : "1.2) the torsion bars alone do not set it: ") +
      carriersText(description, variant);
  const auto n =
      std::min<Eigen::Index>(static_cast<Eigen::Index>(classes.size()), frequencies_hz.size());
  for (Eigen::Index i = 0; i < n; ++i) {
    const ModeClass& c = classes[static_cast<std::size_t>(i)];
    if (c.kind != ModeKind::Hull || c.hull_motions.empty() ||
        c.hull_motions.front() != HullMotion::Bounce)
      continue;
    const double f = frequencies_hz(i);
    const double ratio = f / e.bounce_hz;
    if (ratio <= limit)
      return "";
    return "the hull's bounce (mode " + std::to_string(i + 1) + ", " + fixed(f, 2) + " Hz) is " +
           fixed(ratio, 2) + " times the " + fixed(e.bounce_hz, 2) + " Hz of " +
           estimateText(e, variant) + beyond;
  }
  // No mode led by the bounce among those solved: judged only when none bounces at all (an
  // off-centre CoG turns the bounce into pitch+bounce, which is not "above them all") and they
  // already reach beyond the limit (the bounce lies above the last of them).
  for (Eigen::Index i = 0; i < n; ++i)
    if (classes[static_cast<std::size_t>(i)].has(HullMotion::Bounce))
      return "";
  if (n == 0 || frequencies_hz(n - 1) <= limit * e.bounce_hz)
    return "";
  return "no hull bounce mode among the " + std::to_string(n) + " lowest modes (up to " +
         fixed(frequencies_hz(n - 1), 2) + " Hz, " + fixed(frequencies_hz(n - 1) / e.bounce_hz, 1) +
         " times the " + fixed(e.bounce_hz, 2) + " Hz of " + estimateText(e, variant) +
         "; more modes, --count, show where it is)" + beyond;
}

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
