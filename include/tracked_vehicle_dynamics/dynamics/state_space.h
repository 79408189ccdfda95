// A linear (affine) time-invariant system as a plain value, continuous or discrete
// (STYLE.md #10; cf. drake's LinearSystem / AffineSystem):
//
//   continuous (sample_time == 0):  z'     = A z + B w + f0
//   discrete   (sample_time  > 0):  z[k+1] = A z[k] + B w[k] + B1 w[k+1] + f0
//   both:                           y      = C z + D w + y0
//
// B1 ("next_input_matrix") is non-empty only for a discrete system obtained with a first-order
// (triangle) hold; it keeps z the physical state instead of MATLAB's shifted FOH state.
//
// fromSecondOrder() writes  M q'' + C q' + K q = K_u u + C_u u' + f_g  with
//   z = [q; q'] [2n],  w = [u; u'] [2 n_inputs] (road heights [m] and their rates [m/s]),
//   A = [0 I; -M^-1 K  -M^-1 C],  B = [0 0; M^-1 K_u  M^-1 C_u],  f0 = [0; M^-1 f_g],
// and stacks the outputs in OutputLayout order:
//   displacement  H q                                   C = [H 0]
//   velocity      H q'                                  C = [0 H]
//   acceleration  H M^-1 (-K q - C q' + K_u u + C_u u' + f_g)
//                 C = [-H M^-1 K  -H M^-1 C], D = [H M^-1 K_u  H M^-1 C_u], y0 = H M^-1 f_g.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/dynamics/output_layout.h"
#include "tracked_vehicle_dynamics/dynamics/second_order_system.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

/// How a sampled input w[k] is reconstructed between samples by a discretisation.
enum class InputHold {
  /// w(t) = w[k] on [t_k, t_k+1): the usual zero-order hold.
  ZeroOrder,
  /// w(t) linear between w[k] and w[k+1] (triangle hold): exact for piecewise-linear inputs,
  /// e.g. a terrain profile sampled in space and interpolated linearly.
  FirstOrder,
};

/// "zero_order" or "first_order": the hold's name in node parameters and reports.
const char* holdName(InputHold hold);
/// The hold named by holdName()'s text; nullopt for any other text.
std::optional<InputHold> holdFromName(const std::string& name);

struct StateSpace {
  Matrix state_matrix;        ///< A [n_states x n_states]
  Matrix input_matrix;        ///< B [n_states x n_inputs]
  Matrix output_matrix;       ///< C [n_outputs x n_states]
  Matrix feedthrough_matrix;  ///< D [n_outputs x n_inputs]
  /// B1 [n_states x n_inputs]: weight of w[k+1] in a discrete first-order-hold system; empty
  /// (0 x 0) otherwise.
  Matrix next_input_matrix;
  Vector state_offset;   ///< f0 [n_states]: constant forcing (e.g. gravity); empty means zero
  Vector output_offset;  ///< y0 [n_outputs]; empty means zero
  /// Sample time [s]: 0 for a continuous system.
  double sample_time = 0.0;
  /// Hold used to obtain a discrete system (meaningless when continuous).
  InputHold hold = InputHold::ZeroOrder;
  /// One per output row (may be empty).
  std::vector<std::string> output_names;

  DofIndex stateCount() const { return state_matrix.rows(); }
  DofIndex inputCount() const { return input_matrix.cols(); }
  DofIndex outputCount() const { return output_matrix.rows(); }
  bool isContinuous() const { return sample_time == 0.0; }
};

/// Throws InputError naming the matrix and its size when A, B, C, D, B1, f0, y0 or the names
/// are inconsistent, or when the sample time is negative or not finite.
void validateStateSpace(const StateSpace& system);

/// Continuous first-order form of a second-order system (equations above).
/// quantities: output blocks, in order; generalized_force: f_g [n] [N, N m] (empty: none).
/// Throws InputError for inconsistent sizes, SolverError when M is not positive definite.
StateSpace fromSecondOrder(
    const SecondOrderSystem& system,
    const std::vector<OutputQuantity>& quantities = {OutputQuantity::Displacement},
    const Vector& generalized_force = Vector());

/// Input vector w = [u; u'] from road heights u [m] and rates u' [m/s] (same length).
/// Throws InputError when the lengths differ.
Vector roadInput(const Vector& heights, const Vector& rates);

/// Input time series W [n_samples x 2 n_inputs] = [U, U'] from sampled heights
/// U [n_samples x n_inputs] at a fixed step dt [s]. U' by central differences
/// (u[k+1] - u[k-1]) / (2 dt), second-order accurate inside, one-sided (first-order) at both
/// ends. Throws InputError for dt <= 0 or fewer than 2 samples.
Matrix roadInputSeries(const Matrix& heights, double dt);

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
