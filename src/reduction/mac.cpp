#include "tracked_vehicle_dynamics/reduction/mac.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/SVD>

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

// Orthonormal basis of the significant part of the columns' span (singular values above
// kNegligibleShape times the largest column norm of the whole set).
Matrix orthonormalBasis(const Matrix& columns, double set_norm) {
  const Eigen::JacobiSVD<Matrix> svd(columns, Eigen::ComputeThinU);
  Eigen::Index rank = 0;
  while (rank < svd.singularValues().size() &&
         svd.singularValues()(rank) > kNegligibleShape * set_norm)
    ++rank;
  return svd.matrixU().leftCols(rank);
}

}  // namespace

std::vector<std::pair<Eigen::Index, Eigen::Index>> degenerateGroups(const Vector& f,
                                                                    double relative_gap) {
  std::vector<std::pair<Eigen::Index, Eigen::Index>> groups;
  for (Eigen::Index i = 0; i < f.size(); ++i) {
    if (i > 0 &&
        std::abs(f(i) - f(i - 1)) <= relative_gap * std::max(std::abs(f(i)), std::abs(f(i - 1))))
      groups.back().second = i + 1;
    else
      groups.emplace_back(i, i + 1);
  }
  return groups;
}

Matrix eigenspaceMac(const Matrix& phi_a, const Vector& f_a, const Matrix& phi_b, const Vector& f_b,
                     double relative_gap) {
  const Matrix plain = mac(phi_a, phi_b);  // checks the shapes
  if (f_a.size() != phi_a.cols() || f_b.size() != phi_b.cols())
    throw InputError("eigenspaceMac: " + std::to_string(f_a.size()) + " and " +
                     std::to_string(f_b.size()) + " frequencies for " +
                     std::to_string(phi_a.cols()) + " and " + std::to_string(phi_b.cols()) +
                     " shapes");
  if (!(relative_gap >= 0.0))
    throw InputError("eigenspaceMac: relative gap must be >= 0");
  const auto groups_a = degenerateGroups(f_a, relative_gap);
  const auto groups_b = degenerateGroups(f_b, relative_gap);
  const double norm_a = phi_a.cols() ? phi_a.colwise().norm().maxCoeff() : 0.0;
  const double norm_b = phi_b.cols() ? phi_b.colwise().norm().maxCoeff() : 0.0;
  std::vector<Matrix> basis_b;
  for (const auto& [b0, b1] : groups_b)
    basis_b.push_back(b1 - b0 > 1 ? orthonormalBasis(phi_b.middleCols(b0, b1 - b0), norm_b)
                                  : Matrix());
  Matrix out = plain;
  for (const auto& [a0, a1] : groups_a) {
    const Matrix qa =
        a1 - a0 > 1 ? orthonormalBasis(phi_a.middleCols(a0, a1 - a0), norm_a) : Matrix();
    for (std::size_t g = 0; g < groups_b.size(); ++g) {
      const auto [b0, b1] = groups_b[g];
      if (a1 - a0 == 1 && b1 - b0 == 1)
        continue;  // two single modes: the plain MAC
      // A single mode's basis is its normalised shape (none when negligible: MAC 0).
      auto single = [](const Matrix& phi, Eigen::Index j, double set_norm) {
        const double n = phi.col(j).norm();
        return n > kNegligibleShape * set_norm ? Matrix(phi.col(j) / n) : Matrix(phi.rows(), 0);
      };
      const Matrix left = a1 - a0 > 1 ? qa : single(phi_a, a0, norm_a);
      const Matrix right = b1 - b0 > 1 ? basis_b[g] : single(phi_b, b0, norm_b);
      double value = 0.0;
      if (left.cols() > 0 && right.cols() > 0) {
        const Eigen::JacobiSVD<Matrix> svd(left.transpose() * right);
        value = std::min(1.0, svd.singularValues()(0) * svd.singularValues()(0));
      }
      out.block(a0, b0, a1 - a0, b1 - b0).setConstant(value);
    }
  }
  return out;
}

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
