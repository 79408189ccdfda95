// Linear statics with unilateral springs (contacts that push but cannot pull): an active-set
// iteration on K x = f. One axis a of each listed spring's frame is its normal, n = s R e_a
// (s = +-1: the direction in which it pushes its node n1); its normal force is
//   N = k_a n . (u_2 - u_1)   (u = 0 at ground),
// compressive when N > 0. A spring in tension (N < 0) loses its normal stiffness k_a (released);
// a released one whose ends overlap again (the N it would carry > 0) gets it back; the model is
// re-solved until no spring changes. Only the normal is released: the other axes keep their
// stiffness (the linear model's tie), so the problem stays a linear complementarity problem with
// a symmetric positive definite matrix, whose solution is unique: N >= 0 on the active springs,
// no overlap on the released ones. Releasing every axis instead has no such solution in general
// (a trailing-arm wheel whose patch also ties it along the chain is pulled down with the tie and
// sinks into the link without it).
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/model.h"
#include "tracked_vehicle_dynamics/fem/static_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"

namespace tracked_vehicle_dynamics {
namespace fem {

struct UnilateralSpring {
  std::size_t spring = 0;  ///< index into Model::springs
  int axis = 2;            ///< the frame axis (0 x, 1 y, 2 z) that is its normal
  double sign = 1.0;       ///< +1: it pushes n1 along +axis; -1: along -axis
};

struct UnilateralStaticResult {
  Model model;                 ///< the input model with the released springs' normal stiffness 0
  System system;               ///< `model` assembled
  StaticResult statics;        ///< its solution under the load (gravity, and travel inertia)
  std::vector<bool> released;  ///< per UnilateralSpring, in the order given
  std::vector<double> normal_force;  ///< N of each (0 when released) [N]
  int iterations = 0;                ///< solves done
};

/// The SolverError of solveUnilateralStatic when a set of released springs leaves a free motion:
/// it carries that set, so that a caller who knows the structure can say what came loose.
class UnilateralFreeMotionError : public SolverError {
 public:
  UnilateralFreeMotionError(const std::string& message, std::vector<bool> released_springs)
      : SolverError(message), released(std::move(released_springs)) {}
  std::vector<bool> released;  ///< per UnilateralSpring, in the order given
};

/// Solves of the active-set iteration before it gives up (the bundled tracked vehicle settles in
/// 4).
constexpr int kMaxActiveSetSolves = 100;

/// How the active set changes between solves.
enum class ActiveSetUpdate {
  /// every violated spring at once; the worst one at a time once a set repeats, or from the last
  /// solved set once a change leaves a free motion
  AllViolated,
  WorstOnly,  ///< the worst violated spring only (slower; what the first falls back to)
};

/// Solves the gravity load case of `model` with the listed springs unilateral, plus the travel
/// inertia of a forward acceleration `forward_acceleration` [m/s^2] of the vehicle (f_g + a f_a,
/// System::travel_load; braking is a < 0), 0 for gravity alone. Throws InputError
/// for a spring index out of range, an axis not in 0..2 or a zero sign or normal stiffness,
/// SolverError when the released springs leave a free motion (the structure would lift off
/// entirely, or a part would hang on nothing but released springs: a mechanism; the message names
/// the released springs and the DOFs that move freely; UnilateralFreeMotionError when springs
/// were released) or the active set has not settled after
/// `max_iterations` solves.
UnilateralStaticResult solveUnilateralStatic(const Model& model,
                                             const std::vector<UnilateralSpring>& springs,
                                             int max_iterations = kMaxActiveSetSolves,
                                             ActiveSetUpdate update = ActiveSetUpdate::AllViolated,
                                             double forward_acceleration = 0.0);

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
