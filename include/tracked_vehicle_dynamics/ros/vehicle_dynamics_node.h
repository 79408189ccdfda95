// vehicle_dynamics_node: the reduced vehicle model in real time on ROS time (doc/ros_node.md).
//
//   terrain_profile (TerrainProfile) ──► OnlineVehicle::addTerrain   (TerrainBuffer)
//   speed (std_msgs/Float64, m/s)    ──► OnlineVehicle::setSpeed, when it arrives
//   speed_stamped (TwistStamped)     ──► OnlineVehicle::setSpeed, at the step of its stamp
//   ~reset, ~reset_to (ResetVehicle) ──► OnlineVehicle::reset, resetTo
//   tick at ~rate on ROS time        ──► OnlineVehicle::step() for every step due
//       ──► tf2 odom→base_link→{road wheels, moving named points}, odom (nav_msgs/Odometry),
//           hull/accel, hull/twist, imu/<point> (sensor_msgs/Imu, ~imu_points), road_wheels,
//           comfort, /diagnostics
//   start-up                         ──► /tf_static base_link→{named points rigid with the hull}
//
// Time: the node keeps the time of its current sample. Each tick runs every fixed step due up to
// ROS time now (so use_sim_time with `rosbag play --clock` works and a late tick is caught up);
// more than ~catch_up_limit of simulated time is not caught up: the older part is skipped
// (resynchronisation, warned and counted). ROS time going backwards (a bag loop) resets the
// vehicle and re-applies the terrain and speed that arrived just before the jump but belong to
// the new time (rosbag sends a loop's first messages before its first /clock, on other
// connections). Bad input never stops the node: it is rejected or held, with a throttled warning
// and a diagnostics entry.
//
// Threading: the vehicle is owned by one tick at a time, which takes its own callback queue
// (terrain, speed, speed_stamped, ~reset, ~reset_to and, with use_sim_time, /clock) first: no
// locks, a deterministic step order, and a message is used at the next tick (latency <= one
// period plus the step; a stamped speed at the step of its stamp, if that comes later).
// - Real time: the tick runs in roscpp's network thread (NetworkThreadTimer), one wake-up per
//   tick where a thread of our own costs two and a hand-off (a ros::Timer costs more still).
//   The step is microseconds, so the network thread's other work waits little.
// - Simulated time: a thread of our own, woken by every /clock message.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/AccelStamped.h>
#include <geometry_msgs/TransformStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <nav_msgs/Odometry.h>
#include <ros/callback_queue.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Clock.h>
#include <sensor_msgs/Imu.h>
#include <std_msgs/Float64.h>
#include <std_srvs/Empty.h>
#include <tf2_msgs/TFMessage.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include "tracked_vehicle_dynamics/Comfort.h"
#include "tracked_vehicle_dynamics/ResetVehicle.h"
#include "tracked_vehicle_dynamics/RoadWheels.h"
#include "tracked_vehicle_dynamics/TerrainProfile.h"
#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "tracked_vehicle_dynamics/ros/network_thread_timer.h"
#include "tracked_vehicle_dynamics/ros/node_parameters.h"
#include "tracked_vehicle_dynamics/ros/online_names.h"

namespace tracked_vehicle_dynamics {
namespace ros_layer {

/// The node's resolved name ("/sim/vehicle_dynamics"), the prefix of its log lines: with several
/// vehicles in one launch, each line says which node it comes from.
inline const char* nodeName() {
  return ros::this_node::getName().c_str();
}

/// Thrown by the constructor when the node was asked to shut down (Ctrl-C, rosnode kill) while
/// it loaded or built its model: nothing is advertised after ROS has shut down (a publish then
/// trips an assertion in roscpp), and the node ends quietly, as asked.
class StartUpInterrupted : public std::runtime_error {
 public:
  StartUpInterrupted()
      : std::runtime_error("shut down during start-up, before the model was ready") {}
};

class VehicleDynamicsNode {
 public:
  /// Reads the parameters, loads or builds the reduced model, advertises, subscribes and starts
  /// the loop. Throws ParameterError naming the parameter (or the description file) at fault,
  /// StartUpInterrupted when ROS shut down while the model was being loaded or built.
  VehicleDynamicsNode(ros::NodeHandle nh, ros::NodeHandle private_nh);
  /// Stops the tick (timerfd or loop thread).
  ~VehicleDynamicsNode();
  VehicleDynamicsNode(const VehicleDynamicsNode&) = delete;
  VehicleDynamicsNode& operator=(const VehicleDynamicsNode&) = delete;

 private:
  /// Counts of what happened, for diagnostics (never reset).
  struct Events {
    std::uint64_t patches_accepted = 0, patches_rejected = 0;
    std::uint64_t patches_narrow = 0;  // accepted, but narrower than the contacts' lateral span
    // accepted, but a slope, spacing or step at its start unlike ground (terrain_plausibility.h)
    std::uint64_t patches_implausible = 0;
    std::uint64_t patches_behind = 0;       // valid, but wholly behind the terrain kept: dropped
    std::uint64_t patches_other_frame = 0;  // header.frame_id set, not this vehicle's odom frame
    std::uint64_t speeds_accepted = 0, speeds_rejected = 0;
    std::uint64_t speeds_stamped = 0;  // of the accepted, on speed_stamped
    std::uint64_t speeds_late = 0;     // stamped a whole step or more before the sample they met
    std::uint64_t speeds_other_time_base = 0;  // stamped more than kStampRange from ROS time
    std::uint64_t speeds_of_pass_before = 0;   // stamped in the pass before a jump back: dropped
    std::uint64_t speeds_superseded = 0;       // stamped before the stamped speed in force: dropped
    std::uint64_t speeds_caught_up = 0;  // late to a standing vehicle: the missed steps made up
    std::uint64_t speed_timeouts = 0;    // stops after ~speed_timeout without a speed message
    std::uint64_t uncovered_steps = 0;   // steps with at least one contact off the terrain
    std::uint64_t diverged = 0;
    std::uint64_t time_jumps_back = 0, resyncs = 0, skipped_steps = 0;
    std::uint64_t clock_steps = 0;            // real time: steps of the system clock, either way
    std::uint64_t ticks = 0, late_ticks = 0;  // late: more than one step due at a tick
    std::uint64_t resets = 0;
    std::uint64_t patches_reapplied = 0, speeds_reapplied = 0;  // after a jump back
    // Restarts after a jump back held for the loop's first patch, and holds that ran out.
    std::uint64_t terrain_holds = 0, terrain_holds_expired = 0;
    // Runs started at ~initial_speed held (a step or more) until their terrain covered the
    // contacts, and holds that ran out before it did.
    std::uint64_t start_holds = 0, start_holds_expired = 0;
    std::uint64_t speed_holds_expired = 0;  // the terrain came, an awaited speed did not
  };
  /// A terrain patch kept for kRewindWindow of wall time, in case ROS time jumps back to it.
  struct RecentPatch {
    TerrainProfile::ConstPtr msg;
    ros::Time ros_arrival;  // the loop's ROS time when it was handled
    ros::SteadyTime arrival;
    std::string dropped;  // dropped as wholly behind: where it lay (reportDroppedPatch); else ""
  };
  /// Change of a counter since the previous diagnostics report.
  struct Window {
    std::uint64_t last = 0;
    std::uint64_t delta(std::uint64_t total) {
      const std::uint64_t d = total - last;
      last = total;
      return d;
    }
  };

  void loadVehicle();
  reduction::ReducedModel loadGivenModel(const vehicle::VehicleDescription& description);
  void setUpFrames();
  /// Index of the named point `name`; ParameterError naming ~`key` and the known points if none.
  std::size_t pointIndex(const std::string& name, const std::string& key) const;
  /// ~imu_points: each a published point frame, listed once, a valid topic name imu/<point>.
  void setUpImus();
  void onTerrain(const TerrainProfile::ConstPtr& msg);
  /// terrain::patchWarnings for a patch about to be added (not yet named), and in `stepped`
  /// whether it steps more than kLargestPlausibleStep off the ground the contacts read before it.
  /// " (a step takes X us …)" when the recent steps are slower than the period, else "".
  std::string slowStepCause() const;
  std::vector<std::string> judgePatch(const TerrainPatch& patch, bool* stepped) const;
  /// `speed`: taken when it arrives (vehicle_dynamics_node_speed.cpp).
  void onSpeed(const std_msgs::Float64::ConstPtr& msg);
  /// `speed_stamped`: twist.linear.x taken at header.stamp (scheduleSpeed).
  void onSpeedStamped(const geometry_msgs::TwistStamped::ConstPtr& msg);
  /// Why a stamped speed's frame is not one whose x is the vehicle's heading; empty if it is.
  std::string speedFrameProblem(const std::string& frame) const;
  /// A speed message refused: counted, kept for the diagnostics, warned (throttled).
  void rejectSpeed(const std::string& why);
  /// Which topic a valid speed came on; both in one run is warned about once.
  void noteSpeedSource(bool stamped);
  /// A stamped speed within reach of ROS time: dropped if older than the stamped speed in force;
  /// taken now if its stamp is not after the current sample (late when a whole step before it),
  /// else kept until the step at its stamp.
  void scheduleSpeed(double speed, const ros::Time& stamp);
  /// The kept stamped speeds due at the current sample, in stamp order.
  void applyDueSpeeds();
  /// The commanded speed from ROS time `t` on, with the hold's and the timeout's bookkeeping.
  /// `catch_up_steps` > 0: the vehicle stood still while that many steps missed the speed, which
  /// OnlineVehicle::setSpeedSince makes up.
  void takeSpeed(double speed, const ros::Time& t, std::int64_t catch_up_steps = 0);
  /// A stamped speed more than a second from ROS time `t`: taken now, counted and warned.
  void takeSpeedOfOtherTimeBase(double speed, const ros::Time& stamp, const ros::Time& t);
  /// The kept stamped speeds older than kRewindWindow are forgotten; one held back as maybe a
  /// bag loop's next pass, with no jump back since, is taken now as another time base's.
  void expireRecentSpeeds();
  /// The speeds kept for a jump back belong to the run a reset ends.
  void forgetRecentSpeeds();
  /// After a jump back to `now`: the last unstamped speed if it arrived within kRewindWindow,
  /// then each stamped one of the new time (stamped nearer `now` than its arrival's ROS time).
  void reapplyRecentSpeeds(const ros::Time& now);
  bool onReset(std_srvs::Empty::Request& request, std_srvs::Empty::Response& response);
  /// ~reset_to: restart at a station in static equilibrium on its terrain (or on flat ground).
  /// An invalid request gets success = false naming the field, and changes nothing.
  bool onResetTo(ResetVehicle::Request& request, ResetVehicle::Response& response);
  /// Why a speed [m/s] is not accepted (not finite, negative, above ~max_speed); empty if it is.
  std::string speedProblem(double speed) const;
  /// Once: a speed change a driver would feel, taken without a slew (no travel inertia).
  void warnOfUnslewedSpeedChange(double speed, const ros::Time& now);
  void onClock(const rosgraph_msgs::Clock::ConstPtr& msg);
  /// The simulated-time loop thread: waits for /clock (and messages), then step().
  void run();
  /// Real time: takes the messages that arrived, then step().
  void tick();
  /// Steps to ROS time now, publishes, diagnoses.
  void step();
  /// ROS time and monotonic time now. On real time the pair is read within 1 ms of each other;
  /// false when a few tries could not (a loaded machine), and then followClockStep() judges the
  /// next pair afresh.
  bool readClocks(ros::Time* ros_now, ros::SteadyTime* steady_now);
  /// Real time: a step of the system clock since the last tick (the offset between ROS and
  /// monotonic time changed by more than 20 ms) is followed by moveTime().
  void followClockStep(const ros::Time& ros_now, const ros::SteadyTime& steady_now);
  /// The system clock stepped by `step_ns` (found at ROS time `ros_now`): the vehicle's time
  /// and what is kept in ROS time (stamped speeds waiting, the stamp of the one in force, the
  /// run's start) move by as much; counted and said.
  void moveTime(std::int64_t step_ns, const ros::Time& ros_now);
  /// /diagnostics on monotonic wall time while ROS time stands still (use_sim_time with no /clock
  /// yet, or a paused one): the reports paced on ROS time would say nothing, not even why.
  void reportOnWallTime(const ros::SteadyTime& wall);
  /// Publishes /diagnostics now and schedules the next report ~diagnostic_period after `now`.
  void reportDiagnostics(const ros::Time& now);
  /// updater_.force_update(), an exception logged (throttled) instead of passed on.
  void publishDiagnostics();
  /// A valid speed (message, ~reset_to, or re-applied after a jump back) at ROS time `now`.
  void markSpeedTime(const ros::Time& now);
  /// Seconds since the last valid speed, for ~speed_timeout, at ROS time `now` and monotonic
  /// time `steady`.
  double secondsSinceSpeed(const ros::Time& now, const ros::SteadyTime& steady) const;
  /// The loop queue's messages, services and /clock (waiting up to `wait` for the first).
  void handleMessages(const ros::WallDuration& wait);
  /// ROS time now; with use_sim_time the latest /clock this loop has seen.
  ros::Time now() const;
  /// Runs the steps due up to `now` and publishes.
  void advanceTo(const ros::Time& now);
  /// A new run: the vehicle restarts (OnlineVehicle::resetTo, by default station 0 on flat
  /// ground) and the old run's speed timeout is forgotten. Returns the uncovered contacts.
  int restart(double station = 0.0, double speed = 0.0, ResetTerrain terrain = ResetTerrain::Clear);
  /// A run started at ~initial_speed (the start, ~reset, a jump back) takes it as a speed message
  /// at `t` (~speed_timeout, the unslewed-change warning); nothing at 0.
  void takeInitialSpeed(const ros::Time& t);
  /// On simulated time, a run started at ~initial_speed with no terrain waits until its terrain
  /// covers the contacts (a hold, at most holdLimit()) instead of driving off over flat ground;
  /// nothing at 0, with terrain, or on real time.
  void holdForFirstPatch();
  /// The stored terrain reaches every contact from now over `steps` steps at the current speed.
  bool terrainCoversHeldSteps(std::int64_t steps) const;
  /// ", speed V m/s (~initial_speed)" for the reset messages; empty at 0.
  std::string initialSpeedText() const;
  /// A reset the user asked for (~reset, ~reset_to): the inputs kept for a bag loop belong to
  /// the old run.
  void forgetRecentInputs();
  /// Simulated time went back (a bag loop): restart at `now`, re-apply the recent inputs that
  /// belong to the new time (reapplyRecentInputs) and publish the equilibrium.
  void restartAfterJump(const ros::Time& now);
  /// After a jump back to `now`: the patches that arrived in the last kRewindWindow of wall time
  /// stamped nearer `now` than the ROS time they arrived at, and the last speed if it arrived in
  /// that window, go to the restarted vehicle. Clears the kept inputs.
  void reapplyRecentInputs(const ros::Time& now);
  /// The earliest stamp of the kept inputs that belong to the new time `now` after a jump back
  /// (as reapplyRecentInputs judges them) and are not after it; zero when none.
  ros::Time earliestRecentStamp(const ros::Time& now) const;
  /// Before the first step after a jump back: moves the restart's time back to `stamp`, a new
  /// input's, when it lies at most holdLimit() before the jump's time (a bag loop's start).
  void alignRestart(const ros::Time& stamp);
  /// Standing (speed 0) where the last start or reset put it, on the flat ground it cleared to.
  bool standingOnClearedGround() const;
  /// Keeps an accepted patch for reapplyRecentInputs: taken (dropped empty), or dropped as
  /// wholly behind (`dropped` says where it lay), which is a fault only when no jump back
  /// re-applies it in time (expireRecentPatches).
  void rememberPatch(const TerrainProfile::ConstPtr& msg, std::string dropped);
  /// A patch was taken into the terrain: the run's first patch time, and the end of a hold.
  void notePatchTaken(const ros::Time& stamp);
  /// The longest a held restart waits [s] of simulated time: half ~catch_up_limit.
  double holdLimit() const;
  /// The kept patches older than kRewindWindow are forgotten; those dropped are reported now.
  void expireRecentPatches();
  /// A valid patch wholly behind the vehicle, dropped for good: counted, named and said.
  void reportDroppedPatch(const std::string& where);
  void publishState();
  void publishComfort();

  void diagnoseLoop(diagnostic_updater::DiagnosticStatusWrapper& status);
  void diagnoseTerrain(diagnostic_updater::DiagnosticStatusWrapper& status);
  void diagnoseInput(diagnostic_updater::DiagnosticStatusWrapper& status);
  void diagnoseModel(diagnostic_updater::DiagnosticStatusWrapper& status);
  void diagnoseGroundContact(diagnostic_updater::DiagnosticStatusWrapper& status);

  ros::NodeHandle nh_, private_nh_;
  NodeParameters params_;
  ros::CallbackQueue loop_queue_;  // everything the tick handles
  ros::NodeHandle loop_nh_, loop_private_nh_;

  std::unique_ptr<OnlineVehicle> vehicle_;
  reduction::VehicleReductionReport report_;
  double load_seconds_ = 0.0;
  double setup_seconds_ = 0.0;   // OnlineVehicle's construction (the discretisation) [s]
  std::string given_reduction_;  ///< the reduction key of ~reduced_model's file, when given
  DofIndex model_dofs_ = 0, model_inputs_ = 0, model_outputs_ = 0;
  std::string model_damping_;
  double damping_coupling_ = 0.0;  // Phi^T C Phi off its diagonal that ~method modal drops
  std::vector<std::size_t> published_points_;  // indices into geometry().points, on /tf
  std::vector<std::size_t> static_points_;     // rigid with the hull: once on /tf_static
  std::vector<std::size_t> imu_points_;        // ~imu_points, indices into geometry().points
  /// The hull's transforms at the front of tf_msg_, in order (setUpFrames()).
  enum class HullLink {
    Whole,      // odom -> base_link: the pose
    Path,       // odom -> footprint: (s, 0, 0)
    AbovePath,  // footprint -> base_link: the pose less (s, 0, 0)
  };
  std::vector<HullLink> hull_links_;

  ros::Subscriber terrain_sub_, speed_sub_, speed_stamped_sub_, clock_sub_;
  // /tf is published like tf2_ros::TransformBroadcaster does, from a message kept between
  // publications (no per-sample allocation of frame ids).
  // Each with its subscriber count, kept by roscpp's connect/disconnect callbacks (on the spin
  // thread): the loop reads an atomic instead of asking roscpp's TopicManager for every topic
  // at every sample, under a mutex its network thread takes right after each publication.
  struct CountedPublisher {
    ros::Publisher publisher;
    std::atomic<std::uint32_t> subscribers{0};
    bool listened() const { return subscribers.load(std::memory_order_relaxed) > 0; }
  };
  template <class M>
  void advertise(const std::string& topic, std::uint32_t queue_size, CountedPublisher* out);
  CountedPublisher tf_pub_, accel_pub_, twist_pub_, wheels_pub_, comfort_pub_, odom_pub_;
  std::vector<std::unique_ptr<CountedPublisher>> imu_pubs_;  // one per imu_points_ entry
  ros::ServiceServer reset_service_, reset_to_service_;
  std::unique_ptr<tf2_ros::StaticTransformBroadcaster> static_broadcaster_;
  std::vector<geometry_msgs::TransformStamped> pending_static_;  // until the first /clock
  bool flat_since_restart_ = true;  // no patch since the start or a reset that cleared the terrain
  // A restart after a jump back of ROS time (a bag loop) whose run before it had terrain from its
  // start, and none re-applied: the vehicle is held at its restart, unstepped, until the new
  // pass's first patch (and, if the run before moved and no speed came back with the jump, a
  // speed) has arrived, then steps the held time on them (advanceTo).
  struct Hold {
    bool active = false;
    bool terrain = false;         // a patch of the new pass was taken
    bool awaiting_speed = false;  // a speed message is awaited too
    bool speed = false;           // and has arrived
    // A run started moving at ~initial_speed, held for its first patch (holdForFirstPatch), not a
    // loop's restart: its end without terrain is no loop's fault.
    bool at_start = false;
    bool counted = false;          // held a step: counted in events_.start_holds
    ros::Time old_time, new_time;  // the jump's: a patch stamped nearer new_time is the new pass's
  };
  Hold hold_;
  // The run since the last start or restart: its ROS start time, and how long after it its first
  // patch came ([s]; < 0: none yet). A run whose terrain came later than a hold may last is not
  // held for at the next jump (a bag whose terrain begins late would otherwise wait every loop).
  ros::Time run_start_;
  double first_patch_lag_ = -1.0;
  std::uint64_t patches_behind_at_restart_ = 0;  // events_.patches_behind at the last restart
  // The last start or reset cleared the terrain (the contacts hold the flat ground u = 0 until a
  // patch covers them), at this station.
  bool restart_cleared_ = true;
  double restart_station_ = 0.0;
  int last_uncovered_ = 0;  // contacts off the terrain at the last step
  // The last patch taken since then that stepped more than terrain::kLargestPlausibleStep from
  // the ground before it (empty: none): the terrain after it, and every output on it, sit that
  // far off (absolute altitudes, units) until a reset clears the terrain.
  std::string stepped_patch_;
  // The last patch taken named another frame than the odom frame, or was narrower than the
  // contacts: the terrain status WARNs until a patch without the fault is taken (a source that
  // sends one patch per few report periods would otherwise flicker between WARN and OK).
  bool latest_patch_other_frame_ = false, latest_patch_narrow_ = false;
  diagnostic_updater::Updater updater_;

  // Messages reused every publication.
  tf2_msgs::TFMessage tf_msg_;
  geometry_msgs::AccelStamped accel_msg_;
  geometry_msgs::TwistStamped twist_msg_;
  RoadWheels wheels_msg_;
  Comfort comfort_msg_;
  nav_msgs::Odometry odom_msg_;
  std::vector<sensor_msgs::Imu> imu_msgs_;  // one per imu_points_ entry

  // Time keeping: sample_time_ is the ROS time of the vehicle's current sample.
  bool use_sim_time_ = false;
  ros::Time latest_clock_;
  bool clock_started_ = false;
  // Publishers of /clock the last report saw more than one of (0 otherwise): two time sources
  // (a simulator and a rosbag play --clock, two replays) make ROS time jump back and forth.
  std::uint32_t clock_publishers_said_ = 0;
  ros::Time sample_time_;
  std::int64_t step_ns_ = 0;
  std::int64_t max_catch_up_steps_ = 1;
  std::int64_t publish_every_ = 1, comfort_every_ = 100;
  std::int64_t contact_every_ = 0;  // steps between ground-contact checks; 0: none
  std::int64_t steps_since_start_ = 0;

  Events events_;
  Window loop_resyncs_, loop_late_, loop_jumps_, loop_clock_steps_, loop_diverged_,
      terrain_rejected_, terrain_uncovered_, terrain_narrow_, terrain_implausible_, terrain_behind_,
      terrain_other_frame_, speed_rejected_, speed_timed_out_, speed_late_, speed_time_base_;
  std::string last_patch_error_, last_speed_error_, last_narrow_patch_, last_behind_patch_,
      last_implausible_patch_, last_other_frame_patch_;
  std::deque<RecentPatch> recent_patches_;  // sim time only
  double recent_speed_ = 0.0;
  /// A stamped speed kept until the step at its stamp.
  struct PendingSpeed {
    double speed;
    ros::Time stamp;
  };
  std::deque<PendingSpeed> pending_speeds_;  // in stamp order
  /// A stamped speed kept for kRewindWindow of wall time (sim time), for a jump back.
  struct RecentSpeed {
    double speed;
    ros::Time stamp, ros_arrival;
    ros::SteadyTime arrival;
    bool deferred;  // far behind ROS time, not taken yet: maybe a bag loop's next pass
  };
  std::deque<RecentSpeed> recent_stamped_speeds_;
  double max_speed_lateness_ = 0.0;  // [s] of the late stamped speeds since the last report
  std::string last_other_time_base_;
  bool stamped_speed_seen_ = false, unstamped_speed_seen_ = false, speed_sources_warned_ = false;
  ros::Time last_speed_taken_;     // ROS time from which the commanded speed was last set
  ros::Time applied_speed_stamp_;  // stamp of the stamped speed in force (zero: none this run)
  // The last jump back of simulated time: the time it left, and when (monotonic) it came.
  ros::Time last_jump_old_time_, last_jump_new_time_;
  bool restart_movable_ = false;  // restarted after a jump back, not stepped yet (alignRestart)
  bool speed_message_in_run_ = false;  // a speed message was taken since the last (re)start
  ros::SteadyTime last_jump_arrival_;
  ros::SteadyTime recent_speed_arrival_;  // zero: none kept
  ros::Time last_step_time_;              // ROS time of the previous step() call
  ros::Time last_speed_time_;             // ROS time of the last valid speed message
  ros::SteadyTime last_speed_steady_;     // the same on the monotonic clock
  ros::Time next_diagnostics_;            // ROS time of the next /diagnostics report
  // Real time: ROS time minus monotonic time at the last tick [ns] (followClockStep), and the
  // last step of the system clock it found ("+0.300 s at ROS time …"; empty: none).
  std::int64_t clock_offset_ns_ = 0;
  bool clock_offset_known_ = false;
  std::string last_clock_step_;
  bool stopped_by_timeout_ = false;      // ~speed_timeout stopped the vehicle; a speed clears it
  bool unslewed_change_warned_ = false;  // warnOfUnslewedSpeedChange() said its once
  std::chrono::steady_clock::time_point tick_start_;  // before the tick's message callbacks
  ros::SteadyTime last_time_change_;                  // monotonic time at which ROS time last moved
  ros::SteadyTime next_wall_report_;                  // reportOnWallTime() publishes from then on
  ros::SteadyTime clock_wait_start_;    // sim time: when the wait for /clock began (zero: none)
  ros::SteadyTime next_clock_warning_;  // the next WARN of that wait, not before
  bool cached_ = false;                 // the reduced model is in the cache file
  std::string not_cached_reason_;
  std::int64_t max_steps_in_tick_ = 0;
  DurationStatistics step_window_, tick_window_, step_total_, tick_total_;

  std::atomic<bool> stop_{false};
  std::unique_ptr<NetworkThreadTimer> tick_timer_;  // real time: calls tick()
  std::thread loop_;                                // last: started when everything else exists
};

}  // namespace ros_layer
}  // namespace tracked_vehicle_dynamics
