#include "tracked_vehicle_dynamics/reduction/mogesec.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

namespace {

// Weights closer than this (relative) are ties, resolved to the lowest index.
constexpr double kTieTolerance = 1e-12;

void checkOptions(const MogesecOptions& o) {
  if (o.count < 0)
    throw InputError("mogesec: count " + std::to_string(o.count) + " is negative");
  if (!(o.modal_exponent > 0.0))
    throw InputError("mogesec: modal exponent k_Phi = " + std::to_string(o.modal_exponent) +
                     " must be positive");
  if (!(o.geometric_exponent > 0.0))
    throw InputError("mogesec: geometric exponent k_g = " + std::to_string(o.geometric_exponent) +
                     " must be positive");
  if (!(o.norm_order >= 1.0))
    throw InputError("mogesec: norm order p = " + std::to_string(o.norm_order) +
                     " must be at least 1");
  if (!(o.colocation_tolerance >= 0.0))
    throw InputError("mogesec: colocation tolerance must not be negative");
}

double distance(const Vector3& a, const Vector3& b, double p) {
  const Vector3 d = (a - b).cwiseAbs();
  if (p == 2.0)
    return d.norm();
  return std::pow(std::pow(d.x(), p) + std::pow(d.y(), p) + std::pow(d.z(), p), 1.0 / p);
}

// Running state of eq. 14: sum_i d(q, i)^-(k_g p) over the masters so far, and co-location flags.
class GeometricWeight {
 public:
  GeometricWeight(const std::vector<Vector3>& positions, const MogesecOptions& o)
      : positions_(positions),
        options_(o),
        inverse_sum_(Vector::Zero(static_cast<DofIndex>(positions.size()))),
        colocated_(positions.size(), false),
        exponent_(o.geometric_exponent * o.norm_order) {}

  void addMaster(DofIndex master) {
    ++masters_;
    const Vector3& x = positions_[static_cast<std::size_t>(master)];
    for (std::size_t q = 0; q < positions_.size(); ++q) {
      const double d = distance(positions_[q], x, options_.norm_order);
      if (d <= options_.colocation_tolerance)
        colocated_[q] = true;
      else if (exponent_ == 4.0)  // the paper's k_g = p = 2: skip std::pow
        inverse_sum_(static_cast<DofIndex>(q)) += 1.0 / ((d * d) * (d * d));
      else
        inverse_sum_(static_cast<DofIndex>(q)) += std::pow(d, -exponent_);
    }
  }

  double operator()(DofIndex q) const {
    if (masters_ == 0)
      return 1.0;
    if (colocated_[static_cast<std::size_t>(q)])
      return 0.0;
    return 1.0 / inverse_sum_(q);
  }

 private:
  const std::vector<Vector3>& positions_;
  const MogesecOptions& options_;
  Vector inverse_sum_;
  std::vector<bool> colocated_;
  double exponent_;  ///< k_g p: eq. 14 sums ||q - q_i||_p^(-k_g p)
  int masters_ = 0;
};

}  // namespace

MogesecResult mogesec(const Matrix& shapes, const std::vector<Vector3>& positions,
                      const std::vector<DofIndex>& initial_masters, const MogesecOptions& options) {
  checkOptions(options);
  const DofIndex n = shapes.rows();
  if (static_cast<DofIndex>(positions.size()) != n)
    throw InputError("mogesec: " + std::to_string(positions.size()) + " positions for " +
                     std::to_string(n) + " candidate DOFs (rows of the shapes)");
  if (!shapes.allFinite())
    throw InputError("mogesec: the mode shapes contain a non-finite entry");
  std::vector<bool> chosen(static_cast<std::size_t>(n), false);
  for (std::size_t i = 0; i < initial_masters.size(); ++i) {
    const DofIndex m = initial_masters[i];
    if (m < 0 || m >= n)
      throw InputError("mogesec: initial master [" + std::to_string(i) + "] = " +
                       std::to_string(m) + " is outside the " + std::to_string(n) + " candidates");
    if (chosen[static_cast<std::size_t>(m)])
      throw InputError("mogesec: initial master " + std::to_string(m) + " is listed twice");
    chosen[static_cast<std::size_t>(m)] = true;
  }
  const DofIndex left = n - static_cast<DofIndex>(initial_masters.size());
  if (options.count > left)
    throw InputError("mogesec: " + std::to_string(options.count) + " DOFs requested but only " +
                     std::to_string(left) + " candidates are not initial masters");

  MogesecResult result;
  // Eq. 13.
  result.modal_weight =
      options.modal_exponent == 2.0
          ? Vector(shapes.rowwise().squaredNorm())
          : Vector(shapes.cwiseAbs().array().pow(options.modal_exponent).rowwise().sum());
  if (options.count > 0 && !(result.modal_weight.maxCoeff() > 0.0))
    throw InputError("mogesec: the mode shapes are zero on every candidate DOF");

  GeometricWeight geometric(positions, options);
  for (const DofIndex m : initial_masters)
    geometric.addMaster(m);

  Vector wg(n);
  for (int pick = 0; pick < options.count; ++pick) {
    double max_phi = 0.0, max_g = 0.0;
    for (DofIndex q = 0; q < n; ++q) {
      if (chosen[static_cast<std::size_t>(q)])
        continue;
      wg(q) = geometric(q);
      max_phi = std::max(max_phi, result.modal_weight(q));
      max_g = std::max(max_g, wg(q));
    }
    MogesecPick best{-1, -1.0, 0.0, 0.0};
    for (DofIndex q = 0; q < n; ++q) {
      if (chosen[static_cast<std::size_t>(q)])
        continue;
      // Eq. 12; a factor that is zero on every remaining candidate cannot rank them (see header).
      const double phi_n = max_phi > 0.0 ? result.modal_weight(q) / max_phi : 1.0;
      const double g_n = max_g > 0.0 ? wg(q) / max_g : 1.0;
      const double w = phi_n * g_n;
      if (best.index < 0 ||
          w > best.weight * (1.0 + kTieTolerance) + std::numeric_limits<double>::min())
        best = MogesecPick{q, w, phi_n, g_n};
    }
    chosen[static_cast<std::size_t>(best.index)] = true;
    geometric.addMaster(best.index);
    result.picks.push_back(best);
  }
  return result;
}

CandidateFilter CandidateFilter::lateralAndVertical() {
  CandidateFilter filter;
  filter.directions = {{false, true, true, false, false, false}};
  return filter;
}

std::vector<DofIndex> candidateDofs(const fem::DofMap& dofs, const CandidateFilter& filter) {
  const std::unordered_set<NodeId> excluded(filter.excluded_nodes.begin(),
                                            filter.excluded_nodes.end());
  std::vector<DofIndex> out;
  for (DofIndex i = 0; i < dofs.activeCount(); ++i) {
    const fem::DofRef d = dofs.dofOf(i);
    if (filter.directions[static_cast<std::size_t>(d.direction)] && !excluded.count(d.node))
      out.push_back(i);
  }
  return out;
}

MasterSelection selectMasters(const fem::DofMap& dofs, const ModeShapes& shapes,
                              const std::vector<DofIndex>& initial_masters,
                              const CandidateFilter& filter, const MogesecOptions& options) {
  if (shapes.rows() != dofs.activeCount())
    throw InputError("selectMasters: the shapes have " + std::to_string(shapes.rows()) +
                     " rows, expected one per active DOF (" + std::to_string(dofs.activeCount()) +
                     ")");
  for (std::size_t i = 0; i < initial_masters.size(); ++i)
    if (initial_masters[i] < 0 || initial_masters[i] >= dofs.activeCount())
      throw InputError("selectMasters: initial master [" + std::to_string(i) +
                       "] = " + std::to_string(initial_masters[i]) + " is not an active DOF (0.." +
                       std::to_string(dofs.activeCount() - 1) + ")");
  std::vector<DofIndex> candidates = candidateDofs(dofs, filter);
  // Initial masters join the candidates so that their positions count in eq. 14.
  std::unordered_map<DofIndex, DofIndex> row_of;
  for (std::size_t r = 0; r < candidates.size(); ++r)
    row_of[candidates[r]] = static_cast<DofIndex>(r);
  std::vector<DofIndex> initial_rows;
  for (const DofIndex m : initial_masters) {
    auto it = row_of.find(m);
    if (it == row_of.end()) {
      it = row_of.emplace(m, static_cast<DofIndex>(candidates.size())).first;
      candidates.push_back(m);
    }
    initial_rows.push_back(it->second);
  }
  Matrix restricted(static_cast<DofIndex>(candidates.size()), shapes.cols());
  std::vector<Vector3> positions;
  positions.reserve(candidates.size());
  for (std::size_t r = 0; r < candidates.size(); ++r) {
    restricted.row(static_cast<DofIndex>(r)) = shapes.row(candidates[r]);
    positions.push_back(dofs.positionOf(candidates[r]));
  }
  const MogesecResult result = mogesec(restricted, positions, initial_rows, options);

  MasterSelection selection;
  selection.masters = initial_masters;
  for (MogesecPick pick : result.picks) {
    pick.index = candidates[static_cast<std::size_t>(pick.index)];
    selection.masters.push_back(pick.index);
    selection.picks.push_back(pick);
  }
  return selection;
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
