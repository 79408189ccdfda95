// Subcommands of the `tvd` command-line tool; each registers itself on the CLI11 app.
#pragma once

#include <CLI/CLI.hpp>

namespace tracked_vehicle_dynamics {
namespace tools {

void registerModesCommand(CLI::App& app);
void registerMacCommand(CLI::App& app);
void registerReduceCommand(CLI::App& app);
void registerSimulateCommand(CLI::App& app);
void registerFrfCommand(CLI::App& app);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
