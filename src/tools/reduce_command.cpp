// `tvd reduce`: the Craig-Bampton reduced model of a vehicle (paper §3, Table 5), saved as .mat.
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <utility>

#include "commands.h"
#include "output_files.h"
#include "reduction_options.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/json_writer.h"
#include "tracked_vehicle_dynamics/io/mat_file.h"
#include "tracked_vehicle_dynamics/reduction/global_modes.h"
#include "tracked_vehicle_dynamics/reduction/reduced_model_file.h"
#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "tracked_vehicle_dynamics/vehicle/track_tension.h"
#include "vehicle_analysis.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {

struct ReduceOptions {
  std::string vehicle_file;
  std::string variant = "tracked";
  ReductionFlags reduction_flags;
  bool json = false;
  std::string out_file;
  std::string basis_file;  // --basis: T_CMS and the full model's DOF table
};

// basis.mat: x = T x_R (paper eq. 8) over the full model's active DOFs, rows named as
// `tvd modes --matrices` names them (the same assembly), columns as the reduced model's.
void writeBasis(const std::string& path, const reduction::ReductionBasis& basis,
                const reduction::ReducedModel& model, const Metadata& metadata) {
  io::MatWriter mat(path);
  mat.writeMatrix("T", basis.transformation);
  writeDofTable(mat, basis.dofs);
  mat.writeStrings("reduced_dof_labels", model.dof_labels);
  mat.writeString("description_hash", model.description_hash);
  mat.writeString("reduction", model.reduction);
  mat.writeString("version", model.version);
  writeMetadata(mat, metadata);
  mat.close();
}

void run(const ReduceOptions& opt) {
  const reduction::VehicleReductionOptions options = opt.reduction_flags.options("reduce");
  const vehicle::VehicleDescription description = loadVehicle(opt.vehicle_file);
  const vehicle::Variant variant = vehicle::parseVariant(opt.variant);
  reduction::VehicleReductionReport report;
  reduction::ReductionBasis basis;
  reduction::ReducedModel model = reduction::reduceVehicle(
      description, variant, options, &report, opt.basis_file.empty() ? nullptr : &basis);
  model.creator = "tvd reduce";
  // Both files or neither: staged, then moved into place together.
  OutputFileSet written;
  if (!opt.out_file.empty())
    written.write(opt.out_file,
                  [&](const std::string& path) { reduction::saveReducedModel(model, path); });
  if (!opt.basis_file.empty()) {
    const Metadata metadata = {{"vehicle", description.name},
                               {"vehicle_file", opt.vehicle_file},
                               {"variant", vehicle::variantName(variant)}};
    written.write(opt.basis_file,
                  [&](const std::string& path) { writeBasis(path, basis, model, metadata); });
    basis = {};  // 50 MB on the tracked vehicle: not kept through the report
  }
  written.commit();
  // On stderr as every command's (the text and JSON outputs carry them too).
  for (const std::string& w : report.warnings)
    std::cerr << "tvd: warning: " << w << "\n";

  // CMS error of each full-model mode in the band, pairing the i-th modes (the reduced model is a
  // Rayleigh-Ritz approximation: its i-th frequency approaches the full one from above), and the
  // worst (above 0.1 Hz): the reduction's own, those its band check judged.
  const std::vector<double>& errors = report.relative_frequency_errors;
  const std::size_t pairs = errors.size();
  const double worst = report.max_relative_frequency_error;

  // The MoGeSeC picks (paper Fig. 12): the masters after the imposed ones, in pick order.
  struct MogesecMaster {
    int pick = 0;
    std::string dof, part;
    Vector3 position;
    double weight = 0.0, modal_weight = 0.0, geometric_weight = 0.0;
  };
  std::vector<MogesecMaster> mogesec;
  const std::size_t first_pick = model.masters.size() - report.mogesec_picks.size();
  for (std::size_t k = 0; k < report.mogesec_picks.size(); ++k) {
    const std::size_t i = first_pick + k;
    const reduction::MogesecPick& p = report.mogesec_picks[k];
    mogesec.push_back({static_cast<int>(k + 1), model.dof_labels[i], report.mogesec_parts[k],
                       model.master_positions.row(static_cast<Eigen::Index>(i)).transpose(),
                       p.weight, p.modal_weight, p.geometric_weight});
  }

  if (opt.json) {
    io::JsonWriter json(std::cout);
    json.beginObject()
        .field("vehicle", description.name)
        .field("vehicle_file", opt.vehicle_file)
        .field("variant", vehicle::variantName(variant))
        .field("track_tension_n", vehicle::modelTrackTension(description, variant))
        .field("full_dofs", static_cast<long long>(report.full_dofs))
        .field("interface_dofs", static_cast<long long>(report.interface_dofs))
        .field("input_dofs", static_cast<long long>(model.masterCount() - report.interface_dofs -
                                                    report.mogesec_dofs))
        .field("mogesec_dofs", static_cast<long long>(report.mogesec_dofs))
        .field("flexible_modes", report.flexible_modes)
        .field("initial_flexible_modes", report.initial_fixed_interface_modes)
        .field("reduced_dofs", static_cast<long long>(report.reduced_dofs))
        .field("reduced_size_percent", 100.0 * report.reduced_dofs / report.full_dofs);
    if (options.rule == reduction::VehicleModeRule::MacCorrelation)  // the modes it paired
      json.field("mac_candidate_modes", report.mac_candidate_modes)
          .field("mac_reference_modes", report.mac_reference_modes);
    json.key("selected_modes").beginArray();
    for (const auto& m : model.selected_modes)
      json.beginObject()
          .field("mode", m.mode + 1)
          .field("frequency_hz", m.frequency_hz)
          .field("reason", m.reason)
          .endObject();
    json.endArray().key("band_modes").beginArray();
    for (std::size_t i = 0; i < pairs; ++i)
      json.beginObject()
          .field("mode", static_cast<long long>(i + 1))
          .field("full_hz", report.full_frequencies_hz[i])
          .field("reduced_hz", report.reduced_frequencies_hz[i])
          .field("relative_error", errors[i])
          .endObject();
    json.endArray().key("mogesec_masters").beginArray();
    for (const MogesecMaster& m : mogesec)
      json.beginObject()
          .field("pick", m.pick)
          .field("dof", m.dof)
          .field("part", m.part)
          .field("position_m", std::vector<double>{m.position.x(), m.position.y(), m.position.z()})
          .field("weight", m.weight)
          .field("modal_weight", m.modal_weight)
          .field("geometric_weight", m.geometric_weight)
          .endObject();
    json.endArray()
        .field("max_relative_frequency_error", worst)
        .field("build_seconds", report.build_seconds)
        .field("modes_seconds", report.modes_seconds)
        .field("selection_seconds", report.selection_seconds)
        .field("reduce_seconds", report.reduce_seconds)
        .field("total_seconds", report.total_seconds)
        .field("description_hash", model.description_hash);
    if (!opt.out_file.empty())
      json.field("out", opt.out_file);
    if (!opt.basis_file.empty())
      json.field("basis", opt.basis_file);
    ReducedModelSource source;
    source.model = std::move(model);  // not used after the JSON
    source.file = opt.out_file;
    source.variant = variant;
    source.options = options;
    source.warnings = report.warnings;
    writeReductionJson(json.key("reduction"), source);
    json.endObject();
    return;
  }
  std::cout << description.name << " (" << vehicle::variantName(variant)
            << "): " << report.full_dofs << " active DOFs -> " << report.reduced_dofs
            << " CMS DOFs (" << std::fixed << std::setprecision(1)
            << 100.0 * report.reduced_dofs / report.full_dofs << " %)\n";
  if (const std::string tension = vehicle::trackTensionText(description, variant); !tension.empty())
    std::cout << "  " << tension << "\n";
  std::cout << "  interface DOFs " << report.interface_dofs << ", hull and wheel DOFs "
            << model.masterCount() - report.interface_dofs - report.mogesec_dofs
            << ", MoGeSeC DOFs " << report.mogesec_dofs << ", flexible modes "
            << report.flexible_modes;
  if (report.flexible_modes != report.initial_fixed_interface_modes && options.mode_count == 0)
    std::cout << " (raised from " << report.initial_fixed_interface_modes
              << ", twice the selected global modes, until the modes up to "
              << brief(options.band_hz) << " Hz are within "
              << brief(100.0 * reduction::kBandFrequencyTolerance) << " %)";
  std::cout << "\n  selected global modes";
  if (options.rule == reduction::VehicleModeRule::MacCorrelation) {
    // Both sets: the global modes (global_modes.h).
    const vehicle::Variant other = variant == vehicle::Variant::Tracked
                                       ? vehicle::Variant::Untracked
                                       : vehicle::Variant::Tracked;
    std::cout << " (MAC >= " << brief(options.mac_threshold) << " between the "
              << report.mac_candidate_modes << " " << vehicle::variantName(variant)
              << " modes up to " << brief(options.band_hz) << " Hz and the "
              << report.mac_reference_modes << " " << vehicle::variantName(other) << " ones, of "
              << options.global_modes << " each, with "
              << brief(100.0 * reduction::kGlobalEnergyShare)
              << " % or more of their kinetic energy in the hull and running gear)";
  }
  std::cout << ":\n";
  for (const auto& m : model.selected_modes)
    std::cout << "    mode " << std::setw(2) << m.mode + 1 << std::setw(8) << std::setprecision(2)
              << m.frequency_hz << " Hz  " << m.reason << "\n";
  std::cout << "  MoGeSeC masters (in pick order; weight = modal x geometric):\n";
  for (const MogesecMaster& m : mogesec)
    std::cout << "    " << std::setw(2) << m.pick << "  " << m.dof << " (" << m.part << ") at ("
              << std::setprecision(2) << m.position.x() << ", " << m.position.y() << ", "
              << m.position.z() << ") m, weight " << std::setprecision(3) << m.weight << "\n";
  std::cout << "  modes up to " << options.band_hz << " Hz, full vs reduced:\n";
  for (std::size_t i = 0; i < pairs; ++i)
    std::cout << "    " << std::setw(2) << i + 1 << std::setw(9) << std::setprecision(3)
              << report.full_frequencies_hz[i] << std::setw(9) << report.reduced_frequencies_hz[i]
              << " Hz  " << std::showpos << std::setprecision(3) << 100.0 * errors[i]
              << std::noshowpos << " %\n";
  std::cout << "  worst frequency error " << std::setprecision(3) << 100.0 * worst << " %; time "
            << report.total_seconds << " s (build " << report.build_seconds << ", modes "
            << report.modes_seconds << ", selection " << report.selection_seconds << ", reduction "
            << report.reduce_seconds << ")\n";
  for (const std::string& w : report.warnings)
    std::cout << "  warning: " << w << "\n";
  if (!opt.out_file.empty())
    std::cout << "  wrote " << opt.out_file << "\n";
  if (!opt.basis_file.empty())
    std::cout << "  wrote " << opt.basis_file << " (T_CMS, " << report.full_dofs << " x "
              << report.reduced_dofs << ")\n";
}

}  // namespace

void registerReduceCommand(CLI::App& app) {
  auto opt = std::make_shared<ReduceOptions>();
  CLI::App* cmd =
      app.add_subcommand("reduce", "Craig-Bampton reduction of a vehicle (MAC + MoGeSeC)");
  addVehicleOption(cmd, &opt->vehicle_file);
  addVariantOption(cmd, &opt->variant, "untracked | tracked");
  opt->reduction_flags.addTo(cmd);
  cmd->add_flag("--json", opt->json, "print a JSON document");
  cmd->add_option("--out", opt->out_file, "write the reduced model (.mat)")
      ->check(outputFile({".mat"}));
  cmd->add_option("--basis", opt->basis_file,
                  "write the Craig-Bampton basis T (x = T x_R over the full model's active "
                  "DOFs, as tvd modes --matrices numbers them) and its DOF table (.mat)")
      ->check(outputFile({".mat"}));
  cmd->callback([opt]() {
    for (const auto& [name, out] :
         {std::make_pair("--out", opt->out_file), std::make_pair("--basis", opt->basis_file)})
      refuseOutputOverInput("reduce", name, out, {{"--vehicle", opt->vehicle_file}});
    if (!opt->basis_file.empty() && !opt->out_file.empty() &&
        sameOutputFile(opt->basis_file, opt->out_file))
      throw InputError("reduce: --basis and --out name the same file " + opt->out_file);
    run(*opt);
  });
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
