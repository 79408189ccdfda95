// The reduction options of `tvd reduce`, `frf` and `simulate` (one registration, one check), and
// the reduced model frf and simulate run: computed, from the cache, or from `--reduced FILE`.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/io/json_writer.h"
#include "tracked_vehicle_dynamics/reduction/reduced_model.h"
#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"

namespace tracked_vehicle_dynamics {
namespace tools {

/// The flags --rule, --band, --global-modes, --masters, --modes and --mac-threshold, bound to
/// one VehicleReductionOptions (the ROS node's ~reduction/rule, band_hz, global_modes,
/// mogesec_masters, mode_count and mac_threshold: the same defaults and ranges, --global-modes
/// up to reduction::kMaxGlobalModes, --masters and --modes up to reduction::kMaxReductionCount;
/// the command line also refuses --mac-threshold with --rule band, which the node's parameter
/// file always sets).
class ReductionFlags {
 public:
  /// Registers the flags on `command`; `this` must outlive the parse (commands keep it in their
  /// shared options struct).
  void addTo(CLI::App* command);

  /// The options given. Throws InputError "<command>: --mac-threshold applies to --rule mac
  /// only" when the threshold is given with the band rule.
  reduction::VehicleReductionOptions options(const std::string& command) const;

  /// The first reduction flag given on the command line ("--band"), empty when none was.
  std::string firstGiven() const;

 private:
  std::string rule_ = "mac";
  reduction::VehicleReductionOptions options_;
  std::vector<CLI::Option*> flags_;
  CLI::Option* mac_threshold_ = nullptr;
};

/// Where frf and simulate take the reduced model from, as the command line says: `--reduced
/// FILE`, or the cache with the reduction flags. Registered by addTo(); checked by check().
class ReducedModelFlags {
 public:
  /// Registers --reduced, --cache-dir and the reduction flags on `command`.
  void addTo(CLI::App* command);

  /// Throws InputError (naming `command` and the flags) when --reduced is given with --model
  /// full, with a reduction flag or with --cache-dir, or a reduction flag or --cache-dir with
  /// --model full.
  void check(const std::string& command, const std::string& model) const;

  const ReductionFlags& reduction() const { return reduction_; }
  const std::string& reducedFile() const { return reduced_file_; }
  const std::string& cacheDir() const { return cache_dir_; }

 private:
  ReductionFlags reduction_;
  std::string reduced_file_;
  std::string cache_dir_;
  CLI::Option* cache_dir_option_ = nullptr;
};

/// The reduced model a command runs, and how it was obtained.
struct ReducedModelSource {
  enum class Kind { Computed, Cache, File };
  reduction::ReducedModel model;
  Kind kind = Kind::Computed;
  std::string file;  ///< the cache file (when it was written or read) or the --reduced file
  vehicle::Variant variant = vehicle::Variant::Tracked;
  reduction::VehicleReductionOptions options;  ///< as the model was reduced
  /// What the reduction warned about (VehicleReductionReport::warnings; for a model from the
  /// cache or a file, the warnings of the run that reduced it, ReducedModel::warnings).
  std::vector<std::string> warnings;
  /// E.g. that a stale or corrupt cache file was rebuilt.
  std::vector<std::string> notes;
};

/// "computed", "cache", "file".
const char* sourceName(ReducedModelSource::Kind kind);

/// The reduced model for `description`: from `flags.reducedFile()` when given, otherwise
/// loadOrReduceVehicle() with the reduction flags in the cache directory (default
/// defaultCacheDir()); the reduction's warnings (a cut eigenspace, a cache that cannot be written)
/// and notes (a cache file rebuilt) are printed to stderr and kept in the result. A file is loaded
/// with the cache's checks (format and software version, description hash, checksum) and must hold
/// a reduction tvd writes; `variant_given` is the --variant of the command line, if any, and must
/// then be the file's. Throws InputError
/// "FILE: <what is wrong>; run tvd reduce again" for a file that cannot be used.
ReducedModelSource obtainReducedModel(const vehicle::VehicleDescription& description,
                                      vehicle::Variant variant, bool variant_given,
                                      const std::string& command, const ReducedModelFlags& flags);

/// Writes the JSON object that states the reduction: source, file, variant, rule, band_hz,
/// global_modes, mac_threshold, mogesec_masters, mode_count (the options), then what the model
/// holds: selected_global_modes, fixed_interface_modes, master_dofs, reduced_dofs, full_dofs,
/// and its warnings and notes.
void writeReductionJson(io::JsonWriter& json, const ReducedModelSource& source);

/// One line for the text output: "rule band, 0-40 Hz, 12 global modes -> 24 fixed-interface
/// modes, 113 masters; from m.mat".
std::string describeReduction(const ReducedModelSource& source);

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
