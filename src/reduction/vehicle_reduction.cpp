#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

#include "tracked_vehicle_dynamics/enum_names.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/io/fnv1a.h"
#include "tracked_vehicle_dynamics/io/number_text.h"
#include "tracked_vehicle_dynamics/reduction/fixed_interface_modes.h"
#include "tracked_vehicle_dynamics/reduction/global_modes.h"
#include "tracked_vehicle_dynamics/reduction/mac.h"
#include "tracked_vehicle_dynamics/reduction/mode_count_cut.h"
#include "tracked_vehicle_dynamics/reduction/mode_selection.h"
#include "tracked_vehicle_dynamics/reduction/mogesec.h"
#include "tracked_vehicle_dynamics/reduction/reduced_model_file.h"
#include "tracked_vehicle_dynamics/vehicle/mode_classification.h"

namespace tracked_vehicle_dynamics {
namespace reduction {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

struct AssembledVariant {
  vehicle::VehicleModel vehicle;
  fem::System system;
  fem::ModalBasis modes;
};

AssembledVariant buildAndSolve(const vehicle::VehicleDescription& description,
                               vehicle::Variant variant, int modes) {
  AssembledVariant out;
  out.vehicle = vehicle::buildVehicleModel(description, variant);
  out.system = fem::assemble(out.vehicle.model);
  fem::ModalRequest request;
  request.count = modes;
  out.modes = fem::solveModes(out.system.stiffness, out.system.mass, request);
  return out;
}

// The imposed masters (paper §3.1.2): the vertical DOF of every road-input node (the ground
// interface), the six hull DOFs and each suspension arm's rotation (one DOF per road wheel).
std::vector<DofIndex> interfaceMasters(const AssembledVariant& v, DofIndex* interface_count) {
  const fem::DofMap& dofs = v.system.dofs;
  std::vector<DofIndex> masters;
  for (const vehicle::RoadInput& input : v.vehicle.layout.road_inputs) {
    const DofIndex a = dofs.active(input.node, static_cast<int>(Direction::Uz));
    if (a >= 0)
      masters.push_back(a);
  }
  *interface_count = static_cast<DofIndex>(masters.size());
  for (int d = 0; d < kDofsPerNode; ++d)
    masters.push_back(dofs.requireActive(v.vehicle.layout.hull, d));
  for (const vehicle::WheelStation& wheel : v.vehicle.layout.wheels)
    masters.push_back(dofs.requireActive(wheel.arm, static_cast<int>(Direction::Ry)));
  return masters;
}

// Whether each mode of `v` is global (global_modes.h): only those pair in the MAC selection, as
// candidates and as references.
std::vector<bool> globalModes(const AssembledVariant& v) {
  return reduction::globalModes(v.vehicle, v.system, v.modes);
}

// A warning when global_modes ends inside a repeated eigenvalue of `v` (mode_count_cut.h) that
// takes part in the selection: the MAC against the part of an eigenspace kept is round-off. A
// group whose modes are not global (`global`, globalModes()) has no MAC: the bundled un-tracked
// vehicle's 12 track-local modes at 107.72 Hz, which the default 40 cuts after 6. Nor does a
// group above `candidate_limit_hz` (the band, for the variant reduced): its modes are no
// candidates. A solver that skipped modes below the last group is always reported.
void warnIfCut(const AssembledVariant& v, vehicle::Variant variant, int global_modes,
               const std::vector<bool>& global, double candidate_limit_hz,
               std::vector<std::string>* warnings) {
  const char* name = vehicle::variantName(variant);
  std::optional<ModeCountCut> cut;
  try {
    cut = modeCountCut(v.system.stiffness, v.system.mass, v.modes.frequencies_hz);
  } catch (const SolverError& e) {
    // A diagnostic: a factorisation that fails at its shift must not stop a reduction that worked.
    warnings->push_back("global_modes " + std::to_string(global_modes) +
                        ": could not check whether the count cuts a repeated eigenvalue of the " +
                        name + " variant (" + e.what() + ")");
    return;
  }
  if (!cut)
    return;
  if (cut->missed == 0) {
    // Which group a solver's missed modes belong to is not known, so only a cut group is judged.
    if (cut->frequency_hz > candidate_limit_hz)
      return;
    const bool takes_part =
        std::any_of(global.begin() + cut->fewer, global.end(), [](bool g) { return g; });
    if (!takes_part)
      return;
  }
  std::ostringstream text;
  text << "global_modes " << global_modes << ": ";
  if (cut->missed > 0)
    // Which group lost the modes is not known without solving more, so no count is promised.
    text << "the " << name << " variant has " << cut->missed << " more mode(s) below "
         << brief(cut->frequency_hz)
         << " Hz than the solver returned: it returned part of a repeated eigenvalue there, so "
            "a MAC selection against that eigenspace depends on round-off. A global_modes count "
            "whose modes all lie below "
         << brief(cut->frequency_hz) << " Hz is not affected";
  else
    // Counts that end at a gap: below the group, every mode is returned (the Sylvester count
    // says so); above it only if the Lanczos run returns the whole group, which the check of
    // that run reports.
    text << "cuts a repeated eigenvalue of the " << name << " variant: " << cut->kept << " of its "
         << cut->size << " modes at " << brief(cut->frequency_hz)
         << " Hz are kept, and the MAC against part of an eigenspace depends on round-off; "
         << (cut->fewer > 0 ? std::to_string(cut->fewer) + " global modes end below it, " +
                                  std::to_string(cut->more)
                            : std::to_string(cut->more))
         << " above it if the solver returns all " << cut->size
         << " (a run warns when it does not)";
  warnings->push_back(text.str());
}

std::vector<double> frequenciesBelow(const Vector& hz, double limit) {
  std::vector<double> out;
  for (Eigen::Index i = 0; i < hz.size(); ++i)
    if (hz(i) <= limit)
      out.push_back(hz(i));
  return out;
}

// How far the default goes to reach kBandFrequencyTolerance (vehicle_reduction.h): at most this
// many fixed-interface modes and this many additions (each a whole Craig-Bampton reduction, 0.5 s
// on the bundled tracked vehicle), adding max(selected count, kMinAutoStep) modes at a time.
constexpr int kMaxAutoFixedInterfaceModes = 200;
constexpr int kMaxAutoAdditions = 8;
constexpr int kMinAutoStep = 4;

// The worst relative frequency error of the reduced model against the full model's modes below
// the band, pairing them in order: by Rayleigh-Ritz the reduced model's r-th frequency is at or
// above the full model's r-th (a Craig-Bampton basis is a subspace), so the r-th pair is
// mode r and the error (f_red - f_full) / f_full. Modes at or below kNearRigidHz are left out as
// in the report (a relative error of a near-zero frequency says nothing about the model).
constexpr double kNearRigidHz = 0.1;

// The CMS error of a pair, (f_red - f_full) / f_full.
double relativeFrequencyError(double full_hz, double reduced_hz) {
  return (reduced_hz - full_hz) / full_hz;
}

struct BandCheck {
  double worst = 0.0;
  int mode = 0;  // 0-based
  double full_hz = 0.0, reduced_hz = 0.0;
};

BandCheck checkBand(const std::vector<double>& full_hz, const Vector& reduced_hz) {
  BandCheck c;
  const auto n =
      std::min<Eigen::Index>(static_cast<Eigen::Index>(full_hz.size()), reduced_hz.size());
  for (Eigen::Index r = 0; r < n; ++r) {
    const double f = full_hz[static_cast<std::size_t>(r)];
    if (f <= kNearRigidHz)
      continue;
    const double e = std::abs(relativeFrequencyError(f, reduced_hz(r)));
    if (e > c.worst)
      c = {e, static_cast<int>(r), f, reduced_hz(r)};
  }
  return c;
}

}  // namespace

DampingOptions vehicleDamping(const vehicle::DampingDescription& d) {
  DampingOptions o;
  if (d.model == vehicle::DampingModel::Modal) {
    o.model = DampingModel::Modal;
    o.modal_ratio = d.modal_ratio;
  } else {
    o.model = DampingModel::Rayleigh;
    o.alpha = d.rayleigh_alpha;
    o.beta = d.rayleigh_beta;
  }
  return o;
}

std::vector<OutputDof> vehicleOutputs(const vehicle::VehicleModel& v,
                                      const vehicle::VehicleDescription& description) {
  std::vector<OutputDof> outputs;
  for (int d = 0; d < kDofsPerNode; ++d)
    outputs.push_back({std::string("hull ") + directionName(d), {v.layout.hull, d}});
  for (const vehicle::WheelStation& wheel : v.layout.wheels)
    outputs.push_back({wheel.name + " uz", {wheel.centre, static_cast<int>(Direction::Uz)}});
  for (const vehicle::NamedPoint& point : description.named_points) {
    const auto it = v.layout.named_points.find(point.name);
    if (it == v.layout.named_points.end())
      throw InputError("named point '" + point.name + "' has no node in the vehicle model");
    for (int d = 0; d < 3; ++d)
      outputs.push_back({point.name + " " + directionName(d), {it->second, d}});
  }
  return outputs;
}

ReducedModel reduceVehicle(const vehicle::VehicleDescription& description, vehicle::Variant variant,
                           const VehicleReductionOptions& options, VehicleReductionReport* report,
                           ReductionBasis* basis) {
  if (options.global_modes <= 0)
    throw InputError("reduction: global_modes must be positive");
  if (!(options.band_hz > 0))
    throw InputError("reduction: band_hz must be positive");
  if (options.mogesec_masters < 0)
    throw InputError("reduction: mogesec_masters must not be negative");
  VehicleReductionReport local;
  VehicleReductionReport& rep = report ? *report : local;
  rep.warnings.clear();
  rep.mac_reference_modes = 0;
  rep.mac_candidate_modes = 0;
  const auto start = Clock::now();

  // 1. The full model and its global modes.
  const AssembledVariant model = buildAndSolve(description, variant, options.global_modes);
  rep.full_dofs = model.system.size();
  rep.build_seconds = secondsSince(start) - model.modes.seconds;
  rep.modes_seconds = model.modes.seconds;
  rep.full_frequencies_hz = frequenciesBelow(model.modes.frequencies_hz, options.band_hz);
  // The 2 % check needs every full-model mode in the band. The global modes (the MAC's) may end
  // below it, on a vehicle with many slow chain modes: then the band's modes are solved for the
  // check (a band-limited Lanczos run, up to kMaxGlobalModes), and the additions below reach
  // them; the selection still sees the global modes (a warning says so).
  const Vector& global_hz = model.modes.frequencies_hz;
  const bool global_modes_end_below_band =
      global_hz.size() > 0 && global_hz(global_hz.size() - 1) <= options.band_hz;
  bool band_modes_capped = false;
  if (global_modes_end_below_band) {
    fem::ModalRequest band_request;
    band_request.count = std::max(kMaxGlobalModes, options.global_modes);
    band_request.max_frequency_hz = options.band_hz;
    const fem::ModalBasis band_modes =
        fem::solveModes(model.system.stiffness, model.system.mass, band_request);
    rep.modes_seconds += band_modes.seconds;
    rep.full_frequencies_hz = frequenciesBelow(band_modes.frequencies_hz, options.band_hz);
    band_modes_capped = band_modes.count() >= band_request.count;
  }

  // 2. Mode selection (paper §3.1.1): by MAC against the other variant, or by band.
  const auto selection_start = Clock::now();
  ModeSelectionOptions selection_options;
  ModeSelection selection;
  if (options.rule == VehicleModeRule::MacCorrelation) {
    const vehicle::Variant other_variant = variant == vehicle::Variant::Tracked
                                               ? vehicle::Variant::Untracked
                                               : vehicle::Variant::Tracked;
    // The un-tracked reduction builds the tracked variant too: say why when only that fails.
    const auto other = [&] {
      try {
        return buildAndSolve(description, other_variant, options.global_modes);
      } catch (const InputError& e) {
        if (variant == vehicle::Variant::Tracked)
          throw;
        throw InputError(std::string(e.what()) +
                         " (the un-tracked reduction builds the tracked variant for its MAC mode "
                         "selection; the band rule does not: `tvd reduce --rule band`, the "
                         "node's ~reduction/rule)");
      }
    }();
    // MAC on the translations of the nodes both variants share (hull, spider, arms, wheel
    // centres), recovered through the constraint transformation since many are slaves.
    const std::vector<fem::DofRef> common =
        vehicle::commonTranslationalDofs(model.vehicle, other.vehicle);
    ModeReference reference;
    // Between eigenspaces: the wheels' repeated bounce frequency makes single-vector MACs
    // round-off dependent (mac.h).
    reference.mac = eigenspaceMac(vehicle::physicalShapes(model.system, common, model.modes.shapes),
                                  model.modes.frequencies_hz,
                                  vehicle::physicalShapes(other.system, common, other.modes.shapes),
                                  other.modes.frequencies_hz);
    reference.frequencies_hz = other.modes.frequencies_hz;
    // Only global modes pair: the others' rows and columns are zero.
    const std::vector<bool> own = globalModes(model);
    const std::vector<bool> global = globalModes(other);
    reference.mac = globalPairs(std::move(reference.mac), own, global);
    for (Eigen::Index j = 0; j < reference.mac.rows(); ++j)
      if (own[static_cast<std::size_t>(j)] && model.modes.frequencies_hz(j) <= options.band_hz)
        ++rep.mac_candidate_modes;
    rep.mac_reference_modes += static_cast<int>(std::count(global.begin(), global.end(), true));
    // The candidates are the reduced variant's global modes in the band, the references the other
    // variant's global modes.
    warnIfCut(model, variant, options.global_modes, own, options.band_hz, &rep.warnings);
    warnIfCut(other, other_variant, options.global_modes, global,
              std::numeric_limits<double>::infinity(), &rep.warnings);
    selection_options.rule = ModeSelectionRule::Correlation;
    selection_options.max_frequency_hz = options.band_hz;
    selection_options.mac_threshold = options.mac_threshold;
    selection_options.reference_name = std::string(vehicle::variantName(other_variant));
    selection = selectModes(model.modes.frequencies_hz, selection_options, &reference);
  } else {
    const auto solved = static_cast<int>(model.modes.frequencies_hz.size());
    if (options.mode_count > solved)
      throw ReductionOptionsError(
          "reduction: mode_count " + std::to_string(options.mode_count) +
          " (tvd --modes, ~reduction/mode_count) with rule band also selects the lowest " +
          std::to_string(options.mode_count) + " global modes, but only " + std::to_string(solved) +
          " were solved (tvd --global-modes, ~reduction/global_modes): raise that, or give "
          "mode_count 0 to select the modes below the band");
    selection_options.rule =
        options.mode_count > 0 ? ModeSelectionRule::Count : ModeSelectionRule::FrequencyBand;
    selection_options.count = options.mode_count;
    selection_options.max_frequency_hz = options.band_hz;
    selection = selectModes(model.modes.frequencies_hz, selection_options);
  }
  if (selection.count() == 0)
    throw ReductionOptionsError(
        "reduction: no global mode selected below " + brief(options.band_hz) + " Hz" +
        (options.rule == VehicleModeRule::MacCorrelation
             ? " (MAC threshold " + brief(options.mac_threshold) +
                   " among the global modes of each variant's lowest " +
                   std::to_string(options.global_modes) +
                   "; more global_modes (tvd --global-modes, "
                   "~reduction/global_modes) or a lower mac_threshold (tvd --mac-threshold, "
                   "~reduction/mac_threshold) may pair some)"
             : std::string(" (the lowest mode lies above the band; raise --band)")));

  // 3. Masters: the ground interface, hull and wheels, then MoGeSeC on the selected modes. As in
  // the paper (§3.1.2), MoGeSeC starts from the input DOFs (hull and wheels) alone: the pad soles
  // of the ground interface are masters of the basis but not of the spread, so the picks spread
  // along the vehicle instead of clustering where the modes are largest (with the soles in
  // eq. 14, nearly every candidate's nearest master is a sole within 0.2 m and the geometric
  // weight no longer ranks them). The soles are not candidates.
  DofIndex interface_count = 0;
  const std::vector<DofIndex> imposed = interfaceMasters(model, &interface_count);
  Matrix selected_shapes(model.system.size(), selection.count());
  for (int i = 0; i < selection.count(); ++i)
    selected_shapes.col(i) = model.modes.shapes.col(selection.modes[i].mode);
  MogesecOptions mogesec_options;
  mogesec_options.count = options.mogesec_masters;
  CandidateFilter filter = CandidateFilter::lateralAndVertical();
  for (const vehicle::RoadInput& input : model.vehicle.layout.road_inputs)
    filter.excluded_nodes.push_back(input.node);
  const std::vector<DofIndex> inputs(imposed.begin() + interface_count, imposed.end());
  MasterSelection masters;
  try {
    masters = selectMasters(model.system.dofs, selected_shapes, inputs, filter, mogesec_options);
  } catch (const InputError& e) {
    // With the setting the user knows it by (most often a count beyond a small variant's
    // candidates), not as its cause.
    throw ReductionOptionsError(std::string("reduction: MoGeSeC masters of the ") +
                                vehicle::variantName(variant) + " variant, mogesec_masters " +
                                std::to_string(options.mogesec_masters) +
                                " (tvd --masters, ~reduction/mogesec_masters): " + e.what());
  }
  // The basis' masters in interfaceMasters()' order: interface, hull, wheels, then the picks.
  masters.masters.insert(masters.masters.begin(), imposed.begin(),
                         imposed.begin() + interface_count);
  rep.interface_dofs = interface_count;
  rep.mogesec_dofs = static_cast<DofIndex>(masters.picks.size());
  rep.mogesec_picks = masters.picks;
  rep.mogesec_parts.clear();
  for (const MogesecPick& pick : masters.picks)
    rep.mogesec_parts.push_back(
        vehicle::nodePart(model.vehicle.layout, model.system.dofs.dofOf(pick.index).node));
  rep.selection_seconds = secondsSince(selection_start);

  // 4. Craig-Bampton. The paper keeps as many fixed-interface modes as global modes were selected
  // (Table 5); on our tracked model (14 selected) that leaves the chain-coupled modes at 19-23 Hz
  // 7-20 % too stiff and those from 22.9 Hz up 42-74 %, so the default keeps twice as many and,
  // when that is not enough, adds the selected count (at least kMinAutoStep) at a time until every
  // full-model mode below the band is within kBandFrequencyTolerance (checkBand()): the tracked
  // vehicle's 28 leave a mode 5.4 % off and it gets 42 (0.32 %); a light 5-axle vehicle whose MAC
  // keeps 1 mode starts from 2 (20 % off at 22 Hz) and gets 10. --modes N overrides it; the check
  // then only warns. The additions reuse the reducer (craig_bampton.h): factorisation, constraint
  // modes and master blocks are computed once.
  const auto reduce_start = Clock::now();
  ReductionRequest request;
  request.masters = masters.masters;
  // Why each is a master, in interfaceMasters()' order, then the picks in MoGeSeC's order.
  request.master_groups.assign(static_cast<std::size_t>(interface_count), "road input");
  request.master_groups.insert(request.master_groups.end(), kDofsPerNode, "hull");
  request.master_groups.resize(imposed.size(), "wheel arm");
  for (std::size_t k = 0; k < masters.picks.size(); ++k)
    request.master_groups.push_back("MoGeSeC " + std::to_string(k + 1));
  FixedInterfaceOptions fixed_interface;
  fixed_interface.rule = FixedInterfaceRule::SameCount;
  fixed_interface.extra_modes = selection.count();
  const FixedInterfaceModes first_count = options.mode_count > 0
                                              ? FixedInterfaceModes{options.mode_count, 0.0}
                                              : fixedInterfaceModes(selection, fixed_interface);
  request.craig_bampton.fixed_interface = first_count;
  request.craig_bampton.damping = vehicleDamping(description.damping);
  request.outputs = vehicleOutputs(model.vehicle, description);
  request.selection = selection;
  request.description_hash = vehicle::descriptionHashHex(description);
  request.reduction = reductionKey(variant, options);
  request.creator = std::string("reduceVehicle ") + vehicle::variantName(variant);
  // Where each input reads the road: its node's station, or its pad's centre (description).
  request.input_stations =
      vehicle::roadInputStations(model.vehicle.layout, model.system.ground_inputs);
  const CraigBamptonReducer reducer(model.system, request.masters);
  // The fixed-interface modes a slave set can give: a count above it cannot help.
  const int slave_count =
      static_cast<int>(model.system.size()) - static_cast<int>(request.masters.size());
  const int step = std::max(kMinAutoStep, selection.count());
  const int most = std::min(slave_count, kMaxAutoFixedInterfaceModes);
  // With the default count the modes are solved and projected for the first addition's count at
  // once: the first model takes the leading ones and their blocks, and the first addition (the
  // tracked vehicle's 28 -> 42) solves and projects nothing (one Lanczos run for 42 modes, 0.30 s,
  // instead of 0.25 s for 28 and 0.30 s for 42; one projection, 0.27 s, instead of 0.19 s and
  // 0.27 s). A further addition solves and projects for its own count.
  std::optional<FixedInterfaceProjection> phi_s;
  auto solveFor = [&](int count) {
    CraigBamptonOptions o = request.craig_bampton;
    o.fixed_interface.count = count;
    phi_s = reducer.project(reducer.fixedInterfaceModes(o));
  };
  auto build = [&]() {
    const int count = request.craig_bampton.fixed_interface.count;
    if (phi_s && phi_s->count() < count)
      solveFor(count);
    return buildReducedModel(model.system, request, reducer, phi_s ? &*phi_s : nullptr);
  };
  if (options.mode_count == 0 && first_count.max_frequency_hz == 0.0 && first_count.count < most)
    solveFor(std::min(first_count.count + step, most));
  ReducedModel reduced = build();
  fem::ModalBasis reduced_modes =
      fem::solveModesDense(reduced.system.stiffness, reduced.system.mass);
  BandCheck band = checkBand(rep.full_frequencies_hz, reduced_modes.frequencies_hz);
  int addition = 0;
  for (; options.mode_count == 0 && band.worst > kBandFrequencyTolerance &&
         addition < kMaxAutoAdditions && request.craig_bampton.fixed_interface.count < most;
       ++addition) {
    request.craig_bampton.fixed_interface.count =
        std::min(request.craig_bampton.fixed_interface.count + step, most);
    reduced = build();
    reduced_modes = fem::solveModesDense(reduced.system.stiffness, reduced.system.mass);
    band = checkBand(rep.full_frequencies_hz, reduced_modes.frequencies_hz);
  }
  rep.initial_fixed_interface_modes = first_count.count;
  rep.max_relative_frequency_error = band.worst;
  if (band.worst > kBandFrequencyTolerance) {
    std::ostringstream w;
    w << std::fixed << std::setprecision(2) << "the reduced model's mode " << band.mode + 1
      << " is " << 100.0 * band.worst << " % off the full model's (" << band.full_hz << " -> "
      << band.reduced_hz << " Hz), beyond the " << brief(100.0 * kBandFrequencyTolerance)
      << " % the reduction aims at below " << brief(options.band_hz) << " Hz, with "
      << request.craig_bampton.fixed_interface.count << " fixed-interface modes";
    if (options.mode_count > 0) {
      w << " (--modes / ~reduction/mode_count " << options.mode_count
        << "; 0, the default, adds modes until the modes below the band are within it)";
    } else {
      const int count = request.craig_bampton.fixed_interface.count;
      w << " (the default added " << (count - first_count.count) << " to the " << first_count.count
        << " it starts from and stopped at ";
      if (addition == kMaxAutoAdditions)
        w << kMaxAutoAdditions << " additions of " << step;
      else if (count >= slave_count)
        w << "the " << slave_count << " the interior DOFs allow";
      else
        w << "its limit of " << kMaxAutoFixedInterfaceModes << " modes";
      w << "; --modes N sets a count)";
    }
    if (options.rule == VehicleModeRule::MacCorrelation)
      w << "; --rule band (~reduction/rule) keeps every mode below the band";
    rep.warnings.push_back(w.str());
  }
  // The selection saw the global modes only: when they end below the band, modes between are
  // neither paired by the MAC nor, with the band rule, kept (the check above covers them all).
  if (global_modes_end_below_band) {
    std::ostringstream w;
    w << std::fixed << std::setprecision(2) << "global_modes " << options.global_modes << " end at "
      << global_hz(global_hz.size() - 1) << " Hz, below the band's " << brief(options.band_hz)
      << " Hz: the mode selection saw those " << global_hz.size() << " modes only (";
    // What covers the band: one mode past the band's last. Counted on this variant; the MAC's
    // reference variant has its own count, and warns when it is reduced.
    const auto below = static_cast<int>(rep.full_frequencies_hz.size());
    if (!band_modes_capped && below + 1 <= kMaxGlobalModes)
      w << "this variant has " << below << " modes below " << brief(options.band_hz)
        << " Hz: --global-modes " << below + 1 << ", ~reduction/global_modes, covers the band";
    else
      w << "this variant has at least " << kMaxGlobalModes << " modes below "
        << brief(options.band_hz) << " Hz, beyond what --global-modes takes: --rule band keeps "
        << "every mode below the band";
    w << "); the reduced model was checked against the " << below << " full-model modes below "
      << brief(options.band_hz) << " Hz";
    if (band_modes_capped)
      w << ", the lowest " << below << " of more";
    rep.warnings.push_back(w.str());
  }
  reduced.warnings = rep.warnings;  // saved with it: a cached model warns again when loaded
  rep.reduce_seconds = secondsSince(reduce_start);
  rep.flexible_modes = static_cast<int>(reduced.modeCount());
  rep.reduced_dofs = reduced.size();
  // Paired with the full model's modes below the band, r-th with r-th (checkBand()), also where
  // a reduced frequency lies above the band.
  rep.reduced_frequencies_hz.assign(
      reduced_modes.frequencies_hz.data(),
      reduced_modes.frequencies_hz.data() +
          std::min<Eigen::Index>(static_cast<Eigen::Index>(rep.full_frequencies_hz.size()),
                                 reduced_modes.frequencies_hz.size()));
  rep.relative_frequency_errors.clear();
  for (std::size_t r = 0; r < rep.reduced_frequencies_hz.size(); ++r)
    rep.relative_frequency_errors.push_back(
        relativeFrequencyError(rep.full_frequencies_hz[r], rep.reduced_frequencies_hz[r]));
  rep.total_seconds = secondsSince(start);
  // After the timings, which are the reduction's own: the last build's reduction again, keeping
  // T, on the projection it used (neither the eigen-solve nor the projection is repeated) or,
  // where it kept none (--modes N, a band-limited count), on the same eigen-solve of the same
  // count, so the modes and their signs are those of M_R and K_R.
  if (basis != nullptr) {
    CraigBamptonOptions o = request.craig_bampton;
    o.keep_transformation = true;
    o.recovery_dofs.clear();
    basis->transformation = (phi_s ? reducer.reduce(o, *phi_s) : reducer.reduce(o)).transformation;
    basis->dofs = model.system.dofs;
  }
  return reduced;
}

const char* modeRuleName(VehicleModeRule rule) {
  switch (rule) {  // no default: a new rule without a name is a compiler warning
    case VehicleModeRule::MacCorrelation:
      return "mac";
    case VehicleModeRule::Band:
      return "band";
  }
  return "?";
}

std::optional<VehicleModeRule> modeRuleFromName(const std::string& name) {
  return enumFromName(name, {VehicleModeRule::MacCorrelation, VehicleModeRule::Band}, modeRuleName);
}

namespace {

std::string number(double value, bool legacy) {
  if (!legacy)
    return io::roundTripText(value);
  std::string text;
  io::appendGeneral(text, value, 17);
  return text;
}

/// Every reduction option, the doubles to the last bit in their shortest text (0.7, which reads
/// back as the same double). `legacy`: as versions up to 0.3.2 wrote them, %.17g
/// (0.69999999999999996), still read from their files.
std::string optionsText(const VehicleReductionOptions& o, bool legacy = false) {
  char text[200];
  std::snprintf(text, sizeof(text),
                "rule %s; global_modes %d; band_hz %s; mac_threshold %s; "
                "mogesec_masters %d; modes %d",
                modeRuleName(o.rule), o.global_modes, number(o.band_hz, legacy).c_str(),
                number(o.mac_threshold, legacy).c_str(), o.mogesec_masters, o.mode_count);
  return text;
}

}  // namespace

std::string reductionKey(vehicle::Variant variant, const VehicleReductionOptions& options) {
  return std::string("variant ") + vehicle::variantName(variant) + "; " + optionsText(options);
}

bool parseReductionKey(const std::string& key, vehicle::Variant* variant,
                       VehicleReductionOptions* options) {
  char variant_name[16] = {}, rule[8] = {};
  VehicleReductionOptions o;
  int end = 0;
  const int fields =
      io::scanC(key.c_str(),
                "variant %15[a-z]; rule %7[a-z]; global_modes %d; band_hz %lf; mac_threshold %lf; "
                "mogesec_masters %d; modes %d%n",
                variant_name, rule, &o.global_modes, &o.band_hz, &o.mac_threshold,
                &o.mogesec_masters, &o.mode_count, &end);
  if (fields != 7 || static_cast<std::size_t>(end) != key.size())
    return false;
  const std::string name = variant_name;
  if (name != "tracked" && name != "untracked")
    return false;
  const vehicle::Variant v = vehicle::parseVariant(name);
  const std::optional<VehicleModeRule> named_rule = modeRuleFromName(rule);
  if (!named_rule)
    return false;
  o.rule = *named_rule;
  // Exactly reductionKey()'s text (or the %.17g one of earlier versions): no other spelling,
  // every double to the last bit.
  const std::string legacy =
      std::string("variant ") + vehicle::variantName(v) + "; " + optionsText(o, true);
  if (reductionKey(v, o) != key && legacy != key)
    return false;
  *variant = v;
  *options = o;
  return true;
}

std::string reducedModelCachePath(const std::string& cache_dir, vehicle::Variant variant,
                                  const std::string& description_hash,
                                  const VehicleReductionOptions& options) {
  std::string name = std::string(vehicle::variantName(variant)) + "_" + description_hash;
  const std::string text = optionsText(options);
  if (text != optionsText(VehicleReductionOptions{})) {
    const std::uint64_t key = io::fnv1a(text);
    char hex[17];
    std::snprintf(hex, sizeof(hex), "%08llx", static_cast<unsigned long long>(key >> 32));
    name += std::string("_") + hex;
  }
  return (std::filesystem::path(cache_dir) / (name + ".mat")).string();
}

namespace {

// A vehicle's reduced model drives on road inputs, each reading the road where it stands: a file
// without them (a generic model's, or one edited and re-signed) passed the file's own checks,
// which allow a model without stations, and then read the stations of nothing (a null
// dereference in the terrain coverage check).
void requireRoadInputs(const std::string& path, const ReducedModel& model) {
  const DofIndex inputs = model.system.inputCount();
  if (inputs == 0)
    throw StaleCacheError(path +
                          ": the model has no road input (K_u has no column): not a "
                          "vehicle's reduced model");
  if (model.system.input_stations.size() != inputs || model.system.input_lateral.size() != inputs)
    throw StaleCacheError(path + ": " + std::to_string(inputs) + " road inputs but " +
                          std::to_string(model.system.input_stations.size()) +
                          " input_stations and " +
                          std::to_string(model.system.input_lateral.size()) +
                          " input_lateral: where each input reads the road is missing");
}

// The outputs vehicleOutputs() gives the description's vehicle (the file holds its hash): the
// hull's six, each road wheel's uz and each named point's three. A file edited and signed again
// with renamed outputs passed the file's checks and failed later as "frf: the model has no
// output 'hull uz'", naming neither the file nor what is wrong with it.
void requireVehicleOutputs(const std::string& path, const ReducedModel& model,
                           const vehicle::VehicleDescription& description) {
  std::vector<std::string> expected;
  for (int d = 0; d < kDofsPerNode; ++d)
    expected.push_back(std::string("hull ") + directionName(d));
  for (int side = 0; side < 2; ++side)
    for (int axle = 1; axle <= description.running_gear.axle_count; ++axle)
      expected.push_back(vehicle::roadWheelName(side, axle) + " uz");
  for (const vehicle::NamedPoint& point : description.named_points)
    for (int d = 0; d < 3; ++d)
      expected.push_back(point.name + " " + directionName(d));
  const std::vector<std::string>& names = model.system.output_names;
  for (const std::string& name : expected)
    if (std::find(names.begin(), names.end(), name) == names.end())
      throw StaleCacheError(path + ": the model has no output '" + name +
                            "', which the vehicle's reduced model has (output_names edited?)");
}

}  // namespace

VehicleModelFile loadVehicleModelFile(const std::string& path,
                                      const vehicle::VehicleDescription& description) {
  VehicleModelFile f;
  // A file the user names: another build of this release is taken with a warning (the cache,
  // loadOrReduceVehicle, rebuilds on any other version).
  ReducedModelLoadOptions load;
  load.require_same_version = false;
  f.model = loadReducedModel(path, vehicle::descriptionHashHex(description), load);
  requireRoadInputs(path, f.model);
  requireVehicleOutputs(path, f.model, description);
  if (!parseReductionKey(f.model.reduction, &f.variant, &f.options))
    throw StaleCacheError(path + ": its reduction '" + f.model.reduction +
                          "' is not one tvd reduce writes");
  return f;
}

ReducedModel loadOrReduceVehicle(const std::string& vehicle_file, vehicle::Variant variant,
                                 const std::string& cache_dir,
                                 const VehicleReductionOptions& options,
                                 VehicleReductionReport* report) {
  return loadOrReduceVehicle(vehicle::loadVehicleDescription(vehicle_file), variant, cache_dir,
                             options, report);
}

ReducedModel loadOrReduceVehicle(const vehicle::VehicleDescription& description,
                                 vehicle::Variant variant, const std::string& cache_dir,
                                 const VehicleReductionOptions& options,
                                 VehicleReductionReport* report) {
  VehicleReductionReport local;
  VehicleReductionReport& rep = report ? *report : local;
  rep.cache_rebuilt = false;
  const auto start = Clock::now();
  const std::string hash = vehicle::descriptionHashHex(description);
  const std::filesystem::path path = reducedModelCachePath(cache_dir, variant, hash, options);
  rep.cache_file = path.string();
  if (std::filesystem::exists(path)) {
    try {
      ReducedModelLoadOptions load;
      load.expected_reduction = reductionKey(variant, options);
      ReducedModel cached = loadReducedModel(path.string(), hash, load);
      requireRoadInputs(path.string(), cached);
      requireVehicleOutputs(path.string(), cached, description);
      rep.from_cache = true;
      rep.cache_note = "loaded " + path.string();
      rep.reduced_dofs = cached.size();
      rep.full_dofs = cached.full_dof_count;
      rep.flexible_modes = static_cast<int>(cached.modeCount());
      rep.warnings = cached.warnings;
      rep.total_seconds = secondsSince(start);
      return cached;
    } catch (const StaleCacheError& e) {
      rep.cache_note = std::string("rebuilt, the cached model cannot be used: ") + e.what();
      rep.cache_rebuilt = true;
    }
  } else {
    rep.cache_note = "built: no cached model " + path.string();
  }
  ReducedModel model = reduceVehicle(description, variant, options, &rep);
  try {
    std::filesystem::create_directories(cache_dir);
    saveReducedModel(model, path.string());
  } catch (const std::exception& e) {
    rep.cache_error = e.what();
    rep.cache_note += "; not cached: " + rep.cache_error;
  }
  rep.from_cache = false;
  rep.total_seconds = secondsSince(start);
  return model;
}

}  // namespace reduction
}  // namespace tracked_vehicle_dynamics
