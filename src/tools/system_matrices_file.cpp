#include "system_matrices_file.h"

#include "tracked_vehicle_dynamics/io/mat_file.h"

namespace tracked_vehicle_dynamics {
namespace tools {

void writeSystemMatrices(const std::string& path, const fem::Model& model, const fem::System& sys,
                         const VehicleMatrixExtras* vehicle, const Metadata& metadata) {
  io::MatWriter mat(path);
  // Sparse, as assembled: the tracked vehicle's 14 000 DOFs are 1.6 GB each as dense doubles.
  mat.writeSparse("M", sys.mass);
  mat.writeSparse("K", sys.stiffness);
  mat.writeSparse("C", sys.damping);
  mat.writeSparse("K_u", sys.input_stiffness);
  mat.writeSparse("C_u", sys.input_damping);
  mat.writeMatrix("gravity_load", sys.gravity_load);
  mat.writeMatrix("travel_load", sys.travel_load);
  writeDofTable(mat, sys);
  Matrix input_node(static_cast<Eigen::Index>(sys.ground_inputs.size()), 1);
  for (std::size_t i = 0; i < sys.ground_inputs.size(); ++i)
    input_node(static_cast<Eigen::Index>(i), 0) = static_cast<double>(sys.ground_inputs[i].node);
  mat.writeMatrix("input_node", input_node);
  Matrix node_id(static_cast<Eigen::Index>(model.nodes.size()), 1);
  Matrix node_position(node_id.rows(), 3);
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    node_id(static_cast<Eigen::Index>(i), 0) = static_cast<double>(model.nodes[i].id);
    node_position.row(static_cast<Eigen::Index>(i)) = model.nodes[i].position.transpose();
  }
  mat.writeMatrix("node_id", node_id);
  mat.writeMatrix("node_position", node_position);
  if (vehicle != nullptr) {
    mat.writeMatrix("input_station", vehicle->input_stations);
    const vehicle::DampingDescription& d = vehicle->damping;
    mat.writeString("damping_model",
                    d.model == vehicle::DampingModel::Modal ? "modal" : "rayleigh");
    mat.writeScalar("modal_damping_ratio",
                    d.model == vehicle::DampingModel::Modal ? d.modal_ratio : 0.0);
    mat.writeScalar("rayleigh_alpha",
                    d.model == vehicle::DampingModel::Rayleigh ? d.rayleigh_alpha : 0.0);
    mat.writeScalar("rayleigh_beta",
                    d.model == vehicle::DampingModel::Rayleigh ? d.rayleigh_beta : 0.0);
  }
  writeMetadata(mat, metadata);
  mat.close();
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
