// `tvd modes`: modal analysis of a generic FE model file (or of a vehicle, see --vehicle).
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>

#include "commands.h"
#include "output_files.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/io/json_writer.h"
#include "tracked_vehicle_dynamics/io/model_yaml.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {

struct ModesOptions {
  std::string model_file;
  int count = 20;
  double max_frequency_hz = 0.0;
  bool json = false;
  std::string out_dir;
};

void printTable(const std::string& name, const fem::System& sys, const fem::ModalBasis& basis,
                double assemble_seconds) {
  std::cout << "model: " << name << "\n"
            << "active DOFs: " << sys.size() << "   modes: " << basis.count()
            << "   assembly: " << std::fixed << std::setprecision(3) << assemble_seconds
            << " s   solve: " << basis.seconds << " s\n\n"
            << "  mode   frequency [Hz]\n";
  for (int i = 0; i < basis.count(); ++i)
    std::cout << std::setw(6) << i + 1 << std::setw(17) << std::setprecision(4)
              << basis.frequencies_hz(i) << "\n";
}

void run(const ModesOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  const fem::Model model = io::loadModelYaml(opt.model_file);
  const fem::System sys = fem::assemble(model);
  const double assemble_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  fem::ModalRequest request;
  request.count = opt.count;
  request.max_frequency_hz = opt.max_frequency_hz;
  const fem::ModalBasis basis = fem::solveModes(sys.stiffness, sys.mass, request);

  if (!opt.out_dir.empty()) writeModeFiles(opt.out_dir, sys, basis);
  if (opt.json) {
    io::JsonWriter json(std::cout);
    json.beginObject()
        .field("model", model.name)
        .field("file", opt.model_file)
        .field("active_dofs", static_cast<long long>(sys.size()))
        .field("mass_kg", model.totalMass())
        .field("frequencies_hz", basis.frequencies_hz)
        .field("eigenvalues", basis.eigenvalues)
        .field("assemble_seconds", assemble_seconds)
        .field("solve_seconds", basis.seconds)
        .field("lanczos_iterations", basis.iterations);
    if (!opt.out_dir.empty()) json.field("out_dir", opt.out_dir);
    json.endObject();
  } else {
    printTable(model.name.empty() ? opt.model_file : model.name, sys, basis, assemble_seconds);
    if (!opt.out_dir.empty()) std::cout << "\nwrote modes.csv, shapes.csv, modes.mat to " << opt.out_dir << "\n";
  }
}

}  // namespace

void registerModesCommand(CLI::App& app) {
  auto opt = std::make_shared<ModesOptions>();
  CLI::App* cmd = app.add_subcommand("modes", "Modal analysis: lowest natural frequencies and mode shapes");
  cmd->add_option("--model", opt->model_file, "FE model file (YAML, see doc/model_file.md)")
      ->required()
      ->check(CLI::ExistingFile);
  cmd->add_option("--count,-n", opt->count, "number of modes")->check(CLI::Range(1, 100000));
  cmd->add_option("--max-frequency", opt->max_frequency_hz,
                  "return every mode below this frequency [Hz] (at most --count)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--json", opt->json, "print a JSON document instead of the table");
  cmd->add_option("--out", opt->out_dir, "write modes.csv, shapes.csv and modes.mat to this directory");
  cmd->callback([opt]() { run(*opt); });
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
