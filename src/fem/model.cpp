#include "tracked_vehicle_dynamics/fem/model.h"

#include <string>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace fem {

NodeId Model::addNode(NodeId id, const Vector3& position) {
  nodes.push_back(Node{id, position});
  return id;
}

std::unordered_map<NodeId, std::size_t> Model::nodeIndex() const {
  std::unordered_map<NodeId, std::size_t> index;
  index.reserve(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const auto [it, inserted] = index.emplace(nodes[i].id, i);
    if (!inserted) {
      throw InputError("model: nodes[" + std::to_string(i) + "]: duplicate node id " +
                       std::to_string(nodes[i].id) + " (also nodes[" + std::to_string(it->second) +
                       "])");
    }
  }
  return index;
}

const Material* Model::findMaterial(const std::string& material_name) const {
  for (const Material& material : materials) {
    if (material.name == material_name) {
      return &material;
    }
  }
  return nullptr;
}

const Section* Model::findSection(const std::string& section_name) const {
  for (const Section& section : sections) {
    if (section.name == section_name) {
      return &section;
    }
  }
  return nullptr;
}

double Model::totalMass() const {
  double total = 0.0;
  for (const Mass& mass : masses) {
    total += mass.mass;
  }
  if (beams.empty()) {
    return total;
  }
  const auto index = nodeIndex();
  for (std::size_t i = 0; i < beams.size(); ++i) {
    const Beam& beam = beams[i];
    const std::string item = "model: beams[" + std::to_string(i) + "]: ";
    const auto n1 = index.find(beam.n1);
    const auto n2 = index.find(beam.n2);
    if (n1 == index.end() || n2 == index.end()) {
      const NodeId missing = n1 == index.end() ? beam.n1 : beam.n2;
      throw InputError(item + "node " + std::to_string(missing) + " does not exist");
    }
    const Material* material = findMaterial(beam.material);
    if (material == nullptr) {
      throw InputError(item + "material '" + beam.material + "' does not exist");
    }
    const Section* section = findSection(beam.section);
    if (section == nullptr) {
      throw InputError(item + "section '" + beam.section + "' does not exist");
    }
    const double length = (nodes[n2->second].position - nodes[n1->second].position).norm();
    total += material->density * section->area * length;
  }
  return total;
}

}  // namespace fem
}  // namespace tracked_vehicle_dynamics
