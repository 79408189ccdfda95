#include "wheel_rate_report.h"

#include <iomanip>
#include <sstream>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace tools {

void writeWheelRateEstimate(io::JsonWriter& json, const vehicle::WheelRateEstimate& e) {
  json.key("wheel_rate_estimate")
      .beginObject()
      .field("wheel_rate_n_m", e.wheel_rate)
      .field("series_rate_n_m", e.series_rate)
      .field("road_wheels", e.wheels)
      .field("sprung_mass_kg", e.sprung_mass)
      .field("sag_m", e.sag)
      .field("bounce_hz", e.bounce_hz)
      .field("cog_x_m", e.cog_x)
      .field("pitch_deg", e.pitch * kRadToDegree)
      .endObject();
}

std::string wheelRateEstimateText(const vehicle::WheelRateEstimate& e) {
  std::ostringstream text;
  text << std::fixed << "torsion bars and pads alone (hand estimate): sag " << std::setprecision(1)
       << e.sag * 1e3 << " mm, bounce " << std::setprecision(2) << e.bounce_hz << " Hz (wheel rate "
       << brief(e.wheel_rate) << " N/m, " << e.wheels << " road wheels, " << brief(e.sprung_mass)
       << " kg), pitch " << std::setprecision(2) << e.pitch * kRadToDegree
       << " deg (positive nose down; its CoG x " << std::setprecision(3) << e.cog_x << " m)";
  return text.str();
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
