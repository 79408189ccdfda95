// The speeds of a `tvd ride` sweep as the command line gives them.
#pragma once

#include <string>
#include <vector>

namespace tracked_vehicle_dynamics {
namespace tools {

/// Most speeds a sweep may hold (each is one simulation, plus the bisection's).
constexpr std::size_t kMaxSweepSpeeds = 200;

/// "FIRST:LAST:STEP" (FIRST, FIRST + STEP, ... up to LAST, which is included when the steps land
/// on it to 1e-9 of STEP) or a comma-separated list "5,10,20", in km/h. Every speed must be in
/// (0, 200] and the list strictly increasing. Throws InputError quoting `text` and saying what is
/// wrong.
std::vector<double> parseSpeedSweep(const std::string& text);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
