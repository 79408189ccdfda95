// Decimal text of a double for files a user reads and a program reads back.
#pragma once

#include <string>

namespace tracked_vehicle_dynamics {
namespace io {

/// The shortest decimal that reads back (strtod) as exactly `value`: 0.7, not the
/// 0.69999999999999996 of %.17g, while every bit is kept. Negative zero is written "0" (it
/// compares equal, and "-0" in a table reads as a sign error); infinities "inf"/"-inf", NaN "nan".
std::string roundTripText(double value);

}  // namespace io
}  // namespace tracked_vehicle_dynamics
