#include "tracked_vehicle_dynamics/io/number_text.h"

#include <charconv>
#include <cmath>

namespace tracked_vehicle_dynamics {
namespace io {

std::string roundTripText(double value) {
  if (value == 0.0)
    return "0";
  if (std::isnan(value))
    return "nan";
  // std::to_chars without a precision is the shortest round-trip form (C++17 [charconv]);
  // 32 characters hold any double's ("-1.7976931348623157e+308" is 24).
  char buffer[32];
  const std::to_chars_result r = std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, r.ptr);
}

void appendGeneral(std::string& text, double value, int precision) {
  // "-1.2345678901234567e-308" is 24 characters; to_chars never writes past the end it is given.
  char buffer[32];
  const std::to_chars_result r =
      std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::general, precision);
  text.append(buffer, r.ptr);
}

}  // namespace io
}  // namespace tracked_vehicle_dynamics
