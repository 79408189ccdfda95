// `tvd mac`: MAC between the un-tracked and tracked variants (paper eq. 11, Fig. 9) and the
// correlation table of Table 4.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>

#include "commands.h"
#include "output_files.h"
#include "reduction_options.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/json_writer.h"
#include "tracked_vehicle_dynamics/io/mat_file.h"
#include "tracked_vehicle_dynamics/reduction/global_modes.h"
#include "tracked_vehicle_dynamics/reduction/mac.h"
#include "vehicle_analysis.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {

struct MacOptions {
  std::string vehicle_file;
  int count = 40;
  double threshold = reduction::kPaperMacThreshold;
  double band_hz = 30.0;
  bool json = false;
  std::string out_dir;
};

// One row of the correlation table: an un-tracked hull or wheel mode (or a group of modes of one
// repeated frequency) and its tracked partners.
struct CorrelationRow {
  int untracked_mode = 0;  // 0-based, the group's first
  int multiplicity = 1;    // modes in the group
  reduction::ModeCorrelation correlation;
};

// A row without a global tracked mode of non-zero MAC has no partner (correlateModes() would
// name the first column).
bool hasPartner(const CorrelationRow& r) {
  return r.correlation.best_match >= 0 && r.correlation.best_mac > 0.0;
}

void run(const MacOptions& opt) {
  std::vector<std::string> warnings;
  const vehicle::VehicleDescription description = loadVehicle(opt.vehicle_file, &warnings);
  const VehicleAnalysis uv = analyseVehicle(description, vehicle::Variant::Untracked, opt.count);
  const VehicleAnalysis tv = analyseVehicle(description, vehicle::Variant::Tracked, opt.count);
  // MAC on the translations of the nodes both variants share (rotations ignored, paper §3.1.1).
  const std::vector<fem::DofRef> common = vehicle::commonTranslationalDofs(uv.vehicle, tv.vehicle);
  const Matrix uv_shapes = vehicle::physicalShapes(uv.system, common, uv.modes.shapes);
  const Matrix tv_shapes = vehicle::physicalShapes(tv.system, common, tv.modes.shapes);
  // Fig. 9: the MAC of eq. (11) between single modes.
  const Matrix mac = reduction::mac(uv_shapes, tv_shapes);
  // Table 4, as the reduction's mode selection sees it: between eigenspaces, since which vectors
  // of a repeated frequency (the un-tracked wheels bouncing alone) the solver returns, and so
  // their single-mode MACs, is round-off (mac.h).
  const Matrix space_mac = reduction::eigenspaceMac(uv_shapes, uv.modes.frequencies_hz, tv_shapes,
                                                    tv.modes.frequencies_hz);
  // Paired as the reduction pairs them: global modes only (global_modes.h), so a chain mode that
  // leaves the hull and wheels at rest is no one's partner whatever its MAC.
  const std::vector<bool> uv_global = reduction::globalModes(uv.vehicle, uv.system, uv.modes);
  const std::vector<bool> tv_global = reduction::globalModes(tv.vehicle, tv.system, tv.modes);
  const Matrix pairing = reduction::globalPairs(space_mac, uv_global, tv_global);
  const std::vector<reduction::ModeCorrelation> correlations =
      reduction::correlateModes(pairing, opt.threshold);

  // Table 4 lists the un-tracked hull and wheel-bounce modes of the band, one row per eigenspace.
  std::vector<CorrelationRow> rows;
  for (const auto& [first, end] : reduction::degenerateGroups(uv.modes.frequencies_hz)) {
    const int i = static_cast<int>(first);
    if (uv.modes.frequencies_hz(i) > opt.band_hz)
      break;
    // A hull or wheel mode (by its label) that is also global: the rows the reduction pairs.
    if (uv.classes[i].kind == vehicle::ModeKind::TrackLocal || !uv_global[first])
      continue;
    rows.push_back({i, static_cast<int>(end - first), correlations[i]});
  }

  if (!opt.out_dir.empty()) {
    makeOutputDirectory(opt.out_dir);
    OutputFileSet written;  // mac.mat and mac.csv, both or neither
    written.write(opt.out_dir + "/mac.mat", [&](const std::string& path) {
      io::MatWriter mat(path);
      mat.writeMatrix("mac", mac);
      mat.writeMatrix("eigenspace_mac", space_mac);
      mat.writeMatrix("untracked_frequencies_hz", uv.modes.frequencies_hz);
      mat.writeMatrix("tracked_frequencies_hz", tv.modes.frequencies_hz);
      std::vector<std::string> uv_types, tv_types;
      for (const auto& c : uv.classes)
        uv_types.push_back(c.label);
      for (const auto& c : tv.classes)
        tv_types.push_back(c.label);
      mat.writeStrings("untracked_mode_types", uv_types);
      mat.writeStrings("tracked_mode_types", tv_types);
      mat.writeScalar("threshold", opt.threshold);
      // What the MAC is computed on, to recompute it: the common DOFs and both variants' shapes
      // there (rows in the same order).
      Matrix common_node(static_cast<Eigen::Index>(common.size()), 1);
      Matrix common_direction(common_node.rows(), 1);
      for (std::size_t i = 0; i < common.size(); ++i) {
        common_node(static_cast<Eigen::Index>(i), 0) = static_cast<double>(common[i].node);
        common_direction(static_cast<Eigen::Index>(i), 0) = common[i].direction;
      }
      mat.writeMatrix("common_dof_node", common_node);
      mat.writeMatrix("common_dof_direction", common_direction);
      mat.writeMatrix("untracked_common_shapes", uv_shapes);
      mat.writeMatrix("tracked_common_shapes", tv_shapes);
      // 1 for a global mode (global_modes.h), one per mode.
      for (const auto& [name, global] : {std::make_pair("untracked_global", &uv_global),
                                         std::make_pair("tracked_global", &tv_global)}) {
        Vector flags(static_cast<Eigen::Index>(global->size()));
        for (std::size_t i = 0; i < global->size(); ++i)
          flags(static_cast<Eigen::Index>(i)) = (*global)[i] ? 1.0 : 0.0;
        mat.writeMatrix(name, flags);
      }
      writeMetadata(mat, {{"vehicle", description.name},
                          {"vehicle_file", opt.vehicle_file},
                          {"common_dofs", static_cast<double>(common.size())}});
      mat.close();
    });
    // One row per un-tracked mode, then one column per tracked mode, named by its number.
    std::vector<std::string> headers = {"untracked_mode"};
    Matrix table(mac.rows(), mac.cols() + 1);
    table.col(0) = Vector::LinSpaced(mac.rows(), 1.0, static_cast<double>(mac.rows()));
    table.rightCols(mac.cols()) = mac;
    for (int j = 0; j < mac.cols(); ++j)
      headers.push_back(std::to_string(j + 1));
    written.write(opt.out_dir + "/mac.csv",
                  [&](const std::string& path) { writeTable(path, headers, table, 10); });
    written.commit();
  }

  if (opt.json) {
    io::JsonWriter json(std::cout);
    json.beginObject()
        .field("vehicle", description.name)
        .field("vehicle_file", opt.vehicle_file)
        .field("common_dofs", static_cast<long long>(common.size()))
        .field("threshold", opt.threshold)
        .field("untracked_frequencies_hz", uv.modes.frequencies_hz)
        .field("tracked_frequencies_hz", tv.modes.frequencies_hz)
        .field("mac", mac)
        .field("eigenspace_mac", space_mac);
    // Which modes pair (global_modes.h): the correlation below looks among these only.
    for (const auto& [name, global] : {std::make_pair("untracked_global", &uv_global),
                                       std::make_pair("tracked_global", &tv_global)}) {
      json.key(name).beginArray();
      for (bool g : *global)
        json.value(g);
      json.endArray();
    }
    json.key("correlation").beginArray();
    for (const CorrelationRow& r : rows) {
      json.beginObject()
          .field("untracked_mode", r.untracked_mode + 1)
          .field("multiplicity", r.multiplicity)
          .field("untracked_hz", uv.modes.frequencies_hz(r.untracked_mode))
          .field("type", uv.classes[r.untracked_mode].label);
      if (hasPartner(r)) {
        json.field("tracked_mode", r.correlation.best_match + 1)
            .field("tracked_hz", tv.modes.frequencies_hz(r.correlation.best_match))
            .field("tracked_type", tv.classes[r.correlation.best_match].label);
      } else {  // null: no global tracked mode shares any motion with it
        const double none = std::numeric_limits<double>::quiet_NaN();
        json.field("tracked_mode", none).field("tracked_hz", none).field("tracked_type", none);
      }
      // The best match is shown whatever its MAC; below the threshold it is no correlation.
      json.field("mac", r.correlation.best_mac)
          .field("matched", hasPartner(r) && r.correlation.best_mac >= opt.threshold)
          .key("other_matches")
          .beginArray();
      for (const auto& m : r.correlation.matches) {
        if (m.mode == r.correlation.best_match)
          continue;
        json.beginObject()
            .field("tracked_mode", m.mode + 1)
            .field("tracked_hz", tv.modes.frequencies_hz(m.mode))
            .field("mac", m.mac)
            .endObject();
      }
      json.endArray().endObject();
    }
    json.endArray();
    // The description's warnings, then each variant's (statics and modes), named.
    for (const auto& [name, analysis] :
         {std::make_pair("untracked", &uv), std::make_pair("tracked", &tv)})
      for (const std::string& w : analysis->warnings)
        warnings.push_back(std::string(name) + ": " + w);
    json.field("warnings", warnings).endObject();
    return;
  }

  std::cout << "MAC between the un-tracked (" << uv.system.size() << " DOFs) and tracked ("
            << tv.system.size() << " DOFs) models on " << common.size()
            << " common translational DOFs; first " << opt.count << " modes.\n\n"
            << "correlation (like Table 4): un-tracked hull and wheel modes up to " << opt.band_hz
            << " Hz (modes of one repeated frequency as one row, compared as an eigenspace); best "
               "tracked match, then (other matches with MAC >= "
            << opt.threshold << "), among the tracked modes with "
            << brief(100.0 * reduction::kGlobalEnergyShare)
            << " % or more of their kinetic energy in the hull and running gear, as the reduction "
               "pairs them; a best match below the threshold is shown and marked (< "
            << brief(opt.threshold) << ")\n\n";
  std::cout
      << "  UV mode  f_UV [Hz]  type                      TV mode  f_TV [Hz]   MAC   others\n";
  for (const CorrelationRow& r : rows) {
    const int best = r.correlation.best_match;
    const std::string modes = r.multiplicity == 1
                                  ? std::to_string(r.untracked_mode + 1)
                                  : std::to_string(r.untracked_mode + 1) + "-" +
                                        std::to_string(r.untracked_mode + r.multiplicity);
    std::cout << std::setw(9) << modes << std::setw(11) << std::fixed << std::setprecision(2)
              << uv.modes.frequencies_hz(r.untracked_mode) << "  " << std::left << std::setw(26)
              << (r.multiplicity == 1
                      ? uv.classes[r.untracked_mode].label
                      : uv.classes[r.untracked_mode].label + " x" + std::to_string(r.multiplicity))
              << std::right;
    if (hasPartner(r))
      std::cout << std::setw(7) << best + 1 << std::setw(11) << tv.modes.frequencies_hz(best);
    else
      std::cout << std::setw(7) << "-" << std::setw(11) << "-";
    // Three decimals where two would round a MAC below the threshold up to it ("0.70 (< 0.7)").
    const bool below = hasPartner(r) && r.correlation.best_mac < opt.threshold;
    const int decimals =
        below && std::round(100.0 * r.correlation.best_mac) >= 100.0 * opt.threshold ? 3 : 2;
    std::cout << std::setw(6) << std::setprecision(decimals) << r.correlation.best_mac
              << std::setprecision(2)
              << (below ? " (< " + brief(opt.threshold) + ") " : std::string("   "));
    for (const auto& m : r.correlation.matches)
      if (m.mode != best)
        std::cout << "(" << m.mode + 1 << ": " << std::setprecision(2)
                  << tv.modes.frequencies_hz(m.mode) << " Hz, " << m.mac << ") ";
    std::cout << "\n";
  }
}

}  // namespace

void registerMacCommand(CLI::App& app) {
  auto opt = std::make_shared<MacOptions>();
  CLI::App* cmd = app.add_subcommand(
      "mac", "MAC between the un-tracked and tracked variants and their correlation (Table 4)");
  addVehicleOption(cmd, &opt->vehicle_file);
  // Both variants' modes, as the reduction's --global-modes: the same limit.
  cmd->add_option("--count,-n", opt->count,
                  "modes of each variant, 1 .. " + std::to_string(reduction::kMaxGlobalModes) +
                      " (paper: 40)")
      ->check(CLI::Range(1, reduction::kMaxGlobalModes));
  // (0, 1] as reduce's --mac-threshold, which it also answers to (the same threshold: a user
  // checking reduce's selection types the option reduce took): at 0 every mode would correlate.
  cmd->add_option("--threshold,--mac-threshold", opt->threshold,
                  "MAC threshold of a match, in (0, 1] (paper: 0.7; also --mac-threshold, as "
                  "reduce)")
      ->check(finiteNumberWhere([](double v) { return v > 0.0 && v <= 1.0; }, "a number in (0, 1]",
                                "NUMBER"));
  cmd->add_option("--band", opt->band_hz, "bandwidth of the correlation table [Hz]")
      ->check(positiveNumber());
  cmd->add_flag("--json", opt->json, "print a JSON document (MAC matrix, correlation table)");
  cmd->add_option("--out", opt->out_dir,
                  "write mac.csv and mac.mat to this directory (created if missing)")
      ->check(outputDirectory());
  cmd->callback([opt]() { run(*opt); });
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
