#include "tracked_vehicle_dynamics/vehicle/ground_pressure.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

namespace tracked_vehicle_dynamics {
namespace vehicle {

namespace {
/// Rowland's constant for rigid-link tracks (W in kN, lengths in m, MMP in kPa).
constexpr double kRowlandConstant = 1.26;
}  // namespace

GroundPressure groundPressure(const VehicleModel& vehicle, const VehicleDescription& description,
                              const StaticSummary& statics) {
  const VehicleLayout& layout = vehicle.layout;
  if (statics.pad_loads.size() != layout.road_inputs.size())
    throw std::logic_error("groundPressure: the static summary has " +
                           std::to_string(statics.pad_loads.size()) + " reactions, the model " +
                           std::to_string(layout.road_inputs.size()) + " road inputs");
  const TrackAssemblyDescription& track = description.track_assembly;
  const double footprint = track.width * track.pitch;
  const double half_track = 0.5 * description.running_gear.track_centre_distance;

  // Inputs grouped by assembly, in the order the assemblies first appear.
  std::map<int, std::size_t> slot;
  std::vector<AssemblyGroundLoad> loads;
  std::vector<int> inputs;
  for (std::size_t i = 0; i < layout.road_inputs.size(); ++i) {
    const RoadInput& in = layout.road_inputs[i];
    auto [it, added] = slot.emplace(in.assembly, loads.size());
    if (added) {
      AssemblyGroundLoad a;
      a.side = in.side;
      a.assembly = layout.assemblies.at(static_cast<std::size_t>(in.assembly)).index;
      loads.push_back(a);
      inputs.push_back(0);
    }
    AssemblyGroundLoad& a = loads[it->second];
    const double f = statics.pad_loads[i];
    a.load += f;
    a.x += in.x;
    ++inputs[it->second];
    // The track's centre line is at y = +-b/2; inner pads are the ones nearer the hull's.
    (std::abs(in.y) < half_track ? a.inner : a.outer) += f;
  }
  GroundPressure g;
  for (std::size_t k = 0; k < loads.size(); ++k) {
    loads[k].x /= inputs[k];
    loads[k].pressure = loads[k].load / footprint;
  }
  std::stable_sort(loads.begin(), loads.end(),
                   [](const AssemblyGroundLoad& a, const AssemblyGroundLoad& b) {
                     return a.side != b.side ? a.side < b.side : a.x > b.x;
                   });
  g.assemblies = std::move(loads);
  for (std::size_t k = 0; k < g.assemblies.size(); ++k) {
    const AssemblyGroundLoad& a = g.assemblies[k];
    g.side_load[a.side == 0 ? 0 : 1] += a.load;
    if (a.load < 0.0)
      ++g.lifting;
    // Strictly larger by more than round-off: of mirror-image twins the left one is the peak.
    if (g.peak < 0 ||
        a.pressure > g.assemblies[static_cast<std::size_t>(g.peak)].pressure +
                         1e-9 * std::abs(g.assemblies[static_cast<std::size_t>(g.peak)].pressure))
      g.peak = static_cast<int>(k);
  }
  // The pressure peak under each wheel: the assemblies within half an axle spacing of its centre.
  const auto nodes = vehicle.model.nodeIndex();
  const double reach = 0.5 * description.running_gear.axle_spacing;
  for (const WheelStation& w : layout.wheels) {
    const double x = vehicle.model.nodes[nodes.at(w.centre)].position.x();
    double peak = -std::numeric_limits<double>::infinity();
    for (const AssemblyGroundLoad& a : g.assemblies)
      if (a.side == w.side && std::abs(a.x - x) <= reach)
        peak = std::max(peak, a.pressure);
    if (!std::isfinite(peak))
      peak = 0.0;  // no assembly under it (cannot happen on a built model)
    g.wheel_peak_pressure.push_back(peak);
    g.wheel_x.push_back(x);
    g.mean_peak_pressure += peak / static_cast<double>(layout.wheels.size());
  }
  const double weight = statics.weight;
  g.nominal_pressure = weight / (2.0 * track.width * track.ground_length);
  const double wheel_diameter = 2.0 * description.road_wheel.radius;
  g.rowland_mean_maximum_pressure = kRowlandConstant * weight /
                                    (2.0 * description.running_gear.axle_count * track.width *
                                     std::sqrt(track.pitch * wheel_diameter));
  return g;
}

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
