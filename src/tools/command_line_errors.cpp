#include "command_line_errors.h"

#include <algorithm>
#include <cstdlib>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/number_text.h"

namespace tracked_vehicle_dynamics {
namespace tools {
namespace {

/// Whether `token` reads as a number ("-5", "-1e3"): a value, not an option.
bool isNumber(const std::string& token) {
  char* end = nullptr;
  io::strtodC(token.c_str(), &end);
  return !token.empty() && end == token.c_str() + token.size();
}

/// What an option's type asks for, in words.
std::string wanted(const CLI::Option* option) {
  if (option == nullptr)
    return "a value";
  const std::string type = option->get_type_name();
  if (type.rfind("FLOAT", 0) == 0)
    return "a number";
  if (type.rfind("INT", 0) == 0)
    return "an integer";
  if (type.rfind("UINT", 0) == 0)
    return "a non-negative integer";
  return "a value";
}

/// Whether an option takes an integer (CLI11's INT or UINT type).
bool takesInteger(const CLI::Option* option) {
  const std::string type = option->get_type_name();
  return type.rfind("INT", 0) == 0 || type.rfind("UINT", 0) == 0;
}

/// The text of `message` before the first ':' (CLI11 puts the option's name there).
std::string leadingName(const std::string& message) {
  const std::size_t colon = message.find(':');
  return colon == std::string::npos ? std::string() : message.substr(0, colon);
}

/// The nearest long option of `command` to `name` ("--trak" -> "--track"), or empty.
std::string nearestOption(const CLI::App& command, const std::string& name) {
  std::string best;
  std::size_t best_distance = 3;  // within two edits
  // "---" or the "-" of "-=3" is dashes only: nothing typed to compare (substr(npos) threw).
  const std::size_t start = name.find_first_not_of('-');
  if (start == std::string::npos)
    return {};
  const std::string typed = name.substr(start);
  for (const CLI::Option* option : command.get_options()) {
    for (const std::string& lname : option->get_lnames()) {
      const std::size_t d = lname.rfind(typed, 0) == 0 ? 1 : editDistance(typed, lname);
      if (d < best_distance) {
        best_distance = d;
        best = "--" + lname;
      }
    }
  }
  return best;
}

std::string describe(const CLI::App& app, const CLI::ParseError& error,
                     const std::vector<std::string>& args, const std::string& program) {
  std::string message = error.what();
  const std::vector<CLI::App*> parsed = app.get_subcommands();
  const bool has_subcommands = !app.get_subcommands({}).empty();
  if (has_subcommands && parsed.empty()) {
    if (!dynamic_cast<const CLI::RequiredError*>(&error))
      return message;
    std::string known;  // the registered subcommands, in registration order
    for (const CLI::App* sub : app.get_subcommands({}))
      known += (known.empty() ? "" : ", ") + sub->get_name();
    if (!args.empty() && args[0][0] != '-')
      return "unknown subcommand '" + args[0] + "' (one of: " + known + ")";
    return (args.empty() ? std::string() : "unknown option " + args[0] + ": ") +
           "a subcommand is required (one of: " + known + "; " + program + " --help lists them)";
  }
  // The command whose options were given: the subcommand, or the program itself.
  const CLI::App& command = has_subcommands ? *parsed.front() : app;
  const std::string prefix = has_subcommands ? command.get_name() + ": " : std::string();
  const std::string see = " (" + program + (has_subcommands ? " " + command.get_name() : "") +
                          " --help lists the options)";
  // An unknown option first: whatever else CLI11 found follows from it.
  bool after_command = !has_subcommands;
  for (const std::string& token : args) {
    if (!after_command) {
      after_command = token == command.get_name();
      continue;
    }
    if (token == "--")
      break;
    if (token.size() < 2 || token[0] != '-' || isNumber(token))
      continue;
    const std::string name = token.substr(0, token.find('='));
    if (command.get_option_no_throw(name) != nullptr || app.get_option_no_throw(name) != nullptr)
      continue;
    const std::string nearest = nearestOption(command, name);
    return prefix + "unknown option " + name +
           (nearest.empty() ? see : " (did you mean " + nearest + "?)");
  }
  const std::string name = leadingName(message);
  const CLI::Option* option = name.empty() ? nullptr : command.get_option_no_throw(name);
  if (dynamic_cast<const CLI::ConversionError*>(&error)) {
    // "Could not convert: --speed-kmh = abc"
    const std::string marker = "Could not convert: ";
    const std::size_t equals = message.find(" = ");
    if (message.rfind(marker, 0) == 0 && equals != std::string::npos) {
      const std::string option_name = message.substr(marker.size(), equals - marker.size());
      return prefix + option_name + ": '" + message.substr(equals + 3) + "' is not " +
             wanted(command.get_option_no_throw(option_name));
    }
  } else if (dynamic_cast<const CLI::ArgumentMismatch*>(&error) && option != nullptr) {
    if (message.find("At Most") != std::string::npos) {
      const std::size_t received = message.rfind(' ');
      return prefix + name + " is given " + message.substr(received + 1) + " times: give it once";
    }
    if (message.find("missing") != std::string::npos)
      return prefix + name + " needs " + wanted(option) + " after it";
  } else if (dynamic_cast<const CLI::ValidationError*>(&error) && option != nullptr &&
             takesInteger(option)) {
    // A range check on an integer option runs on the text: "1.5" reads "not in range 1 to 500";
    // checkNumberTexts() refuses a base prefix ("0x10") with a bare refusal worded here.
    for (std::size_t i = 0; i < args.size(); ++i) {
      std::string value;
      if (args[i] == name && i + 1 < args.size())
        value = args[i + 1];
      else if (args[i].rfind(name + "=", 0) == 0)
        value = args[i].substr(name.size() + 1);
      else
        continue;
      char* end = nullptr;
      std::strtoll(value.c_str(), &end, 10);
      if (value.empty() || end != value.c_str() + value.size())
        return prefix + name + ": '" + value + "' is not " + wanted(option);
    }
  } else if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
    // Only stray values are left (unknown options were named above). CLI11's message lists them
    // in reverse order, joined by spaces; remaining() has them as given, each whole.
    const std::vector<std::string> strays = command.remaining();
    std::string listed;
    for (const std::string& stray : strays)
      listed += (listed.empty() ? " '" : ", '") + stray + "'";
    if (listed.empty()) {
      const std::string marker = "not expected: ";
      const std::size_t at = message.find(marker);
      if (at != std::string::npos)
        listed = " '" + message.substr(at + marker.size()) + "'";
    }
    return prefix + (strays.size() > 1 ? "unexpected arguments" : "unexpected argument") + listed +
           ": every value follows its option (a value with spaces is quoted)";
  }
  return prefix + message;
}

}  // namespace

std::string describeParseError(const CLI::App& app, const CLI::ParseError& error,
                               const std::vector<std::string>& args, const std::string& program) {
  // Called from the programs' catch handlers, where an exception would end in std::terminate:
  // the plain CLI11 message rather than an abort, whatever the rewording trips over.
  try {
    return describe(app, error, args, program);
  } catch (const std::exception&) {
    return error.what();
  }
}

int runReportingErrors(const char* program, int (*run)(int, char**), int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << program << ": internal error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
