// The hand estimate of vehicle::wheelRateEstimate as `tvd modes` and `tvd statics` report it:
// the same JSON object and text line in both, beside what the model computes.
#pragma once

#include <string>

#include "tracked_vehicle_dynamics/io/json_writer.h"
#include "tracked_vehicle_dynamics/vehicle/wheel_rate_estimate.h"

namespace tracked_vehicle_dynamics {
namespace tools {

/// Writes the key "wheel_rate_estimate" and its object {wheel_rate_n_m, series_rate_n_m,
/// road_wheels, sprung_mass_kg, sag_m, bounce_hz}.
void writeWheelRateEstimate(io::JsonWriter& json, const vehicle::WheelRateEstimate& estimate);

/// "torsion bars and pads alone (hand estimate): sag 14.5 mm, bounce 4.14 Hz (wheel rate
/// 1.58e+06 N/m, 14 road wheels, 30300 kg)".
std::string wheelRateEstimateText(const vehicle::WheelRateEstimate& estimate);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
