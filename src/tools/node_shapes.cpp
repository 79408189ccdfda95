#include "node_shapes.h"

#include <algorithm>
#include <iomanip>

#include "tracked_vehicle_dynamics/io/atomic_file.h"
#include "tracked_vehicle_dynamics/vehicle/mode_classification.h"

namespace tracked_vehicle_dynamics {
namespace tools {

void writeNodeShapes(const std::string& path, const vehicle::VehicleModel& vehicle,
                     const fem::System& system, const fem::ModalBasis& basis) {
  std::vector<fem::Node> nodes = vehicle.model.nodes;
  std::sort(nodes.begin(), nodes.end(),
            [](const fem::Node& a, const fem::Node& b) { return a.id < b.id; });
  std::vector<fem::DofRef> dofs;
  for (const fem::Node& n : nodes)
    for (int d = 0; d < 3; ++d)
      dofs.push_back(fem::DofRef{n.id, d});
  // u_phys = T u_active: slaves follow their masters, fixed DOFs are zero.
  const Matrix u = vehicle::physicalShapes(system, dofs, basis.shapes);

  io::AtomicTextFile file(path);
  std::ostream& out = file.stream();
  out << std::setprecision(10) << "node,part,x_m,y_m,z_m";
  for (int k = 1; k <= basis.count(); ++k)
    out << ",mode_" << k << "_ux,mode_" << k << "_uy,mode_" << k << "_uz";
  out << "\n";
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const fem::Node& n = nodes[i];
    out << n.id << "," << vehicle::nodePart(vehicle.layout, n.id) << "," << n.position.x() << ","
        << n.position.y() << "," << n.position.z();
    for (int k = 0; k < basis.count(); ++k)
      for (int d = 0; d < 3; ++d)
        out << "," << u(static_cast<DofIndex>(3 * i + d), k);
    out << "\n";
  }
  file.commit();
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
