#include "tracked_vehicle_dynamics/reduction/mac.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

namespace {

// Squared column norms, with the columns that are round-off next to the largest of their set
// set to zero (see the header).
Vector significantSquaredNorms(const Matrix& phi) {
  Vector norms = phi.colwise().squaredNorm().transpose();
  if (norms.size() == 0)
    return norms;
  const double cutoff = kNegligibleShape * kNegligibleShape * norms.maxCoeff();
  for (Eigen::Index j = 0; j < norms.size(); ++j)
    if (norms(j) <= cutoff)
      norms(j) = 0.0;
  return norms;
}

}  // namespace

Matrix mac(const Matrix& phi_a, const Matrix& phi_b) {
  if (phi_a.rows() != phi_b.rows())
    throw InputError("mac: shapes A have " + std::to_string(phi_a.rows()) + " rows and shapes B " +
                     std::to_string(phi_b.rows()) + "; both must be over the same DOFs");
  if (!phi_a.allFinite())
    throw InputError("mac: shapes A contain a non-finite entry");
  if (!phi_b.allFinite())
    throw InputError("mac: shapes B contain a non-finite entry");
  const Matrix cross = phi_a.transpose() * phi_b;
  const Vector norm_a = significantSquaredNorms(phi_a);
  const Vector norm_b = significantSquaredNorms(phi_b);
  Matrix out(phi_a.cols(), phi_b.cols());
  for (Eigen::Index k = 0; k < out.cols(); ++k)
    for (Eigen::Index j = 0; j < out.rows(); ++j) {
      const double denominator = norm_a(j) * norm_b(k);
      // Cauchy-Schwarz bounds the ratio by 1; the clamp removes round-off above it.
      out(j, k) = denominator > 0.0 ? std::min(1.0, cross(j, k) * cross(j, k) / denominator) : 0.0;
    }
  return out;
}

std::vector<ModeCorrelation> correlateModes(const Matrix& mac_ab, double threshold) {
  if (!(threshold > 0.0 && threshold <= 1.0))
    throw InputError("correlateModes: MAC threshold " + std::to_string(threshold) +
                     " is not in (0, 1]");
  std::vector<ModeCorrelation> out(static_cast<std::size_t>(mac_ab.rows()));
  for (Eigen::Index j = 0; j < mac_ab.rows(); ++j) {
    ModeCorrelation& c = out[static_cast<std::size_t>(j)];
    c.mode = static_cast<int>(j);
    for (Eigen::Index k = 0; k < mac_ab.cols(); ++k) {
      const double value = mac_ab(j, k);
      if (c.best_match < 0 || value > c.best_mac) {
        c.best_match = static_cast<int>(k);
        c.best_mac = value;
      }
      if (value >= threshold)
        c.matches.push_back(ModeMatch{static_cast<int>(k), value});
    }
    std::stable_sort(c.matches.begin(), c.matches.end(),
                     [](const ModeMatch& a, const ModeMatch& b) { return a.mac > b.mac; });
  }
  return out;
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
