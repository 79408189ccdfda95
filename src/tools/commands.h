// Subcommands of the `tvd` command-line tool; each registers itself on the CLI11 app.
#pragma once

#include <CLI/CLI.hpp>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/file_type.h"
#include "tracked_vehicle_dynamics/io/number_text.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace tracked_vehicle_dynamics {
namespace tools {

/// Option checks with a short message ("must be a positive number, got -2"; CLI11's own
/// PositiveNumber/NonNegativeNumber print their range up to 1.8e308): a finite number that
/// satisfies `ok`, otherwise "must be <requirement>, got <text>".
template <typename Predicate>
CLI::Validator finiteNumberWhere(Predicate ok, const std::string& requirement,
                                 const std::string& name) {
  return CLI::Validator(
      [ok, requirement](std::string& text) -> std::string {
        double v = 0.0;
        if (!CLI::detail::lexical_cast(text, v) || !std::isfinite(v) || !ok(v))
          return "must be " + requirement + ", got " + text;
        return std::string();
      },
      name);
}
inline CLI::Validator positiveNumber() {
  return finiteNumberWhere([](double v) { return v > 0.0; }, "a positive number", "POSITIVE");
}
inline CLI::Validator nonNegativeNumber() {
  return finiteNumberWhere([](double v) { return v >= 0.0; }, "a number >= 0", "NONNEGATIVE");
}

/// A number in [lo, hi] (CLI::Range lets NaN through and prints its bounds to 17 digits).
inline CLI::Validator numberIn(double lo, double hi, const std::string& unit = "") {
  return CLI::Validator(
      [lo, hi, unit](std::string& text) -> std::string {
        double v = 0.0;
        if (!CLI::detail::lexical_cast(text, v) || !(v >= lo && v <= hi)) {
          return "must be a number in " + io::formatC("[%.16g, %.16g]", lo, hi) +
                 (unit.empty() ? "" : " " + unit) + ", got " + text;
        }
        return std::string();
      },
      "NUMBER");
}
/// An integer in [0, hi], compared as an integer: a double would round 2^53 + 1 down to 2^53 and
/// let it through.
inline CLI::Validator unsignedIn(std::uint64_t hi) {
  return CLI::Validator(
      [hi](std::string& text) -> std::string {
        std::uint64_t v = 0;
        if (!CLI::detail::lexical_cast(text, v) || v > hi)
          return "must be an integer in [0, " + std::to_string(hi) + "], got " + text;
        return std::string();
      },
      "UINT");
}
inline CLI::Validator finiteNumber() {
  return finiteNumberWhere([](double) { return true; }, "a finite number", "FINITE");
}

/// The number options of `options`. One without a check of its own refuses an empty value
/// ("--speed-kmh ''", a shell variable left unset), which CLI11 reads as 0 (frf then took it for
/// synchronous excitation without a word). Every integer is read in decimal: CLI11 reads "010"
/// as octal 8 and "0x10" as 16 (--seed 010 gave another road than --seed 10); leading zeros are
/// dropped and a base prefix refused, in front of the option's own checks, which then read the
/// decimal text.
inline void checkNumberTexts(const std::vector<CLI::Option*>& options) {
  for (CLI::Option* option : options) {
    // "INT", or with the names of its checks: "INT:INT in [1 - 500]".
    const std::string type = option->get_type_name();
    const std::string base = type.substr(0, type.find(':'));
    if (base == "INT" || base == "UINT")
      option->transform(CLI::Validator(
          [](std::string& text) {
            const std::size_t sign = !text.empty() && (text[0] == '+' || text[0] == '-') ? 1 : 0;
            if (text.size() > sign + 1 && text[sign] == '0') {
              const std::size_t first = text.find_first_not_of('0', sign);
              // A bare refusal: describeParseError() words every refused integer text from the
              // option's type, "--count: '0x10' is not an integer" (test_tvd_cli.py
              // test_integers_are_read_in_decimal), so no message written here is shown.
              if (first != std::string::npos &&
                  !std::isdigit(static_cast<unsigned char>(text[first])))
                return std::string("base prefix");
              text.erase(sign, (first == std::string::npos ? text.size() : first) - sign);
              if (text.size() == sign)
                text += '0';
            }
            return std::string();
          },
          ""));  // no text of its own in --help: the option's type says it
    if (type == "FLOAT" || type == "INT" || type == "UINT")  // no check of its own
      option->check(CLI::Validator(
          [](std::string& text) {
            return text.empty() ? std::string("'' is not a number") : std::string();
          },
          ""));
  }
}

/// Empty when a file can be created in `dir`, else why not. access(W_OK) is not enough: it says
/// yes to root on /sys or /proc, where creating a file fails, and the run would then lose its
/// results at the end. So a file is made and removed (mkstemp: never one that exists).
inline std::string cannotCreateIn(const std::filesystem::path& dir) {
  std::string name = (dir / ".tvd_write_probe.XXXXXX").string();
  const int fd = ::mkstemp(name.data());  // a fresh name: never a file that exists
  if (fd < 0)
    return std::string("a file cannot be created in the directory ") + dir.string() + ": " +
           std::strerror(errno);
  ::close(fd);
  ::unlink(name.c_str());
  return std::string();
}

/// An output file, checked before any work: one of `extensions` (".csv", any case) and in a
/// directory that exists and is writable.
inline CLI::Validator outputFile(const std::vector<std::string>& extensions) {
  return CLI::Validator(
      [extensions](std::string& text) -> std::string {
        const std::filesystem::path path(text);
        const std::string ext = io::lowerExtension(text);
        std::string allowed;
        for (const std::string& e : extensions)
          allowed += (allowed.empty() ? "" : " or ") + e;
        if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end())
          return "'" + text + "' must end in " + allowed;
        const std::filesystem::path dir =
            path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
        std::error_code ec;
        if (std::filesystem::is_directory(path, ec))
          return "'" + text + "' is a directory";
        if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
          return "'" + text + "': " + dir.string() + " is not a directory";
        if (!std::filesystem::is_directory(dir, ec))
          return "'" + text + "': the directory " + dir.string() + " does not exist";
        if (::access(dir.c_str(), W_OK) != 0)
          return "'" + text + "': the directory " + dir.string() + " is not writable";
        if (const std::string why = cannotCreateIn(dir); !why.empty())
          return "'" + text + "': " + why;
        return std::string();
      },
      "FILE");
}

/// Refuses, before any work, an output file that is one of the command's input files (the same
/// file however spelt: std::filesystem::equivalent), which writing it would destroy. `inputs`:
/// (option, path) pairs; empty paths and names of no file (built-in tracks) pass. `command`
/// prefixes the message (a tvd subcommand; empty for a program of one command).
inline void refuseOutputOverInput(const std::string& command, const std::string& out_option,
                                  const std::string& out,
                                  const std::vector<std::pair<std::string, std::string>>& inputs) {
  if (out.empty())
    return;
  for (const auto& [option, path] : inputs) {
    std::error_code ec;
    if (!path.empty() && std::filesystem::equivalent(out, path, ec) && !ec)
      throw InputError((command.empty() ? "" : command + ": ") + out_option + " " + out +
                       " is the " + option +
                       " file: writing it would destroy the input; write elsewhere");
  }
}

/// Whether two output paths name one file however spelt ("r.mat" and "/abs/dir/r.mat", or
/// through a link to the directory): the same once made absolute and normal with the links of
/// their existing parts resolved (std::filesystem::weakly_canonical), or, when both exist, one
/// file (std::filesystem::equivalent: hard links too). Two outputs staged under one name would
/// both be renamed onto it, the second replacing the first.
inline bool sameOutputFile(const std::string& a, const std::string& b) {
  namespace fs = std::filesystem;
  std::error_code ea, eb, ee;
  const fs::path ca = fs::weakly_canonical(a, ea), cb = fs::weakly_canonical(b, eb);
  if (!ea && !eb && ca == cb)
    return true;
  return fs::equivalent(a, b, ee) && !ee;
}

/// An output directory, checked before any work: an existing writable directory, or one that can
/// be created (its nearest existing ancestor is a writable directory).
inline CLI::Validator outputDirectory() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        namespace fs = std::filesystem;
        std::error_code ec;
        if (text.empty())
          return "must name a directory, got ''";
        fs::path dir(text);
        if (fs::is_symlink(fs::symlink_status(dir, ec)) && !fs::exists(dir, ec))
          return "'" + text + "' is a link to nothing";
        if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
          return "'" + text + "' exists and is not a directory";
        fs::path existing = dir;
        while (!existing.empty() && !fs::exists(existing, ec))
          existing = existing.parent_path();
        if (existing.empty())
          existing = ".";
        if (!fs::is_directory(existing, ec))
          return "'" + text + "': " + existing.string() + " is not a directory";
        if (::access(existing.c_str(), W_OK) != 0)
          return "'" + text + "': the directory " + existing.string() + " is not writable";
        if (const std::string why = cannotCreateIn(existing); !why.empty())
          return "'" + text + "': " + why;
        return std::string();
      },
      "DIR");
}

/// --vehicle FILE, required and existing: the vehicle description every vehicle command reads.
inline CLI::Option* addVehicleOption(CLI::App* cmd, std::string* file,
                                     const std::string& help = "vehicle description") {
  return cmd->add_option("--vehicle", *file, help)->required()->check(CLI::ExistingFile);
}

/// --variant untracked | tracked (vehicle::variantName's names), with `help`.
inline CLI::Option* addVariantOption(CLI::App* cmd, std::string* variant, const std::string& help) {
  return cmd->add_option("--variant", *variant, help)
      ->check(CLI::IsMember({vehicle::variantName(vehicle::Variant::Untracked),
                             vehicle::variantName(vehicle::Variant::Tracked)}));
}

void registerModesCommand(CLI::App& app);
void registerMacCommand(CLI::App& app);
void registerReduceCommand(CLI::App& app);
void registerSimulateCommand(CLI::App& app);
void registerRideCommand(CLI::App& app);
void registerFrfCommand(CLI::App& app);
void registerTerrainCommand(CLI::App& app);
void registerStaticsCommand(CLI::App& app);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
