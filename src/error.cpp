#include "tracked_vehicle_dynamics/error.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "tracked_vehicle_dynamics/io/number_text.h"

namespace tracked_vehicle_dynamics {

std::string brief(double value) {
  // Not "-nan" (the sign bit of a NaN means nothing) nor "-0" (equal to 0, and read as a sign
  // mistake).
  if (std::isnan(value))
    return "nan";
  if (value == 0.0)
    return "0";
  // Six digits, unless the value is exactly one of up to ten: a value the user typed (200.0001
  // against a bound of 200) must not be shown as the bound it breaks, while a computed value
  // (0.1 + 0.2), which no short decimal gives exactly, keeps its six.
  for (int digits = 6; digits <= 10; ++digits) {
    std::string text;
    io::appendGeneral(text, value, digits);
    if (io::strtodC(text.c_str(), nullptr) == value)
      return text;
  }
  std::string text;
  io::appendGeneral(text, value, 6);
  return text;
}

std::string beyond(double value, double bound) {
  const std::string shown_bound = brief(bound);
  std::string shown = brief(value);
  for (int digits = 7; shown == shown_bound && value != bound && digits <= 17; ++digits) {
    shown.clear();
    io::appendGeneral(shown, value, digits);
  }
  return shown;
}

std::size_t editDistance(const std::string& a, const std::string& b) {
  // The classic two-row dynamic programme: d[i][j] = edits turning a[0..i) into b[0..j).
  std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      current[j] = std::min(
          {previous[j] + 1, current[j - 1] + 1, previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
    std::swap(previous, current);
  }
  return previous[b.size()];
}

}  // namespace tracked_vehicle_dynamics
