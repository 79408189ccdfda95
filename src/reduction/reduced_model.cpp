#include "tracked_vehicle_dynamics/reduction/reduced_model.h"

#include <ctime>
#include <functional>
#include <map>
#include <set>
#include <stdexcept>
#include <string>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/number_text.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

namespace {

std::string label(const fem::DofRef& d) {
  return "node " + std::to_string(d.node) + " " + directionName(d.direction);
}

std::string modeLabel(DofIndex mode, double frequency_hz) {
  return io::formatC("mode %ld (%.3g Hz)", static_cast<long>(mode + 1), frequency_hz);
}

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char buffer[32];
  std::strftime(buffer, sizeof(buffer), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return buffer;
}

}  // namespace

std::vector<std::vector<std::pair<DofIndex, double>>> outputTerms(
    const fem::DofMap& dofs, const std::vector<OutputDof>& outputs) {
  const SparseMatrix by_row = dofs.transformation().transpose();  // column p = physical row p
  std::vector<std::vector<std::pair<DofIndex, double>>> terms(outputs.size());
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const fem::DofRef& d = outputs[i].dof;
    DofIndex p = 0;
    try {
      p = dofs.physical(d.node, d.direction);
    } catch (const InputError& e) {
      throw InputError("buildReducedModel: output [" + std::to_string(i) + "] '" + outputs[i].name +
                       "': " + e.what());
    }
    for (SparseMatrix::InnerIterator it(by_row, p); it; ++it)
      terms[i].emplace_back(it.row(), it.value());
  }
  return terms;
}

std::vector<std::string> outputNames(const std::vector<OutputDof>& outputs) {
  std::set<std::string> names;
  std::vector<std::string> output_names;
  for (const OutputDof& output : outputs) {
    const std::string name = output.name.empty() ? label(output.dof) : output.name;
    if (!names.insert(name).second)
      throw InputError("buildReducedModel: output name '" + name + "' is used twice");
    output_names.push_back(name);
  }
  return output_names;
}

void inputPositions(const fem::System& system, const Vector& road_stations, Vector* stations,
                    Vector* lateral) {
  const fem::DofMap& dofs = system.dofs;
  const auto inputs = static_cast<DofIndex>(system.ground_inputs.size());
  if (road_stations.size() != 0 && road_stations.size() != inputs)
    throw InputError("input stations: " + std::to_string(road_stations.size()) + " given for " +
                     std::to_string(inputs) + " road inputs");
  Vector x(inputs), y(inputs);
  for (DofIndex q = 0; q < inputs; ++q) {
    const fem::DofRef& d = system.ground_inputs[static_cast<std::size_t>(q)];
    DofIndex active = -1;
    for (int direction = 0; direction < kDofsPerNode && active < 0; ++direction)
      active = dofs.active(d.node, direction);
    if (active < 0) {
      *stations = Vector();
      *lateral = Vector();
      return;
    }
    x(q) = dofs.positionOf(active).x();
    y(q) = dofs.positionOf(active).y();
  }
  *stations = road_stations.size() != 0 ? road_stations : x;
  *lateral = y;
}

namespace {

using Reduce = std::function<CraigBamptonResult(const CraigBamptonOptions&)>;

// The outputs are checked before `reduce` runs, so a bad request is refused before the
// factorisation.
ReducedModel build(const fem::System& system, const ReductionRequest& request,
                   const Reduce& reduce) {
  const fem::DofMap& dofs = system.dofs;
  const auto terms = outputTerms(dofs, request.outputs);
  const std::vector<std::string> output_names = outputNames(request.outputs);

  // One recovery row per active DOF the outputs need.
  CraigBamptonOptions options = request.craig_bampton;
  std::map<DofIndex, DofIndex> recovery_row;
  options.recovery_dofs.clear();
  for (const auto& output : terms)
    for (const auto& [active, coefficient] : output)
      if (recovery_row.emplace(active, static_cast<DofIndex>(options.recovery_dofs.size())).second)
        options.recovery_dofs.push_back(active);
  const CraigBamptonResult cb = reduce(options);

  ReducedModel model;
  dynamics::SecondOrderSystem& s = model.system;
  s.mass = cb.mass;
  s.stiffness = cb.stiffness;
  s.damping = cb.damping;
  s.input_stiffness = cb.input_stiffness;
  s.input_damping = cb.input_damping;
  s.output = Matrix::Zero(static_cast<DofIndex>(terms.size()), cb.size());
  for (std::size_t i = 0; i < terms.size(); ++i)
    for (const auto& [active, coefficient] : terms[i])
      s.output.row(static_cast<DofIndex>(i)) +=
          coefficient * cb.recovery.row(recovery_row.at(active));
  s.output_names = output_names;

  const auto inputs = static_cast<DofIndex>(system.ground_inputs.size());
  for (DofIndex q = 0; q < inputs; ++q)
    model.input_labels.push_back(label(system.ground_inputs[static_cast<std::size_t>(q)]));
  inputPositions(system, request.input_stations, &s.input_stations, &s.input_lateral);

  model.gravity_load = cb.gravity_load;
  model.travel_load = cb.travel_load;
  if (!request.master_groups.empty() && request.master_groups.size() != request.masters.size())
    throw std::logic_error("buildReducedModel: " + std::to_string(request.master_groups.size()) +
                           " master groups for " + std::to_string(request.masters.size()) +
                           " masters");
  model.master_positions.resize(cb.masterCount(), 3);
  for (DofIndex i = 0; i < cb.masterCount(); ++i) {
    const DofIndex master = cb.masters[static_cast<std::size_t>(i)];  // request.masters, in order
    model.masters.push_back(dofs.dofOf(master));
    model.dof_labels.push_back(dofs.label(master));
    model.master_positions.row(i) = dofs.positionOf(master).transpose();
    model.master_groups.push_back(request.master_groups.empty()
                                      ? "master"
                                      : request.master_groups[static_cast<std::size_t>(i)]);
  }
  model.fixed_interface_frequencies_hz = cb.fixed_interface_frequencies_hz;
  for (DofIndex j = 0; j < cb.modeCount(); ++j)
    model.dof_labels.push_back(modeLabel(j, cb.fixed_interface_frequencies_hz(j)));
  model.selected_modes = request.selection.modes;
  // Discrete dampers: any in C (the suspension arms', and a damped ground spring's own term,
  // whose input side is C_u).
  model.damping = describe(options.damping, system.damping.nonZeros() > 0);
  model.description_hash = request.description_hash;
  model.reduction = request.reduction;
  model.version = softwareVersion();
  model.created_utc = utcNow();
  model.creator = request.creator;
  model.full_dof_count = system.size();
  return model;
}

}  // namespace

ReducedModel buildReducedModel(const fem::System& system, const ReductionRequest& request) {
  // craigBampton() checks the masters and options before it factorises.
  return build(system, request, [&](const CraigBamptonOptions& options) {
    return craigBampton(system, request.masters, options);
  });
}

ReducedModel buildReducedModel(const fem::System& system, const ReductionRequest& request,
                               const CraigBamptonReducer& reducer,
                               const FixedInterfaceProjection* fixed_interface) {
  if (!reducer.builtOn(system) || reducer.masters() != request.masters)
    throw std::logic_error(
        "buildReducedModel: the reducer was not built on this system and the "
        "request's " +
        std::to_string(request.masters.size()) + " masters");
  return build(system, request, [&](const CraigBamptonOptions& options) {
    return fixed_interface ? reducer.reduce(options, *fixed_interface) : reducer.reduce(options);
  });
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
