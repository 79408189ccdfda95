#include "tracked_vehicle_dynamics/online/online_vehicle.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "tracked_vehicle_dynamics/dynamics/ground_tie_damping.h"
#include "tracked_vehicle_dynamics/dynamics/modal_system.h"
#include "tracked_vehicle_dynamics/dynamics/output_layout.h"
#include "tracked_vehicle_dynamics/dynamics/speed_profile.h"
#include "tracked_vehicle_dynamics/dynamics/static_equilibrium.h"
#include "tracked_vehicle_dynamics/dynamics/travel_inertia.h"
#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace online {
namespace {

const char* const kHullOutputs[6] = {"hull ux", "hull uy", "hull uz",
                                     "hull rx", "hull ry", "hull rz"};
const char* const kTranslations[3] = {"ux", "uy", "uz"};

// Which inputs' u'_q the simulator uses: those with a C_u column (the force C_u u'), and, when
// modes are quasi-static, every input with a K_u column, since those modes move at
// H Phi_t Omega_t^-2 Phi_t^T K_u u' (simulator.h). Left at 0 there, the hull's velocity lost the
// ground ties' part: on the bundled vehicle (no ground damping) the node's rates were not the
// derivative of its poses, by 0.2 % of the roll rate's peak on the out-of-phase waves.
std::vector<bool> inputsWithRate(const dynamics::SecondOrderSystem& system,
                                 bool quasi_static_modes) {
  std::vector<bool> flags(static_cast<std::size_t>(system.inputCount()), false);
  for (Eigen::Index q = 0; q < system.inputCount(); ++q) {
    const bool damped =
        system.input_damping.size() != 0 && !system.input_damping.col(q).isZero(0.0);
    const bool stiff = !system.input_stiffness.col(q).isZero(0.0);
    flags[static_cast<std::size_t>(q)] = damped || (quasi_static_modes && stiff);
  }
  return flags;
}

// a_max and d_max of the options, checked; one 0 and the other > 0: the 0 one takes the other's
// value (online_vehicle.h).
std::pair<double, double> slewRates(const OnlineVehicleOptions& options) {
  for (const auto& [name, value] :
       {std::pair<const char*, double>{"max_acceleration", options.max_acceleration},
        std::pair<const char*, double>{"max_deceleration", options.max_deceleration}})
    if (!std::isfinite(value) || value < 0.0)
      throw InputError(std::string("online vehicle: ") + name + " " + brief(value) +
                       " m/s^2 must be finite and not negative");
  const double a =
      options.max_acceleration > 0.0 ? options.max_acceleration : options.max_deceleration;
  const double d =
      options.max_deceleration > 0.0 ? options.max_deceleration : options.max_acceleration;
  return {a, d};
}

// The system the simulator runs: the model, with the travel inertia input when the speed slews.
dynamics::SecondOrderSystem simulatedSystem(const reduction::ReducedModel& model,
                                            const OnlineVehicleOptions& options) {
  if (slewRates(options).first == 0.0)
    return model.system;
  if (model.travel_load.size() != model.size())
    throw InputError(
        "online vehicle: the reduced model has no travel inertia load (travel_load), "
        "which a speed slew (max_acceleration, max_deceleration) needs");
  return dynamics::withTravelInertia(model.system, model.travel_load);
}

}  // namespace

std::string resolveComfortPoint(const std::string& requested,
                                const std::vector<std::string>& point_names) {
  const bool named =
      std::find(point_names.begin(), point_names.end(), requested) != point_names.end();
  if (requested == "hull" || named)
    return requested;
  // Unset, the crew seat where the vehicle names one (the bundled vehicle's), else the hull: a
  // vehicle of one's own runs with the defaults.
  if (requested.empty())
    return std::find(point_names.begin(), point_names.end(), kCrewSeatPoint) != point_names.end()
               ? kCrewSeatPoint
               : "hull";
  std::string known = "hull";
  for (const std::string& name : point_names)
    known += ", " + name;
  throw InputError("online vehicle: comfort_point: unknown point '" + requested +
                   "' (the vehicle has: " + known +
                   "); set comfort_point to one of these, or leave it empty for " + kCrewSeatPoint +
                   " where the vehicle names it, else the hull");
}

dynamics::SimulatorOptions simulatorOptions(const reduction::ReducedModel& model,
                                            const OnlineVehicleOptions& options) {
  if (!std::isfinite(options.rate) || options.rate <= 0.0) {
    throw InputError("online vehicle: rate " + brief(options.rate) +
                     " Hz must be positive and finite");
  }
  dynamics::SimulatorOptions sim;
  sim.time_step = 1.0 / options.rate;
  sim.hold = options.hold;
  sim.method = options.method;
  sim.quantities = {dynamics::OutputQuantity::Displacement, dynamics::OutputQuantity::Velocity,
                    dynamics::OutputQuantity::Acceleration};
  sim.generalized_force = model.gravity_load;
  if (sim.method == dynamics::DiscretizationMethod::ModalDecoupled)
    sim.max_mode_frequency_hz = options.max_mode_frequency_hz < 0
                                    ? dynamics::nyquistCutoff(sim.time_step)
                                    : options.max_mode_frequency_hz;
  return sim;
}

namespace {

// The simulator; with the modal method on a decomposition made here, whose modes also tell
// whether the ground-tie modes are dynamic and damped to an inertial frame
// (ground_tie_damping.h): `tie_warning` receives that warning, "" when they are not.
dynamics::Simulator makeSimulator(const reduction::ReducedModel& model,
                                  const OnlineVehicleOptions& options, std::string* tie_warning) {
  const dynamics::SecondOrderSystem system = simulatedSystem(model, options);
  const dynamics::SimulatorOptions sim = simulatorOptions(model, options);
  std::optional<dynamics::ModalSystem> modal;
  if (sim.method == dynamics::DiscretizationMethod::ModalDecoupled)
    modal.emplace(system);
  try {
    const std::string how =
        !modal                               ? "method exact integrates every mode"
        : options.max_mode_frequency_hz == 0 ? "max_mode_frequency 0 keeps every mode dynamic"
        : options.max_mode_frequency_hz > 0
            ? "max_mode_frequency " + brief(options.max_mode_frequency_hz) + " Hz"
            : "max_mode_frequency defaults to rate / 2, " + brief(sim.max_mode_frequency_hz) +
                  " Hz";
    const std::string instead =
        !modal ? "use the modal method, which keeps the modes above max_mode_frequency (rate / "
                 "2 by default) quasi-static"
               : "set max_mode_frequency below them (the ride modes lie far below), which keeps "
                 "them quasi-static";
    *tie_warning = dynamics::groundTieDampingWarning(system, dynamics::groundContacts(model.system),
                                                     modal ? &*modal : nullptr,
                                                     sim.max_mode_frequency_hz, how, instead);
  } catch (const Error&) {
    // Road inputs that are no ground springs (the contact watch says so), or a model not held
    // by them alone: no tie to judge.
  }
  return modal ? dynamics::Simulator(system, *modal, sim) : dynamics::Simulator(system, sim);
}

}  // namespace

OnlineVehicle::OnlineVehicle(const reduction::ReducedModel& model, VehicleGeometry geometry,
                             const OnlineVehicleOptions& options,
                             const std::vector<int>& contact_groups)
    : geometry_(std::move(geometry)),
      options_(options),
      time_step_(1.0 / options.rate),
      simulator_(makeSimulator(model, options, &tie_warning_)),
      sampler_(model.system.input_stations, model.system.input_lateral,
               inputsWithRate(model.system, simulator_.quasiStaticModeCount() > 0)),
      comfort_(options.rate, options.comfort_running_rms_time),
      equilibrium_solver_(model.system, model.gravity_load) {
  if (!std::isfinite(options.lateral_offset)) {
    throw InputError("online vehicle: lateral_offset is not finite");
  }
  if (!std::isfinite(options.terrain_keep_behind) || options.terrain_keep_behind < 0.0) {
    throw InputError("online vehicle: terrain_keep_behind must be >= 0 and finite");
  }
  if (!(options.terrain_max_memory_mb >= OnlineVehicleOptions::kMinTerrainMemoryMb) ||
      !(options.terrain_max_memory_mb <= OnlineVehicleOptions::kMaxTerrainMemoryMb)) {
    throw InputError("online vehicle: terrain_max_memory_mb must be within 1 .. 1e9 MB, got " +
                     brief(options.terrain_max_memory_mb));
  }
  terrain_.setMemoryLimit(static_cast<std::size_t>(options.terrain_max_memory_mb * 1e6));
  if (sampler_.size() != model.system.inputCount()) {
    throw InputError("online vehicle: the model has " + std::to_string(model.system.inputCount()) +
                     " road inputs but " + std::to_string(sampler_.size()) + " input stations");
  }
  base_names_ = model.system.output_names;
  const dynamics::OutputLayout layout(
      base_names_, {dynamics::OutputQuantity::Displacement, dynamics::OutputQuantity::Velocity,
                    dynamics::OutputQuantity::Acceleration});
  disp_offset_ = layout.offset(dynamics::OutputQuantity::Displacement);
  vel_offset_ = layout.offset(dynamics::OutputQuantity::Velocity);
  acc_offset_ = layout.offset(dynamics::OutputQuantity::Acceleration);
  for (const char* name : kHullOutputs)
    hull_rows_.push_back(outputRow(name));
  for (const auto& wheel : geometry_.wheels)
    wheel_rows_.push_back(outputRow(wheel.name + " uz"));
  for (const auto& point : geometry_.points) {
    for (const char* t : kTranslations)
      point_rows_.push_back(outputRow(point.name + " " + t));
    point_rigid_.push_back(movesWithHull(model.system.output, point.position));
  }
  std::vector<std::string> point_names;
  for (const auto& point : geometry_.points)
    point_names.push_back(point.name);
  comfort_point_ = resolveComfortPoint(options.comfort_point, point_names);
  comfort_row_ = acc_offset_ + outputRow(comfort_point_ + " uz");
  comfort_x_row_ = acc_offset_ + outputRow(comfort_point_ + " ux");
  comfort_y_row_ = acc_offset_ + outputRow(comfort_point_ + " uy");

  std::tie(max_acceleration_, max_deceleration_) = slewRates(options);
  input_.setZero(simulator_.inputCount());
  road_input_.setZero(2 * sampler_.size());
  equilibrium_ = equilibrium_solver_.solve(Vector::Zero(sampler_.size()));
  wheel_states_.resize(geometry_.wheels.size());
  for (std::size_t i = 0; i < geometry_.wheels.size(); ++i) {
    wheel_states_[i].name = geometry_.wheels[i].name;
  }
  // The road inputs as ground springs (K_u(:, i) = k_i e_m(i)); a model of another form runs
  // unchecked, and says so. The travel input of a slewing vehicle is no contact.
  // The watch reads only the contacts' coordinates: the simulator recovers those rows of the
  // state alone (Simulator::coordinates), and the watch's contacts index them in that order.
  if (!contact_groups.empty() && static_cast<int>(contact_groups.size()) != sampler_.size())
    throw InputError("online vehicle: " + std::to_string(contact_groups.size()) +
                     " contact groups for " + std::to_string(sampler_.size()) + " road inputs");
  try {
    std::vector<dynamics::GroundContact> contacts = dynamics::groundContacts(model.system);
    if (!contact_groups.empty()) {
      int next = *std::max_element(contact_groups.begin(), contact_groups.end()) + 1;
      for (dynamics::GroundContact& c : contacts)
        c.group = contact_groups[static_cast<std::size_t>(c.input)];
      // A contact on no pad is watched as a pad of its own: its pulling is never taken for a
      // pad rocking on its soles.
      for (dynamics::GroundContact& c : contacts)
        if (c.group < 0)
          c.group = next++;
    }
    std::vector<DofIndex> rows;
    std::vector<DofIndex> index_of(static_cast<std::size_t>(simulator_.stateCount() / 2), -1);
    for (dynamics::GroundContact& c : contacts) {
      DofIndex& index = index_of[static_cast<std::size_t>(c.coordinate)];
      if (index < 0) {
        index = static_cast<DofIndex>(rows.size());
        rows.push_back(c.coordinate);
      }
      c.coordinate = index;
    }
    simulator_.watchCoordinates(rows);
    contact_watch_.emplace(std::move(contacts), simulator_.inputCount() / 2);
  } catch (const InputError& e) {
    contact_watch_reason_ = e.what();
  }
  reset();
  static_outputs_ = simulator_.outputs().segment(disp_offset_, layout.baseCount());
  static_hull_ = hullDisplacement();
}

bool OnlineVehicle::movesWithHull(const Matrix& output, const Vector3& point) const {
  // Rigid with the hull: u_p = u_G + theta x r, r = p - p_G, row by row of H (y = H q):
  // H_px = H_x + r_z H_ry - r_y H_rz, H_py = H_y + r_x H_rz - r_z H_rx,
  // H_pz = H_z + r_y H_rx - r_x H_ry.
  constexpr double kRelativeTolerance = 1e-9;
  const Vector3 r = point - geometry_.cog;
  const auto hull = [&](int k) { return output.row(hull_rows_[k]); };
  const std::size_t first = point_rows_.size() - 3;
  Matrix rigid(3, output.cols()), actual(3, output.cols());
  rigid << hull(0) + r.z() * hull(4) - r.y() * hull(5), hull(1) + r.x() * hull(5) - r.z() * hull(3),
      hull(2) + r.y() * hull(3) - r.x() * hull(4);
  for (int k = 0; k < 3; ++k)
    actual.row(k) = output.row(point_rows_[first + k]);
  const double scale = rigid.norm() + actual.norm();
  return scale > 0.0 && (actual - rigid).norm() <= kRelativeTolerance * scale;
}

Eigen::Index OnlineVehicle::outputRow(const std::string& name) const {
  const auto it = std::find(base_names_.begin(), base_names_.end(), name);
  if (it == base_names_.end()) {
    throw InputError("online vehicle: the reduced model has no output '" + name +
                     "' (expected hull, road wheel and named point outputs)");
  }
  return static_cast<Eigen::Index>(it - base_names_.begin());
}

void OnlineVehicle::reset() {
  resetTo(0.0, 0.0, ResetTerrain::Clear);
}

int OnlineVehicle::resetTo(double station, double speed, ResetTerrain terrain) {
  if (!std::isfinite(station)) {
    throw InputError("online vehicle: reset station " + brief(station) + " m is not finite");
  }
  if (std::abs(station) > kMaxResetStation) {
    throw InputError("online vehicle: reset station " + brief(station) +
                     " m: |station| must not exceed " + brief(kMaxResetStation) +
                     " m (beyond it a step's advance is lost in the station's rounding)");
  }
  setSpeed(speed);            // validates first: a bad speed throws before anything changes
  speed_ = commanded_speed_;  // at once, also with a slew: it restarts at rest relative to it
  travel_acceleration_ = 0.0;
  station_ = station;
  station_carry_ = 0.0;
  peak_acceleration_ = 0.0;
  int uncovered = 0;
  if (terrain == ResetTerrain::Clear) {
    terrain_.clear();
    sampler_.setHeld(Vector::Zero(sampler_.size()));
    input_.setZero();
    simulator_.reset(equilibrium_, input_);
  } else {
    uncovered = restOnTerrain();
  }
  restartContactWatch();
  comfort_.reset();
  return uncovered;
}

void OnlineVehicle::restartContactWatch() {
  if (!contact_watch_)
    return;
  simulator_.coordinates(&watched_state_);
  contact_watch_->restart(simulator_.time(), watched_state_, simulator_.input());
}

void OnlineVehicle::checkGroundContact() {
  if (!contact_watch_)
    return;
  simulator_.coordinates(&watched_state_);
  contact_watch_->check(simulator_.time(), station_, watched_state_, simulator_.input());
}

bool OnlineVehicle::addTerrain(const TerrainPatch& patch) {
  const double keep_from = rearContactStation() - options_.terrain_keep_behind;
  // What lies behind the vehicle since the last patch goes first, so that the memory limit
  // judges the terrain it still needs (a second call below is cheap: nothing more to cut).
  terrain_.dropBehind(keep_from);
  terrain_.addPatch(patch.start_station, patch.spacing, patch.lateral, patch.heights);
  // A patch the call below frees at once: the caller hears of it instead of counting it as
  // terrain.
  const double end =
      patch.start_station + patch.spacing * static_cast<double>(patch.heights.cols() - 1);
  const bool behind = terrain::TerrainBuffer::dropsPatchEnding(end, patch.spacing, keep_from);
  terrain_.dropBehind(keep_from);
  return !behind;
}

void OnlineVehicle::setSpeed(double speed) {
  if (!std::isfinite(speed) || speed < 0.0) {
    throw InputError("online vehicle: speed " + brief(speed) +
                     " m/s must be finite and not negative");
  }
  // The bound of every other entry (tvd's --speed-kmh, the node's ~max_speed): a speed in km/h
  // given as m/s (3.6x) or in mm/s would otherwise run, far beyond the terrain sent.
  constexpr double kMaxSpeed = dynamics::kMaxSpeedKmh / kKmhPerMs;
  if (speed > kMaxSpeed) {
    throw InputError("online vehicle: speed " + brief(speed) + " m/s is above " + brief(kMaxSpeed) +
                     " m/s (" + brief(dynamics::kMaxSpeedKmh) +
                     " km/h), the fastest the model is run at");
  }
  // -0.0 passes the test above; + 0.0 makes it +0.0 (IEEE 754, round to nearest), so that
  // nothing the vehicle reports shows "-0".
  commanded_speed_ = speed + 0.0;
  if (!slews())
    speed_ = commanded_speed_;
}

void OnlineVehicle::advanceStation(double advance) {
  // Kahan's compensated sum, s += ds with the rounding of each addition carried into the next:
  // the plain sum rounds alike at every step (v h is the same), so its error grew with the step
  // count, -4.5e-10 m a step near 1e7 m (1.6 cm in 10 h at 1 kHz), and the vehicle met the
  // terrain that far from where it was sent. Now within an ulp or two of the exact sum of the
  // steps' advances.
  const double corrected = advance - station_carry_;
  const double sum = station_ + corrected;
  station_carry_ = (sum - station_) - corrected;
  station_ = sum;
}

void OnlineVehicle::setSpeedSince(double speed, long steps) {
  if (slews() || speed_ != 0.0 || commanded_speed_ != 0.0)
    throw InputError("online vehicle: setSpeedSince needs a vehicle standing still (speed " +
                     brief(speed_) + " m/s) without a speed slew");
  if (steps < 0)
    throw InputError("online vehicle: setSpeedSince: " + std::to_string(steps) +
                     " steps must not be negative");
  setSpeed(speed);
  // As the steps advance it: s += v h each (step()), the same product summed.
  for (long k = 0; k < steps; ++k)
    advanceStation(speed_ * time_step_);
}

int OnlineVehicle::sampleInput() {
  const int uncovered =
      sampler_.sample(terrain_, station_, speed_, options_.lateral_offset, &road_input_);
  if (slews())
    dynamics::widenTravelInput(road_input_, travel_acceleration_, input_);
  else
    input_ = road_input_;  // same size: a copy, no allocation
  return uncovered;
}

int OnlineVehicle::restOnTerrain() {
  travel_acceleration_ = 0.0;
  // The input the next step interpolates from (first-order hold) is the one a step at this
  // station would have sampled, u' included; the state is at rest on its heights u.
  const int uncovered = sampleInput();
  Vector state = equilibrium_solver_.solve(road_input_.head(sampler_.size()));
  if (!state.allFinite()) {  // not on this terrain either: on flat ground
    input_.setZero();
    state = equilibrium_;
  }
  simulator_.reset(state, input_);
  return uncovered;
}

StepResult OnlineVehicle::step() {
  StepResult result;
  if (slews()) {
    // v_{k+1} = v_k + clamp(v_c - v_k, -d_max h, a_max h); the commanded speed itself once
    // within reach (exactly, not to rounding). s advances by the trapezoid, exact for constant a.
    const double rise = max_acceleration_ * time_step_, fall = max_deceleration_ * time_step_;
    const double change = commanded_speed_ - speed_;
    const double next = change > rise    ? speed_ + rise
                        : change < -fall ? speed_ - fall
                                         : commanded_speed_;
    travel_acceleration_ = (next - speed_) / time_step_;
    advanceStation(0.5 * (speed_ + next) * time_step_);
    speed_ = next;
  } else {
    advanceStation(speed_ * time_step_);
  }
  result.uncovered = sampleInput();
  simulator_.step(input_);
  const double acceleration = simulator_.outputs()(comfort_row_);
  if (!simulator_.outputs().allFinite()) {
    // Cannot happen for finite inputs and a stable model; never publish NaN if it does: back to
    // equilibrium where the vehicle is, on the terrain under it (as resetTo() keeping the
    // terrain), speed kept. Zero inputs would restart it on flat ground and the next step would
    // lift every contact onto the terrain at once: a shock in the comfort metrics.
    restOnTerrain();
    restartContactWatch();
    result.diverged = true;
    return result;
  }
  // The hull is rigid: its rotations are the seat's (hull_rows_ 3..5: rx, ry, rz).
  const Vector& y = simulator_.outputs();
  comfort_.add({y(comfort_x_row_), y(comfort_y_row_), acceleration, y(acc_offset_ + hull_rows_[3]),
                y(acc_offset_ + hull_rows_[4]), y(acc_offset_ + hull_rows_[5])});
  peak_acceleration_ = std::max(peak_acceleration_, std::abs(acceleration));
  return result;
}

Vector6 OnlineVehicle::block(const std::vector<Eigen::Index>& rows, Eigen::Index offset) const {
  const Vector& y = simulator_.outputs();
  Vector6 out;
  for (int i = 0; i < 6; ++i)
    out(i) = y(offset + rows[static_cast<std::size_t>(i)]);
  return out;
}

RigidPose OnlineVehicle::hullPose() const {
  return online::hullPose(station_, geometry_.cog, hullDisplacement());
}

const std::vector<WheelState>& OnlineVehicle::wheels() const {
  const Vector& y = simulator_.outputs();
  for (std::size_t i = 0; i < wheel_rows_.size(); ++i) {
    const Eigen::Index row = wheel_rows_[i];
    WheelState& state = wheel_states_[i];
    state.displacement = y(disp_offset_ + row) - static_outputs_(row);
    state.velocity = y(vel_offset_ + row);
    state.acceleration = y(acc_offset_ + row);
  }
  return wheel_states_;
}

namespace {

// An index the caller passed (e.g. from its own list of frames) for `count` of `what`: an
// InputError naming it and the count, as the package's other errors do (not .at()'s
// std::out_of_range, which names neither).
std::size_t checkedIndex(std::size_t i, std::size_t count, const char* what, const char* call) {
  if (i < count)
    return i;
  const std::string has = count == 0   ? std::string("none")
                          : count == 1 ? "1 " + std::string(what) + " (index 0)"
                                       : std::to_string(count) + " " + what + "s (0 .. " +
                                             std::to_string(count - 1) + ")";
  throw InputError(std::string("online vehicle: ") + call + ": " + what + " index " +
                   std::to_string(i) + " is out of range: the vehicle has " + has);
}

}  // namespace

std::size_t OnlineVehicle::checkedWheel(std::size_t i, const char* call) const {
  return checkedIndex(i, geometry_.wheels.size(), "road wheel", call);
}

std::size_t OnlineVehicle::checkedPoint(std::size_t i, const char* call) const {
  return checkedIndex(i, geometry_.points.size(), "named point", call);
}

Vector3 OnlineVehicle::wheelPosition(std::size_t i) const {
  const Vector3& p = geometry_.wheels[checkedWheel(i, "wheelPosition")].position;
  const Vector6 hull = hullDisplacement();
  const double uz = simulator_.outputs()(disp_offset_ + wheel_rows_[i]);
  // Only the vertical displacement of a wheel centre is an output; along x and y it moves with
  // the hull (the arm is rigid in its plane to first order).
  const Vector3 u_hull = hullPointDisplacement(geometry_.cog, hull, p);
  return relativePosition(geometry_.cog, hull, p, Vector3(u_hull.x(), u_hull.y(), uz));
}

Vector3 OnlineVehicle::pointBlock(std::size_t i, Eigen::Index offset) const {
  const Vector& y = simulator_.outputs();
  const std::size_t first = 3 * i;
  return Vector3(y(offset + point_rows_[first]), y(offset + point_rows_[first + 1]),
                 y(offset + point_rows_[first + 2]));
}

Vector3 OnlineVehicle::pointPosition(std::size_t i) const {
  const Vector3& p = geometry_.points[checkedPoint(i, "pointPosition")].position;
  return relativePosition(geometry_.cog, hullDisplacement(), p, pointBlock(i, disp_offset_));
}

Vector3 OnlineVehicle::pointAcceleration(std::size_t i) const {
  const Vector3& p = geometry_.points[checkedPoint(i, "pointAcceleration")].position;
  const Vector6 u = hullDisplacement(), du = hullVelocity(), ddu = hullAcceleration();
  // The model's (linear) point acceleration less its rigid part u_G'' + theta'' x r is the
  // elastic part, zero for a point on the rigid hull; the rigid part is then taken exactly.
  const Vector3 elastic =
      pointBlock(i, acc_offset_) - (ddu.head<3>() + ddu.tail<3>().cross(p - geometry_.cog));
  // Relative to the path frame, plus the frame's own acceleration along odom x.
  return rigidPointAcceleration(geometry_.cog, u, du, ddu, p) + elastic +
         Vector3(travel_acceleration_, 0.0, 0.0);
}

}  // namespace online
}  // namespace tracked_vehicle_dynamics
