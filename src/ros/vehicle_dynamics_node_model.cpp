// The node's start-up model: the vehicle description, and the reduced model loaded from the
// cache (or reduced into it) or from ~reduced_model, with what the log and diagnostics say of it.
#include <chrono>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "tracked_vehicle_dynamics/dynamics/modal_system.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/heap_reuse.h"
#include "tracked_vehicle_dynamics/reduction/contact_groups.h"
#include "tracked_vehicle_dynamics/reduction/reduced_model_file.h"
#include "tracked_vehicle_dynamics/ros/online_names.h"
#include "tracked_vehicle_dynamics/ros/vehicle_dynamics_node.h"
#include "tracked_vehicle_dynamics/vehicle/track_tension.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"
#include "tracked_vehicle_dynamics/vehicle/wheel_rate_estimate.h"

namespace tracked_vehicle_dynamics {
namespace ros_layer {
namespace {

using Clock = std::chrono::steady_clock;

// A reduction key (reduction::reductionKey: every double to the last bit, for the cache) as a
// reader wants it: 0.7, not 0.69999999999999996.
std::string readableReduction(const std::string& key) {
  vehicle::Variant variant{};
  reduction::VehicleReductionOptions o;
  if (!reduction::parseReductionKey(key, &variant, &o))
    return key;
  return std::string("variant ") + vehicle::variantName(variant) + "; rule " +
         reduction::modeRuleName(o.rule) + "; global_modes " + std::to_string(o.global_modes) +
         "; band_hz " + brief(o.band_hz) + "; mac_threshold " + brief(o.mac_threshold) +
         "; mogesec_masters " + std::to_string(o.mogesec_masters) + "; modes " +
         std::to_string(o.mode_count);
}

}  // namespace

void VehicleDynamicsNode::loadVehicle() {
  const auto start = Clock::now();
  const std::string vehicle_param = private_nh_.resolveName("vehicle");
  try {
    // Parsed once: the reduction and the frames come from the same description.
    const vehicle::VehicleDescription description =
        vehicle::loadVehicleDescription(params_.vehicle);
    for (const std::string& w : vehicle::descriptionWarnings(description))
      ROS_WARN("%s: %s: %s", nodeName(), params_.vehicle.c_str(), w.c_str());
    // The comfort point is a parameter of its own: name it, not the vehicle, when it is unknown.
    // Resolved here, before the reduction, by OnlineVehicle's rule (resolveComfortPoint()):
    // unset (empty), the crew seat where the description names one, else the hull's CoG.
    std::string& point = params_.vehicle_options.comfort_point;
    std::vector<std::string> point_names;
    for (const vehicle::NamedPoint& p : description.named_points)
      point_names.push_back(p.name);
    try {
      point = resolveComfortPoint(point, point_names);
    } catch (const InputError&) {
      std::string known = "hull";
      for (const std::string& name : point_names)
        known += ", " + name;
      throw ParameterError(private_nh_.resolveName("comfort_point") + ": unknown point '" + point +
                           "' (" + known + " in " + params_.vehicle +
                           "); set ~comfort_point (launch argument comfort_point) to one of these");
    }
    if (!params_.comfort_point_given && point == "hull")
      ROS_INFO(
          "%s: ~comfort_point unset and %s names no '%s' point: ride comfort "
          "at the hull's CoG (set ~comfort_point to one of its points for a seat)",
          nodeName(), params_.vehicle.c_str(), kCrewSeatPoint);
    // The reduction's large matrices reuse freed pages (heap_reuse.h) until the model is loaded,
    // before the stepping starts; the free memory then goes back to the system (declared before
    // the model: it outlives it).
    const HeapReuse heap_reuse;
    // A reduction that the options cannot carry out on a valid description (no global mode
    // paired under ~reduction/mac_threshold 1.0) names ~reduction/* and the file; any other
    // failure is the description's (~vehicle, below).
    const reduction::ReducedModel model = [&] {
      if (!params_.reduced_model.empty())
        return loadGivenModel(description);
      try {
        return reduction::loadOrReduceVehicle(description, params_.variant, params_.cache_dir,
                                              params_.reduction_options, &report_);
      } catch (const reduction::ReductionOptionsError& e) {
        throw ParameterError(private_nh_.resolveName("reduction") + "/* (reducing " +
                             params_.vehicle + "): " + e.what());
      }
    }();
    // The model's load (or build) and the discretisation's set-up are timed apart: ~method
    // exact spends seconds in the augmented exponential, which is not the cache's doing.
    load_seconds_ = std::chrono::duration<double>(Clock::now() - start).count();
    const auto setup_start = Clock::now();
    // The pads the contacts belong to, for the ground-contact check's whole-pad records, and
    // where the frames go: from the vehicle's FE layout, which the cache does not keep (built
    // here once, in 4-16 ms on the tracked model).
    const vehicle::VehicleModel layout = vehicle::buildVehicleModel(description, params_.variant);
    vehicle_ = std::make_unique<OnlineVehicle>(model, vehicleGeometry(description, layout),
                                               params_.vehicle_options,
                                               reduction::roadInputGroups(layout, model));
    setup_seconds_ = std::chrono::duration<double>(Clock::now() - setup_start).count();
    // What the model does with the description's track tension, as tvd modes says it.
    if (const std::string tension = vehicle::trackTensionText(description, params_.variant);
        !tension.empty())
      ROS_INFO("%s: %s: %s", nodeName(), params_.vehicle.c_str(), tension.c_str());
    // The model's sag at rest against the hull on its torsion bars alone (as tvd statics and
    // modes say it): a chain or locked wheels carrying the hull, the usual sign of values copied
    // from the paper's vehicle onto a light one, said to integrators who never run tvd.
    const Vector6& rest = vehicle_->staticHullDisplacement();  // ux, uy, uz, rx, ry, rz
    for (const std::string& w :
         vehicle::restWarnings(rest(2), rest(4), description, params_.variant))
      ROS_WARN("%s: %s: %s", nodeName(), params_.vehicle.c_str(), w.c_str());
    model_dofs_ = model.size();
    model_inputs_ = model.system.inputCount();
    model_outputs_ = model.system.outputCount();
    model_damping_ = model.damping;
    // Saved with the model, so a cached or given model warns as the run that reduced it did
    // (e.g. a ~reduction/global_modes that cuts a repeated eigenvalue).
    for (const std::string& warning : model.warnings)
      ROS_WARN("%s: reduction: %s", nodeName(), warning.c_str());
    // ~method exact (or a ~max_mode_frequency above the ground ties) with modal damping: the
    // contact forces of the ground-contact check carry a damping force no road exerts.
    if (!vehicle_->groundTieDampingWarning().empty() && params_.ground_contact_rate > 0.0)
      ROS_WARN("%s: %s", nodeName(), vehicle_->groundTieDampingWarning().c_str());
    // ~method modal keeps only the diagonal of Phi^T C Phi (0 for exact): discrete dampers
    // couple the modes, as tvd simulate warns.
    damping_coupling_ = vehicle_->simulator().maxOffDiagonalDampingRatio();
    const std::string coupling = dynamics::modalDampingCouplingWarning(
        damping_coupling_, "~method modal",
        "~method exact integrates the whole C (seconds to set up on the tracked model)");
    if (!coupling.empty())
      ROS_WARN("%s: %s", nodeName(), coupling.c_str());
  } catch (const Error& e) {
    throw ParameterError(vehicle_param + " (" + params_.vehicle + "): " + e.what());
  }
  ROS_INFO("%s: %s discretisation at %g Hz set up in %.3f s", nodeName(),
           methodName(params_.vehicle_options.method), params_.vehicle_options.rate,
           setup_seconds_);
  if (!params_.reduced_model.empty()) {
    cached_ = true;  // nothing to cache: the file is the model
    ROS_INFO(
        "%s: loaded the reduced %s model of '%s' from ~reduced_model %s in "
        "%.3f s: %ld DOFs, %ld road inputs, %ld outputs (reduction %s; ~reduction/* not used)",
        nodeName(), vehicle::variantName(params_.variant), params_.vehicle.c_str(),
        params_.reduced_model.c_str(), load_seconds_, static_cast<long>(model_dofs_),
        static_cast<long>(model_inputs_), static_cast<long>(model_outputs_),
        readableReduction(given_reduction_).c_str());
    return;
  }
  // loadOrReduceVehicle() still builds when the cache cannot be written, and says why.
  cached_ = report_.from_cache || report_.cache_error.empty();
  not_cached_reason_ = report_.cache_error;
  const char* what = report_.from_cache ? "loaded" : cached_ ? "built and cached" : "built";
  // Why it was built (a stale or corrupt cache file) before what was built.
  if (!report_.cache_note.empty())
    ROS_INFO("%s: cache: %s", nodeName(), report_.cache_note.c_str());
  if (cached_) {
    ROS_INFO(
        "%s: %s the reduced %s model of '%s' in %.2f s: %ld DOFs, %ld road "
        "inputs, %ld outputs (%s)",
        nodeName(), what, vehicle::variantName(params_.variant), params_.vehicle.c_str(),
        load_seconds_, static_cast<long>(model_dofs_), static_cast<long>(model_inputs_),
        static_cast<long>(model_outputs_), report_.cache_file.c_str());
  } else {
    ROS_WARN(
        "%s: %s the reduced %s model of '%s' in %.2f s: %ld DOFs, %ld road "
        "inputs, %ld outputs; not cached: %s (%s): the next start builds it again",
        nodeName(), what, vehicle::variantName(params_.variant), params_.vehicle.c_str(),
        load_seconds_, static_cast<long>(model_dofs_), static_cast<long>(model_inputs_),
        static_cast<long>(model_outputs_), not_cached_reason_.c_str(), report_.cache_file.c_str());
  }
}

// ~reduced_model: a file of `tvd reduce --out`, checked as the cache is (complete MAT file,
// checksum, format version, software release (another build of it warns), the description's
// hash) and holding the ~variant. It is
// the user's explicit choice, so a file that fails a check stops the node instead of being
// rebuilt behind their back; the message says how to make a good one.
reduction::ReducedModel VehicleDynamicsNode::loadGivenModel(
    const vehicle::VehicleDescription& description) {
  const std::string param = private_nh_.resolveName("reduced_model");
  const std::string& file = params_.reduced_model;
  const std::string again = "; write it again with `tvd reduce --vehicle " + params_.vehicle +
                            " --variant " + vehicle::variantName(params_.variant) +
                            " --out FILE.mat`, or leave " + param + " unset to use the cache";
  reduction::VehicleModelFile loaded;
  try {
    loaded = reduction::loadVehicleModelFile(file, description);
  } catch (const reduction::StaleCacheError& e) {
    throw ParameterError(param + ": " + e.what() + again);
  }
  const reduction::ReducedModel& model = loaded.model;
  const vehicle::Variant variant = loaded.variant;
  if (variant != params_.variant)
    throw ParameterError(param + ": " + file + " holds the " + vehicle::variantName(variant) +
                         " variant, " + private_nh_.resolveName("variant") + " is " +
                         vehicle::variantName(params_.variant) + " (launch argument variant)");
  // tvd frf|simulate refuse reduction options with --reduced. The stock parameter file sets
  // every ~reduction/* to its default, so only values changed from the defaults are taken as
  // asked for; they are reported when the file was reduced otherwise.
  const std::string asked = reduction::reductionKey(variant, params_.reduction_options);
  if (asked != model.reduction && asked != reduction::reductionKey(variant, {}))
    ROS_WARN(
        "%s: %s: ~reduction/* ('%s') differ from the reduction of %s "
        "('%s'); the file's model runs and ~reduction/* are not used",
        nodeName(), param.c_str(), readableReduction(asked).c_str(), file.c_str(),
        readableReduction(model.reduction).c_str());
  given_reduction_ = model.reduction;
  report_ = {};
  report_.from_cache = true;  // loaded, not built: what the diagnostics report of a cache hit
  report_.cache_file = file;
  report_.cache_note =
      "~reduced_model " + file + " (reduction " + readableReduction(model.reduction) + ")";
  report_.full_dofs = model.full_dof_count;
  report_.reduced_dofs = model.size();
  report_.flexible_modes = static_cast<int>(model.modeCount());
  return std::move(loaded.model);
}

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
