#include "tracked_vehicle_dynamics/dynamics/frf.h"

#include <Eigen/SparseLU>
#include <cmath>
#include <limits>

#include "checks.h"
#include "tracked_vehicle_dynamics/dynamics/validation.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

namespace {

using ComplexSparseMatrix = Eigen::SparseMatrix<Complex>;

void requireFrequencies(const std::string& where, const Vector& frequencies_hz) {
  if (!frequencies_hz.allFinite() || (frequencies_hz.array() < 0.0).any())
    throw InputError(where + ": frequencies must be finite and >= 0 Hz");
}

// 1, j omega or -omega^2: the output quantity from the displacement amplitude.
Complex quantityFactor(OutputQuantity quantity, double omega) {
  switch (quantity) {
    case OutputQuantity::Displacement:
      return 1.0;
    case OutputQuantity::Velocity:
      return Complex(0.0, omega);
    case OutputQuantity::Acceleration:
      return -omega * omega;
  }
  return 1.0;
}

std::string frequencyText(double f) {
  return std::to_string(f) + " Hz";
}

}  // namespace

ComplexMatrix frfDirect(const SecondOrderSystem& system, const Vector& frequencies_hz,
                        const InputDelay& delay, OutputQuantity quantity) {
  validateSystem(system);
  requireFrequencies("frfDirect", frequencies_hz);
  const DofIndex n = system.size();
  ComplexMatrix frf(frequencies_hz.size(), system.outputCount());
  for (DofIndex i = 0; i < frequencies_hz.size(); ++i) {
    const double omega = kTwoPi * frequencies_hz(i);
    const ComplexVector tau = delay.at(omega, system.inputCount());
    // Z = -omega^2 M + j omega C + K;  F = (j omega C_u + K_u) tau
    ComplexMatrix z(n, n);
    z.real() = system.stiffness - omega * omega * system.mass;
    z.imag() = omega * system.damping;
    ComplexVector force(n);
    force.real() = system.input_stiffness * tau.real() - omega * system.input_damping * tau.imag();
    force.imag() = system.input_stiffness * tau.imag() + omega * system.input_damping * tau.real();
    const Eigen::PartialPivLU<ComplexMatrix> lu(z);
    if (!(lu.rcond() > std::numeric_limits<double>::epsilon()))
      throw SolverError("frfDirect: dynamic stiffness is singular at " +
                        frequencyText(frequencies_hz(i)) + " (undamped resonance?)");
    const ComplexVector x = lu.solve(force);
    frf.row(i) = (quantityFactor(quantity, omega) * (system.output * x)).transpose();
  }
  return frf;
}

ComplexMatrix frfDirect(const SparseSecondOrderSystem& system, const Vector& frequencies_hz,
                        const InputDelay& delay, OutputQuantity quantity) {
  validateSystem(system);
  requireFrequencies("frfDirect", frequencies_hz);
  const ComplexSparseMatrix k = system.stiffness.cast<Complex>();
  const ComplexSparseMatrix m = system.mass.cast<Complex>();
  const ComplexSparseMatrix c = system.damping.cast<Complex>();
  const ComplexSparseMatrix k_u = system.input_stiffness.cast<Complex>();
  const ComplexSparseMatrix c_u = system.input_damping.cast<Complex>();
  const ComplexSparseMatrix h = system.output.cast<Complex>();
  ComplexMatrix frf(frequencies_hz.size(), system.outputCount());
  Eigen::SparseLU<ComplexSparseMatrix, Eigen::COLAMDOrdering<int>> lu;
  bool analysed = false;
  for (DofIndex i = 0; i < frequencies_hz.size(); ++i) {
    const double omega = kTwoPi * frequencies_hz(i);
    const Complex j_omega(0.0, omega);
    // The sum keeps the union pattern of K, M, C at every omega, so one analysis serves all.
    ComplexSparseMatrix z = k + Complex(-omega * omega) * m + j_omega * c;
    z.makeCompressed();
    if (!analysed) {
      lu.analyzePattern(z);
      analysed = true;
    }
    lu.factorize(z);
    if (lu.info() != Eigen::Success)
      throw SolverError("frfDirect: sparse LU of the dynamic stiffness failed at " +
                        frequencyText(frequencies_hz(i)) + ": " + lu.lastErrorMessage());
    const ComplexVector tau = delay.at(omega, system.inputCount());
    const ComplexVector force = k_u * tau + j_omega * (c_u * tau);
    const ComplexVector x = lu.solve(force);
    if (!x.allFinite())
      throw SolverError("frfDirect: dynamic stiffness is singular at " +
                        frequencyText(frequencies_hz(i)) + " (undamped resonance?)");
    frf.row(i) = (quantityFactor(quantity, omega) * (h * x)).transpose();
  }
  return frf;
}

ComplexMatrix frfModal(const ModalSystem& modal, const Vector& frequencies_hz,
                       const InputDelay& delay, OutputQuantity quantity) {
  requireFrequencies("frfModal", frequencies_hz);
  const Vector& omega_r = modal.naturalFrequencies();
  const Vector& d_r = modal.dampingCoefficients();
  ComplexMatrix frf(frequencies_hz.size(), modal.outputCount());
  ComplexVector eta(modal.modeCount());
  // At f = 0 a rigid-body mode's term of eq. 20 is 0/0 (the displacement under a static load on
  // a free body is unbounded; the acceleration's limit depends on its damping): said, not
  // returned as NaN. The vehicles' ground ties leave them none.
  if ((frequencies_hz.array() == 0.0).any()) {
    for (DofIndex r = 0; r < modal.modeCount(); ++r) {
      if (omega_r(r) == 0.0)
        throw SolverError("frfModal: mode " + std::to_string(r) +
                          " is a rigid-body mode (0 Hz) and the grid holds 0 Hz, where its term "
                          "of the modal sum is 0/0: start the grid above 0 Hz");
    }
  }
  for (DofIndex i = 0; i < frequencies_hz.size(); ++i) {
    const double omega = kTwoPi * frequencies_hz(i);
    const ComplexVector tau = delay.at(omega, modal.inputCount());
    // Phi^T F = (Phi^T K_u + j omega Phi^T C_u) tau, then eq. 20 mode by mode.
    eta =
        modal.modalInputStiffness() * tau + Complex(0.0, omega) * (modal.modalInputDamping() * tau);
    for (DofIndex r = 0; r < modal.modeCount(); ++r)
      eta(r) /= Complex(omega_r(r) * omega_r(r) - omega * omega, d_r(r) * omega);
    frf.row(i) = (quantityFactor(quantity, omega) * (modal.modalOutput() * eta)).transpose();
  }
  return frf;
}

ComplexMatrix frfModal(const SecondOrderSystem& system, const Vector& frequencies_hz,
                       const InputDelay& delay, OutputQuantity quantity,
                       const Vector& damping_ratios) {
  return frfModal(ModalSystem(system, damping_ratios), frequencies_hz, delay, quantity);
}

Matrix magnitude(const ComplexMatrix& frf) {
  return frf.cwiseAbs();
}

Matrix phase(const ComplexMatrix& frf) {
  return frf.unaryExpr([](const Complex& z) { return std::arg(z); });
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
