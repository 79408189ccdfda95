// The full (unreduced) FE model in modal form: the reference the reduced model is checked
// against (paper §4: "full" vs "CMS" FRFs and time responses).
//
// The lowest k modes of the sparse (K, M) up to max_frequency_hz (shift-invert Lanczos) are kept
// dynamic; the rest of the model responds statically (the mode-acceleration method):
//   q = Phi_k eta + R f,   R = K^-1 - Phi_k Omega_k^-2 Phi_k^T,   f = K_u u + C_u u' + f_g
//   eta'' + D eta' + Omega_k^2 eta = Phi_k^T f
// with D = diag(2 zeta_r omega_r) + Phi_k^T C_d Phi_k (modal damping as the description says, on
// top of the discrete dampers C_d) or alpha I + beta Omega_k^2 (Rayleigh). Only the output rows
// of the residual are needed: H R B = (K^-1 H^T)^T B - (H Phi_k) Omega_k^-2 (Phi_k^T B), i.e.
// n_outputs sparse solves with one factorisation. Statics are therefore exact (q = K^-1 f at
// rest) and the truncation error in the band falls like (omega / omega_cut)^2.
//
// Frequency response (eq. 20 plus the residual):  y(omega) = H Phi_k x_eta(omega) + H R F(omega),
// with x_eta from eq. 20 while D is diagonal, and from eq. 18 in the k coordinates, whole D
// (frf_state_space.h), when discrete dampers couple the modes. The residual is static in f alone:
// with dampers it leaves out the truncated modes' static response to their force, -R C_d Phi_k
// eta' (zero for modal or Rayleigh damping, R M Phi_k = R K Phi_k = 0): with the residual's
// inertia, 8e-4 of each output's peak up to 30 Hz on the paper vehicle with two arm dampers.
// Time response: a Simulator on `modal` (exact per-mode discretisation) plus residualOutput().
#pragma once

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/dynamics/frf.h"
#include "tracked_vehicle_dynamics/dynamics/second_order_system.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/reduction/reduced_damping.h"
#include "tracked_vehicle_dynamics/reduction/reduced_model.h"
#include "tracked_vehicle_dynamics/types.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

struct FullReferenceOptions {
  /// Modes up to this frequency [Hz] are dynamic (paper band 0-30 Hz; FRFs to 50 Hz).
  double max_frequency_hz = 100.0;
  /// Safety bound on the number of modes solved for.
  int max_modes = 2000;
  /// Damping: Modal (ratio per mode) or Rayleigh; the discrete dampers are always included.
  DampingOptions damping;
  /// Where each road input reads the road [m], as ReductionRequest::input_stations.
  Vector input_stations;
};

struct FullModelReference {
  /// The k modal coordinates: M = I, K = Omega^2, C = D (see above), K_u = Phi^T K_u,
  /// C_u = Phi^T C_u, H = H Phi; output names and input stations/lateral as the reduced model.
  dynamics::SecondOrderSystem modal;
  Vector modal_gravity;     ///< Phi_k^T f_g [k]
  Matrix residual_input;    ///< H R [K_u, C_u] [n_outputs x 2 n_inputs]
  Vector residual_gravity;  ///< H R f_g [n_outputs]
  /// The travel inertia per unit forward acceleration (fem::System::travel_load), like gravity.
  Vector modal_travel;     ///< Phi_k^T f_a [k]
  Vector residual_travel;  ///< H R f_a [n_outputs]
  Vector frequencies_hz;   ///< the k dynamic modes [Hz]
  DofIndex full_dofs = 0;
  double seconds = 0.0;  ///< wall time to build it [s]

  /// Adds the residual part of `quantity` for the input series W (rows w = [u; u'],
  /// [n_samples x 2 n_inputs]) to the outputs Y [n_samples x n_outputs]: displacement
  /// H R (K_u u + C_u u' + f_g); velocity H R K_u u' (C_u u'' is unknown and dropped);
  /// acceleration: nothing (the residual's inertia is neglected by construction).
  /// Throws InputError for mismatched sizes.
  void addResidual(const Matrix& inputs, dynamics::OutputQuantity quantity,
                   Eigen::Ref<Matrix> outputs) const;
  /// max |d_rs| / sqrt(d_rr d_ss) over r != s of D = modal.damping: what eq. 20 would drop.
  double dampingCoupling() const;
  /// dampingCoupling() above dynamics::kModalDampingCouplingTolerance (discrete dampers).
  bool dampingCouplesModes() const;
  /// FRF per unit road height (eq. 18-25) of the outputs: modal part plus the residual
  /// H R (K_u + j omega C_u) tau times 1, j omega or -omega^2. [n_frequencies x n_outputs].
  /// The modal part is eq. 20 for a diagonal D, else eq. 18 solved exactly in the modal
  /// coordinates (dampingCouplesModes(): the whole D). Throws SolverError when an undamped mode
  /// lies on the grid in the coupled case (the diagonal case returns a non-finite entry).
  dynamics::ComplexMatrix frf(const Vector& frequencies_hz, const dynamics::InputDelay& delay,
                              dynamics::OutputQuantity quantity) const;
  /// The reference with the travel acceleration a(t) as one more input after the road inputs
  /// (dynamics::withTravelInertia on `modal`, travel_inertia.h): residual_input gains the column
  /// H R f_a among the displacement inputs and a zero one among their rates, so addResidual()
  /// takes the widened input rows [u; a; u'; 0] and adds H R f_a a to the displacements.
  FullModelReference withTravelInertia() const;
};

/// Builds the reference of an assembled system with outputs as buildReducedModel() makes them.
/// Throws InputError for bad options or outputs, SolverError when K is singular (a free
/// rigid-body motion: no static residual) or the eigensolver fails.
FullModelReference buildFullReference(const fem::System& system,
                                      const std::vector<OutputDof>& outputs,
                                      const FullReferenceOptions& options);

/// The same for a vehicle variant: outputs vehicleOutputs(), damping from the description
/// (options.damping is replaced).
FullModelReference buildVehicleReference(const vehicle::VehicleDescription& description,
                                         vehicle::Variant variant,
                                         FullReferenceOptions options = {});

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
