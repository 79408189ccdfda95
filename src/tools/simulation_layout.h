// The columns `tvd simulate` writes after time and station: each one row of the simulator's
// stacked outputs (output_layout.h), scaled to the unit in its header.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/types.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_geometry.h"

namespace tracked_vehicle_dynamics {
namespace tools {

struct SimulationColumn {
  std::string header;     ///< e.g. "hull_pitch_deg"
  DofIndex row = 0;       ///< row of the simulator's outputs
  double scale = 1.0;     ///< to the header's unit (rad -> deg)
  bool relative = false;  ///< a displacement: reported from the initial static equilibrium
};

struct SimulationLayout {
  std::vector<SimulationColumn> columns;
  std::size_t first_wheel = 0;      ///< first road-wheel column
  std::size_t wheel_count = 0;      ///< road-wheel columns
  std::vector<std::string> points;  ///< named points of the hull (crew seat, sensor mount, ...)

  /// Index of the column named `header` in `columns`; throws std::logic_error when absent.
  std::size_t column(const std::string& header) const;
};

/// Hull heave, vertical acceleration, pitch and roll (the first four, in this order: scripts find
/// columns by name, people by place), the hull's rates and angular and horizontal accelerations,
/// every road-wheel displacement, then per named point its vertical displacement and its
/// accelerations in x, y, z. `simulator_rows`: Simulator::outputNames() ("hull uz/disp", ...);
/// `system_outputs`: the system's output names ("hull uz", "road_wheel_left_1 uz",
/// "crew_seat ux", ...). Throws InputError naming an output the model lacks.
/// The named points of the hull among a model's outputs: every "<point> uz" that is neither the
/// hull's CoG nor a road-wheel centre, in output order.
std::vector<std::string> namedPoints(const std::vector<std::string>& system_outputs);

SimulationLayout simulationLayout(const std::vector<std::string>& simulator_rows,
                                  const std::vector<std::string>& system_outputs);

/// The road under a road-wheel centre: the terrain's height at the wheel's static position on
/// the ground plane, (s + x_w, y_w + y_0) for station s and lateral offset y_0, the line the
/// paper's Fig. 18 draws dashed as h_F and h_R under the front and rear axles.
struct RoadUnderWheel {
  std::string header;  ///< "road_under_road_wheel_left_1_m"
  double x = 0.0;      ///< wheel centre, ahead of the reference point [m]
  double y = 0.0;      ///< wheel centre, left of the path's centre line [m]
};

/// One entry per road-wheel column of `layout`, in its order, placed by `geometry`. Throws
/// InputError when the geometry lacks a wheel the model outputs.
std::vector<RoadUnderWheel> roadUnderWheels(const SimulationLayout& layout,
                                            const vehicle::VehicleGeometry& geometry);

/// Row of `name` in `simulator_rows` (or any list of output names); throws InputError naming it,
/// and the `command` that asked, when absent.
DofIndex outputRow(const std::vector<std::string>& simulator_rows, const std::string& name,
                   const std::string& command = "simulate");

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
