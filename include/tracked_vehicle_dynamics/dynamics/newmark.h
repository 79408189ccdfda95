// Newmark average-acceleration integrator (gamma = 1/2, beta = 1/4: trapezoidal rule,
// unconditionally stable, no numerical damping, period error ~ (omega h)^2 / 12) for the full
// sparse model, the validation reference of the reduced simulation:
//
//   M q'' + C q' + K q = F(t) = K_u u + C_u u' + f_g
//   K_eff = K + gamma/(beta h) C + 1/(beta h^2) M                     (factorised once, LDL^T)
//   K_eff q1 = F1 + M (q/(beta h^2) + v/(beta h) + (1/(2 beta) - 1) a)
//                 + C (gamma/(beta h) q + (gamma/beta - 1) v + h (gamma/(2 beta) - 1) a)
//   a1 = (q1 - q)/(beta h^2) - v/(beta h) - (1/(2 beta) - 1) a
//   v1 = v + h ((1 - gamma) a + gamma a1)
//
// Same conventions as Simulator: w = [u; u'], step(w_{k+1}) advances to the sample of w_{k+1}
// (the force is evaluated at both ends of the step), outputs stacked as OutputLayout says.
// Sparse factorisation by Eigen::SimplicialLDLT (AMD ordering): no CHOLMOD link needed.
#pragma once

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/dynamics/output_layout.h"
#include "tracked_vehicle_dynamics/dynamics/sparse_second_order_system.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

class NewmarkIntegrator {
 public:
  static constexpr double kGamma = 0.5;
  static constexpr double kBeta = 0.25;

  /// time_step h [s] > 0; quantities: output blocks; generalized_force f_g [n] (empty: none).
  /// Throws InputError for inconsistent sizes or h, SolverError when K_eff cannot be factorised.
  NewmarkIntegrator(const SparseSecondOrderSystem& system, double time_step,
                    const std::vector<OutputQuantity>& quantities = {OutputQuantity::Displacement},
                    const Vector& generalized_force = Vector());

  /// t = 0, q = q' = 0, w = 0 (acceleration from M a = f_g).
  void reset();
  /// t = 0 with q [n], q' [n] and w [n_w]; a from M a = F(w) - C q' - K q.
  /// Throws InputError for wrong lengths, SolverError when the force is not balanced and M is
  /// singular (massless DOFs: use the overload with an explicit acceleration).
  void reset(const Vector& displacement, const Vector& velocity, const Vector& input);
  /// Same with an explicit initial acceleration a [n].
  void reset(const Vector& displacement, const Vector& velocity, const Vector& acceleration,
             const Vector& input);
  /// One step to the sample of w_next [n_w]. Throws InputError for a wrong length.
  void step(const Vector& input_next);
  /// Inputs W [n_samples x n_w]; outputs [n_samples x n_y]. Row 0 replaces the current input
  /// (and, when it differs, the acceleration is re-balanced as in reset()).
  Matrix simulate(const Matrix& inputs);

  const Vector& displacement() const { return q_; }
  const Vector& velocity() const { return v_; }
  const Vector& acceleration() const { return a_; }
  const Vector& input() const { return w_; }
  /// Outputs at the current sample, rows as outputNames().
  const Vector& outputs() const { return y_; }
  const std::vector<std::string>& outputNames() const { return layout_.names(); }
  double time() const { return static_cast<double>(steps_) * dt_; }
  double timeStep() const { return dt_; }
  DofIndex size() const { return q_.size(); }
  DofIndex inputCount() const { return w_.size(); }

 private:
  Vector force(const Vector& input) const;
  Vector initialAcceleration(const Vector& displacement, const Vector& velocity,
                             const Vector& input) const;
  void updateOutputs();

  SparseMatrix mass_, damping_, stiffness_, input_matrix_, output_;
  Vector generalized_force_;
  Eigen::SimplicialLDLT<SparseMatrix> effective_stiffness_;
  double dt_;
  OutputLayout layout_;
  Vector q_, v_, a_, w_, y_, rhs_;
  long steps_ = 0;
};

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
