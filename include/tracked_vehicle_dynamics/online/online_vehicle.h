// The real-time vehicle the node runs: a reduced model stepped at a fixed rate on terrain that
// arrives in patches, at a speed that arrives as a number. ROS-free: the node owns one and feeds
// it from topics; tests and benchmarks drive it directly.
//
// Per step k -> k+1 (time step h = 1 / rate):
//   s_{k+1} = s_k + v h                                    station of the reference point [m]
//   w_{k+1} = RoadInputSampler(terrain, s_{k+1}, v)         road inputs [u; u']
//   Simulator::step(w_{k+1})                               exact discretisation (simulator.h)
// and the comfort meter takes the accelerations at the comfort point (its translations, the
// hull's rotations: dynamics/seat_comfort.h). The simulator
// starts from static equilibrium under gravity on flat ground (u = 0), K q0 = f_g, so a vehicle
// at rest on flat terrain stays exactly where it is; resetTo() restarts it at any station in
// static equilibrium on the terrain there, K q0 = f_g + K_u u(s). step() allocates nothing.
//
// With a speed slew (options max_acceleration / max_deceleration > 0) the speed follows the
// commanded speed v_c at a bounded rate, and the model feels the travel inertia of the path frame
// (dynamics/travel_inertia.h: the travel acceleration rides as one more input, w = [u; a; u'; 0]):
//   v_{k+1} = v_k + clamp(v_c - v_k, -d_max h, a_max h),   a_k = (v_{k+1} - v_k) / h
//   s_{k+1} = s_k + (v_k + v_{k+1}) h / 2                  (exact for constant acceleration)
// Without it (both 0, the default) a new speed applies at once and no travel inertia is applied:
// a step in speed would be an infinite acceleration.
// a_k, the rate over [t_k, t_{k+1}], rides in w_{k+1}: with the first-order hold the load ramps
// up over the step in which the speed starts to change (about half a step late), with the
// zero-order hold it acts one step late; at 1 kHz either is a millisecond.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/dynamics/ground_contact_watch.h"
#include "tracked_vehicle_dynamics/dynamics/seat_comfort.h"
#include "tracked_vehicle_dynamics/dynamics/simulator.h"
#include "tracked_vehicle_dynamics/dynamics/static_equilibrium.h"
#include "tracked_vehicle_dynamics/online/road_input_sampler.h"
#include "tracked_vehicle_dynamics/online/vehicle_frames.h"
#include "tracked_vehicle_dynamics/reduction/reduced_model.h"
#include "tracked_vehicle_dynamics/terrain/terrain_buffer.h"
#include "tracked_vehicle_dynamics/types.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_geometry.h"

namespace tracked_vehicle_dynamics {
namespace online {

/// One patch of terrain as TerrainBuffer::addPatch takes it (the content of a TerrainProfile).
struct TerrainPatch {
  double start_station = 0.0;  ///< station of the first sample [m]
  double spacing = 0.0;        ///< station step [m]
  Vector lateral;              ///< lateral position of each line [n_lines] [m]
  Matrix heights;              ///< [n_lines x n_samples] [m]
};

// The node publishes frames at the description's static positions (vehicle_geometry.h).
using vehicle::VehicleGeometry;
using vehicle::vehicleGeometry;

struct OnlineVehicleOptions {
  double rate = 1000.0;  ///< step rate 1/h [Hz]
  dynamics::DiscretizationMethod method = dynamics::DiscretizationMethod::ModalDecoupled;
  dynamics::InputHold hold = dynamics::InputHold::FirstOrder;
  /// Modal method: modes above this frequency [Hz] are quasi-static (see Simulator); < 0 means
  /// the Nyquist frequency rate / 2, 0 keeps every mode dynamic.
  double max_mode_frequency_hz = -1.0;
  /// Position of the vehicle centre line on the terrain's lateral axis [m] (y left).
  double lateral_offset = 0.0;
  /// Output whose accelerations feed the comfort meter: a named point, or "hull" for the hull
  /// centre of gravity. Empty (the default): kCrewSeatPoint when the vehicle names it, else the
  /// hull (resolveComfortPoint()), so a vehicle without a crew seat runs with the defaults.
  std::string comfort_point;
  /// Running r.m.s. integration time of the comfort meter [s].
  double comfort_running_rms_time = 1.0;
  /// Terrain kept behind the rearmost contact when patches are dropped [m].
  double terrain_keep_behind = 1.0;
  /// Largest memory the stored terrain may hold [MB = 1e6 bytes] (TerrainBuffer::setMemoryLimit):
  /// a patch beyond it is refused. 1,000 MB hold 625 km of a one-line terrain sampled every 1 cm,
  /// 125 km of a 9-line one.
  double terrain_max_memory_mb = 1000.0;
  /// Its range [MB]: below 1 MB (125 m of a 9-line terrain at 1 cm) a value is more likely typed
  /// in GB than meant; 1e9 MB is a petabyte, and keeps the byte count far inside size_t.
  /// (The messages of the core and of the node's ~terrain_max_memory say "1 .. 1e9".)
  static constexpr double kMinTerrainMemoryMb = 1.0, kMaxTerrainMemoryMb = 1e9;
  /// Largest rate [m/s^2] at which the speed rises towards the commanded one, and at which it
  /// falls. Both 0: no slew (a new speed applies at once) and no travel inertia. One of them 0
  /// and the other > 0: the 0 one takes the other's value (a slewing vehicle with one direction
  /// unbounded would step its speed, an infinite acceleration the model cannot take).
  double max_acceleration = 0.0;
  double max_deceleration = 0.0;
};

/// The named point an unset comfort_point watches when the vehicle has it (the bundled
/// vehicle's crew seat).
constexpr const char* kCrewSeatPoint = "crew_seat";

/// The point the comfort meter watches for OnlineVehicleOptions::comfort_point `requested` on a
/// vehicle with these named points: empty, kCrewSeatPoint when it is one of them, else "hull";
/// "hull" or one of them, itself. Throws InputError for any other name, listing "hull" and the
/// points.
std::string resolveComfortPoint(const std::string& requested,
                                const std::vector<std::string>& point_names);

/// The Simulator configuration of an OnlineVehicle: step 1/rate, method, hold, the cut-off of
/// quasi-static modes, displacement/velocity/acceleration outputs, gravity. Shared with the
/// benchmark so that both run the same model. Throws InputError for a bad rate.
dynamics::SimulatorOptions simulatorOptions(const reduction::ReducedModel& model,
                                            const OnlineVehicleOptions& options);

/// State of one road wheel at the current sample.
struct WheelState {
  std::string name;
  double displacement = 0.0;  ///< vertical, from static equilibrium [m]
  double velocity = 0.0;      ///< vertical [m/s]
  double acceleration = 0.0;  ///< vertical [m/s^2]
};

/// Largest |station| resetTo() takes [m] (10,000 km). At 1e7 m a double resolves 2e-9 m, a
/// thousandth of a step of 0.1 m/s at 50 kHz; far beyond it a step's advance s + v h rounds
/// back to s and the vehicle stands still while "driving".
constexpr double kMaxResetStation = 1e7;

/// What resetTo() does with the terrain buffer.
enum class ResetTerrain {
  /// Buffer cleared, held heights 0: flat ground (u = 0) until new patches arrive, as reset().
  Clear,
  /// Buffer kept: the inputs are sampled from it at the new station as a step samples them
  /// (uncovered contacts keep their last height, u' = 0).
  Keep,
};

/// What one step met.
struct StepResult {
  int uncovered = 0;      ///< contacts the terrain did not cover (held at their last height)
  bool diverged = false;  ///< outputs were not finite: the vehicle was reset to equilibrium
};

class OnlineVehicle {
 public:
  /// Throws InputError when the model lacks an output the geometry names ("hull ux".."hull rz",
  /// "<wheel> uz", "<point> ux|uy|uz"), the comfort point is not "hull", empty or one of the
  /// geometry's points (resolveComfortPoint()), or the options are invalid
  /// (rate <= 0, ...); SolverError from the simulator or the static equilibrium.
  /// contact_groups: per road input of the model, the pad (track assembly) its contact belongs
  /// to, numbered from 0 (-1: none, watched as a pad of its own), for the ground-contact check's
  /// whole-pad records (reduction::roadInputGroups gives them); empty: no pads. Throws InputError
  /// when it is neither empty nor one per road input.
  OnlineVehicle(const reduction::ReducedModel& model, VehicleGeometry geometry,
                const OnlineVehicleOptions& options = {},
                const std::vector<int>& contact_groups = {});

  /// Back to static equilibrium on flat ground at station 0, speed 0; terrain and comfort
  /// metrics cleared: resetTo(0, 0, ResetTerrain::Clear).
  void reset();
  /// Restarts at station s [m] with speed v [m/s], at rest in static equilibrium on the road
  /// there: w = [u; u'] sampled at s exactly as step() samples it (u = 0 with
  /// ResetTerrain::Clear), then K q0 = f_g + K_u u, q0' = 0 (StaticEquilibriumSolver). Time,
  /// step count and comfort metrics restart from zero. Returns the number of contacts the kept
  /// terrain did not cover (they hold their last height; 0 with Clear). Throws InputError,
  /// changing nothing, when s is not finite or |s| > kMaxResetStation, or v is negative or not
  /// finite.
  int resetTo(double station, double speed, ResetTerrain terrain);
  /// Stores a patch (newest wins where patches overlap) and frees terrain behind the vehicle.
  /// Throws InputError (naming the field or index) for an invalid patch; nothing changes then
  /// but the terrain lying behind the vehicle, which every patch frees first.
  /// Returns false for a valid patch ending wholly behind the terrain kept (more than
  /// terrain_keep_behind behind the rear contact, beyond the bridged gap): it was dropped.
  /// A patch that would take the stored terrain beyond terrain_max_memory_mb (what lies behind
  /// the vehicle freed first) is invalid too.
  bool addTerrain(const TerrainPatch& patch);
  /// Commanded speed [m/s]: used from the next step on, or, with a slew, approached at the
  /// bounded rate from the next step on. Throws InputError if negative, not finite or above
  /// dynamics::kMaxSpeedKmh (200 km/h, 55.6 m/s).
  void setSpeed(double speed);
  /// A speed that should have applied `steps` steps ago, to a vehicle standing still since then
  /// (speed 0, no slew): set now, and the reference point moved on by speed * steps * h at once,
  /// the vibration state kept. On level ground that is exactly where those steps would have left
  /// it, at rest (no travel inertia without a slew). Throws InputError if the vehicle is moving,
  /// slews, or the speed or step count is invalid; nothing changes then.
  void setSpeedSince(double speed, long steps);
  /// One fixed step (see the file comment). No allocation.
  StepResult step();

  double timeStep() const { return time_step_; }     ///< h [s]
  double time() const { return simulator_.time(); }  ///< since reset [s]
  long stepCount() const { return simulator_.stepCount(); }
  double station() const { return station_; }                 ///< [m]
  double speed() const { return speed_; }                     ///< current (slewed) speed [m/s]
  double commandedSpeed() const { return commanded_speed_; }  ///< [m/s]
  /// Forward acceleration a_k of the last step [m/s^2] (0 without a slew, and after a reset).
  double travelAcceleration() const { return travel_acceleration_; }
  /// Whether the speed slews and the model carries the travel inertia (options).
  bool slews() const { return max_acceleration_ > 0.0; }

  /// Hull CoG displacement {u_G [m]; theta [rad]} (rows "hull ux".."hull rz").
  Vector6 hullDisplacement() const { return block(hull_rows_, disp_offset_); }
  /// Its time derivative {m/s; rad/s} (vibration only: without the travel speed).
  Vector6 hullVelocity() const { return block(hull_rows_, vel_offset_); }
  /// Its second derivative {m/s^2; rad/s^2} (relative to the path frame: without the travel
  /// acceleration, travelAcceleration(), which the hull's absolute acceleration adds along x).
  Vector6 hullAcceleration() const { return block(hull_rows_, acc_offset_); }
  /// base_link in odom (vehicle_frames.h).
  RigidPose hullPose() const;
  /// Hull displacement at static equilibrium on flat ground.
  const Vector6& staticHullDisplacement() const { return static_hull_; }

  /// Road wheels, in geometry().wheels order. Fills a buffer the vehicle owns (no allocation per
  /// step): valid until the next call, and not to be called from two threads at once although
  /// it is const.
  const std::vector<WheelState>& wheels() const;
  /// Position [m] in base_link of wheel centre i (vertical motion relative to the hull). Throws
  /// InputError, naming i and the wheel count, when i is not below geometry().wheels.size(); so
  /// do the named points' calls below for geometry().points.size().
  Vector3 wheelPosition(std::size_t i) const;
  /// Position [m] in base_link of named point i.
  Vector3 pointPosition(std::size_t i) const;
  /// Acceleration [m/s^2, odom axes] of named point i: the second time derivative of its
  /// published position (vehicle_frames.h rigidPointAcceleration, exact in the hull rotation,
  /// plus the model's elastic part: rows "<point> ux|uy|uz" less their rigid part) plus the
  /// travel acceleration along odom x (travelAcceleration()). Without gravity.
  Vector3 pointAcceleration(std::size_t i) const;
  /// True when named point i moves rigidly with the hull in the model (its output rows are
  /// u_G + theta x (p - p_G) of the hull rows, to rounding): its base_link position is then its
  /// static position, geometry().points[i].position, at every step.
  bool pointIsRigid(std::size_t i) const { return point_rigid_[checkedPoint(i, "pointIsRigid")]; }

  /// The vertical meter (Wk, absorbed power) of the comfort point.
  const dynamics::ComfortMeter& comfort() const { return comfort_.vertical(); }
  /// Every axis of the comfort point, and the totals (dynamics/seat_comfort.h).
  const dynamics::SeatComfortMeter& seatComfort() const { return comfort_; }
  /// The point the comfort meter watches: options.comfort_point, resolved (resolveComfortPoint():
  /// never empty).
  const std::string& comfortPoint() const { return comfort_point_; }
  /// Largest |vertical acceleration| at the comfort point since reset [m/s^2].
  double peakAcceleration() const { return peak_acceleration_; }

  /// The ground-contact check (dynamics/ground_contact_watch.h): whether the bonded model pulls
  /// on a contact that pressed at rest. Restarted with the vehicle (reset, resetTo, and the reset
  /// after non-finite outputs) from the equilibrium it restarts in. Null when the model's road
  /// inputs are not ground springs on master coordinates (groundContactUnavailable() says why).
  /// Its contacts' `coordinate` numbers the watched coordinates (the distinct contact
  /// coordinates of the model, in contact order), not the model's q.
  const dynamics::GroundContactWatch* groundContactWatch() const {
    return contact_watch_ ? &*contact_watch_ : nullptr;
  }
  /// The same, for its reader's interval (GroundContactWatch::takeInterval).
  dynamics::GroundContactWatch* groundContactWatch() {
    return contact_watch_ ? &*contact_watch_ : nullptr;
  }
  const std::string& groundContactUnavailable() const { return contact_watch_reason_; }
  /// Non-empty when the run integrates the ground-tie modes dynamically with damping that holds
  /// the contacts to an inertial frame (dynamics/ground_tie_damping.h: the exact method, or a
  /// max_mode_frequency above them, with modal damping): the contact forces the watch checks
  /// then carry a damping force no road exerts. Said once at start-up.
  const std::string& groundTieDampingWarning() const { return tie_warning_; }
  /// One check of the sole and pad forces at the current sample: the contacts' coordinates alone
  /// (Simulator::coordinates, O(n_contacts x (modes + inputs)), 30-60 us on the tracked model),
  /// no allocation with the modal method; a few per hundred steps, not one per step. Does nothing
  /// without a watch.
  void checkGroundContact();

  const VehicleGeometry& geometry() const { return geometry_; }
  const terrain::TerrainBuffer& terrain() const { return terrain_; }
  const RoadInputSampler& sampler() const { return sampler_; }
  const dynamics::Simulator& simulator() const { return simulator_; }
  /// Station [m] of the frontmost contact now.
  double frontContactStation() const { return station_ + sampler_.frontmost(); }
  /// Station [m] of the rearmost contact now.
  double rearContactStation() const { return station_ + sampler_.rearmost(); }

 private:
  Vector6 block(const std::vector<Eigen::Index>& rows, Eigen::Index offset) const;
  /// i, when below the number of road wheels (named points); else InputError naming `call`.
  std::size_t checkedWheel(std::size_t i, const char* call) const;
  std::size_t checkedPoint(std::size_t i, const char* call) const;
  /// Named point i's three outputs of the block starting at `offset`.
  Vector3 pointBlock(std::size_t i, Eigen::Index offset) const;
  Eigen::Index outputRow(const std::string& name) const;
  /// station_ += advance, compensated (Kahan): no rounding builds up over millions of steps.
  void advanceStation(double advance);
  /// Samples the road at the current station and speed into road_input_ and the simulator's
  /// input_ (widened with the travel acceleration when slewing); returns the uncovered contacts.
  int sampleInput();
  /// The simulator at rest on the terrain under the vehicle at its station, without travel
  /// acceleration (the static equilibrium on the sampled heights, those heights its input); on
  /// flat ground if that equilibrium is not finite. Returns the uncovered contacts.
  int restOnTerrain();
  /// Whether the last three point_rows_ (a point at `point`) are the hull's rigid motion in H.
  bool movesWithHull(const Matrix& output, const Vector3& point) const;
  /// After every simulator_.reset(): the contact watch's state at rest.
  void restartContactWatch();

  VehicleGeometry geometry_;
  OnlineVehicleOptions options_;
  double time_step_;
  std::string tie_warning_;  // before simulator_, whose construction writes it
  dynamics::Simulator simulator_;
  RoadInputSampler sampler_;
  terrain::TerrainBuffer terrain_;
  dynamics::SeatComfortMeter comfort_;
  std::string comfort_point_;

  dynamics::StaticEquilibriumSolver equilibrium_solver_;
  Vector equilibrium_;  // z0 on flat ground [2k]
  Vector input_;        // the simulator's input, reused every step: w = [u; u'], or with a slew
                        // [u; a; u'; 0] (travel_inertia.h)
  Vector road_input_;   // w = [u; u'] [2 n_inputs] as sampled (with a slew; else input_ is it)
  std::vector<std::string> base_names_;
  Eigen::Index disp_offset_ = 0, vel_offset_ = 0, acc_offset_ = 0;
  std::vector<Eigen::Index> hull_rows_;   // 6 base rows
  std::vector<Eigen::Index> wheel_rows_;  // one base row ("<wheel> uz") per wheel
  std::vector<Eigen::Index> point_rows_;  // 3 base rows per named point
  std::vector<bool> point_rigid_;         // per named point
  Eigen::Index comfort_row_ = 0;          // full row of the comfort point's vertical acceleration
  Eigen::Index comfort_x_row_ = 0, comfort_y_row_ = 0;  // and of its x and y accelerations
  Vector static_outputs_;                               // displacement block at equilibrium
  Vector6 static_hull_ = Vector6::Zero();
  mutable std::vector<WheelState> wheel_states_;

  double max_acceleration_ = 0.0;  // a_max [m/s^2]; 0: no slew
  double max_deceleration_ = 0.0;  // d_max [m/s^2]
  double station_ = 0.0;
  double station_carry_ = 0.0;  ///< what the last addition to station_ lost (advanceStation)
  double speed_ = 0.0;
  double commanded_speed_ = 0.0;
  double travel_acceleration_ = 0.0;
  double peak_acceleration_ = 0.0;
  // Its contacts' coordinates index watched_state_ = [q; q'] of the watched rows.
  std::optional<dynamics::GroundContactWatch> contact_watch_;
  std::string contact_watch_reason_;
  Vector watched_state_;
};

}  // namespace online
}  // namespace tracked_vehicle_dynamics
