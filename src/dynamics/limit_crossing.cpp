#include "tracked_vehicle_dynamics/dynamics/limit_crossing.h"

#include <cmath>
#include <sstream>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

namespace {

double checkedValue(double value, double speed) {
  if (!std::isfinite(value)) {
    std::ostringstream m;
    m << "limit crossing: the metric at speed " << speed << " is not finite";
    throw InputError(m.str());
  }
  return value;
}

}  // namespace

LimitCrossing findLimitCrossing(const std::vector<double>& speeds,
                                const std::vector<double>& values, double limit, double tolerance,
                                const std::function<double(double)>& evaluate) {
  if (speeds.empty())
    throw InputError("limit crossing: no speeds");
  if (values.size() != speeds.size())
    throw InputError("limit crossing: " + std::to_string(values.size()) + " values for " +
                     std::to_string(speeds.size()) + " speeds");
  if (!std::isfinite(limit))
    throw InputError("limit crossing: the limit is not finite");
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
    throw InputError("limit crossing: the tolerance must be a positive number");
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    checkedValue(values[i], speeds[i]);
    if (i > 0 && !(speeds[i] > speeds[i - 1]))
      throw InputError("limit crossing: the speeds must be strictly increasing");
  }
  LimitCrossing result;
  auto at = [&](LimitCrossing::Status status, std::size_t i) {
    result.status = status;
    result.speed = result.lower = result.upper = speeds[i];
    result.lower_value = result.upper_value = values[i];
    return result;
  };
  if (values.front() >= limit)
    return at(LimitCrossing::Status::AtLowest, 0);
  std::size_t i = 1;
  while (i < speeds.size() && values[i] < limit)
    ++i;
  if (i == speeds.size())
    return at(LimitCrossing::Status::NotReached, speeds.size() - 1);

  // Invariant: m(lower) < limit <= m(upper).
  double lo = speeds[i - 1], hi = speeds[i], m_lo = values[i - 1], m_hi = values[i];
  while (hi - lo > tolerance) {
    const double mid = 0.5 * (lo + hi);
    if (!(mid > lo && mid < hi))
      break;  // adjacent doubles: a tolerance below one ulp of the speed
    const double m = checkedValue(evaluate(mid), mid);
    ++result.refinements;
    if (m >= limit) {
      hi = mid;
      m_hi = m;
    } else {
      lo = mid;
      m_lo = m;
    }
  }
  result.status = LimitCrossing::Status::Reached;
  result.lower = lo;
  result.upper = hi;
  result.lower_value = m_lo;
  result.upper_value = m_hi;
  result.speed = lo + (limit - m_lo) / (m_hi - m_lo) * (hi - lo);  // m_hi > m_lo by the invariant
  return result;
}

const char* limitStatusName(LimitCrossing::Status status) {
  switch (status) {
    case LimitCrossing::Status::Reached:
      return "reached";
    case LimitCrossing::Status::AtLowest:
      return "at_lowest_speed";
    case LimitCrossing::Status::NotReached:
      return "not_reached";
  }
  return "?";
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
