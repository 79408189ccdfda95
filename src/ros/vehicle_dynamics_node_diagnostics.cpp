// The node's /diagnostics: one status per concern (loop, terrain, speed input, model, ground
// contact), filled by diagnostic_updater every ~diagnostic_period from what the node has counted.
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <sstream>
#include <string>

#include "tracked_vehicle_dynamics/dynamics/modal_system.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/ros/vehicle_dynamics_node.h"

namespace tracked_vehicle_dynamics {
namespace ros_layer {

namespace {

// Terrain starting this far [m] ahead of the front contact gets a hint at its stations: far
// beyond any look-ahead a source sends (a stopping distance or a sensor's range), near a map's
// offsets of a few hundred metres (review 130: 993 m ahead got no hint at 1 km).
constexpr double kFarAhead = 100.0;

}  // namespace

void VehicleDynamicsNode::diagnoseLoop(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const double period = 1.0 / params_.vehicle_options.rate;
  const std::uint64_t resyncs = loop_resyncs_.delta(events_.resyncs);
  const std::uint64_t late = loop_late_.delta(events_.late_ticks);
  const std::uint64_t jumps = loop_jumps_.delta(events_.time_jumps_back);
  const std::uint64_t clock_steps = loop_clock_steps_.delta(events_.clock_steps);
  const std::uint64_t diverged = loop_diverged_.delta(events_.diverged);
  const double step_p99 = step_window_.percentile(0.99);
  // ROS time that stopped moving (a paused or dead simulator, a bag at its end) is said: the
  // frozen step count alone reads like a healthy loop.
  const double stalled = (ros::SteadyTime::now() - last_time_change_).toSec();
  // More than one /clock: each jumps the other's time back, and every jump resets the vehicle
  // (review 165: two replays on one master reset it 2,460 times in 20 s, said only as jumps).
  const std::uint32_t clock_publishers = use_sim_time_ ? clock_sub_.getNumPublishers() : 0;
  const std::string two_clocks =
      clock_publishers > 1
          ? "/clock has " + std::to_string(clock_publishers) +
                " publishers: ROS time jumps between their clocks, resetting the vehicle at each "
                "jump back (a simulator and a rosbag play --clock, or two replays? one time "
                "source per master)"
          : std::string();
  if (clock_publishers > 1 && clock_publishers != clock_publishers_said_)
    ROS_WARN("%s: %s", nodeName(), two_clocks.c_str());
  clock_publishers_said_ = clock_publishers > 1 ? clock_publishers : 0;
  if (!clock_started_) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "waiting for ROS time (/clock)");
  } else if (diverged > 0) {  // the one ERROR: before any WARN
    status.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "non-finite outputs: reset");
  } else if (clock_publishers > 1) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, two_clocks);
  } else if (use_sim_time_ && stalled > params_.diagnostic_period) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "/clock has not advanced for " + brief(std::round(stalled * 10.0) / 10.0) +
                       " s of wall time: the simulation is paused or stopped");
  } else if (resyncs > 0 && step_window_.mean() > period) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "cannot keep up: a step takes longer than the period (lower ~rate, or use "
                   "~method modal); resynchronised beyond ~catch_up_limit");
  } else if (resyncs > 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   use_sim_time_ ? "/clock ran ahead of the steps beyond ~catch_up_limit (a "
                                   "jump, a coarse clock or slow steps): resynchronised"
                                 : "fell behind ROS time beyond ~catch_up_limit: resynchronised");
  } else if (jumps > 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "ROS time jumped backwards: vehicle reset");
  } else if (clock_steps > 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "the system clock stepped (" + last_clock_step_ +
                       "): the vehicle's time stepped with it, its motion went on");
  } else if (step_p99 > period) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "step time p99 exceeds the period");
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "running");
  }
  status.add("rate [Hz]", params_.vehicle_options.rate);
  status.add("steps", vehicle_->stepCount());
  status.add("simulated time [s]", vehicle_->time());
  status.add("station [m]", vehicle_->station());
  status.add("speed [m/s]", vehicle_->speed());
  status.add("ticks", events_.ticks);
  status.add("late ticks (total)", events_.late_ticks);
  status.add("late ticks (since last report)", late);
  status.add("max steps in one tick", max_steps_in_tick_);
  status.add("resynchronisations (total)", events_.resyncs);
  status.add("skipped time [s]", events_.skipped_steps * period);
  status.add("time jumps back (total)", events_.time_jumps_back);
  if (use_sim_time_)
    status.add("/clock publishers", clock_publishers);
  if (!use_sim_time_) {
    status.add("system clock steps (total)", events_.clock_steps);
    status.add("last system clock step", last_clock_step_.empty() ? "none" : last_clock_step_);
  }
  status.add("resets (total)", events_.resets);
  status.add("patches re-applied after a jump back (total)", events_.patches_reapplied);
  status.add("speeds re-applied after a jump back (total)", events_.speeds_reapplied);
  status.add("restarts held for the loop's terrain (total)", events_.terrain_holds);
  status.add("holds ended without terrain (total)", events_.terrain_holds_expired);
  status.add("holds ended without a speed (total)", events_.speed_holds_expired);
  status.add("runs at ~initial_speed held for their first patch (total)", events_.start_holds);
  status.add("start holds ended without terrain (total)", events_.start_holds_expired);
  status.add("non-finite resets (total)", events_.diverged);
  status.add("step time mean [us]", step_window_.mean() * 1e6);
  status.add("step time p99 [us]", step_p99 * 1e6);
  status.add("step time max [us]", step_window_.max() * 1e6);
  status.add("tick time mean [us]", tick_window_.mean() * 1e6);
  status.add("tick time p99 [us]", tick_window_.percentile(0.99) * 1e6);
  status.add("tick time max [us]", tick_window_.max() * 1e6);
  status.add("step time mean since start [us]", step_total_.mean() * 1e6);
  status.add("step time p99 since start [us]", step_total_.percentile(0.99) * 1e6);
  status.add("tick time p99 since start [us]", tick_total_.percentile(0.99) * 1e6);
  step_window_.clear();
  tick_window_.clear();
}

void VehicleDynamicsNode::diagnoseTerrain(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const std::uint64_t rejected = terrain_rejected_.delta(events_.patches_rejected);
  const std::uint64_t uncovered = terrain_uncovered_.delta(events_.uncovered_steps);
  const std::uint64_t narrow = terrain_narrow_.delta(events_.patches_narrow);
  const std::uint64_t behind = terrain_behind_.delta(events_.patches_behind);
  const std::uint64_t implausible = terrain_implausible_.delta(events_.patches_implausible);
  const std::uint64_t other_frame = terrain_other_frame_.delta(events_.patches_other_frame);
  const terrain::TerrainBuffer& buffer = vehicle_->terrain();
  const double ahead = buffer.coveredUntil() - vehicle_->frontContactStation();
  // Terrain that starts 100 m or more ahead of the vehicle is most often in a map's x, not
  // along this vehicle's path from its start: said beside the waiting or the underrun (review
  // 125: 5,000 patches from x = 5 km piled up with only "waiting" to show for it).
  std::string far_ahead;
  if (!buffer.empty() && buffer.coveredFrom() - vehicle_->frontContactStation() >= kFarAhead) {
    std::ostringstream text;
    text << "; the terrain starts "
         << std::lround(buffer.coveredFrom() - vehicle_->frontContactStation())
         << " m ahead of the front contact: stations along this vehicle's path from its start "
            "(odom x), not a map's x?";
    far_ahead = text.str();
  }
  if (buffer.empty() && rejected > 0) {
    // A source wrong from its first message must not look like one that has not started.
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "no terrain: the patches received were rejected");
  } else if (buffer.empty() && behind > 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "no terrain: the patches received lay wholly behind the vehicle (dropped)");
  } else if (hold_.active && (clock_started_ || !hold_.at_start)) {
    // A bag loop's first patches due any moment (or a run entered at speed, its terrain): the
    // restarted vehicle waits for them, unstepped. (Before the first /clock nothing steps yet.)
    status.summary(diagnostic_msgs::DiagnosticStatus::OK,
                   hold_.at_start
                       ? "holding the vehicle, started at ~initial_speed, until the terrain "
                         "covers its contacts"
                       : "ROS time jumped back: holding the restarted vehicle for the loop's "
                         "first patch");
  } else if (buffer.empty() && flat_since_restart_ &&
             (vehicle_->speed() == 0.0 || !clock_started_)) {
    // Standing on the flat ground of a start or reset until the terrain source begins is the
    // normal way to start, not a fault for an aggregator to flag. A speed given before the first
    // /clock does not move the vehicle yet (review 130: "moving" was said).
    status.summary(diagnostic_msgs::DiagnosticStatus::OK,
                   clock_started_
                       ? "waiting for terrain: standing on flat ground since the start or reset"
                       : "waiting for terrain: standing on flat ground until ROS time (/clock) "
                         "starts");
  } else if (buffer.empty()) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   flat_since_restart_ ? "no terrain yet: moving on flat ground since the start "
                                         "or reset"
                                       : "no terrain: holding the last heights");
  } else if (uncovered > 0) {
    status.summary(
        diagnostic_msgs::DiagnosticStatus::WARN,
        "terrain underrun: contacts off the terrain held at their last height" + far_ahead);
  } else if (rejected > 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "terrain patches rejected");
  } else if (behind > 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "patches wholly behind the vehicle dropped");
  } else if (implausible > 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "patches unlike ground (a step, slope or spacing): units or altitudes?");
  } else if (!stepped_patch_.empty()) {
    // The step's offset stays in every height after it: WARN until a reset clears the terrain.
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "terrain stepped off the ground since the start or reset (altitudes or units?): "
                   "the outputs on it are offset until ~reset");
  } else if (other_frame > 0 || latest_patch_other_frame_) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "patches in another frame than " + params_.odom_frame +
                       ": taken as stations along this vehicle's path");
  } else if (narrow > 0 || latest_patch_narrow_) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "patches narrower than the contacts: the outer ones read the edge lines");
  } else if (last_uncovered_ > 0 && standingOnClearedGround()) {
    // Standing where the last start or reset put it, on the flat ground it cleared to, with the
    // patches elsewhere (a ~reset_to target sent first): waiting, as with no patch; its steps
    // are not counted as uncovered.
    status.summary(diagnostic_msgs::DiagnosticStatus::OK,
                   "waiting for terrain under the contacts: standing on flat ground since the "
                   "start or reset" +
                       far_ahead);
  } else if (last_uncovered_ > 0 && vehicle_->speed() == 0.0) {
    // Stopped with contacts off the terrain (beyond its end, a driver that timed out): they
    // hold the heights they stand on; the underrun was said while it drove there.
    status.summary(diagnostic_msgs::DiagnosticStatus::OK,
                   "standing with contacts off the terrain: they hold the heights they stand on "
                   "until it moves");
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "covered");
  }
  status.add("patches accepted (total)", events_.patches_accepted);
  status.add("patches rejected (total)", events_.patches_rejected);
  status.add("patches rejected (since last report)", rejected);
  status.add("last rejection", last_patch_error_);
  status.add("patches narrower than the contacts (total)", events_.patches_narrow);
  status.add("last narrow patch", last_narrow_patch_);
  status.add("patches in another frame (total)", events_.patches_other_frame);
  status.add("last patch in another frame", last_other_frame_patch_);
  status.add("patches unlike ground (total)", events_.patches_implausible);
  status.add("last patch unlike ground", last_implausible_patch_);
  status.add("step off the ground since the start or reset",
             stepped_patch_.empty() ? std::string("none") : stepped_patch_);
  status.add("patches behind the vehicle, dropped (total)", events_.patches_behind);
  status.add("last patch behind the vehicle", last_behind_patch_);
  status.add("steps with uncovered contacts (total)", events_.uncovered_steps);
  status.add("steps with uncovered contacts (since last report)", uncovered);
  status.add("contacts off the terrain now", last_uncovered_);
  status.add("patches stored", buffer.patchCount());
  status.add("stored [MB]", std::round(static_cast<double>(buffer.storedBytes()) / 1e4) / 100.0);
  status.add("stored limit [MB]", static_cast<double>(buffer.memoryLimit()) / 1e6);
  if (buffer.empty()) {  // not the buffer's +-inf sentinels
    status.add("covered from [m]", "none");
    status.add("covered until [m]", "none");
    status.add("stored until [m]", "none");
    status.add("coverage ahead of the front contact [m]", "none");
  } else {
    status.add("covered from [m]", buffer.coveredFrom());
    status.add("covered until [m]", buffer.coveredUntil());
    // Beyond the contiguous coverage too: patches far ahead (stations not along the path?)
    // hold memory without covering the vehicle.
    status.add("stored until [m]", buffer.furthestEnd());
    status.add("coverage ahead of the front contact [m]", ahead);
  }
  // What a terrain source must cover now: from the rearmost contact to the frontmost one.
  status.add("rearmost contact [m]", vehicle_->rearContactStation());
  status.add("frontmost contact [m]", vehicle_->frontContactStation());
}

void VehicleDynamicsNode::diagnoseInput(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const std::uint64_t rejected = speed_rejected_.delta(events_.speeds_rejected);
  const std::uint64_t timeouts = speed_timed_out_.delta(events_.speed_timeouts);
  const std::uint64_t late = speed_late_.delta(events_.speeds_late);
  const std::uint64_t other_time_base = speed_time_base_.delta(events_.speeds_other_time_base);
  if (timeouts > 0 || stopped_by_timeout_) {  // until the next speed message moves it again
    // With a speed slew the vehicle brakes at ~max_deceleration: "stopping" until it stands.
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   vehicle_->speed() > 0.0
                       ? "no speed message within ~speed_timeout: vehicle stopping"
                       : "no speed message within ~speed_timeout: vehicle stopped");
  } else if (rejected > 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "speed messages rejected");
  } else if (other_time_base > 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "speed_stamped stamped in another time base: taken on arrival");
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "ok");
  }
  status.add("speed [m/s]", vehicle_->speed());
  if (vehicle_->slews()) {  // ~max_acceleration / ~max_deceleration
    status.add("commanded speed [m/s]", vehicle_->commandedSpeed());
    status.add("travel acceleration [m/s^2]", vehicle_->travelAcceleration());
  }
  status.add("max speed [m/s]", params_.max_speed);
  status.add("speeds accepted (total)", events_.speeds_accepted);
  status.add("speeds rejected (total)", events_.speeds_rejected);
  status.add("speeds rejected (since last report)", rejected);
  status.add("last rejection", last_speed_error_);
  // speed_stamped: applied at the step of its stamp; late ones (the sample already a step or
  // more past the stamp) at once, which a replay repeats exactly only at a standstill (where the
  // missed steps are made up).
  status.add("stamped speeds (total)", events_.speeds_stamped);
  status.add("stamped speeds waiting for their stamp", static_cast<long>(pending_speeds_.size()));
  status.add("stamped speeds late (total)", events_.speeds_late);
  status.add("stamped speeds late (since last report)", late);
  status.add("largest lateness since last report [s]", max_speed_lateness_);
  max_speed_lateness_ = 0.0;
  status.add("stamped speeds in another time base (total)", events_.speeds_other_time_base);
  status.add("last in another time base", last_other_time_base_);
  status.add("stamped in the pass before a jump back, dropped (total)",
             events_.speeds_of_pass_before);
  status.add("stamped before the stamped speed in force, dropped (total)",
             events_.speeds_superseded);
  status.add("late to a vehicle standing still, the missed steps made up (total)",
             events_.speeds_caught_up);
  status.add("speed timeout [s]", params_.speed_timeout);
  status.add("stops after the speed timeout (total)", events_.speed_timeouts);
}

void VehicleDynamicsNode::diagnoseModel(diagnostic_updater::DiagnosticStatusWrapper& status) {
  if (!params_.reduced_model.empty()) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "loaded from ~reduced_model");
  } else if (report_.from_cache) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "loaded from cache");
  } else if (cached_) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "built and cached");
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "built; not cached: " + not_cached_reason_);
  }
  if (damping_coupling_ > dynamics::kModalDampingCouplingTolerance)
    status.mergeSummary(diagnostic_msgs::DiagnosticStatus::WARN,
                        "~method modal drops the damping's coupling of the modes");
  status.add("vehicle file", params_.vehicle);
  status.add("vehicle", vehicle_->geometry().vehicle_name);
  status.add("variant", vehicle::variantName(params_.variant));
  status.add("reduced DOFs", static_cast<long>(model_dofs_));
  status.add("road inputs", static_cast<long>(model_inputs_));
  status.add("outputs", static_cast<long>(model_outputs_));
  status.add("full-model DOFs", static_cast<long>(report_.full_dofs));
  status.add("fixed-interface modes", report_.flexible_modes);
  status.add("damping", model_damping_);
  status.add("method", methodName(params_.vehicle_options.method));
  status.add("damping coupling dropped", damping_coupling_);
  status.add("hold", holdName(params_.vehicle_options.hold));
  status.add("cache file", report_.cache_file);
  status.add("cached", cached_);
  status.add("cache note", report_.cache_note);
  status.add("load time [s]", load_seconds_);
  status.add("discretisation set-up time [s]", setup_seconds_);
  status.add("comfort point", vehicle_->comfortPoint());
}

namespace {

// A pad by its side and station in base_link (the mean of its soles' x_q) and, for the model's
// files, its road inputs: "left pad at x = 1.86 m (road inputs 12, 13, 14, 15)".
std::string padName(const dynamics::GroundContactWatch& watch, int group, const Vector& stations) {
  std::string inputs;
  double x = 0.0;
  int soles = 0;
  for (const dynamics::GroundContact& c : watch.contacts())
    if (c.group == group) {
      inputs += (inputs.empty() ? "" : ", ") + std::to_string(c.input);
      x += stations(c.input);
      ++soles;
    }
  const DofIndex first = watch.groupContact(group);
  if (first < 0 || soles == 0)
    return "pad " + std::to_string(group);
  std::ostringstream text;
  text << dynamics::contactSideName(watch.contacts()[static_cast<std::size_t>(first)].side)
       << " pad at x = " << std::setprecision(4) << x / soles << " m (road inputs " << inputs
       << ")";
  return text.str();
}

}  // namespace

void VehicleDynamicsNode::diagnoseGroundContact(
    diagnostic_updater::DiagnosticStatusWrapper& status) {
  // The bonded linear model holds every contact on the road; a contact that pressed at rest and
  // now pulls (F < 0) is where a real vehicle would lift off: the results there are the model's.
  dynamics::GroundContactWatch* const watch = vehicle_->groundContactWatch();
  if (!watch) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK,
                   "not checked: " + vehicle_->groundContactUnavailable());
    return;
  }
  if (contact_every_ == 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "not checked (~ground_contact_rate 0)");
    return;
  }
  if (!vehicle_->groundTieDampingWarning().empty())
    status.add("damped ground ties", vehicle_->groundTieDampingWarning());
  const dynamics::GroundContactRecord interval = watch->takeInterval();
  const dynamics::GroundContactRecord& run = watch->sinceRestart();
  const dynamics::GroundContactNow& now = watch->now();
  // With pads known, a whole pad pulling is what leaves the range: a single sole pulls while its
  // pad rocks onto an edge (the tracked model's least-loaded sole carries 78 N at rest), which is
  // counted but not a WARN; on real roads at speed whole pads follow (ground_contact_watch.h).
  const bool pads = watch->groupCount() > 0;
  // No check since the last report (simulated time paused): the state is the last check's, so
  // is its verdict.
  const long pulling_now = pads ? now.groups_pulling : static_cast<long>(now.pulling);
  if (interval.checks == 0 && run.checks > 0 && pulling_now > 0) {
    status.summaryf(diagnostic_msgs::DiagnosticStatus::WARN,
                    "beyond the linear model's range at the last check: %ld %s pressed at rest "
                    "pulling (no check since the last report: time paused?)",
                    pulling_now, pads ? "pads" : "contacts");
  } else if (pads && interval.groupsBeyondRange()) {
    status.summaryf(diagnostic_msgs::DiagnosticStatus::WARN,
                    "beyond the linear model's range: up to %d pads pressed at rest pulled on the "
                    "road as a whole since the last report (a real vehicle would lift them off)",
                    interval.most_groups_pulling);
  } else if (pads && interval.beyondRange()) {
    status.summaryf(diagnostic_msgs::DiagnosticStatus::OK,
                    "pads on the road: up to %ld soles pressed at rest pulled since the last "
                    "report, no whole pad (a pad rocking on its soles)",
                    static_cast<long>(interval.most_pulling));
  } else if (pads && run.groupsBeyondRange()) {
    status.summaryf(diagnostic_msgs::DiagnosticStatus::OK,
                    "pads on the road since the last report (a pad lifted %.3f s after the start "
                    "or reset, station %.2f m)",
                    run.first_group_beyond_time, run.first_group_beyond_station);
  } else if (pads) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK,
                   run.beyondRange()
                       ? "pads on the road: every pad pressed at rest presses on it"
                       : "in range: every contact pressed at rest presses on the road");
  } else if (interval.beyondRange()) {
    status.summaryf(diagnostic_msgs::DiagnosticStatus::WARN,
                    "beyond the linear model's range: up to %ld contacts pressed at rest pulled "
                    "on the road since the last report (a real vehicle would lift off there)",
                    static_cast<long>(interval.most_pulling));
  } else if (run.beyondRange()) {
    status.summaryf(
        diagnostic_msgs::DiagnosticStatus::OK,
        "in range since the last report (left it %.3f s after the start or reset, station %.2f m)",
        run.first_beyond_time, run.first_beyond_station);
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK,
                   "in range: every contact pressed at rest presses on the road");
  }
  status.add("contacts", static_cast<long>(watch->contactCount()));
  status.add("pulling at rest (the bonded statics)", static_cast<long>(watch->pullingAtRest()));
  // The rate the checks run at: every round(~rate / ~ground_contact_rate) steps, so a requested
  // rate that does not divide ~rate is shown as run (and as asked, when they differ).
  const double check_rate = params_.vehicle_options.rate / static_cast<double>(contact_every_);
  status.add("check rate [Hz]", check_rate);
  if (std::abs(check_rate - params_.ground_contact_rate) > 1e-9 * params_.ground_contact_rate)
    status.add("check rate requested [Hz]", params_.ground_contact_rate);
  status.add("checks (since last report)", interval.checks);
  status.add("checks beyond the range (since last report)", interval.checks_beyond);
  status.add("most pulling at once (since last report)", static_cast<long>(interval.most_pulling));
  // How far beyond: the ground springs' largest total pull against the weight they carry at rest.
  status.add("largest total pull of contacts pressed at rest (since last report) [N]",
             interval.max_pull);
  if (watch->restForce() > 0.0)
    status.add("largest total pull (since last report) [% of the ground force at rest]",
               100.0 * interval.max_pull / watch->restForce());
  status.add("min force of a contact pressed at rest (since last report) [N]", interval.min_force);
  status.add("pulling now", static_cast<long>(now.pulling));
  status.add("ground force left now [N]", now.left);
  status.add("ground force right now [N]", now.right);
  status.add("checks beyond the range (since the last start or reset)", run.checks_beyond);
  if (run.beyondRange()) {
    const dynamics::GroundContact& c =
        watch->contacts()[static_cast<std::size_t>(run.first_beyond_contact)];
    status.add("first beyond the range: time since the start or reset [s]", run.first_beyond_time);
    status.add("first beyond the range: station [m]", run.first_beyond_station);
    status.add("first beyond the range: road input",
               std::to_string(c.input) + " (" + dynamics::contactSideName(c.side) + ")");
  }
  if (!pads)
    return;
  // The same for the pads, each force the sum of its soles'.
  status.add("pads", static_cast<long>(watch->groupCount()));
  status.add("pads pulling at rest (the bonded statics)",
             static_cast<long>(watch->groupsPullingAtRest()));
  status.add("checks with a pad pulling (since last report)", interval.checks_groups_beyond);
  status.add("most pads pulling at once (since last report)",
             static_cast<long>(interval.most_groups_pulling));
  status.add("min force of a pad pressed at rest (since last report) [N]",
             interval.min_group_force);
  status.add("pads pulling now", static_cast<long>(now.groups_pulling));
  status.add("checks with a pad pulling (since the last start or reset)", run.checks_groups_beyond);
  if (run.groupsBeyondRange()) {
    status.add("first pad pulling: time since the start or reset [s]", run.first_group_beyond_time);
    status.add("first pad pulling: station [m]", run.first_group_beyond_station);
    status.add("first pad pulling: pad",
               padName(*watch, run.first_group_beyond, vehicle_->sampler().stations()));
  }
}

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
