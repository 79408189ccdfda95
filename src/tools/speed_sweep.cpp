#include "speed_sweep.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "tracked_vehicle_dynamics/dynamics/speed_profile.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/number_text.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {

[[noreturn]] void reject(const std::string& text, const std::string& why) {
  throw InputError("ride: --speeds '" + text + "': " + why +
                   " (give FIRST:LAST:STEP or a list like 5,10,20, in km/h)");
}

double number(const std::string& text, const std::string& field) {
  char* end = nullptr;
  const double v = io::strtodC(field.c_str(), &end);
  if (field.empty() || end != field.c_str() + field.size() || !std::isfinite(v))
    reject(text, "'" + field + "' is not a number");
  return v;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(text);
  while (std::getline(in, part, separator))
    parts.push_back(part);
  if (!text.empty() && text.back() == separator)
    parts.push_back("");
  return parts;
}

}  // namespace

std::vector<double> parseSpeedSweep(const std::string& text) {
  std::vector<double> speeds;
  if (text.find(':') != std::string::npos) {
    const std::vector<std::string> f = split(text, ':');
    if (f.size() != 3)
      reject(text, "a range has three fields");
    const double first = number(text, f[0]), last = number(text, f[1]), step = number(text, f[2]);
    if (!(step > 0))
      reject(text, "the step must be positive");
    if (!(last >= first))
      reject(text, "LAST must not be below FIRST");
    const double count = std::floor((last - first) / step + 1e-9) + 1;
    // LAST is the top of the sweep the user asked for: a step that passes it would quietly rate a
    // lower top speed, so it is refused rather than rounded.
    const double reached = first + (count - 1) * step;
    if (count <= static_cast<double>(kMaxSweepSpeeds) &&
        std::abs(reached - last) > 1e-9 * std::max(1.0, last)) {
      std::ostringstream m;
      m << "the step " << step << " from " << first << " does not land on LAST " << last
        << " (it stops at " << reached << ")";
      reject(text, m.str());
    }
    if (count > static_cast<double>(kMaxSweepSpeeds))
      reject(text, "more than " + std::to_string(kMaxSweepSpeeds) + " speeds");
    for (long i = 0; i < static_cast<long>(count); ++i)
      speeds.push_back(first + static_cast<double>(i) * step);
  } else {
    for (const std::string& f : split(text, ','))
      speeds.push_back(number(text, f));
    if (speeds.size() > kMaxSweepSpeeds)
      reject(text, "more than " + std::to_string(kMaxSweepSpeeds) + " speeds");
  }
  if (speeds.empty())
    reject(text, "no speeds");
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    if (!(speeds[i] > 0.0 && speeds[i] <= dynamics::kMaxSpeedKmh)) {
      std::ostringstream m;
      m << "speed " << speeds[i] << " km/h is outside (0, " << dynamics::kMaxSpeedKmh << "]";
      reject(text, m.str());
    }
    if (i > 0 && !(speeds[i] > speeds[i - 1]))
      reject(text, "the speeds must be strictly increasing");
  }
  return speeds;
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
