// `tvd modes`: modal analysis of a generic FE model file or of a vehicle description.
#include <Eigen/SparseCholesky>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>

#include "commands.h"
#include "mass_breakdown_report.h"
#include "node_shapes.h"
#include "output_files.h"
#include "system_matrices_file.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/eigenvalue_count.h"
#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/static_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/io/json_writer.h"
#include "tracked_vehicle_dynamics/io/model_yaml.h"
#include "tracked_vehicle_dynamics/vehicle/track_tension.h"
#include "tracked_vehicle_dynamics/vehicle/wheel_rate_estimate.h"
#include "vehicle_analysis.h"
#include "warning_list.h"
#include "wheel_rate_report.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {

// The most modes tvd modes returns (one variant's; the MAC and the reduction solve at most 200).
constexpr int kMaxModesCount = 500;

struct ModesOptions {
  std::string model_file;
  std::string vehicle_file;
  std::string variant = "untracked";
  int count = 20;
  bool count_given = false;  // --count on the command line (with --max-frequency: a cap)
  double max_frequency_hz = 0.0;
  bool json = false;
  std::string out_dir;
  bool matrices = false;  // also DIR/matrices.mat
};

// classes: a vehicle's (one per mode), with the kinetic-energy shares that name each type;
// empty for a generic model.
void printTable(const std::string& name, DofIndex dofs, double mass, const fem::ModalBasis& basis,
                double build_seconds, const std::vector<vehicle::ModeClass>& classes) {
  const bool typed = !classes.empty();
  std::cout << "model: " << name << "\n"
            << "active DOFs: " << dofs << "   mass: " << std::fixed << std::setprecision(1) << mass
            << " kg   modes: " << basis.count() << "   assembly: " << std::setprecision(3)
            << build_seconds << " s   solve: " << basis.seconds << " s\n\n"
            << "  mode   frequency [Hz]"
            << (typed ? "   hull [%]  wheels [%]  track [%]   type" : "") << "\n";
  for (int i = 0; i < basis.count(); ++i) {
    std::cout << std::setw(6) << i + 1 << std::setw(17) << std::setprecision(4)
              << basis.frequencies_hz(i);
    if (typed) {
      const vehicle::ModeClass& c = classes[static_cast<std::size_t>(i)];
      std::cout << std::setprecision(1) << std::setw(11) << 100.0 * c.hull_share << std::setw(12)
                << 100.0 * c.wheel_share << std::setw(11) << 100.0 * c.track_share << "   "
                << c.label;
    }
    std::cout << "\n";
  }
}

/// Refuses a mass matrix that is not positive definite on the free DOFs, naming a DOF: a free
/// DOF without mass (diag M = 0), or a coupled massless motion (a point mass on an offset with no
/// rotary inertia: diag M > 0 everywhere, yet M singular). Either would give infinite
/// frequencies and NaN shapes.
void requirePositiveMass(const fem::System& sys, const std::string& file) {
  const Vector diagonal = sys.mass.diagonal();
  for (DofIndex i = 0; i < sys.size(); ++i)
    if (!(diagonal(i) > 0.0))
      throw InputError(file + ": " + sys.dofs.label(i) +
                       " is free but has no mass or inertia; add a mass or fix the DOF");
  // LDL^T of P M P^T: a pivot that vanishes against the largest diagonal marks the motion.
  Eigen::SimplicialLDLT<SparseMatrix> ldlt(sys.mass);
  const Vector pivots = ldlt.info() == Eigen::Success ? Vector(ldlt.vectorD()) : Vector();
  const double scale = diagonal.cwiseAbs().maxCoeff();
  Eigen::Index worst = -1;
  if (pivots.size() == sys.size() && pivots.minCoeff(&worst) > 1e-12 * scale)
    return;
  // Position k of the permuted matrix holds the DOF i with indices(i) == k.
  const auto& indices = ldlt.permutationP().indices();
  DofIndex dof = 0;
  for (DofIndex i = 0; i < sys.size(); ++i)
    if (worst >= 0 && indices(i) == worst)
      dof = i;
  throw InputError(file + ": the mass matrix is singular: a free motion through " +
                   sys.dofs.label(dof) +
                   " has no mass or inertia (e.g. a point mass on an offset without rotary "
                   "inertia); add inertia or fix the DOF");
}

/// Static deflection under the model's gravity: the largest translation and where.
struct GravitySag {
  bool solved = false;
  std::string note;  // why not, when not solved
  double max_translation = 0.0;
  std::string at;
};

GravitySag gravitySag(const fem::System& sys) {
  GravitySag sag;
  if (sys.gravity_load.size() == 0 || sys.gravity_load.isZero(0.0)) {
    sag.note = "no gravity load";
    return sag;
  }
  try {
    const fem::StaticResult r = fem::solveStatic(sys, sys.gravity_load);
    for (DofIndex i = 0; i < sys.size(); ++i) {
      if (sys.dofs.dofOf(i).direction >= 3 || std::abs(r.displacement(i)) <= sag.max_translation)
        continue;
      sag.max_translation = std::abs(r.displacement(i));
      sag.at = sys.dofs.label(i);
      sag.solved = true;
    }
    if (!sag.solved)
      sag.note = "no translation";
  } catch (const SolverError& e) {  // a free-floating model has modes but no statics
    sag.note = e.what();
  }
  return sag;
}

// With --max-frequency F: the modes below F that the count left out ("" when none). A count
// that stopped below F may have cut some: Sylvester's law counts them (eigenvalue_count.h).
std::string modesBeyondCountWarning(const fem::System& sys, const fem::ModalBasis& basis,
                                    const fem::ModalRequest& request) {
  const Eigen::Index found = basis.frequencies_hz.size();
  if (request.max_frequency_hz <= 0.0 || found < request.count ||
      basis.frequencies_hz(found - 1) >= request.max_frequency_hz)
    return "";
  int below = 0;
  try {
    below = fem::eigenvaluesBelow(sys.stiffness, sys.mass,
                                  std::pow(kTwoPi * request.max_frequency_hz, 2));
  } catch (const SolverError&) {
    return "";  // F is an eigenvalue to working precision: no count, no claim
  }
  if (below <= found)
    return "";
  return std::to_string(below) + " modes lie below " + brief(request.max_frequency_hz) +
         " Hz: the lowest " + std::to_string(found) + " are returned (--count " +
         std::to_string(request.count) +
         (request.count < kMaxModesCount
              ? "; raise it, at most " + std::to_string(kMaxModesCount) + ")"
              : ", the most tvd modes returns)");
}

std::string matricesFile(const ModesOptions& opt) {
  return (std::filesystem::path(opt.out_dir) / "matrices.mat").string();
}

void runModel(const ModesOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  const fem::Model model = io::loadModelYaml(opt.model_file);
  const fem::System sys = fem::assemble(model);
  if (sys.size() == 0)
    throw InputError(opt.model_file +
                     ": no free DOF (every DOF is fixed, or nothing is attached "
                     "to the nodes)");
  requirePositiveMass(sys, opt.model_file);
  const double build_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  fem::ModalRequest request;
  // "Every mode below F": up to --count when it is given, else up to the largest count (a
  // default of 20 cut a 100 kHz request at 20 modes without a word, review 137).
  request.count = opt.max_frequency_hz > 0.0 && !opt.count_given ? kMaxModesCount : opt.count;
  request.max_frequency_hz = opt.max_frequency_hz;
  const fem::ModalBasis basis = fem::solveModes(sys.stiffness, sys.mass, request);
  std::vector<std::string> warnings;
  warn(&warnings, fem::missedModesWarning(basis));
  warn(&warnings, fem::unstableModesWarning(basis));
  warn(&warnings, modesBeyondCountWarning(sys, basis, request));
  const GravitySag sag = gravitySag(sys);
  if (!opt.out_dir.empty()) {
    OutputFileSet written;
    const Metadata metadata = {{"model", model.name}, {"model_file", opt.model_file}};
    writeModeFiles(opt.out_dir, sys, basis, {}, metadata, written);
    if (opt.matrices)
      written.write(matricesFile(opt), [&](const std::string& path) {
        writeSystemMatrices(path, model, sys, nullptr, metadata);
      });
    written.commit();
  }
  if (opt.json) {
    io::JsonWriter json(std::cout);
    json.beginObject()
        .field("model", model.name)
        .field("file", opt.model_file)
        .field("active_dofs", static_cast<long long>(sys.size()))
        .field("mass_kg", model.totalMass())
        .field("frequencies_hz", basis.frequencies_hz)
        .field("eigenvalues", basis.eigenvalues)
        .field("assemble_seconds", build_seconds)
        .field("solve_seconds", basis.seconds);
    json.key("static").beginObject().field("solved", sag.solved);
    if (sag.solved)
      json.field("max_translation_m", sag.max_translation).field("at", sag.at);
    else
      json.field("note", sag.note);
    json.endObject().field("warnings", warnings).endObject();
  } else {
    printTable(model.name.empty() ? opt.model_file : model.name, sys.size(), model.totalMass(),
               basis, build_seconds, {});
    if (sag.solved)
      std::cout << "\nstatic deflection under gravity: largest translation " << std::setprecision(6)
                << sag.max_translation * 1000.0 << " mm at " << sag.at << "\n";
    else
      std::cout << "\nstatic deflection under gravity: not computed (" << sag.note << ")\n";
  }
}

void runVehicle(const ModesOptions& opt) {
  std::vector<std::string> warnings;
  const vehicle::VehicleDescription description = loadVehicle(opt.vehicle_file, &warnings);
  const vehicle::Variant variant = vehicle::parseVariant(opt.variant);
  const VehicleAnalysis a = analyseVehicle(description, variant, opt.count);
  warnings.insert(warnings.end(), a.warnings.begin(), a.warnings.end());
  std::vector<std::string> types;
  for (const auto& c : a.classes)
    types.push_back(c.label);
  if (!opt.out_dir.empty()) {
    OutputFileSet written;
    const Metadata metadata = {{"vehicle", description.name},
                               {"vehicle_file", opt.vehicle_file},
                               {"variant", vehicle::variantName(variant)}};
    writeModeFiles(opt.out_dir, a.system, a.modes, a.classes, metadata, written);
    if (opt.matrices) {
      const VehicleMatrixExtras extras{
          vehicle::roadInputStations(a.vehicle.layout, a.system.ground_inputs),
          description.damping};
      written.write(matricesFile(opt), [&](const std::string& path) {
        writeSystemMatrices(path, a.vehicle.model, a.system, &extras, metadata);
      });
    }
    const std::string node_shapes =
        (std::filesystem::path(opt.out_dir) / "node_shapes.csv").string();
    written.write(node_shapes, [&](const std::string& path) {
      writeNodeShapes(path, a.vehicle, a.system, a.modes);
    });
    written.commit();
  }
  const vehicle::MassBreakdown& m = a.vehicle.layout.mass;
  if (opt.json) {
    io::JsonWriter json(std::cout);
    json.beginObject()
        .field("vehicle", description.name)
        .field("vehicle_file", opt.vehicle_file)
        .field("variant", vehicle::variantName(variant))
        .field("active_dofs", static_cast<long long>(a.system.size()))
        .field("mass_kg", a.vehicle.model.totalMass())
        .field("track_tension_n", vehicle::modelTrackTension(description, variant));
    writeMassBreakdown(json, m);
    json.field("frequencies_hz", a.modes.frequencies_hz).field("mode_types", types);
    // What names each type: the shares of each mode's kinetic energy (mode_classification.h).
    json.key("energy_shares").beginObject();
    for (std::size_t k = 0; k < kEnergyShareNames.size(); ++k) {
      std::vector<double> column;
      for (const auto& c : a.classes)
        column.push_back(energyShares(c)[k]);
      json.field(kEnergyShareNames[k], column);
    }
    json.endObject()
        .field("build_seconds", a.build_seconds)
        .field("solve_seconds", a.modes.seconds)
        .key("static")
        .beginObject()
        .field("hull_sag_m", a.statics.hull_sag)
        .field("hull_pitch_deg", a.statics.hull_pitch * kRadToDegree)
        .field("hull_roll_deg", a.statics.hull_roll * kRadToDegree)
        .field("weight_n", a.statics.weight)
        .field("ground_reaction_sum_n", a.statics.ground_reaction)
        .field("relative_balance_error", a.statics.balanceError())
        .field("road_wheel_loads_n", a.statics.wheel_loads)
        .endObject();
    writeWheelRateEstimate(json, vehicle::wheelRateEstimate(description, variant));
    json.field("warnings", warnings).endObject();
    return;
  }
  printTable(description.name + " (" + vehicle::variantName(variant) + ")", a.system.size(),
             a.vehicle.model.totalMass(), a.modes, a.build_seconds, a.classes);
  std::cout << massBreakdownText(m) << "\n";
  if (const std::string tension = vehicle::trackTensionText(description, variant); !tension.empty())
    std::cout << tension << "\n";
  // The bonded model's (every contact pulls as well as pushes): the state the dynamics start
  // from; tvd statics' default lets the contacts only push, which can differ much (a light chain).
  std::cout << "\nstatic equilibrium under gravity (the linear model's, every contact bonded; "
               "tvd statics: contacts that only push): hull sag "
            << std::setprecision(4) << -a.statics.hull_sag * 1000.0 << " mm (z "
            << a.statics.hull_sag * 1000.0 << " mm), pitch " << a.statics.hull_pitch * kRadToDegree
            << " deg; ground reactions " << std::setprecision(1) << a.statics.ground_reaction
            << " N = weight " << a.statics.weight << " N\n"
            << wheelRateEstimateText(vehicle::wheelRateEstimate(description, variant)) << "\n";
}

}  // namespace

void registerModesCommand(CLI::App& app) {
  auto opt = std::make_shared<ModesOptions>();
  CLI::App* cmd = app.add_subcommand(
      "modes", "Modal analysis: natural frequencies, mode shapes (and mode types of a vehicle)");
  auto* model =
      cmd->add_option("--model", opt->model_file, "generic FE model file (YAML, doc/model_file.md)")
          ->check(CLI::ExistingFile);
  auto* vehicle = cmd->add_option("--vehicle", opt->vehicle_file,
                                  "vehicle description (e.g. config/vehicles/paper_vehicle.yaml)")
                      ->check(CLI::ExistingFile);
  model->excludes(vehicle);
  CLI::Option* variant =
      addVariantOption(cmd, &opt->variant, "vehicle variant: untracked | tracked");
  // At most 500: one variant's modes (the MAC and the reduction solve both: at most 200).
  CLI::Option* count = cmd->add_option("--count,-n", opt->count, "number of modes (1 .. 500)")
                           ->check(CLI::Range(1, kMaxModesCount));
  CLI::Option* max_frequency =
      cmd->add_option("--max-frequency", opt->max_frequency_hz,
                      "return every mode below this frequency [Hz] (> 0; --model only): at most "
                      "--count when it is given, else at most 500, and a warning when more lie "
                      "below")
          ->check(positiveNumber())
          ->default_str("none: --count modes");
  max_frequency->needs(model);
  variant->needs(vehicle);
  cmd->add_flag("--json", opt->json, "print a JSON document instead of the table");
  cmd->add_option(
         "--out", opt->out_dir,
         "write modes.csv, shapes.csv and modes.mat to this directory (created if missing; a "
         "vehicle's also node_shapes.csv)")
      ->check(outputDirectory());
  cmd->add_flag("--matrices", opt->matrices,
                "with --out: also DIR/matrices.mat, the assembled model (sparse M, K, C, K_u, C_u, "
                "gravity and travel loads, DOF and node tables; README)")
      ->needs("--out");
  cmd->callback([opt, model, vehicle, count]() {
    if (model->count() == 0 && vehicle->count() == 0)
      throw InputError("modes: give --model FILE or --vehicle FILE");
    // The files the directory receives: none of them may be the input.
    if (!opt->out_dir.empty())
      for (const char* name :
           {"modes.csv", "shapes.csv", "modes.mat", "node_shapes.csv", "matrices.mat"})
        refuseOutputOverInput("modes", "--out",
                              (std::filesystem::path(opt->out_dir) / name).string(),
                              {{"--model", opt->model_file}, {"--vehicle", opt->vehicle_file}});
    opt->count_given = count->count() > 0;
    if (vehicle->count())
      runVehicle(*opt);
    else
      runModel(*opt);
  });
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
