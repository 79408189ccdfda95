// tvd: the offline command-line tool (modes, statics, MAC, reduction, FRF, simulation, ride limits,
// terrain).
#include <CLI/CLI.hpp>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "command_line_errors.h"
#include "commands.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/heap_reuse.h"
#include "tracked_vehicle_dynamics/io/staged_files.h"
#include "tracked_vehicle_dynamics/reduction/reduced_model.h"

namespace {

int run(int argc, char** argv) {
  namespace tvd = tracked_vehicle_dynamics;
  // Large matrices reuse the pages of freed ones instead of faulting in fresh mappings
  // (heap_reuse.h): a tracked reduction in 0.73 s instead of 2.8 s on a virtual machine.
  const tvd::HeapReuse heap_reuse;
  // Ctrl-C, SIGTERM or SIGHUP during a write leaves no staged file beside the output, and a file
  // size limit fails the write instead of killing tvd (staged_files.h).
  tvd::io::removeStagedFilesOnSignals();
  CLI::App app{"tvd: tracked vehicle vertical dynamics from a reduced finite-element model"};
  app.set_version_flag("--version", std::string(tvd::reduction::softwareVersion()));
  app.require_subcommand(1);
  // Every option's help shows its default value ("[30]"): the subcommands inherit this.
  app.option_defaults()->always_capture_default();
  tvd::tools::registerModesCommand(app);
  tvd::tools::registerStaticsCommand(app);
  tvd::tools::registerMacCommand(app);
  tvd::tools::registerReduceCommand(app);
  tvd::tools::registerFrfCommand(app);
  tvd::tools::registerSimulateCommand(app);
  tvd::tools::registerRideCommand(app);
  tvd::tools::registerTerrainCommand(app);
  for (CLI::App* command : app.get_subcommands({}))
    tvd::tools::checkNumberTexts(command->get_options());
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help/--version exit 0; every other command-line error is bad input: status 2, reported
    // on one line like every other error (CLI11's own report adds "Run with --help ...").
    const std::vector<std::string> args(argv + 1, argv + argc);
    // CLI11 answers --help (or --version) before it meets a command it does not know, so
    // "tvd chek --help" printed the program's help and passed; it is refused as "tvd chek" is.
    const bool unknown_command =
        app.get_subcommands().empty() && !args.empty() && !args[0].empty() && args[0][0] != '-';
    if (e.get_exit_code() == 0 && !unknown_command)
      return app.exit(e);
    std::string message =
        e.get_exit_code() == 0
            ? tvd::tools::describeParseError(app, CLI::RequiredError("SUBCOMMAND"), args, "tvd")
            : tvd::tools::describeParseError(app, e, args, "tvd");
    for (char& c : message)
      if (c == '\n')
        c = ' ';
    std::cerr << "tvd: error: " << message << "\n";
    return 2;
  } catch (const tvd::InputError& e) {
    std::cerr << "tvd: error: " << e.what() << "\n";
    return 2;
  } catch (const tvd::SolverError& e) {
    std::cerr << "tvd: solver error: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "tvd: error: " << e.what() << "\n";
    return 1;
  }
  // The results printed (text or --json) are the run's output as much as its files: a full disk
  // or a closed pipe must not pass for success.
  errno = 0;
  std::cout.flush();
  if (!std::cout) {
    const int error = errno;
    std::cerr << "tvd: error: cannot write standard output"
              << (error != 0 ? std::string(": ") + std::strerror(error)
                             : std::string(" (a full disk, or a closed pipe?)"))
              << "\n";
    return 2;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return tracked_vehicle_dynamics::tools::runReportingErrors("tvd", run, argc, argv);
}
