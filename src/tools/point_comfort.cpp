#include "point_comfort.h"

#include <cmath>
#include <sstream>
#include <utility>

#include "simulation_layout.h"

namespace tracked_vehicle_dynamics {
namespace tools {

ComfortRows comfortRows(const std::vector<std::string>& names, const std::string& point,
                        const std::string& command) {
  const auto row = [&](const std::string& name) { return outputRow(names, name, command); };
  return {row(point + " ux/acc"), row(point + " uy/acc"), row(point + " uz/acc"),
          row("hull rx/acc"),     row("hull ry/acc"),     row("hull rz/acc")};
}

PointComfort::PointComfort(std::string point, const ComfortRows& rows, double dt)
    : point_(std::move(point)), rows_(rows), meter_(1.0 / dt) {}

void PointComfort::add(const OutputRow& outputs) {
  meter_.add({outputs(rows_.x), outputs(rows_.y), outputs(rows_.z), outputs(rows_.roll),
              outputs(rows_.pitch), outputs(rows_.yaw)});
}

void PointComfort::writeJson(io::JsonWriter& json) const {
  const dynamics::BasicMethodRatios r = dynamics::basicMethodRatios(meter_.vertical().metrics());
  json.beginObject()
      .field("point", point_)
      // The vertical ones also by ride's names, with the axis as the other axes' keys have it;
      // the first two names are kept for scripts written before 0.5.2.
      .field("weighted_rms_m_s2", meter_.vertical().weightedRms())
      .field("vdv_m_s1_75", meter_.vertical().vibrationDoseValue())
      .field("weighted_rms_z_m_s2", meter_.vertical().weightedRms())
      .field("vdv_z_m_s1_75", meter_.vertical().vibrationDoseValue())
      .field("mtvv_m_s2", meter_.vertical().maximumTransientVibrationValue())
      .field("mtvv_linear_m_s2", meter_.vertical().maximumTransientVibrationValueLinear())
      .field("peak_weighted_m_s2", meter_.vertical().peakWeighted())
      .field("crest_factor", r.crest_factor)
      .field("mtvv_ratio", r.mtvv_ratio)
      .field("mtvv_linear_ratio", r.mtvv_linear_ratio)
      .field("vdv_ratio", r.vdv_ratio)
      .field("basic_method_sufficient", r.basicMethodSufficient())
      .field("absorbed_power_w", meter_.vertical().absorbedPower().value_or(0.0))
      .field("weighted_rms_x_m_s2", meter_.longitudinal().weightedRms())
      .field("weighted_rms_y_m_s2", meter_.lateral().weightedRms())
      .field("vibration_total_value_m_s2", meter_.translationalTotalValue())
      .field("weighted_rms_roll_rad_s2", meter_.roll().weightedRms())
      .field("weighted_rms_pitch_rad_s2", meter_.pitch().weightedRms())
      .field("weighted_rms_yaw_rad_s2", meter_.yaw().weightedRms())
      .field("rotational_total_value_m_s2", meter_.rotationalTotalValue())
      .field("seat_surface_total_value_m_s2", meter_.seatSurfaceTotalValue())
      .endObject();
}

void PointComfort::writeText(std::ostream& out) const {
  out << "    " << point_ << ": a_wz " << meter_.vertical().weightedRms() << " m/s^2, VDV "
      << meter_.vertical().vibrationDoseValue() << " m/s^1.75, absorbed power "
      << meter_.vertical().absorbedPower().value_or(0.0) << " W, a_wx "
      << meter_.longitudinal().weightedRms() << ", a_wy " << meter_.lateral().weightedRms()
      << ", a_v " << meter_.translationalTotalValue() << " m/s^2\n";
  out << "      rotation (We): roll " << meter_.roll().weightedRms() << ", pitch "
      << meter_.pitch().weightedRms() << ", yaw " << meter_.yaw().weightedRms() << " rad/s^2, a_r "
      << meter_.rotationalTotalValue() << " m/s^2; six axes " << meter_.seatSurfaceTotalValue()
      << " m/s^2\n";
  if (meter_.vertical().sampleCount() == 0 || !(meter_.vertical().weightedRms() > 0.0))
    return;
  // ISO 2631-1 6.2.1 and 6.3.3: whether a_wz alone describes this run.
  const dynamics::BasicMethodRatios r = dynamics::basicMethodRatios(meter_.vertical().metrics());
  out << "      MTVV " << meter_.vertical().maximumTransientVibrationValue() << " m/s^2 ("
      << meter_.vertical().maximumTransientVibrationValueLinear()
      << " by a 1 s linear window), crest factor " << r.crest_factor << ", MTVV/a_wz "
      << r.mtvv_ratio << " (" << r.mtvv_linear_ratio << ")"
      << ", VDV/(a_wz T^1/4) " << r.vdv_ratio << ": ";
  using L = dynamics::BasicMethodRatios;
  if (r.basicMethodSufficient())
    out << "a_wz suffices (ISO 2631-1 6.2.1, 6.3.3)\n";
  else {
    std::ostringstream limits;  // in the shortest form, whatever the stream's format
    limits << L::kMaxCrestFactor << ", " << L::kMaxMtvvRatio << ", " << L::kMaxVdvRatio;
    out << "over ISO 2631-1's limits (" << limits.str()
        << "; 6.2.1, 6.3.3): report the VDV and MTVV beside a_wz\n";
  }
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
