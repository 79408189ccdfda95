// The whole reduction pipeline for a vehicle description (paper §3):
//   buildVehicleModel() -> assemble() -> modes of both variants -> MAC mode selection
//   -> MoGeSeC master DOFs -> Craig-Bampton -> ReducedModel (cached as a .mat file).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/dof_map.h"
#include "tracked_vehicle_dynamics/reduction/mogesec.h"
#include "tracked_vehicle_dynamics/reduction/reduced_model.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

/// How the masters and fixed-interface modes are chosen.
enum class VehicleModeRule {
  /// The paper's way: the modes of this variant that correlate (MAC >= threshold, on the common
  /// translational DOFs) with the other variant's modes below the band limit (Fig. 9/10).
  MacCorrelation,
  /// Every mode below band_hz (or the lowest `mode_count` modes when given).
  Band,
};

/// "mac" or "band": the rule's name in option values, reduction keys and reports.
const char* modeRuleName(VehicleModeRule rule);
/// The rule named by modeRuleName()'s text; nullopt for any other text.
std::optional<VehicleModeRule> modeRuleFromName(const std::string& name);

/// The reduction's aim below the band (paper §3.2: the reduced model's frequencies within 2 % of
/// the full model's at worst): the default fixed-interface count is raised until it holds.
constexpr double kBandFrequencyTolerance = 0.02;

/// The largest global_modes the command line and the node take: the selection solves that many
/// modes of both variants, and the Lanczos cost grows steeply with the count (bundled vehicle,
/// un-tracked: 100 modes take 0.6 s; beyond 200, kMaxGlobalModesReason).
constexpr int kMaxGlobalModes = 200;
/// Why, as the command line and the node append it to a refusal.
constexpr const char* kMaxGlobalModesReason =
    " (more take minutes to solve: 200 take 7-13 s, 300 about 4 min, 500 over 10 min)";
/// The largest mogesec_masters and mode_count they take: a reduced model of thousands of DOFs
/// is no longer small (the tracked vehicle's default has 431).
constexpr int kMaxReductionCount = 1000;

/// A reduction that the options given cannot carry out on a valid description (no global mode
/// paired under the MAC threshold, more MoGeSeC masters than candidates): the caller names its
/// reduction settings (the node's ~reduction/*), not the description, as the culprit.
class ReductionOptionsError : public InputError {
 public:
  using InputError::InputError;
};

struct VehicleReductionOptions {
  VehicleModeRule rule = VehicleModeRule::MacCorrelation;
  int global_modes = 40;       ///< modes of each variant computed for MAC (paper: 40)
  double band_hz = 30.0;       ///< bandwidth of interest [Hz] (paper: 0-30 Hz)
  double mac_threshold = 0.7;  ///< paper Fig. 9: 70 %
  int mogesec_masters = 9;     ///< extra MoGeSeC master DOFs (paper Table 5: 9)
  /// Fixed-interface modes; 0: twice the selected global modes, raised by the selected count (at
  /// least 4) until every full-model mode below band_hz is reproduced within 2 % (at most 8
  /// times, up to 200 modes).
  int mode_count = 0;
};

/// The variant and every reduction option as text, e.g. "variant tracked; rule mac; global_modes
/// 40; ...": recorded in the model (ReducedModel::reduction) and required of a cached one.
std::string reductionKey(vehicle::Variant variant, const VehicleReductionOptions& options);

/// The inverse of reductionKey(): the variant and options of a model's `reduction` text. Returns
/// false (and leaves both unchanged) when `key` is not exactly what reductionKey() writes.
bool parseReductionKey(const std::string& key, vehicle::Variant* variant,
                       VehicleReductionOptions* options);

/// A reduced vehicle model read from a file the user names (`tvd reduce --out`, or a cache file),
/// with the variant and options its reduction key records.
struct VehicleModelFile {
  ReducedModel model;
  vehicle::Variant variant = vehicle::Variant::Tracked;
  VehicleReductionOptions options;
};

/// Loads `path` with the cache's checks (complete MAT file, checksum, format and software
/// release, the hash of `description`; another build of this release is taken, with a warning in
/// its `warnings`) and parses its reduction key. Throws StaleCacheError,
/// whose message starts with the file name and says what is wrong, also for a key that
/// reductionKey() does not write; callers append how to make a good file.
VehicleModelFile loadVehicleModelFile(const std::string& path,
                                      const vehicle::VehicleDescription& description);

/// The damping the description asks for (modal ratio or Rayleigh, plus its discrete dampers).
DampingOptions vehicleDamping(const vehicle::DampingDescription& damping);

/// Output rows of every reduced vehicle model, in this order:
///   "hull ux", "hull uy", "hull uz", "hull rx", "hull ry", "hull rz"   (hull CoG node)
///   "<wheel name> uz" for every road wheel (e.g. "road_wheel_left_1 uz")
///   "<point name> ux|uy|uz" for every named point of the description.
std::vector<OutputDof> vehicleOutputs(const vehicle::VehicleModel& vehicle,
                                      const vehicle::VehicleDescription& description);

/// What was done and how long it took, for logs and `tvd reduce --json`.
struct VehicleReductionReport {
  DofIndex full_dofs = 0;
  /// The ground interface: the uz of every road-input node (the hull's six DOFs and the wheel
  /// arms' ry, MoGeSeC's other imposed masters, are not counted here).
  DofIndex interface_dofs = 0;
  DofIndex mogesec_dofs = 0;
  /// Each MoGeSeC pick, in pick order (built models only): its weights at the moment it was
  /// picked, and vehicle::nodePart() of its node.
  std::vector<MogesecPick> mogesec_picks;
  std::vector<std::string> mogesec_parts;
  int flexible_modes = 0;
  /// Rule mac: the modes the MAC selection paired, those with at least 1 % of their kinetic
  /// energy in the hull and running gear: the reduced variant's up to band_hz (candidates) and the
  /// other variant's (references), of global_modes each; 0 with rule band.
  int mac_candidate_modes = 0;
  int mac_reference_modes = 0;
  /// The fixed-interface modes the reduction started from (twice the selected, or mode_count)
  /// before the band check added any; flexible_modes when none was added.
  int initial_fixed_interface_modes = 0;
  /// max_r |f_red,r - f_full,r| / f_full,r over the full-model modes below the band (above
  /// 0.1 Hz), pairing the r-th modes (reduced_frequencies_hz).
  double max_relative_frequency_error = 0.0;
  DofIndex reduced_dofs = 0;
  /// Full-model modes in the band, the reference of the 2 % check: the global modes below the
  /// band or, when those end below it, the band's modes solved for the check (up to
  /// kMaxGlobalModes of them).
  std::vector<double> full_frequencies_hz;
  /// The reduced model's lowest modes, as many as full_frequencies_hz (paired r-th with r-th;
  /// a pair's reduced frequency may lie above the band).
  std::vector<double> reduced_frequencies_hz;
  /// (f_red,r - f_full,r) / f_full,r of each pair, signed (>= 0 by Rayleigh-Ritz, to rounding):
  /// what the band check and max_relative_frequency_error judge (the latter above 0.1 Hz only).
  std::vector<double> relative_frequency_errors;
  double build_seconds = 0.0, modes_seconds = 0.0, selection_seconds = 0.0, reduce_seconds = 0.0,
         total_seconds = 0.0;
  bool from_cache = false;
  std::string cache_file;
  std::string cache_note;      ///< why the cache was (not) used
  bool cache_rebuilt = false;  ///< a cached model existed but was stale or corrupt (cache_note)
  std::string cache_error;     ///< why a model built here could not be cached (empty: it was)
  /// Rule mac: global_modes ends inside a repeated eigenvalue of a variant that the selection
  /// uses (global_modes.h), or the solver skipped part of one (one line each,
  /// naming the variant, the frequency, the modes kept of the group and the counts that would
  /// not cut it; mode_count_cut.h). Saved with the model (ReducedModel::warnings), so a model
  /// from the cache reports the warnings of the run that built it.
  std::vector<std::string> warnings;
};

/// The Craig-Bampton basis of a reduced vehicle model, x = T_CMS x_R (eq. 8), for a caller that
/// recovers the full model's displacements from the reduced coordinates, or checks the
/// projection M_R = T^T M T, K_R = T^T K T (tvd reduce --basis).
struct ReductionBasis {
  Matrix transformation;  ///< T_CMS [full_dofs x reduced_dofs], columns as ReducedModel's
  fem::DofMap dofs;       ///< the full model's DOF map: its active DOFs are the rows of T
};

/// Runs the pipeline on a loaded description. With `basis`, also returns T_CMS of the model it
/// returns (dense: 14 372 x 431 doubles, 50 MB, on the bundled tracked vehicle; made only when
/// asked, from the modes and factorisation the reduction already has).
ReducedModel reduceVehicle(const vehicle::VehicleDescription& description, vehicle::Variant variant,
                           const VehicleReductionOptions& options,
                           VehicleReductionReport* report = nullptr,
                           ReductionBasis* basis = nullptr);

/// The cache file of a reduced model: `cache_dir/<variant>_<description hash>.mat` for the
/// default options, `cache_dir/<variant>_<description hash>_<options key>.mat` otherwise, the
/// key a hash of every option, so models reduced with other options never share a file.
std::string reducedModelCachePath(const std::string& cache_dir, vehicle::Variant variant,
                                  const std::string& description_hash,
                                  const VehicleReductionOptions& options);

/// Loads reducedModelCachePath() when it exists and matches the description's hash and
/// the software version; otherwise runs reduceVehicle() and saves the result there (the cache
/// directory is created). `report->from_cache` and `report->cache_note` say which happened.
ReducedModel loadOrReduceVehicle(const std::string& vehicle_file, vehicle::Variant variant,
                                 const std::string& cache_dir,
                                 const VehicleReductionOptions& options = {},
                                 VehicleReductionReport* report = nullptr);
/// The same on a description already loaded (callers that also need its geometry parse the
/// file once).
ReducedModel loadOrReduceVehicle(const vehicle::VehicleDescription& description,
                                 vehicle::Variant variant, const std::string& cache_dir,
                                 const VehicleReductionOptions& options = {},
                                 VehicleReductionReport* report = nullptr);

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
