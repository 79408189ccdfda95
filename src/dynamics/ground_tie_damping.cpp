#include "tracked_vehicle_dynamics/dynamics/ground_tie_damping.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {
namespace {

constexpr double kTwoPi = 2.0 * 3.14159265358979323846;

void checkContacts(const SecondOrderSystem& system, const std::vector<GroundContact>& contacts,
                   DofIndex inputs) {
  for (const GroundContact& c : contacts)
    if (c.coordinate < 0 || c.coordinate >= system.size() || c.input < 0 || c.input >= inputs)
      throw InputError("ground tie damping: contact of road input " + std::to_string(c.input) +
                       " on coordinate " + std::to_string(c.coordinate) + " lies outside the " +
                       std::to_string(system.size()) + "-coordinate system");
}

}  // namespace

Vector absoluteContactDamping(const SecondOrderSystem& system,
                              const std::vector<GroundContact>& contacts) {
  checkContacts(system, contacts, system.inputCount());
  const DofIndex n = system.size();
  // K r = K_u 1 over the contacts only (a travel input is no road).
  Vector lift = Vector::Zero(n);
  Vector road_damping = Vector::Zero(n);  // C_u 1
  for (const GroundContact& c : contacts) {
    lift(c.coordinate) += c.stiffness;
    road_damping(c.coordinate) += c.damping;
  }
  const Eigen::LDLT<Matrix> factor(system.stiffness);
  const Vector r = factor.solve(lift);
  if (factor.info() != Eigen::Success || !r.allFinite() ||
      (system.stiffness * r - lift).norm() > 1e-6 * lift.norm())
    throw SolverError(
        "ground tie damping: K is singular: the model is not held by its ground springs alone, "
        "so a uniform lift of the road moves it in no single rigid way");
  const Vector absolute = system.damping * r - road_damping;
  Vector ratio(static_cast<Eigen::Index>(contacts.size()));
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const GroundContact& c = contacts[i];
    const double mass = system.mass(c.coordinate, c.coordinate);
    ratio(static_cast<Eigen::Index>(i)) =
        mass > 0.0 ? std::abs(absolute(c.coordinate)) / (2.0 * std::sqrt(c.stiffness * mass)) : 0.0;
  }
  return ratio;
}

double lowestGroundTieModeHz(const ModalSystem& modal, const std::vector<GroundContact>& contacts,
                             double above_hz) {
  const ModeShapes& phi = modal.shapes();
  const Vector& omega = modal.naturalFrequencies();
  for (const GroundContact& c : contacts)
    if (c.coordinate < 0 || c.coordinate >= phi.rows())
      throw InputError("ground tie damping: contact of road input " + std::to_string(c.input) +
                       " on coordinate " + std::to_string(c.coordinate) + " lies outside the " +
                       std::to_string(phi.rows()) + "-coordinate modes");
  for (Eigen::Index r = 0; r < omega.size(); ++r) {  // ascending
    if (!(omega(r) > 0.0) || omega(r) <= kTwoPi * above_hz)
      continue;           // a rigid-body mode strains nothing
    double energy = 0.0;  // 2 x the ground springs' share, sum_i k_i phi_r(m(i))^2
    for (const GroundContact& c : contacts)
      energy += c.stiffness * phi(c.coordinate, r) * phi(c.coordinate, r);
    if (energy > 0.5 * omega(r) * omega(r))
      return omega(r) / kTwoPi;
  }
  return std::numeric_limits<double>::infinity();
}

std::string groundTieDampingWarning(const SecondOrderSystem& system,
                                    const std::vector<GroundContact>& contacts,
                                    const ModalSystem* modal, double max_dynamic_hz,
                                    double nyquist_hz, const std::string& how,
                                    const std::string& instead) {
  if (contacts.empty())
    return "";
  // The damping first: it is cheap, and without it no mode needs finding.
  const Vector ratio = absoluteContactDamping(system, contacts);
  const double worst = ratio.maxCoeff();
  if (!(worst >= kNegligibleTieDamping))
    return "";
  std::optional<ModalSystem> own;
  if (modal == nullptr)
    modal = &own.emplace(system);
  const double lowest_hz = lowestGroundTieModeHz(*modal, contacts, nyquist_hz);
  if (!std::isfinite(lowest_hz) || (max_dynamic_hz > 0.0 && lowest_hz > max_dynamic_hz))
    return "";  // no tie mode the step cannot resolve, or all of them quasi-static
  double stiffest = 0.0;
  for (const GroundContact& c : contacts)
    stiffest = std::max(stiffest, c.stiffness);
  return "ground contact: the ground-tie modes from " + brief(std::round(lowest_hz)) +
         " Hz up (each contact's mass on its ground spring, up to " + brief(stiffest) +
         " N/m; above the step's Nyquist frequency, " + brief(nyquist_hz) +
         " Hz) are integrated dynamically (" + how +
         "), and the model's damping holds the contacts to an inertial frame with up to " +
         brief(std::round(worst * 1000.0) / 10.0) +
         " % of a tie's critical damping (modal or mass-proportional damping acts on absolute "
         "velocities): the contact forces then carry about 2 zeta sqrt(k m) times the road's "
         "vertical speed under each contact, a force no road exerts, while the bodies' motions "
         "barely change. For contact forces, " +
         instead;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
