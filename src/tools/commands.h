// Subcommands of the `tvd` command-line tool; each registers itself on the CLI11 app.
#pragma once

#include <CLI/CLI.hpp>

#include <cmath>
#include <string>

namespace tracked_vehicle_dynamics {
namespace tools {

/// Option checks with a short message ("must be positive, got -2"): CLI11's own
/// PositiveNumber/NonNegativeNumber print their range up to 1.8e308.
inline CLI::Validator positiveNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double v = 0.0;
        if (!CLI::detail::lexical_cast(text, v) || !(v > 0.0) || !std::isfinite(v))
          return "must be a positive number, got " + text;
        return std::string();
      },
      "POSITIVE");
}
inline CLI::Validator nonNegativeNumber() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double v = 0.0;
        if (!CLI::detail::lexical_cast(text, v) || !(v >= 0.0) || !std::isfinite(v))
          return "must be a number >= 0, got " + text;
        return std::string();
      },
      "NONNEGATIVE");
}

void registerModesCommand(CLI::App& app);
void registerMacCommand(CLI::App& app);
void registerReduceCommand(CLI::App& app);
void registerSimulateCommand(CLI::App& app);
void registerFrfCommand(CLI::App& app);
void registerTerrainCommand(CLI::App& app);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
