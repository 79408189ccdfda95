#include "tracked_vehicle_dynamics/ros/vehicle_dynamics_node.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>
#include <utility>

#include <pthread.h>

#include <ros/topic_manager.h>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/ros/conversions.h"
#include "tracked_vehicle_dynamics/ros/online_names.h"
#include "tracked_vehicle_dynamics/terrain/terrain_plausibility.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"

#include "node_logging.h"

namespace tracked_vehicle_dynamics {
namespace ros_layer {
namespace {

using Clock = std::chrono::steady_clock;

using node_logging::kRewindWindow;
using node_logging::kWarnPeriod;

// Terrain messages queued: a source sending a whole track at start-up (hundreds of patches) must
// not lose the oldest (roscpp drops them from a full queue without a count).
constexpr std::uint32_t kTerrainQueue = 10000;

// On simulated time, a wait for the first /clock this long [s of wall time] is logged as a WARN,
// again every kClockWaitWarnPeriod while it lasts.
constexpr double kClockWaitWarnAfter = 10.0;
constexpr double kClockWaitWarnPeriod = 30.0;

// Publisher queues hold at least this many messages; more when one tick may publish more.
constexpr std::uint32_t kMinQueue = 10;

// "patch at x = 12 m: <doubt>: <doubt>" (terrain::patchWarnings' texts, which do not name it).
std::string patchDoubts(const TerrainPatch& patch, const std::vector<std::string>& doubts) {
  std::ostringstream text;
  text << "patch at x = " << patch.start_station << " m";
  for (const std::string& doubt : doubts)
    text << ": " << doubt;
  return text.str();
}

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

VehicleDynamicsNode::VehicleDynamicsNode(ros::NodeHandle nh, ros::NodeHandle private_nh)
    : nh_(nh),
      private_nh_(private_nh),
      params_(readParameters(private_nh)),
      loop_nh_(nh),
      loop_private_nh_(private_nh),
      // The updater reads its period from "diagnostic_period" under this handle, at every report
      // and as the parameter changes on the master: a namespace that does not hold it, so that
      // the node's own validated ~diagnostic_period, read once, sets the pace (reportDiagnostics):
      // a rosparam set of 1e10 or 0 at run time would otherwise throw out of every report, or
      // publish at ~rate.
      updater_(nh, ros::NodeHandle(private_nh, "diagnostic_updater")) {
  loop_nh_.setCallbackQueue(&loop_queue_);
  loop_private_nh_.setCallbackQueue(&loop_queue_);
  use_sim_time_ = ros::Time::isSimTime();
  loadVehicle();  // seconds when the model is built: a Ctrl-C meanwhile only flags the shutdown
  if (!ros::ok())
    throw StartUpInterrupted();
  setUpFrames();

  const double rate = params_.vehicle_options.rate;
  step_ns_ = std::max<std::int64_t>(1, std::llround(1e9 / rate));
  max_catch_up_steps_ = std::max<std::int64_t>(1, std::llround(params_.catch_up_limit * rate));
  // The run starts at ~initial_speed (at rest relative to it: no travel inertia), as a speed
  // message would set it now (on simulated time, ~speed_timeout counts from the first /clock).
  if (params_.initial_speed > 0.0) {
    vehicle_->resetTo(0.0, params_.initial_speed, ResetTerrain::Clear);
    takeInitialSpeed(now());
    holdForFirstPatch();
  }
  publish_every_ = std::max<std::int64_t>(1, std::llround(rate / params_.publish_rate));
  comfort_every_ = std::max<std::int64_t>(1, std::llround(rate / params_.comfort_rate));
  if (params_.ground_contact_rate > 0.0)
    contact_every_ = std::max<std::int64_t>(1, std::llround(rate / params_.ground_contact_rate));

  // One tick publishes up to max_catch_up_steps_ / publish_every_ samples before roscpp writes
  // any of them (on real time the tick runs in the network thread that writes them): each
  // queue holds a whole catch-up, so none is dropped.
  const auto queue = [this](std::int64_t every) {
    return static_cast<std::uint32_t>(
        std::max<std::int64_t>(kMinQueue, (max_catch_up_steps_ + every - 1) / every + 1));
  };
  advertise<tf2_msgs::TFMessage>("/tf", std::max<std::uint32_t>(100, queue(publish_every_)),
                                 &tf_pub_);
  advertise<geometry_msgs::AccelStamped>("hull/accel", queue(publish_every_), &accel_pub_);
  advertise<geometry_msgs::TwistStamped>("hull/twist", queue(publish_every_), &twist_pub_);
  advertise<RoadWheels>("road_wheels", queue(publish_every_), &wheels_pub_);
  advertise<Comfort>("comfort", queue(comfort_every_), &comfort_pub_);
  advertise<nav_msgs::Odometry>("odom", queue(publish_every_), &odom_pub_);
  for (std::size_t i : imu_points_) {
    imu_pubs_.push_back(std::make_unique<CountedPublisher>());
    advertise<sensor_msgs::Imu>("imu/" + vehicle_->geometry().points[i].name, queue(publish_every_),
                                imu_pubs_.back().get());
  }
  reset_service_ = loop_private_nh_.advertiseService("reset", &VehicleDynamicsNode::onReset, this);
  reset_to_service_ =
      loop_private_nh_.advertiseService("reset_to", &VehicleDynamicsNode::onResetTo, this);

  // The node's name first: two copies of one vehicle share the rest.
  updater_.setHardwareID(std::string(nodeName()) + ": " + vehicle_->geometry().vehicle_name +
                         (report_.cache_file.empty() ? "" : " (" + report_.cache_file + ")"));
  updater_.add("loop", this, &VehicleDynamicsNode::diagnoseLoop);
  updater_.add("terrain", this, &VehicleDynamicsNode::diagnoseTerrain);
  updater_.add("speed", this, &VehicleDynamicsNode::diagnoseInput);
  updater_.add("model", this, &VehicleDynamicsNode::diagnoseModel);
  updater_.add("ground contact", this, &VehicleDynamicsNode::diagnoseGroundContact);

  // Subscribed last: nothing arrives before the vehicle exists. The no-delay hint keeps the
  // message -> step latency low.
  // A terrain source may send a whole track at once: roscpp drops the oldest messages of a full
  // queue without a count, so it holds a burst of kTerrainQueue patches (ros_node.md).
  terrain_sub_ =
      loop_nh_.subscribe("terrain_profile", kTerrainQueue, &VehicleDynamicsNode::onTerrain, this,
                         ros::TransportHints().tcpNoDelay());
  speed_sub_ = loop_nh_.subscribe("speed", 10, &VehicleDynamicsNode::onSpeed, this,
                                  ros::TransportHints().tcpNoDelay());
  // Stamped speeds may be sent ahead of their time, a whole plan in one burst: the queue holds
  // as many as may wait for their stamps (a second of them at 1 kHz), so roscpp drops none of
  // them unsaid between two ticks (the ones beyond are refused and counted).
  speed_stamped_sub_ =
      loop_nh_.subscribe("speed_stamped", 1000, &VehicleDynamicsNode::onSpeedStamped, this,
                         ros::TransportHints().tcpNoDelay());
  if (use_sim_time_) {
    clock_sub_ = loop_nh_.subscribe("/clock", 10, &VehicleDynamicsNode::onClock, this,
                                    ros::TransportHints().tcpNoDelay());
  }
  // Publishing happens every round(rate / publish_rate) steps: the rate it gives is the one
  // logged, and a requested rate that does not divide ~rate is said to be rounded (against ~rate
  // as given: its own rounding to whole nanoseconds is said on its own).
  const double published_rate = rate / static_cast<double>(publish_every_);
  if (std::abs(params_.requested_rate / static_cast<double>(publish_every_) -
               params_.publish_rate) > 1e-9 * params_.requested_rate)
    ROS_WARN(
        "%s: ~publish_rate %g Hz does not divide ~rate %g Hz: publishing "
        "every %lld steps, at %g Hz",
        nodeName(), params_.publish_rate, rate, static_cast<long long>(publish_every_),
        published_rate);
  ROS_INFO("%s: %s (%s) at %.0f Hz, publishing at %g Hz, %s/%s", nodeName(),
           vehicle_->geometry().vehicle_name.c_str(), vehicle::variantName(params_.variant), rate,
           published_rate, methodName(params_.vehicle_options.method),
           holdName(params_.vehicle_options.hold));
  for (const std::string& warning : params_.warnings)
    ROS_WARN("%s: %s", nodeName(), warning.c_str());
  for (const std::string& unknown : params_.unknown_parameters)
    ROS_WARN("%s: parameter %s is set but not a parameter of this node: ignored", nodeName(),
             unknown.c_str());
  if (use_sim_time_)
    ROS_INFO(
        "%s: on simulated time (/use_sim_time true): the vehicle starts with "
        "the first /clock message",
        nodeName());
  // Last: a constructor that throws skips ~VehicleDynamicsNode (which stops the loop), and a
  // running std::thread destroyed with the members ends the process.
  if (use_sim_time_)
    loop_ = std::thread(&VehicleDynamicsNode::run, this);
  else
    tick_timer_ = std::make_unique<NetworkThreadTimer>(step_ns_, [this] { tick(); });
}

template <class M>
void VehicleDynamicsNode::advertise(const std::string& topic, std::uint32_t queue_size,
                                    CountedPublisher* out) {
  // The count is read by the topic's name, as Publisher::getNumSubscribers() does, not through
  // `publisher`: that is assigned when advertise() returns, and where a spinner already runs (the
  // node embedded in another process) a subscriber's connect callback may come before.
  const auto recount = [out](const ros::SingleSubscriberPublisher& link) {
    out->subscribers.store(static_cast<std::uint32_t>(
                               ros::TopicManager::instance()->getNumSubscribers(link.getTopic())),
                           std::memory_order_relaxed);
  };
  out->publisher = nh_.advertise<M>(topic, queue_size, recount, recount);
  // A shutdown after the check that follows loadVehicle() leaves an invalid publisher, which a
  // publish would trip on (an assertion in roscpp).
  if (!out->publisher)
    throw StartUpInterrupted();
}

// A step slower than the period (~method exact at a high ~rate) falls behind for good: the
// cause, not only the symptom, is what the user can act on. From the steps since the last
// diagnostics report, as the loop status judges them; built only when the warning is printed.
std::string VehicleDynamicsNode::slowStepCause() const {
  const double step_mean = step_window_.mean();
  if (!(step_mean * 1e9 > static_cast<double>(step_ns_)))
    return std::string();
  return " (a step takes " + brief(std::round(step_mean * 1e7) / 10.0) +
         " us on average, more than the period of " + brief(step_ns_ * 1e-3) +
         " us: lower ~rate, or use ~method modal)";
}

std::vector<std::string> VehicleDynamicsNode::judgePatch(const TerrainPatch& patch,
                                                         bool* stepped) const {
  // Against the terrain the contacts read before it, or the flat ground of a start or reset.
  const bool flat_ground = flat_since_restart_ && vehicle_->terrain().empty();
  terrain::PatchStep step;
  std::vector<std::string> doubts =
      terrain::patchWarnings(patch.start_station, patch.spacing, patch.lateral, patch.heights,
                             vehicle_->terrain(), flat_ground, &step);
  *stepped = step.implausible();
  return doubts;
}

void VehicleDynamicsNode::onTerrain(const TerrainProfile::ConstPtr& msg) {
  try {
    const TerrainPatch patch = fromMsg(*msg);
    // Judged against the terrain before it is added (the step at its start), said once taken.
    bool stepped = false;
    const std::vector<std::string> doubts = judgePatch(patch, &stepped);
    const bool taken = vehicle_->addTerrain(patch);
    std::string dropped;
    if (!taken) {
      std::ostringstream text;
      text << "patch at x = " << patch.start_station << " .. "
           << patch.start_station + patch.spacing * static_cast<double>(patch.heights.cols() - 1)
           << " m, rearmost contact at " << vehicle_->rearContactStation() << " m";
      dropped = text.str();
    }
    // Valid, but behind what the buffer keeps: a source lagging the vehicle, or a station frame
    // mistake, counted and said. On simulated time it is kept instead, and judged when a jump
    // back re-applies it or its window closes: a bag loop's first patches reach the node before
    // the /clock message of the jump, while the vehicle stands at the end of the pass before,
    // and are no fault (reapplyRecentInputs, expireRecentPatches).
    if (use_sim_time_)
      rememberPatch(msg, dropped);
    else if (!taken)
      reportDroppedPatch(dropped);
    if (!taken)
      return;
    flat_since_restart_ = false;
    notePatchTaken(msg->header.stamp);
    ++events_.patches_accepted;
    // The stations are along this vehicle's path by definition (TerrainProfile.msg), whatever
    // the header says; a patch that names another frame (map, or another vehicle's odom) is
    // taken all the same, but is more often a wiring mistake than a choice. The odom frame
    // without ~frame_prefix passes: a terrain source (or a bag made by tvd_make_bag) that
    // knows of no prefix.
    const std::string& frame = msg->header.frame_id;
    latest_patch_other_frame_ =
        !frame.empty() && frame != "/" &&
        !node_logging::namesOwnFrame(frame, params_.odom_frame, params_.frame_prefix);
    if (latest_patch_other_frame_) {
      ++events_.patches_other_frame;
      last_other_frame_patch_ = "patch at x = " + brief(patch.start_station) + " m in frame '" +
                                frame + "', not '" + params_.odom_frame + "'";
      TVD_WARN_THROTTLE(kWarnPeriod,
                        "%s: terrain %s: taken as stations along this vehicle's path all the same",
                        nodeName(), last_other_frame_patch_.c_str());
    }
    // Contacts beyond a patch's outer lines take the edge line's heights (terrain.h); a patch
    // narrower than the vehicle is more often a unit or frame mistake than a choice. One line is
    // a road uniform across the width (a profile: tvd_make_bag writes such files so), which
    // every contact reads as meant.
    const Vector& y = vehicle_->sampler().lateral();
    const double offset = params_.vehicle_options.lateral_offset;
    latest_patch_narrow_ = y.size() > 0 && patch.lateral.size() > 1 &&
                           (y.minCoeff() + offset < patch.lateral(0) - 1e-9 ||
                            y.maxCoeff() + offset > patch.lateral(patch.lateral.size() - 1) + 1e-9);
    if (latest_patch_narrow_) {
      ++events_.patches_narrow;
      std::ostringstream text;
      text << "patch at x = " << patch.start_station << " m spans y = " << patch.lateral(0)
           << " .. " << patch.lateral(patch.lateral.size() - 1) << " m, the contacts "
           << y.minCoeff() + offset << " .. " << y.maxCoeff() + offset << " m";
      last_narrow_patch_ = text.str();
      TVD_WARN_THROTTLE(kWarnPeriod,
                        "%s: terrain %s: narrower than the contacts, the outer ones read the "
                        "patch's edge lines",
                        nodeName(), last_narrow_patch_.c_str());
    }
    if (!doubts.empty()) {
      ++events_.patches_implausible;
      last_implausible_patch_ = patchDoubts(patch, doubts);
      if (stepped)
        stepped_patch_ = last_implausible_patch_;
      TVD_WARN_THROTTLE(kWarnPeriod, "%s: terrain %s", nodeName(), last_implausible_patch_.c_str());
    }
  } catch (const std::exception& e) {  // InputError, or bad_alloc for an absurd patch
    ++events_.patches_rejected;
    last_patch_error_ = e.what();
    TVD_WARN_THROTTLE(kWarnPeriod, "%s: terrain patch rejected: %s", nodeName(), e.what());
  }
}

bool VehicleDynamicsNode::standingOnClearedGround() const {
  return restart_cleared_ && vehicle_->speed() == 0.0 && vehicle_->station() == restart_station_;
}

void VehicleDynamicsNode::notePatchTaken(const ros::Time& stamp) {
  // During a hold, a late patch of the pass before (stamped nearer the old time than the new,
  // and not after the old pass's end: a source stamping in another time base counts as new)
  // neither ends it nor starts the new run's terrain. Unstamped patches cannot be told apart.
  // (Differences in double seconds: ros::Time's own throws beyond 2^31 s, for a wild stamp.)
  const double s = stamp.toSec();
  if (hold_.active && !stamp.isZero() && s <= hold_.old_time.toSec() + 1.0 &&
      std::abs(s - hold_.old_time.toSec()) < std::abs(s - hold_.new_time.toSec()))
    return;
  alignRestart(stamp);  // a bag loop's first patch after the jump back: the loop's start
  if (first_patch_lag_ < 0.0)
    first_patch_lag_ = run_start_.isZero() ? 0.0 : std::max(0.0, (now() - run_start_).toSec());
  if (hold_.active)
    hold_.terrain = true;  // advanceTo ends the hold once its inputs are in
}

double VehicleDynamicsNode::holdLimit() const {
  // Half of ~catch_up_limit: the held steps, and one /clock increment more at the release, are
  // then stepped within one tick's catch-up, without a resynchronisation.
  return 0.5 * params_.catch_up_limit;
}

void VehicleDynamicsNode::rememberPatch(const TerrainProfile::ConstPtr& msg, std::string dropped) {
  expireRecentPatches();
  recent_patches_.push_back({msg, latest_clock_, ros::SteadyTime::now(), std::move(dropped)});
}

void VehicleDynamicsNode::expireRecentPatches() {
  const ros::SteadyTime oldest = ros::SteadyTime::now() - ros::WallDuration(kRewindWindow);
  while (!recent_patches_.empty() && recent_patches_.front().arrival < oldest) {
    if (!recent_patches_.front().dropped.empty())
      reportDroppedPatch(recent_patches_.front().dropped);
    recent_patches_.pop_front();
  }
}

void VehicleDynamicsNode::reportDroppedPatch(const std::string& where) {
  ++events_.patches_behind;
  last_behind_patch_ = where;
  TVD_WARN_THROTTLE(kWarnPeriod,
                    "%s: terrain %s: wholly behind the vehicle by more than ~terrain_keep_behind "
                    "(%g m), dropped",
                    nodeName(), where.c_str(), params_.vehicle_options.terrain_keep_behind);
}

bool VehicleDynamicsNode::onReset(std_srvs::Empty::Request&, std_srvs::Empty::Response&) {
  ROS_INFO("%s: reset requested: back to static equilibrium at station 0%s", nodeName(),
           initialSpeedText().c_str());
  // Not published here: the current sample's stamp is already out, and tf2 discards a second
  // transform at the same stamp (TF_REPEATED_DATA). The next published sample shows the reset.
  // The old run's kept inputs first: a patch of it dropped behind is counted to it.
  forgetRecentInputs();
  restart(0.0, params_.initial_speed);
  takeInitialSpeed(now());
  holdForFirstPatch();
  return true;
}

bool VehicleDynamicsNode::onResetTo(ResetVehicle::Request& request,
                                    ResetVehicle::Response& response) {
  // Checked here, before anything changes: the node's ~max_speed applies as to `speed`.
  std::string why;
  if (!std::isfinite(request.station))
    why = "station " + brief(request.station) + " m is not finite";
  else if (std::abs(request.station) > kMaxResetStation)
    why = "station " + brief(request.station) + " m: |station| must not exceed " +
          brief(kMaxResetStation) + " m (beyond it a step's advance is lost in its rounding)";
  else
    why = speedProblem(request.speed);
  if (!why.empty()) {
    response.success = false;
    response.message = "~reset_to rejected: " + why + "; nothing changed";
    ROS_WARN("%s: %s", nodeName(), response.message.c_str());
    return true;  // the call itself succeeded: the answer is in the response
  }
  const ResetTerrain terrain = request.keep_terrain ? ResetTerrain::Keep : ResetTerrain::Clear;
  // The old run's kept inputs first: a patch of it dropped behind is counted to it.
  forgetRecentInputs();
  int uncovered = 0;
  try {
    uncovered = restart(request.station, request.speed, terrain);
  } catch (const std::exception& e) {  // checked above, so not expected
    response.success = false;
    response.message = std::string("~reset_to failed: ") + e.what();
    ROS_ERROR("%s: %s", nodeName(), response.message.c_str());
    return true;
  }
  // As ~reset: not published here (the current sample's stamp is already out, and tf2 discards
  // a second transform at it, TF_REPEATED_DATA); the next published sample shows the new state.
  // The requested speed counts as a speed message for ~speed_timeout.
  markSpeedTime(now());
  last_speed_taken_ = now();
  std::ostringstream text;
  text.precision(10);  // the default 6 digits would print station 123456.7 m as 123457
  text << "at station " << request.station << " m, speed " << request.speed
       << " m/s, in static equilibrium ";
  if (terrain == ResetTerrain::Clear)
    text << "on flat ground (terrain cleared)";
  else if (uncovered == 0)
    text << "on the terrain there";
  else
    text << "on the terrain there; " << uncovered << " of " << vehicle_->sampler().size()
         << " contacts off the terrain hold their last height";
  response.success = true;
  response.message = text.str();
  ROS_INFO("%s: ~reset_to: %s", nodeName(), response.message.c_str());
  return true;
}

int VehicleDynamicsNode::restart(double station, double speed, ResetTerrain terrain) {
  const int uncovered = vehicle_->resetTo(station, speed, terrain);
  restart_cleared_ = terrain == ResetTerrain::Clear;
  restart_station_ = station;
  // Cleared terrain means flat ground (u = 0) until a patch arrives, wherever the restart is.
  if (terrain == ResetTerrain::Clear) {
    flat_since_restart_ = true;
    stepped_patch_.clear();  // the offset terrain is gone
    latest_patch_other_frame_ = latest_patch_narrow_ = false;
  }
  stopped_by_timeout_ = false;  // a new run: the old one's driver timed out, not this one's
  restart_movable_ = false;     // restartAfterJump() allows it for its own restart
  speed_message_in_run_ = false;
  pending_speeds_.clear();  // the old run's schedule
  applied_speed_stamp_ = ros::Time();
  last_speed_taken_ = ros::Time();  // the restart's speed is no message's (~reset_to sets it)
  hold_ = Hold();
  run_start_ = now();
  // Terrain kept (~reset_to keep_terrain) is there from the run's start.
  first_patch_lag_ = terrain == ResetTerrain::Keep && !vehicle_->terrain().empty() ? 0.0 : -1.0;
  patches_behind_at_restart_ = events_.patches_behind;
  ++events_.resets;
  return uncovered;
}

void VehicleDynamicsNode::takeInitialSpeed(const ros::Time& t) {
  // The run's ~initial_speed counts as a speed message at `t`: ~speed_timeout runs from here (on
  // simulated time before the first /clock, t = 0: from the first /clock, as a speed message's).
  if (params_.initial_speed <= 0.0)
    return;
  markSpeedTime(t);
  last_speed_taken_ = t;
}

void VehicleDynamicsNode::holdForFirstPatch() {
  // A vehicle at rest waits for its terrain where it stands; one started moving would drive off
  // over the flat ground of the start before the source's first patches are in (a bag's come on
  // their own connection, a few /clock ticks after the first: up to 10 steps of "terrain
  // underrun" at the start of a replay entered at speed). It is held until its terrain covers
  // the contacts (terrainCoversHeldSteps), at most holdLimit(), as a bag loop's restart is (the
  // held steps are then stepped on it exactly); beyond, it drives on over the flat ground, which
  // the terrain diagnostics say.
  // On real time there is no replay to wait for, and the held steps would be caught up in one
  // late tick: a live source's patches reach the node as it runs (the contacts hold flat ground
  // until they do, which the terrain diagnostics say).
  if (!use_sim_time_ || params_.initial_speed <= 0.0 || !vehicle_->terrain().empty() ||
      max_catch_up_steps_ < 2 || hold_.active)
    return;
  hold_ = Hold();
  hold_.active = true;
  hold_.at_start = true;
}

bool VehicleDynamicsNode::terrainCoversHeldSteps(std::int64_t steps) const {
  // A held restart steps on once the terrain reaches every contact over the held steps: from the
  // rearmost contact now to the frontmost after `steps` steps at the speed (a bag's first patches
  // come in a burst, its first one alone 2 m behind the vehicle: released on it, the held steps
  // ran off its front, review 147).
  const auto& terrain = vehicle_->terrain();
  const double ahead = std::max(vehicle_->speed(), vehicle_->commandedSpeed()) *
                       static_cast<double>(steps) * static_cast<double>(step_ns_) * 1e-9;
  return !terrain.empty() && terrain.coveredFrom() <= vehicle_->rearContactStation() &&
         terrain.coveredUntil() >= vehicle_->frontContactStation() + ahead;
}

std::string VehicleDynamicsNode::initialSpeedText() const {
  return params_.initial_speed > 0.0
             ? ", speed " + brief(params_.initial_speed) + " m/s (~initial_speed)"
             : std::string();
}

void VehicleDynamicsNode::forgetRecentInputs() {
  for (const RecentPatch& recent : recent_patches_)
    if (!recent.dropped.empty())
      reportDroppedPatch(recent.dropped);
  recent_patches_.clear();
  forgetRecentSpeeds();
}

VehicleDynamicsNode::~VehicleDynamicsNode() {
  stop_ = true;
  tick_timer_.reset();
  if (loop_.joinable())
    loop_.join();
}

void VehicleDynamicsNode::onClock(const rosgraph_msgs::Clock::ConstPtr& msg) {
  // A bag loop is handled here, in queue order: the terrain and speed queued after this /clock
  // message (the bag's first patches) then reach the restarted vehicle instead of being wiped
  // by a restart at the next tick.
  if (clock_started_ && (msg->clock - sample_time_).toNSec() < -step_ns_)
    restartAfterJump(msg->clock);
  latest_clock_ = msg->clock;
}

void VehicleDynamicsNode::restartAfterJump(const ros::Time& now) {
  ++events_.time_jumps_back;
  // Every reset is said: each one loses the vehicle's state and speed. Not when two /clock
  // publishers jump the time back and forth hundreds of times a second: then once a second of
  // wall time (rosconsole's throttle reads ROS time, which each jump re-opens), and the
  // diagnostics name the cause.
  const std::uint32_t clock_publishers = clock_sub_.getNumPublishers();
  if (clock_publishers > 1)
    TVD_WARN_THROTTLE(1.0,
                      "%s: ROS time jumped back by %.3f s: resetting the vehicle to equilibrium "
                      "at station 0%s (/clock has %u publishers; %llu jumps back so far)",
                      nodeName(), (sample_time_ - now).toSec(), initialSpeedText().c_str(),
                      clock_publishers, static_cast<unsigned long long>(events_.time_jumps_back));
  else
    ROS_WARN(
        "%s: ROS time jumped back by %.3f s: resetting the vehicle to equilibrium at station 0%s",
        nodeName(), (sample_time_ - now).toSec(), initialSpeedText().c_str());
  // Held for if the run before had terrain from its start (or was itself held), and moving.
  // A hold needs a catch-up of two steps at least (~catch_up_limit): the held steps are stepped
  // in one tick at the release.
  const bool hold_for_terrain =
      max_catch_up_steps_ >= 2 &&
      ((hold_.active && !hold_.at_start) ||
       (!flat_since_restart_ && first_patch_lag_ >= 0.0 && first_patch_lag_ <= holdLimit()));
  // A speed is awaited only from a run that a speed message moved: one moving at ~initial_speed
  // or a ~reset_to's speed alone restarts as it started (review 147: every loop waited out the
  // hold for a speed that never came).
  const bool had_speed = (speed_message_in_run_ && vehicle_->commandedSpeed() > 0.0) ||
                         (hold_.active && hold_.awaiting_speed);
  const ros::Time old_time = sample_time_;
  last_jump_old_time_ = old_time;
  last_jump_new_time_ = now;
  last_jump_arrival_ = ros::SteadyTime::now();
  const std::uint64_t speeds_before = events_.speeds_reapplied;
  const std::uint64_t patches_before = events_.patches_reapplied;
  const bool other_frame = latest_patch_other_frame_, narrow = latest_patch_narrow_;
  // Each pass starts as the first did: at ~initial_speed, as if a speed message had come now.
  // (A speed that came back with the jump, re-applied below, overrides it.)
  restart(0.0, params_.initial_speed);
  takeInitialSpeed(now);
  sample_time_ = now;
  run_start_ = now;
  restart_movable_ = !now.isZero();
  alignRestart(earliestRecentStamp(now));
  reapplyRecentInputs(now);
  // The re-applied patches are the ones judged when they arrived: so are their faults.
  if (events_.patches_reapplied > patches_before) {
    latest_patch_other_frame_ = other_frame;
    latest_patch_narrow_ = narrow;
  }
  // The old pass's patches lost in the re-application belong to it, not to the new run.
  patches_behind_at_restart_ = events_.patches_behind;
  // A bag loop's first patches may reach the node after its /clock has moved on (a loaded
  // machine, separate connections): stepping meanwhile would drive the restarted vehicle over the
  // flat ground of the restart, unlike the first loop. So when the run before had terrain and
  // none came back with the jump, the vehicle waits for it, and for a speed when one is due (at
  // most holdLimit() of simulated time, which the catch-up then steps exactly on the patches;
  // advanceTo ends the hold).
  if (hold_for_terrain && vehicle_->terrain().empty()) {
    hold_.active = true;
    hold_.awaiting_speed = had_speed && events_.speeds_reapplied == speeds_before;
    hold_.old_time = old_time;
    hold_.new_time = now;
    ++events_.terrain_holds;
  } else {
    holdForFirstPatch();  // the start's hold, at ~initial_speed with no terrain re-applied
  }
  if (now.isZero()) {
    // Back to time 0 (a simulator's world reset): ROS time 0 means "no time yet", as before the
    // first /clock. The vehicle waits at rest and its first sample is stamped when the clock
    // runs again, not 0.0.
    clock_started_ = false;
    reportDiagnostics(now);
    return;
  }
  publishState();
  reportDiagnostics(now);
}

ros::Time VehicleDynamicsNode::earliestRecentStamp(const ros::Time& now) const {
  // The inputs reapplyRecentInputs() takes as the new time's (stamped nearer `now` than the ROS
  // time they arrived at), stamped at or before `now`.
  const ros::SteadyTime oldest = ros::SteadyTime::now() - ros::WallDuration(kRewindWindow);
  ros::Time earliest;
  const auto consider = [&](const ros::Time& stamp, const ros::Time& ros_arrival,
                            const ros::SteadyTime& arrival) {
    if (arrival < oldest || stamp > now || !node_logging::ofNewTime(stamp, ros_arrival, now))
      return;
    if (earliest.isZero() || stamp < earliest)
      earliest = stamp;
  };
  for (const RecentPatch& recent : recent_patches_)
    consider(recent.msg->header.stamp, recent.ros_arrival, recent.arrival);
  for (const RecentSpeed& recent : recent_stamped_speeds_)
    consider(recent.stamp, recent.ros_arrival, recent.arrival);
  return earliest;
}

void VehicleDynamicsNode::alignRestart(const ros::Time& stamp) {
  // rosbag play's /clock follows the wall clock: the first /clock after a loop's jump back is a
  // few milliseconds past the loop's start (6 to 9 ms measured, review 131), and the restart,
  // stamped there, put every later loop that much behind the first and off its step grid (35 to
  // 41 mm of station at 20 km/h). The loop's first inputs are stamped at its start: before any
  // step, the restart moves back to them (at most holdLimit(), which the catch-up then steps).
  if (!restart_movable_ || stamp.isZero() || stamp >= sample_time_ ||
      last_jump_new_time_.toSec() - stamp.toSec() > holdLimit())
    return;
  sample_time_ = stamp;
  run_start_ = stamp;
}

void VehicleDynamicsNode::reportDiagnostics(const ros::Time& now) {
  next_diagnostics_ = now + ros::Duration(params_.diagnostic_period);
  publishDiagnostics();
}

void VehicleDynamicsNode::publishDiagnostics() {
  // A report must not end the loop, nor a failing step silence the reports: each on its own.
  try {
    updater_.force_update();
  } catch (const std::exception& e) {
    TVD_ERROR_THROTTLE(kWarnPeriod, "%s: publishing /diagnostics failed: %s", nodeName(), e.what());
  }
}

void VehicleDynamicsNode::reapplyRecentInputs(const ros::Time& now) {
  // A patch of the new time (a bag's next loop) that arrived before the jump was stamped near
  // `now`, long before the old time it arrived at; one of the old time was stamped near the
  // old time. Unstamped patches cannot be told apart and are not re-applied.
  const ros::SteadyTime oldest = ros::SteadyTime::now() - ros::WallDuration(kRewindWindow);
  for (const RecentPatch& recent : recent_patches_) {
    const ros::Time& stamp = recent.msg->header.stamp;
    // Not of the new time: a patch dropped as wholly behind is lost for good.
    if (recent.arrival < oldest || !node_logging::ofNewTime(stamp, recent.ros_arrival, now)) {
      if (!recent.dropped.empty())
        reportDroppedPatch(recent.dropped);
      continue;
    }
    try {
      const TerrainPatch patch = fromMsg(*recent.msg);
      // Judged again against the restarted vehicle's flat ground: a loop of absolute altitudes
      // steps off it as the first loop did.
      bool stepped = false;
      const std::vector<std::string> doubts = judgePatch(patch, &stepped);
      if (stepped)
        stepped_patch_ = patchDoubts(patch, doubts) + " (re-applied after the time jump back)";
      if (!vehicle_->addTerrain(patch)) {  // still wholly behind the restarted vehicle: lost
        if (!recent.dropped.empty())
          reportDroppedPatch(recent.dropped);
        continue;
      }
      flat_since_restart_ = false;
      if (first_patch_lag_ < 0.0)
        first_patch_lag_ = 0.0;
      ++events_.patches_reapplied;
    } catch (const std::exception& e) {  // accepted once, so not expected
      TVD_WARN_THROTTLE(kWarnPeriod, "%s: terrain patch rejected: %s", nodeName(), e.what());
    }
  }
  recent_patches_.clear();
  reapplyRecentSpeeds(now);
}

void VehicleDynamicsNode::reportOnWallTime(const ros::SteadyTime& wall) {
  if (wall < next_wall_report_)
    return;
  next_wall_report_ = wall + ros::WallDuration(params_.diagnostic_period);
  // On simulated time with no /clock the vehicle waits, which /diagnostics say; a log read
  // without them said nothing after the start-up line (review 130).
  if (use_sim_time_ && !clock_started_) {
    if (clock_wait_start_.isZero())
      clock_wait_start_ = wall;
    const double waited = (wall - clock_wait_start_).toSec();
    if (waited >= kClockWaitWarnAfter && wall >= next_clock_warning_) {
      ROS_WARN(
          "%s: on simulated time (/use_sim_time true) with no /clock for %.0f s of wall time: "
          "the vehicle waits at rest (is the simulator, or rosbag play --clock, running?)",
          nodeName(), waited);
      next_clock_warning_ = wall + ros::WallDuration(kClockWaitWarnPeriod);
    }
  }
  publishDiagnostics();
}

ros::Time VehicleDynamicsNode::now() const {
  return use_sim_time_ ? latest_clock_ : ros::Time::now();
}

void VehicleDynamicsNode::run() {
  // Named so that top -H, perf and the benchmark tell the integration loop from roscpp's threads.
  pthread_setname_np(pthread_self(), "tvd_step_loop");
  // Every /clock message wakes the loop; the timeout only keeps it responsive to shutdown when
  // the clock stops.
  const ros::WallDuration sim_wait(0.05);
  while (!stop_ && ros::ok()) {
    handleMessages(sim_wait);
    tick_start_ = Clock::now();  // the wait for /clock is not the node's time
    step();
  }
}

void VehicleDynamicsNode::tick() {
  // The tick's time includes handling the messages that arrived: a huge terrain patch is copied
  // and checked here, on the loop's thread, and delays the steps.
  tick_start_ = Clock::now();
  // A step of the system clock is followed before the messages' stamps are judged against the
  // vehicle's time (a new stamped speed would be dropped as older than the one in force).
  ros::Time t;
  ros::SteadyTime wall;
  if (readClocks(&t, &wall))
    followClockStep(t, wall);
  handleMessages(ros::WallDuration(0));
  step();
}

void VehicleDynamicsNode::handleMessages(const ros::WallDuration& wait) {
  // roscpp passes a subscriber callback's exception out of callAvailable: here it would end the
  // loop's thread, and with it the process. None is expected (each callback catches what its
  // message can cause); one that escapes is reported and the loop goes on.
  try {
    loop_queue_.callAvailable(wait);
  } catch (const std::exception& e) {
    TVD_ERROR_THROTTLE(kWarnPeriod, "%s: handling a message failed: %s", nodeName(), e.what());
  }
}

void VehicleDynamicsNode::step() {
  ros::Time t;
  ros::SteadyTime wall;
  const bool paired = readClocks(&t, &wall);
  if (!recent_patches_.empty())
    expireRecentPatches();  // a patch dropped behind, with no jump back to re-apply it, is lost
  if (!recent_stamped_speeds_.empty())
    expireRecentSpeeds();
  if (t != last_step_time_) {
    last_step_time_ = t;
    last_time_change_ = wall;
  } else if (wall - last_time_change_ > ros::WallDuration(params_.diagnostic_period)) {
    reportOnWallTime(wall);
  }
  if (t.isZero())
    return;  // use_sim_time and no /clock yet
  if (paired)
    followClockStep(t, wall);  // real time: the system clock stepped since the last tick?
  // A speed (or ~reset_to) received before simulated time started was stamped 0: its timeout
  // counts from the first /clock, not from the epoch (it would stop the vehicle at once).
  if (!clock_started_ && last_speed_time_.isZero())
    last_speed_time_ = t;
  // A driver that stopped publishing must not leave the vehicle driving on: it stops where it is
  // and the next speed message moves it again. With a speed slew it brakes to a stop at
  // ~max_deceleration (the commanded speed is what the timeout zeroes, once). The stamped speeds
  // it sent ahead go with it: applied later, they would undo the stop.
  const double since_speed = params_.speed_timeout > 0.0 ? secondsSinceSpeed(t, wall) : 0.0;
  if (params_.speed_timeout > 0.0 &&
      (vehicle_->commandedSpeed() > 0.0 || !pending_speeds_.empty()) &&
      since_speed > params_.speed_timeout) {
    const std::string schedule = pending_speeds_.empty()
                                     ? std::string()
                                     : " (dropping the " + std::to_string(pending_speeds_.size()) +
                                           " stamped speeds still waiting for their stamps)";
    ROS_WARN("%s: no speed message for %.3f s (~speed_timeout %.3f s): %s %.3f m%s", nodeName(),
             since_speed, params_.speed_timeout,
             vehicle_->slews() ? "braking to a stop at ~max_deceleration from station"
                               : "stopping the vehicle at station",
             vehicle_->station(), schedule.c_str());
    pending_speeds_.clear();
    vehicle_->setSpeed(0.0);
    last_speed_taken_ = t;
    ++events_.speed_timeouts;
    stopped_by_timeout_ = true;
  }
  try {
    advanceTo(t);
  } catch (const std::exception& e) {
    // Nothing in a step is expected to throw; if it does, the node reports it and goes on.
    TVD_ERROR_THROTTLE(kWarnPeriod, "%s: step failed: %s", nodeName(), e.what());
  }
  // Paced on the node's own time (sim: its /clock; a time that stepped back re-arms it).
  if (t >= next_diagnostics_ || (next_diagnostics_ - t).toSec() > params_.diagnostic_period)
    reportDiagnostics(t);
}

void VehicleDynamicsNode::advanceTo(const ros::Time& now) {
  const auto tick_start = tick_start_;
  ++events_.ticks;
  if (!clock_started_) {
    clock_started_ = true;
    clock_wait_start_ = ros::SteadyTime();  // a later wait (time reset to 0) counts afresh
    sample_time_ = now;
    if (run_start_.isZero())
      run_start_ = now;
    if (!pending_static_.empty()) {
      for (auto& t : pending_static_)
        t.header.stamp = now;
      static_broadcaster_->sendTransform(pending_static_);
      pending_static_.clear();
    }
    publishState();
    return;
  }
  const std::int64_t ahead_ns = (now - sample_time_).toNSec();
  if (ahead_ns < -step_ns_) {
    if (use_sim_time_) {
      // A clock reset not seen by onClock(): the terrain and station of the past no longer apply.
      restartAfterJump(now);
      return;
    }
    // The system clock stepped back unseen by followClockStep() (a tick whose clocks could not
    // be read as a pair): the vehicle's time follows it as far as the last sample shows.
    moveTime(ahead_ns, now);
    return;
  }
  // On the wall clock the ticks come from the monotonic timer; rounding absorbs its wake-up
  // jitter, which would otherwise alternate 0 and 2 steps per tick. Simulated time is exact.
  std::int64_t due = ahead_ns <= 0   ? 0
                     : use_sim_time_ ? ahead_ns / step_ns_
                                     : (ahead_ns + step_ns_ / 2) / step_ns_;
  if (due == 0)
    return;
  if (hold_.active) {
    // A run entered at speed that a speed 0 stopped needs no terrain ahead: nothing to wait for.
    // (A loop's restart stands until its speed comes: it waits for its terrain all the same.)
    const bool standing =
        hold_.at_start && vehicle_->speed() == 0.0 && vehicle_->commandedSpeed() == 0.0;
    const bool covered = hold_.terrain && terrainCoversHeldSteps(due);
    const bool inputs = standing || (covered && (!hold_.awaiting_speed || hold_.speed));
    const bool due_out =
        static_cast<double>(due) * static_cast<double>(step_ns_) * 1e-9 >= holdLimit();
    if (!inputs && !due_out) {
      if (hold_.at_start && !hold_.counted) {  // counted once it holds a step
        hold_.counted = true;
        ++events_.start_holds;
      }
      return;  // the steps wait for the new pass's inputs (restartAfterJump)
    }
    const bool terrain = hold_.terrain, at_start = hold_.at_start;
    hold_ = Hold();
    if (at_start) {
      // Ran out: no terrain source yet (the diagnostics say "moving"), or one whose patches do
      // not reach the contacts.
      if (!inputs)
        ++events_.start_holds_expired;
    } else if (!terrain) {
      ++events_.terrain_holds_expired;
      TVD_WARN_THROTTLE(kWarnPeriod,
                        "%s: no terrain patch within half ~catch_up_limit (%.3f s) of simulated "
                        "time after ROS time jumped back, although the run before had terrain "
                        "from its start: driving on from station %.2f m on flat ground",
                        nodeName(), holdLimit(), vehicle_->station());
    } else if (!inputs) {
      // The terrain came, the speed did not (a driver that sends it once, or latched): the
      // vehicle goes on at the restart's speed, as it would have without the hold.
      ++events_.speed_holds_expired;
    }
  }
  if (due > 1 && !use_sim_time_)  // on simulated time the /clock period sets the steps per tick
    ++events_.late_ticks;
  if (due > max_catch_up_steps_) {
    const std::int64_t skipped = due - max_catch_up_steps_;
    ++events_.resyncs;
    events_.skipped_steps += static_cast<std::uint64_t>(skipped);
    // On simulated time a tick follows /clock: so far ahead, the clock jumped, ticks coarsely,
    // or ran faster than the node could step; "behind" alone would blame the node.
    if (use_sim_time_)
      TVD_WARN_THROTTLE(kWarnPeriod,
                        "%s: ROS time (/clock) is %.3f s ahead of the last sample, more than "
                        "~catch_up_limit (%.3f s): a clock jump, a /clock coarser than the limit, "
                        "or steps slower than the clock; skipping %.3f s and resynchronising (the "
                        "vehicle state and station are kept)%s",
                        nodeName(), ahead_ns * 1e-9, params_.catch_up_limit,
                        skipped * step_ns_ * 1e-9, slowStepCause().c_str());
    else
      TVD_WARN_THROTTLE(kWarnPeriod,
                        "%s: %.3f s behind ROS time, more than ~catch_up_limit "
                        "(%.3f s): skipping %.3f s and resynchronising%s",
                        nodeName(), ahead_ns * 1e-9, params_.catch_up_limit,
                        skipped * step_ns_ * 1e-9, slowStepCause().c_str());
    sample_time_ += ros::Duration().fromNSec(skipped * step_ns_);
    due = max_catch_up_steps_;
  }
  max_steps_in_tick_ = std::max(max_steps_in_tick_, due);
  for (std::int64_t k = 0; k < due; ++k) {
    restart_movable_ = false;  // stepped: the restart's time is taken
    applyDueSpeeds();  // the stamped speeds whose time has come: this step is driven by them
    const auto step_start = Clock::now();
    const StepResult result = vehicle_->step();
    const double step_seconds = secondsSince(step_start);
    step_window_.add(step_seconds);
    step_total_.add(step_seconds);
    sample_time_ += ros::Duration().fromNSec(step_ns_);
    ++steps_since_start_;
    last_uncovered_ = result.uncovered;
    // Standing still is not an underrun: before any terrain arrived (the normal start), where a
    // start or reset put it while the patches lie elsewhere (a ~reset_to target sent first), or
    // stopped beyond the terrain's end (a driver timed out, ~speed_timeout braking past the
    // patches sent ahead): contacts that do not move hold the heights they stand on. The
    // underrun was counted and said while it drove off the terrain.
    const bool waiting = vehicle_->speed() == 0.0;
    if (result.uncovered > 0 && !waiting) {
      ++events_.uncovered_steps;
      if (vehicle_->terrain().empty()) {
        // Only this run's: a bag loop's earlier passes dropped (and re-applied) patches too.
        const std::uint64_t dropped = events_.patches_behind - patches_behind_at_restart_;
        const std::string behind =
            dropped == 0 ? std::string()
                         : " (" + std::to_string(dropped) +
                               " patches arrived wholly behind the vehicle since the last start "
                               "or reset and were dropped)";
        TVD_WARN_THROTTLE(kWarnPeriod,
                          "%s: no terrain stored%s, moving at %.3f m/s at station %.2f m: the "
                          "contacts hold their last height",
                          nodeName(), behind.c_str(), vehicle_->speed(), vehicle_->station());
      } else {
        TVD_WARN_THROTTLE(kWarnPeriod,
                          "%s: no terrain under %d of %d contacts at station "
                          "%.2f m (terrain covers %.2f .. %.2f m): holding their last height",
                          nodeName(), result.uncovered, vehicle_->sampler().size(),
                          vehicle_->station(), vehicle_->terrain().coveredFrom(),
                          vehicle_->terrain().coveredUntil());
      }
    }
    if (result.diverged) {
      ++events_.diverged;
      TVD_ERROR_THROTTLE(kWarnPeriod, "%s: non-finite outputs: back to equilibrium", nodeName());
    }
    if (steps_since_start_ % publish_every_ == 0)
      publishState();
    if (steps_since_start_ % comfort_every_ == 0)
      publishComfort();
    if (contact_every_ > 0 && steps_since_start_ % contact_every_ == 0)
      vehicle_->checkGroundContact();
  }
  const double tick_seconds = secondsSince(tick_start);
  tick_window_.add(tick_seconds);
  tick_total_.add(tick_seconds);
}

void VehicleDynamicsNode::publishState() {
  // Only what someone listens to is built (a recorder or a tf listener subscribes).
  const bool tf = tf_pub_.listened();
  const bool twist = twist_pub_.listened();
  const bool accel = accel_pub_.listened();
  const bool wheels = wheels_pub_.listened();
  const OnlineVehicle& v = *vehicle_;
  const RigidPose pose = v.hullPose();
  const Vector6 displacement = v.hullDisplacement();  // {u_G; theta}
  const Vector6 velocity = v.hullVelocity();          // their rates (vibration only)

  if (tf) {
    auto& transforms = tf_msg_.transforms;
    for (auto& t : transforms)
      t.header.stamp = sample_time_;
    std::size_t k = 0;
    for (HullLink link : hull_links_) {
      RigidPose hull;
      if (link == HullLink::Whole)
        hull = pose;
      else if (link == HullLink::Path)
        hull.translation.x() = v.station();  // the footprint: (s, 0, 0), unrotated
      else
        hull = relativeToPath(pose, v.station());
      toMsg(hull, &transforms[k++].transform);
    }
    RigidPose relative;
    for (std::size_t i = 0; i < v.geometry().wheels.size(); ++i) {
      relative.translation = v.wheelPosition(i);
      toMsg(relative, &transforms[k++].transform);
    }
    for (std::size_t i : published_points_) {
      relative.translation = v.pointPosition(i);
      toMsg(relative, &transforms[k++].transform);
    }
    tf_pub_.publisher.publish(tf_msg_);
  }

  // Hull CoG motion in base_link axes; the travel speed is part of the hull's velocity. The
  // angular velocity is the body rate of the published orientation (vehicle_frames.h).
  const Matrix3 to_base = pose.rotation.toRotationMatrix().transpose();
  const bool odom = odom_pub_.listened();
  const bool imu =
      std::any_of(imu_pubs_.begin(), imu_pubs_.end(), [](const auto& p) { return p->listened(); });
  if (twist || odom || imu) {
    const Vector6 base_twist = baseLinkTwist(v.speed(), v.geometry().cog, displacement, velocity);
    const geometry_msgs::Vector3 angular = toMsg(Vector3(base_twist.tail<3>()));
    if (twist) {
      twist_msg_.header.stamp = sample_time_;
      twist_msg_.twist.linear =
          toMsg(to_base * (velocity.head<3>() + Vector3(v.speed(), 0.0, 0.0)));
      twist_msg_.twist.angular = angular;
      twist_pub_.publisher.publish(twist_msg_);
    }
    if (odom) {
      // nav_msgs/Odometry: the pose of base_link in odom (as on /tf) and the twist of its
      // origin in its own axes (child_frame_id); covariance diagonals from ~variance/*.
      odom_msg_.header.stamp = sample_time_;
      toMsg(pose, &odom_msg_.pose.pose);
      odom_msg_.twist.twist.linear = toMsg(Vector3(base_twist.head<3>()));
      odom_msg_.twist.twist.angular = angular;
      odom_pub_.publisher.publish(odom_msg_);
    }
    for (std::size_t k = 0; k < imu_points_.size(); ++k) {
      if (!imu_pubs_[k]->listened())
        continue;
      // The point's frame is parallel to base_link: the hull's orientation and body rate, and
      // the specific force of the point's acceleration, the second derivative of its published
      // position plus the travel acceleration along odom x (REP-145: gravity included).
      sensor_msgs::Imu& msg = imu_msgs_[k];
      msg.header.stamp = sample_time_;
      msg.orientation = toMsg(pose.rotation);
      msg.angular_velocity = angular;
      msg.linear_acceleration =
          toMsg(specificForce(pose.rotation, v.pointAcceleration(imu_points_[k])));
      imu_pubs_[k]->publisher.publish(msg);
    }
  }
  if (accel) {
    const Vector6 acceleration = v.hullAcceleration();
    accel_msg_.header.stamp = sample_time_;
    // Absolute: the model's acceleration relative to the path frame plus the frame's own travel
    // acceleration along odom x (0 without a speed slew), in base_link axes.
    accel_msg_.accel.linear =
        toMsg(to_base * (acceleration.head<3>() + Vector3(v.travelAcceleration(), 0.0, 0.0)));
    // The derivative of the body rate on hull/twist.
    accel_msg_.accel.angular =
        toMsg(bodyAcceleration(displacement.tail<3>(), velocity.tail<3>(), acceleration.tail<3>()));
    accel_pub_.publisher.publish(accel_msg_);
  }
  if (wheels) {
    wheels_msg_.header.stamp = sample_time_;
    toMsg(v.wheels(), v.station(), v.speed(), &wheels_msg_, params_.frame_prefix);
    wheels_pub_.publisher.publish(wheels_msg_);
  }
}

void VehicleDynamicsNode::publishComfort() {
  if (!comfort_pub_.listened())
    return;
  const ComfortReport report =
      comfortReport(vehicle_->seatComfort(), vehicle_->comfortPoint(),
                    params_.vehicle_options.comfort_running_rms_time, vehicle_->peakAcceleration());
  comfort_msg_.header.stamp = sample_time_;
  toMsg(report, &comfort_msg_);
  comfort_pub_.publisher.publish(comfort_msg_);
}

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
