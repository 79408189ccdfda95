#include "point_comfort.h"

#include "simulation_layout.h"

#include <cmath>
#include <sstream>
#include <utility>

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {

dynamics::ComfortOptions verticalOptions() {
  dynamics::ComfortOptions o;
  o.weighting = dynamics::Weighting::Wk;
  o.absorbed_power = dynamics::absorbedPowerVerticalSections();
  return o;
}

dynamics::ComfortOptions horizontalOptions() {
  dynamics::ComfortOptions o;
  o.weighting = dynamics::Weighting::Wd;
  return o;
}

dynamics::ComfortOptions rotationalOptions() {
  dynamics::ComfortOptions o;
  o.weighting = dynamics::Weighting::We;
  return o;
}

}  // namespace

ComfortRows comfortRows(const std::vector<std::string>& names, const std::string& point,
                        const std::string& command) {
  const auto row = [&](const std::string& name) { return outputRow(names, name, command); };
  return {row(point + " ux/acc"), row(point + " uy/acc"), row(point + " uz/acc"),
          row("hull rx/acc"),     row("hull ry/acc"),     row("hull rz/acc")};
}

PointComfort::PointComfort(std::string point, const ComfortRows& rows, double dt)
    : point_(std::move(point)),
      rows_(rows),
      vertical_(1.0 / dt, verticalOptions()),
      longitudinal_(1.0 / dt, horizontalOptions()),
      lateral_(1.0 / dt, horizontalOptions()),
      roll_(1.0 / dt, rotationalOptions()),
      pitch_(1.0 / dt, rotationalOptions()),
      yaw_(1.0 / dt, rotationalOptions()) {}

void PointComfort::add(const OutputRow& outputs) {
  vertical_.add(outputs(rows_.z));
  longitudinal_.add(outputs(rows_.x));
  lateral_.add(outputs(rows_.y));
  roll_.add(outputs(rows_.roll));
  pitch_.add(outputs(rows_.pitch));
  yaw_.add(outputs(rows_.yaw));
}

double PointComfort::totalValue() const {
  return dynamics::seatTranslationalTotalValue(longitudinal_.weightedRms(), lateral_.weightedRms(),
                                               vertical_.weightedRms());
}

double PointComfort::rotationalTotalValue() const {
  return dynamics::seatRotationalTotalValue(roll_.weightedRms(), pitch_.weightedRms(),
                                            yaw_.weightedRms());
}

double PointComfort::overallTotalValue() const {
  return std::hypot(totalValue(), rotationalTotalValue());
}

void PointComfort::writeJson(io::JsonWriter& json) const {
  const dynamics::BasicMethodRatios r = dynamics::basicMethodRatios(vertical_.metrics());
  json.beginObject()
      .field("point", point_)
      .field("weighted_rms_m_s2", vertical_.weightedRms())
      .field("vdv_m_s1_75", vertical_.vibrationDoseValue())
      .field("mtvv_m_s2", vertical_.maximumTransientVibrationValue())
      .field("peak_weighted_m_s2", vertical_.peakWeighted())
      .field("crest_factor", r.crest_factor)
      .field("mtvv_ratio", r.mtvv_ratio)
      .field("vdv_ratio", r.vdv_ratio)
      .field("basic_method_sufficient", r.basicMethodSufficient())
      .field("absorbed_power_w", vertical_.absorbedPower().value_or(0.0))
      .field("weighted_rms_x_m_s2", longitudinal_.weightedRms())
      .field("weighted_rms_y_m_s2", lateral_.weightedRms())
      .field("vibration_total_value_m_s2", totalValue())
      .field("weighted_rms_roll_rad_s2", roll_.weightedRms())
      .field("weighted_rms_pitch_rad_s2", pitch_.weightedRms())
      .field("weighted_rms_yaw_rad_s2", yaw_.weightedRms())
      .field("rotational_total_value_m_s2", rotationalTotalValue())
      .field("overall_total_value_m_s2", overallTotalValue())
      .endObject();
}

void PointComfort::writeText(std::ostream& out) const {
  out << "    " << point_ << ": a_wz " << vertical_.weightedRms() << " m/s^2, VDV "
      << vertical_.vibrationDoseValue() << " m/s^1.75, absorbed power "
      << vertical_.absorbedPower().value_or(0.0) << " W, a_wx " << longitudinal_.weightedRms()
      << ", a_wy " << lateral_.weightedRms() << ", a_v " << totalValue() << " m/s^2\n";
  out << "      rotation (We): roll " << roll_.weightedRms() << ", pitch " << pitch_.weightedRms()
      << ", yaw " << yaw_.weightedRms() << " rad/s^2, a_r " << rotationalTotalValue()
      << " m/s^2; six axes " << overallTotalValue() << " m/s^2\n";
  if (vertical_.sampleCount() == 0 || !(vertical_.weightedRms() > 0.0))
    return;
  // ISO 2631-1 6.2.1 and 6.3.3: whether a_wz alone describes this run.
  const dynamics::BasicMethodRatios r = dynamics::basicMethodRatios(vertical_.metrics());
  out << "      MTVV " << vertical_.maximumTransientVibrationValue() << " m/s^2, crest factor "
      << r.crest_factor << ", MTVV/a_wz " << r.mtvv_ratio << ", VDV/(a_wz T^1/4) " << r.vdv_ratio
      << ": ";
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
