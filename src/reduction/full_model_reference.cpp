#include "tracked_vehicle_dynamics/reduction/full_model_reference.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "tracked_vehicle_dynamics/dynamics/frf_state_space.h"
#include "tracked_vehicle_dynamics/dynamics/modal_system.h"
#include "tracked_vehicle_dynamics/dynamics/travel_inertia.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/eigenvalue_count.h"
#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/sparse_cholesky.h"
#include "tracked_vehicle_dynamics/io/number_text.h"
#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

namespace {

// Below this size every mode is found by the dense solver.
constexpr DofIndex kDenseLimit = 400;

// The modes of (K, M) up to `limit_hz` and the next one above it. The modes below the limit are
// counted first (Sylvester's law, one LDL^T: eigenvalue_count.h), so that one Lanczos run asks
// for them and one more; the count grows (doubling) only when the highest mode found still lies
// below the limit (a copy of a repeated eigenvalue skipped) or no count was had (the limit an
// eigenvalue to working precision). Growing from 60 alone solved 266 modes of a six-axle tracked
// vehicle as 60, 120, 240 and 480 (28 s against 2.6 s).
fem::ModalBasis modesUpTo(const fem::System& system, double limit_hz, int max_modes) {
  const DofIndex n = system.size();
  if (n <= kDenseLimit)
    return fem::solveModesDense(Matrix(system.stiffness), Matrix(system.mass));
  int count = static_cast<int>(std::min<DofIndex>(60, n - 1));
  try {
    const int below =
        fem::eigenvaluesBelow(system.stiffness, system.mass, std::pow(kTwoPi * limit_hz, 2));
    if (below > max_modes)
      throw InputError("full-model reference: " + std::to_string(below) + " modes below " +
                       std::to_string(limit_hz) + " Hz, more than " + std::to_string(max_modes) +
                       "; lower the frequency limit (tvd: --max-mode-hz), the modes above it "
                       "enter statically");
    count = static_cast<int>(std::min<DofIndex>(std::max(below + 1, 20), n - 1));
  } catch (const SolverError&) {
    // No count: the growing request below finds the limit all the same.
  }
  for (;;) {
    fem::ModalRequest request;
    request.count = count;
    fem::ModalBasis modes = fem::solveModes(system.stiffness, system.mass, request);
    if (modes.frequencies_hz(modes.count() - 1) > limit_hz)
      return modes;
    if (count >= max_modes || count >= n - 1)
      throw InputError("full-model reference: more than " + std::to_string(count) +
                       " modes below " + std::to_string(limit_hz) +
                       " Hz; lower the frequency limit (tvd: --max-mode-hz), the modes above it "
                       "enter statically");
    count = static_cast<int>(std::min<DofIndex>(std::min(2 * count, max_modes), n - 1));
  }
}

SparseMatrix outputMatrix(const fem::System& system, const std::vector<OutputDof>& outputs) {
  const auto terms = outputTerms(system.dofs, outputs);
  std::vector<Eigen::Triplet<double>> entries;
  for (std::size_t i = 0; i < terms.size(); ++i)
    for (const auto& [active, coefficient] : terms[i])
      entries.emplace_back(static_cast<DofIndex>(i), active, coefficient);
  SparseMatrix h(static_cast<DofIndex>(outputs.size()), system.size());
  h.setFromTriplets(entries.begin(), entries.end());
  return h;
}

}  // namespace

void FullModelReference::addResidual(const Matrix& inputs, dynamics::OutputQuantity quantity,
                                     Eigen::Ref<Matrix> outputs) const {
  const DofIndex n_u = modal.inputCount();
  if (inputs.cols() != 2 * n_u || outputs.cols() != residual_input.rows() ||
      outputs.rows() != inputs.rows())
    throw InputError("full-model reference: inputs [" + std::to_string(inputs.rows()) + " x " +
                     std::to_string(inputs.cols()) + "] and outputs [" +
                     std::to_string(outputs.rows()) + " x " + std::to_string(outputs.cols()) +
                     "] do not match " + std::to_string(2 * n_u) + " inputs and " +
                     std::to_string(residual_input.rows()) + " outputs");
  switch (quantity) {
    case dynamics::OutputQuantity::Displacement:
      outputs.noalias() += inputs * residual_input.transpose();
      outputs.rowwise() += residual_gravity.transpose();
      break;
    case dynamics::OutputQuantity::Velocity:
      outputs.noalias() += inputs.rightCols(n_u) * residual_input.leftCols(n_u).transpose();
      break;
    case dynamics::OutputQuantity::Acceleration:
      break;
  }
}

FullModelReference FullModelReference::withTravelInertia() const {
  FullModelReference out = *this;
  out.modal = dynamics::withTravelInertia(modal, modal_travel);
  // [H R K_u | H R C_u] -> [H R K_u, H R f_a | H R C_u, 0]: the travel input's rate carries no
  // load (C_u' = [C_u, 0]).
  const DofIndex n_u = modal.inputCount();
  const DofIndex n_y = residual_input.rows();
  out.residual_input.resize(n_y, 2 * (n_u + 1));
  out.residual_input << residual_input.leftCols(n_u), residual_travel,
      residual_input.rightCols(n_u), Vector::Zero(n_y);
  return out;
}

double FullModelReference::dampingCoupling() const {
  return dynamics::maxOffDiagonalRatio(modal.damping);
}

bool FullModelReference::dampingCouplesModes() const {
  return dampingCoupling() > dynamics::kModalDampingCouplingTolerance;
}

dynamics::ComplexMatrix FullModelReference::frf(const Vector& frequencies_hz,
                                                const dynamics::InputDelay& delay,
                                                dynamics::OutputQuantity quantity) const {
  // Discrete dampers make D = Phi_k^T C Phi_k full: eq. 20's modal damping would drop what
  // couples the modes (a wheel's peak moved by 105 % with two arm dampers), so eq. 18 is then
  // solved in the k modal coordinates exactly (frf_state_space.h: one Hessenberg reduction,
  // O(k^2) per frequency). The residual below is static either way.
  dynamics::ComplexMatrix out = dampingCouplesModes()
                                    ? dynamics::frfStateSpace(modal, dynamics::ModalSystem(modal),
                                                              frequencies_hz, delay, quantity)
                                    : dynamics::frfModal(modal, frequencies_hz, delay, quantity);
  const DofIndex n_u = modal.inputCount();
  for (Eigen::Index i = 0; i < frequencies_hz.size(); ++i) {
    const double omega = kTwoPi * frequencies_hz(i);
    const dynamics::ComplexVector tau = delay.at(omega, n_u);
    // H R (K_u + j omega C_u) tau, then d/dt -> j omega.
    dynamics::ComplexVector x = residual_input.leftCols(n_u) * tau;
    x += dynamics::Complex(0.0, omega) * (residual_input.rightCols(n_u) * tau);
    dynamics::Complex factor(1.0, 0.0);
    if (quantity == dynamics::OutputQuantity::Velocity)
      factor = {0.0, omega};
    if (quantity == dynamics::OutputQuantity::Acceleration)
      factor = {-omega * omega, 0.0};
    out.row(i) += (factor * x).transpose();
  }
  return out;
}

FullModelReference buildFullReference(const fem::System& system,
                                      const std::vector<OutputDof>& outputs,
                                      const FullReferenceOptions& options) {
  if (!(options.max_frequency_hz > 0) || !std::isfinite(options.max_frequency_hz))
    throw InputError("full-model reference: max_frequency_hz must be positive and finite");
  if (options.max_modes <= 0)
    throw InputError("full-model reference: max_modes must be positive");
  if (options.damping.modal_ratios.size() != 0)
    throw InputError("full-model reference: per-mode damping ratios apply to a reduced model only");
  const auto start = std::chrono::steady_clock::now();

  FullModelReference ref;
  ref.full_dofs = system.size();
  const fem::ModalBasis modes = modesUpTo(system, options.max_frequency_hz, options.max_modes);
  DofIndex k = 0;
  while (k < modes.count() && modes.frequencies_hz(k) <= options.max_frequency_hz)
    ++k;
  if (k == 0) {
    throw InputError(io::formatC(
        "full-model reference: no mode lies below %g Hz (the lowest is at %.4g Hz); raise "
        "the frequency limit (tvd: --max-mode-hz)",
        options.max_frequency_hz, modes.count() > 0 ? modes.frequencies_hz(0) : 0.0));
  }
  const Matrix phi = modes.shapes.leftCols(k);
  const Vector omega2 = modes.eigenvalues.head(k).cwiseMax(0.0);
  ref.frequencies_hz = modes.frequencies_hz.head(k);

  // Static residual on the output rows: G = K^-1 H^T (one factorisation, n_y solves).
  const SparseMatrix h = outputMatrix(system, outputs);
  fem::SparseCholesky k_factor;
  if (!k_factor.factorize(system.stiffness))
    throw SolverError(
        "full-model reference: K is singular (a free rigid-body motion), so the "
        "static residual K^-1 f does not exist; support the model");
  if (omega2.size() > 0 && omega2.minCoeff() <= 0.0)
    throw SolverError("full-model reference: a rigid-body mode (0 Hz) with a factorisable K");
  const Matrix g = k_factor.solve(Matrix(h.transpose()));
  const DofIndex n_u = system.input_stiffness.cols();
  Matrix b(system.size(), 2 * n_u);
  b << Matrix(system.input_stiffness), Matrix(system.input_damping);
  const Matrix h_phi = h * phi;
  const Matrix phi_b = phi.transpose() * b;
  const Vector inverse_omega2 = omega2.cwiseInverse();
  ref.residual_input = g.transpose() * b - h_phi * inverse_omega2.asDiagonal() * phi_b;
  const Vector& f_g = system.gravity_load;
  ref.modal_gravity = phi.transpose() * f_g;
  ref.residual_gravity =
      g.transpose() * f_g - h_phi * inverse_omega2.asDiagonal() * ref.modal_gravity;
  const Vector& f_a = system.travel_load;
  if (f_a.size() != system.size())
    throw InputError("full-model reference: travel inertia load has " + std::to_string(f_a.size()) +
                     " entries, expected " + std::to_string(system.size()));
  ref.modal_travel = phi.transpose() * f_a;
  ref.residual_travel =
      g.transpose() * f_a - h_phi * inverse_omega2.asDiagonal() * ref.modal_travel;

  // The modal coordinates, damped as the options say (discrete dampers projected on top).
  dynamics::SecondOrderSystem& s = ref.modal;
  s.mass = Matrix::Identity(k, k);
  s.stiffness = omega2.asDiagonal();
  s.damping = phi.transpose() * (system.damping * phi);
  const Vector omega = omega2.cwiseSqrt();
  switch (options.damping.model) {
    case DampingModel::Modal:
      s.damping.diagonal() += 2.0 * options.damping.modal_ratio * omega;
      break;
    case DampingModel::Rayleigh:
      s.damping.diagonal().array() += options.damping.alpha + options.damping.beta * omega2.array();
      break;
    case DampingModel::Discrete:
      break;
  }
  s.input_stiffness = phi_b.leftCols(n_u);
  s.input_damping = phi_b.rightCols(n_u);
  s.output = h_phi;
  s.output_names = outputNames(outputs);
  inputPositions(system, options.input_stations, &s.input_stations, &s.input_lateral);
  ref.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return ref;
}

FullModelReference buildVehicleReference(const vehicle::VehicleDescription& description,
                                         vehicle::Variant variant, FullReferenceOptions options) {
  const vehicle::VehicleModel model = vehicle::buildVehicleModel(description, variant);
  const fem::System system = fem::assemble(model.model);
  options.damping = vehicleDamping(description.damping);
  options.input_stations = vehicle::roadInputStations(model.layout, system.ground_inputs);
  return buildFullReference(system, vehicleOutputs(model, description), options);
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
