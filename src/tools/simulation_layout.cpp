#include "simulation_layout.h"

#include <algorithm>
#include <stdexcept>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}
}  // namespace

DofIndex outputRow(const std::vector<std::string>& simulator_rows, const std::string& name,
                   const std::string& command) {
  const auto it = std::find(simulator_rows.begin(), simulator_rows.end(), name);
  if (it == simulator_rows.end())
    throw InputError(command + ": the model has no output '" + name + "'");
  return static_cast<DofIndex>(it - simulator_rows.begin());
}

std::size_t SimulationLayout::column(const std::string& header) const {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c].header == header)
      return c;
  throw std::logic_error("simulate: no column " + header);
}

std::vector<std::string> namedPoints(const std::vector<std::string>& system_outputs) {
  std::vector<std::string> points;
  for (const std::string& n : system_outputs) {
    const std::string point = n.substr(0, n.rfind(' '));
    if (endsWith(n, " uz") && point != "hull" && point.rfind("road_wheel", 0) != 0)
      points.push_back(point);
  }
  return points;
}

SimulationLayout simulationLayout(const std::vector<std::string>& simulator_rows,
                                  const std::vector<std::string>& system_outputs) {
  SimulationLayout layout;
  auto add = [&](std::string header, const std::string& output, double scale = 1.0) {
    layout.columns.push_back(
        {std::move(header), outputRow(simulator_rows, output), scale, endsWith(output, "/disp")});
  };
  add("hull_heave_m", "hull uz/disp");
  add("hull_vertical_accel_m_s2", "hull uz/acc");
  add("hull_pitch_deg", "hull ry/disp", kRadToDegree);
  add("hull_roll_deg", "hull rx/disp", kRadToDegree);
  add("hull_heave_rate_m_s", "hull uz/vel");
  add("hull_pitch_rate_deg_s", "hull ry/vel", kRadToDegree);
  add("hull_roll_rate_deg_s", "hull rx/vel", kRadToDegree);
  add("hull_pitch_accel_deg_s2", "hull ry/acc", kRadToDegree);
  add("hull_roll_accel_deg_s2", "hull rx/acc", kRadToDegree);
  add("hull_longitudinal_accel_m_s2", "hull ux/acc");
  add("hull_lateral_accel_m_s2", "hull uy/acc");
  add("hull_surge_m", "hull ux/disp");
  // The hull's yaw and sway: the lateral and yaw modes the out-of-phase waves and any uneven
  // road excite, which an azimuth stabiliser or a point of one's own needs (a_y(P) = a_y(G) +
  // yaw'' x_P - roll'' z_P, relative to the CoG).
  add("hull_sway_m", "hull uy/disp");
  add("hull_yaw_deg", "hull rz/disp", kRadToDegree);
  add("hull_yaw_rate_deg_s", "hull rz/vel", kRadToDegree);
  add("hull_yaw_accel_deg_s2", "hull rz/acc", kRadToDegree);
  layout.first_wheel = layout.columns.size();
  for (const std::string& n : system_outputs)
    if (n.rfind("road_wheel", 0) == 0)
      add(n.substr(0, n.find(' ')) + "_m", n + "/disp");
  layout.wheel_count = layout.columns.size() - layout.first_wheel;
  layout.points = namedPoints(system_outputs);
  for (const std::string& point : layout.points) {
    add(point + "_vertical_m", point + " uz/disp");
    add(point + "_accel_x_m_s2", point + " ux/acc");
    add(point + "_accel_y_m_s2", point + " uy/acc");
    add(point + "_accel_z_m_s2", point + " uz/acc");
  }
  return layout;
}

std::vector<RoadUnderWheel> roadUnderWheels(const SimulationLayout& layout,
                                            const vehicle::VehicleGeometry& geometry) {
  std::vector<RoadUnderWheel> roads;
  for (std::size_t c = layout.first_wheel; c < layout.first_wheel + layout.wheel_count; ++c) {
    const std::string& header = layout.columns[c].header;  // "<wheel>_m"
    const std::string wheel = header.substr(0, header.size() - 2);
    const auto it =
        std::find_if(geometry.wheels.begin(), geometry.wheels.end(),
                     [&](const vehicle::VehicleGeometry::Body& b) { return b.name == wheel; });
    if (it == geometry.wheels.end())
      throw InputError("simulate: the vehicle description has no road wheel '" + wheel +
                       "', which the model outputs");
    roads.push_back({"road_under_" + header, it->position.x(), it->position.y()});
  }
  return roads;
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
