// Decimal text of a double for files a user reads and a program reads back, the same in every
// locale: a program that links the core and calls setlocale(LC_ALL, "") (a GUI, Python through
// ctypes) must not get "2,14" in a JSON array or a different vehicle hash.
#pragma once

#include <string>

namespace tracked_vehicle_dynamics {
namespace io {

/// The shortest decimal that reads back (strtod) as exactly `value`: 0.7, not the
/// 0.69999999999999996 of %.17g, while every bit is kept. Negative zero is written "0" (it
/// compares equal, and "-0" in a table reads as a sign error); infinities "inf"/"-inf", NaN "nan".
std::string roundTripText(double value);

/// Appends `value` as printf's "%.{precision}g" (what an ostream with setprecision(precision)
/// writes: "nan", "-nan", "inf", "-0" included) by std::to_chars, which C++17 specifies as that
/// printf conversion, at a fraction of the stream's cost: a result table of 28 million numbers
/// is written in seconds rather than a quarter of a minute. precision in [1, 17].
void appendGeneral(std::string& text, double value, int precision);

/// printf's formatting in the "C" locale, whatever locale the process has set: '.' is the
/// decimal point. For patterns to_chars has no form for ("%#.3g", "%.*f" within a sentence).
std::string formatC(const char* pattern, ...) __attribute__((format(printf, 1, 2)));

/// strtod in the "C" locale (strtod_l): "1.5" reads as 1.5 under a comma locale too.
double strtodC(const char* text, char** end);

/// sscanf in the "C" locale; returns what sscanf returns.
int scanC(const char* text, const char* pattern, ...) __attribute__((format(scanf, 2, 3)));

}  // namespace io
}  // namespace tracked_vehicle_dynamics
