#include "tracked_vehicle_dynamics/dynamics/ground_tie_damping.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "tracked_vehicle_dynamics/dynamics/validation.h"
#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {
namespace {

// Every contact on one of `coordinates` coordinates and one of `inputs` inputs (< 0: unchecked).
void checkContacts(const std::vector<GroundContact>& contacts, DofIndex coordinates,
                   DofIndex inputs, const char* of) {
  for (const GroundContact& c : contacts)
    if (c.coordinate < 0 || c.coordinate >= coordinates || c.input < 0 ||
        (inputs >= 0 && c.input >= inputs))
      throw InputError("ground tie damping: contact of road input " + std::to_string(c.input) +
                       " on coordinate " + std::to_string(c.coordinate) + " lies outside the " +
                       std::to_string(coordinates) + "-coordinate " + of);
}

void checkContacts(const SecondOrderSystem& system, const std::vector<GroundContact>& contacts) {
  validateSystem(system);
  checkContacts(contacts, system.size(), system.inputCount(), "system");
}

// k_m: the ground stiffness on each contact's coordinate, the sum of the contacts acting there.
std::map<DofIndex, double> tieStiffness(const std::vector<GroundContact>& contacts) {
  std::map<DofIndex, double> k;
  for (const GroundContact& c : contacts)
    k[c.coordinate] += c.stiffness;
  return k;
}

}  // namespace

Vector absoluteContactDamping(const SecondOrderSystem& system,
                              const std::vector<GroundContact>& contacts) {
  checkContacts(system, contacts);
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
  const std::map<DofIndex, double> k = tieStiffness(contacts);
  Vector ratio(static_cast<Eigen::Index>(contacts.size()));
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const DofIndex m = contacts[i].coordinate;
    const double mass = system.mass(m, m);
    ratio(static_cast<Eigen::Index>(i)) =
        mass > 0.0 ? std::abs(absolute(m)) / (2.0 * std::sqrt(k.at(m) * mass)) : 0.0;
  }
  return ratio;
}

std::vector<GroundContact> stiffTies(const SecondOrderSystem& system,
                                     const std::vector<GroundContact>& contacts) {
  checkContacts(system, contacts);
  const std::map<DofIndex, double> k = tieStiffness(contacts);
  std::vector<GroundContact> stiff;
  for (const GroundContact& c : contacts) {
    const double tie = k.at(c.coordinate);
    const double rest = system.stiffness(c.coordinate, c.coordinate) - tie;  // K_mm - k_m
    if (tie >= kStiffTieRatio * std::max(rest, 0.0))
      stiff.push_back(c);
  }
  return stiff;
}

std::pair<double, double> groundTieModeRangeHz(const ModalSystem& modal,
                                               const std::vector<GroundContact>& contacts) {
  const ModeShapes& phi = modal.shapes();
  const Vector& omega = modal.naturalFrequencies();
  checkContacts(contacts, phi.rows(), modal.inputCount(), "modes");
  constexpr double kNone = std::numeric_limits<double>::infinity();
  std::pair<double, double> range{kNone, kNone};
  for (Eigen::Index r = 0; r < omega.size(); ++r) {  // ascending
    if (!(omega(r) > 0.0))
      continue;           // a rigid-body mode strains nothing
    double energy = 0.0;  // 2 x the ground springs' share, sum_i k_i phi_r(m(i))^2
    for (const GroundContact& c : contacts)
      energy += c.stiffness * phi(c.coordinate, r) * phi(c.coordinate, r);
    if (energy > 0.5 * omega(r) * omega(r)) {
      if (std::isinf(range.first))
        range.first = omega(r) / kTwoPi;
      range.second = omega(r) / kTwoPi;
    }
  }
  return range;
}

std::string groundTieDampingWarning(const SecondOrderSystem& system,
                                    const std::vector<GroundContact>& contacts,
                                    const ModalSystem* modal, double max_dynamic_hz,
                                    const std::string& how, const std::string& instead) {
  const std::vector<GroundContact> ties = stiffTies(system, contacts);
  if (ties.empty())
    return "";
  // The damping first: it is cheap, and without it no mode needs finding.
  const Vector ratio = absoluteContactDamping(system, ties);
  const double worst = ratio.maxCoeff();
  if (!(worst >= kNegligibleTieDamping))
    return "";
  std::optional<ModalSystem> own;
  if (modal == nullptr)
    modal = &own.emplace(system);
  const auto [lowest_hz, highest_hz] = groundTieModeRangeHz(*modal, ties);
  const bool all_dynamic = !(max_dynamic_hz > 0.0);
  if (std::isinf(lowest_hz) || (!all_dynamic && lowest_hz > max_dynamic_hz))
    return "";  // no tie mode, or all of them quasi-static
  double stiffest = 0.0;
  for (const GroundContact& c : ties)
    stiffest = std::max(stiffest, c.stiffness);
  const std::string which = all_dynamic || highest_hz <= max_dynamic_hz
                                ? "the ground-tie modes (" + brief(std::round(lowest_hz)) + " to " +
                                      brief(std::round(highest_hz)) + " Hz"
                                : "the ground-tie modes from " + brief(std::round(lowest_hz)) +
                                      " Hz up to the cut-off " + brief(max_dynamic_hz) +
                                      " Hz (of " + brief(std::round(lowest_hz)) + " to " +
                                      brief(std::round(highest_hz)) + " Hz";
  return "ground contact: " + which + ": each contact's mass on its ground spring, up to " +
         brief(stiffest) + " N/m, a penalty for a rigid contact) are integrated dynamically (" +
         how + "), and the model's damping holds the contacts to an inertial frame with up to " +
         brief(std::round(worst * 1000.0) / 10.0) +
         " % of a tie's critical damping (modal or mass-proportional damping acts on absolute "
         "velocities): the contact forces then carry about 2 zeta sqrt(k m) times the road's "
         "vertical speed under each contact, a force no road exerts, while the bodies' motions "
         "barely change. For contact forces, " +
         instead;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
