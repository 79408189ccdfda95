#include "tracked_vehicle_dynamics/fem/unilateral_static.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace fem {

namespace {

/// Forces below this share of the largest normal force are round-off, not tension: a spring that
/// carries nothing in exact arithmetic must not flip in and out of the active set.
constexpr double kForceTolerance = 1e-9;

/// The normal force N = k_a n . (u_2 - u_1) a spring with normal stiffness `k` carries (or would
/// carry, when released) in the solution `u` (physical displacements).
double normalForce(const System& system, const Vector& u, const Spring& s,
                   const UnilateralSpring& c, double k) {
  auto nodal = [&](NodeId id) -> Vector3 {
    if (id == kGround)
      return Vector3::Zero();
    return u.segment<3>(system.dofs.physical(id, 0));
  };
  return k * c.sign * s.frame.col(c.axis).dot(nodal(s.n2) - nodal(s.n1));
}

/// The names of the released springs, the first kNamesShown of them, for an error message.
std::string releasedNames(const Model& model, const std::vector<UnilateralSpring>& springs,
                          const std::vector<bool>& released) {
  constexpr int kNamesShown = 8;
  std::string names;
  int shown = 0, more = 0;
  for (std::size_t i = 0; i < springs.size(); ++i) {
    if (!released[i])
      continue;
    if (shown == kNamesShown) {
      ++more;
      continue;
    }
    names += (shown++ ? ", " : "") + model.springs[springs[i].spring].name;
  }
  if (more > 0)
    names += " and " + std::to_string(more) + " more";
  return names;
}

}  // namespace

UnilateralStaticResult solveUnilateralStatic(const Model& model,
                                             const std::vector<UnilateralSpring>& springs,
                                             int max_iterations, ActiveSetUpdate update,
                                             double forward_acceleration) {
  std::vector<double> normal_stiffness;
  for (const UnilateralSpring& c : springs) {
    if (c.spring >= model.springs.size())
      throw InputError("unilateral spring " + std::to_string(c.spring) + " does not exist (the " +
                       "model has " + std::to_string(model.springs.size()) + " springs)");
    const Spring& s = model.springs[c.spring];
    if (c.axis < 0 || c.axis > 2 || (c.sign != 1.0 && c.sign != -1.0))
      throw InputError("unilateral spring " + s.name + ": normal axis " + std::to_string(c.axis) +
                       ", sign " + std::to_string(c.sign) + " (expected axis 0..2, sign +-1)");
    if (!(s.stiffness(c.axis) > 0.0))
      throw InputError("unilateral spring " + s.name + " has no stiffness along its normal");
    normal_stiffness.push_back(s.stiffness(c.axis));
  }
  UnilateralStaticResult r;
  r.model = model;
  r.released.assign(springs.size(), false);
  r.normal_force.assign(springs.size(), 0.0);
  std::set<std::vector<bool>> visited{r.released};
  bool single_change = update == ActiveSetUpdate::WorstOnly;
  // The set of the last solve that succeeded, while the sets change several springs at a time.
  std::vector<bool> last_solved;
  for (r.iterations = 1; r.iterations <= max_iterations; ++r.iterations) {
    for (std::size_t i = 0; i < springs.size(); ++i)
      r.model.springs[springs[i].spring].stiffness(springs[i].axis) =
          r.released[i] ? 0.0 : normal_stiffness[i];
    r.system = assemble(r.model);
    try {
      r.statics = solveStatic(r.system, r.system.steadyLoad(forward_acceleration));
    } catch (const SolverError& e) {
      // Releasing every tensioned spring at once can overshoot into a set that leaves a part
      // free where the solution does not (an un-tracked vehicle whose centre of gravity lies far
      // aft: two pads lifted entirely with their wheels' patches, free bodies, for one solve):
      // back to the last solved set, and one spring at a time from there. (A total lift-off is
      // then reported at the first set that leaves a free motion on the way.)
      if (!single_change && !last_solved.empty()) {
        single_change = true;
        r.released = last_solved;
        continue;
      }
      const auto lifted = std::count(r.released.begin(), r.released.end(), true);
      if (lifted == 0)
        throw;
      throw UnilateralFreeMotionError(
          "with the " + std::to_string(lifted) + " unilateral springs in tension released (" +
              releasedNames(r.model, springs, r.released) + "): " + e.what(),
          r.released);
    }
    if (!single_change)
      last_solved = r.released;
    const Vector u = r.system.dofs.transformation() * r.statics.displacement;
    // Each spring's force with its own stiffness: what it carries when active, what it would
    // carry (its penetration times k) when released.
    std::vector<double> force(springs.size());
    double scale = 0.0;
    for (std::size_t i = 0; i < springs.size(); ++i) {
      force[i] = normalForce(r.system, u, r.model.springs[springs[i].spring], springs[i],
                             normal_stiffness[i]);
      if (!r.released[i])
        scale = std::max(scale, std::abs(force[i]));
    }
    const double tolerance = kForceTolerance * scale;
    // The violation of each contact: tension on an active one, penetration of a released one.
    std::vector<double> violation(springs.size(), 0.0);
    for (std::size_t i = 0; i < springs.size(); ++i) {
      const double v = r.released[i] ? force[i] : -force[i];
      if (v > tolerance)
        violation[i] = v;
    }
    bool changed = false;
    if (!single_change) {
      std::vector<bool> next = r.released;
      for (std::size_t i = 0; i < springs.size(); ++i)
        if (violation[i] > 0.0) {
          next[i] = !next[i];
          changed = true;
        }
      // Changing every violated contact at once can cycle (neighbouring pad soles taking the
      // load from each other in turn); from the first repeated set on, change only the worst.
      if (changed && !visited.insert(next).second) {
        single_change = true;
        changed = false;
      } else {
        r.released = std::move(next);
      }
    }
    if (single_change) {
      const auto worst = std::max_element(violation.begin(), violation.end());
      if (*worst > 0.0) {
        const std::size_t i = static_cast<std::size_t>(worst - violation.begin());
        r.released[i] = !r.released[i];
        changed = true;
      }
    }
    if (!changed) {
      for (std::size_t i = 0; i < springs.size(); ++i)
        r.normal_force[i] = r.released[i] ? 0.0 : force[i];
      return r;
    }
  }
  throw SolverError("unilateral contacts did not settle after " + std::to_string(max_iterations) +
                    " solves (springs keep lifting off and touching down)");
}

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
