#include "point_comfort.h"

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

}  // namespace

PointComfort::PointComfort(std::string point, DofIndex x_row, DofIndex y_row, DofIndex z_row,
                           double dt)
    : point_(std::move(point)),
      x_row_(x_row),
      y_row_(y_row),
      z_row_(z_row),
      vertical_(1.0 / dt, verticalOptions()),
      longitudinal_(1.0 / dt, horizontalOptions()),
      lateral_(1.0 / dt, horizontalOptions()) {}

void PointComfort::add(const OutputRow& outputs) {
  vertical_.add(outputs(z_row_));
  longitudinal_.add(outputs(x_row_));
  lateral_.add(outputs(y_row_));
}

double PointComfort::totalValue() const {
  return std::sqrt(std::pow(longitudinal_.weightedRms(), 2) + std::pow(lateral_.weightedRms(), 2) +
                   std::pow(vertical_.weightedRms(), 2));
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
      .endObject();
}

void PointComfort::writeText(std::ostream& out) const {
  out << "    " << point_ << ": a_wz " << vertical_.weightedRms() << " m/s^2, VDV "
      << vertical_.vibrationDoseValue() << " m/s^1.75, absorbed power "
      << vertical_.absorbedPower().value_or(0.0) << " W, a_wx " << longitudinal_.weightedRms()
      << ", a_wy " << lateral_.weightedRms() << ", a_v " << totalValue() << " m/s^2\n";
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
