// The mass breakdown of a vehicle model (paper Table 1's total, part by part), as `tvd modes` and
// `tvd statics` report it: the same JSON object and text line in both.
#pragma once

#include <string>

#include "tracked_vehicle_dynamics/io/json_writer.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace tools {

/// Writes the key "mass_breakdown_kg" and its object {hull, road_wheels, track_assemblies,
/// sprockets, idlers, return_rollers} [kg] (every part, 0 for a part the variant lacks).
void writeMassBreakdown(io::JsonWriter& json, const vehicle::MassBreakdown& mass);

/// "mass breakdown: hull 30300.0 kg, road wheels 16800.0 kg, ... (total 55668.0 kg)": the parts
/// of non-zero mass, in the order of the JSON, and MassBreakdown::total.
std::string massBreakdownText(const vehicle::MassBreakdown& mass);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
