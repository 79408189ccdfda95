// CLI11's parse errors as the tools' one-line messages (tvd, tvd_make_bag). CLI11 checks required
// options before unknown ones, so a misspelt option reads "--track is required"; its conversion and
// count errors name the C++ side ("Could not convert", "1 required INT:INT ... missing"). The user
// typed an option: they are told which one, what it wanted, and the nearest known spelling.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace tracked_vehicle_dynamics {
namespace tools {

/// The message for `error`, thrown by app.parse(args) (args: argv without the program name;
/// `program` names it in the hints: "tvd", "tvd_make_bag"). Checked in order: an unknown
/// subcommand (for an app with subcommands); an unknown option of the parsed subcommand, or of
/// the app without subcommands (with the nearest option name when one is within two edits or
/// starts with it); then CLI11's error in plain words. One line, prefixed with the subcommand's
/// name ("simulate: ") when there is one.
std::string describeParseError(const CLI::App& app, const CLI::ParseError& error,
                               const std::vector<std::string>& args, const std::string& program);

/// Runs a program's `run(argc, argv)` and returns its status; an exception that escapes it (the
/// commands' set-up: CLI11 refuses a duplicate or malformed option by throwing, before the
/// parse's own handlers) is reported as "<program>: internal error: ..." with status 1, not an
/// abort without a word.
int runReportingErrors(const char* program, int (*run)(int, char**), int argc, char** argv);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
