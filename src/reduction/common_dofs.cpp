#include "tracked_vehicle_dynamics/reduction/common_dofs.h"

#include <map>
#include <string>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

namespace {

constexpr int kTranslations = 3;  // ux, uy, uz come first (types.h Direction)

std::string name(const fem::DofRef& d) {
  return "node " + std::to_string(d.node) + " " + directionName(d.direction);
}

std::map<fem::DofRef, DofIndex> rowIndex(const std::vector<fem::DofRef>& dofs, const char* which) {
  std::map<fem::DofRef, DofIndex> index;
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    if (dofs[i].direction < 0 || dofs[i].direction >= kDofsPerNode)
      throw InputError(std::string("commonTranslationalRows: ") + which + "[" + std::to_string(i) +
                       "] has direction " + std::to_string(dofs[i].direction) + ", not in 0..5");
    if (!index.emplace(dofs[i], static_cast<DofIndex>(i)).second)
      throw InputError(std::string("commonTranslationalRows: ") + which + " lists " +
                       name(dofs[i]) + " twice (rows " + std::to_string(index[dofs[i]]) + " and " +
                       std::to_string(i) + ")");
  }
  return index;
}

}  // namespace

std::vector<fem::DofRef> activeDofRefs(const fem::DofMap& dofs) {
  std::vector<fem::DofRef> out;
  out.reserve(static_cast<std::size_t>(dofs.activeCount()));
  for (DofIndex i = 0; i < dofs.activeCount(); ++i)
    out.push_back(dofs.dofOf(i));
  return out;
}

CommonDofs commonTranslationalRows(const std::vector<fem::DofRef>& dofs_a,
                                   const std::vector<fem::DofRef>& dofs_b) {
  rowIndex(dofs_a, "dofs_a");  // checks A the same way as B
  const std::map<fem::DofRef, DofIndex> index_b = rowIndex(dofs_b, "dofs_b");
  CommonDofs common;
  for (std::size_t i = 0; i < dofs_a.size(); ++i) {
    if (dofs_a[i].direction >= kTranslations)
      continue;
    const auto it = index_b.find(dofs_a[i]);
    if (it == index_b.end())
      continue;
    common.dofs.push_back(dofs_a[i]);
    common.rows_a.push_back(static_cast<DofIndex>(i));
    common.rows_b.push_back(it->second);
  }
  return common;
}

Matrix selectRows(const Matrix& shapes, const std::vector<DofIndex>& rows) {
  Matrix out(static_cast<DofIndex>(rows.size()), shapes.cols());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i] < 0 || rows[i] >= shapes.rows())
      throw InputError("selectRows: rows[" + std::to_string(i) + "] = " + std::to_string(rows[i]) +
                       " is outside the " + std::to_string(shapes.rows()) + " rows of the shapes");
    out.row(static_cast<DofIndex>(i)) = shapes.row(rows[i]);
  }
  return out;
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
