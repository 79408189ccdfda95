#include "tracked_vehicle_dynamics/reduction/reduced_damping.h"

#include <cmath>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/low_mode_refinement.h"
#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/io/number_text.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

namespace {

void checkCoefficient(double value, const char* name) {
  if (!std::isfinite(value) || value < 0.0)
    throw InputError(std::string("reducedDamping: ") + name + " = " + brief(value) +
                     " must be finite and non-negative");
}

std::string number(double value) {
  return io::formatC("%g", value);
}

}  // namespace

Matrix reducedDamping(const Matrix& m_r, const Matrix& k_r, const Matrix& c_discrete,
                      const DampingOptions& options) {
  const DofIndex k = m_r.rows();
  if (m_r.cols() != k || k_r.rows() != k || k_r.cols() != k || c_discrete.rows() != k ||
      c_discrete.cols() != k)
    throw InputError("reducedDamping: M_R " + std::to_string(m_r.rows()) + "x" +
                     std::to_string(m_r.cols()) + ", K_R " + std::to_string(k_r.rows()) + "x" +
                     std::to_string(k_r.cols()) + " and C_R " + std::to_string(c_discrete.rows()) +
                     "x" + std::to_string(c_discrete.cols()) + " must be square of one size");
  switch (options.model) {
    case DampingModel::Discrete:
      return c_discrete;
    case DampingModel::Rayleigh:
      checkCoefficient(options.alpha, "alpha");
      checkCoefficient(options.beta, "beta");
      return c_discrete + options.alpha * m_r + options.beta * k_r;
    case DampingModel::Modal: {
      Vector zeta = options.modal_ratios.size() ? options.modal_ratios
                                                : Vector::Constant(k, options.modal_ratio);
      if (zeta.size() != k)
        throw InputError("reducedDamping: " + std::to_string(zeta.size()) +
                         " modal damping ratios for " + std::to_string(k) + " reduced modes");
      for (DofIndex i = 0; i < k; ++i)
        checkCoefficient(zeta(i), "modal damping ratio");
      // C = M Phi diag(2 zeta omega) Phi^T M: diagonal in the modes Phi it is built on, and in
      // the modes a later solve of (K_R, M_R) finds only as far as both agree. The dense solve
      // mixes the low modes of a vehicle on stiff ground ties by eps lambda_max over their gap
      // (low_mode_refinement.h): refined, as ModalSystem refines them, the modal damping stays
      // uncoupled in ModalSystem's modes to ~1e-10 instead of ~1e-5 on a light vehicle.
      fem::ModalBasis modes = fem::solveModesDense(k_r, m_r);
      fem::refineLowModes(k_r, m_r, &modes.eigenvalues, &modes.shapes);
      const Vector omega = modes.eigenvalues.cwiseMax(0.0).cwiseSqrt();
      const Matrix mphi = m_r * modes.shapes;
      Matrix c = mphi * (2.0 * zeta.cwiseProduct(omega)).asDiagonal() * mphi.transpose();
      c = 0.5 * (c + c.transpose());
      return c_discrete + c;
    }
  }
  return c_discrete;
}

std::string describe(const DampingOptions& options, bool discrete_dampers) {
  const std::string plus = discrete_dampers ? " + discrete dampers" : "";
  switch (options.model) {
    case DampingModel::Discrete:
      return discrete_dampers ? "discrete dampers only" : "none (no discrete dampers)";
    case DampingModel::Rayleigh:
      return "Rayleigh alpha=" + number(options.alpha) + " 1/s beta=" + number(options.beta) +
             " s" + plus;
    case DampingModel::Modal:
      return options.modal_ratios.size()
                 ? "modal, zeta per mode (" + std::to_string(options.modal_ratios.size()) +
                       " ratios)" + plus
                 : "modal zeta=" + number(options.modal_ratio) + plus;
  }
  return "unknown";
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
