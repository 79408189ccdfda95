// `tvd simulate`: time response of the reduced vehicle over a test track (paper §4.2).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.h"
#include "drive.h"
#include "drive_over.h"
#include "output_files.h"
#include "point_comfort.h"
#include "reduction_options.h"
#include "simulation_layout.h"
#include "terrain_coverage.h"
#include "track_option.h"
#include "tracked_vehicle_dynamics/dynamics/comfort.h"
#include "tracked_vehicle_dynamics/dynamics/ground_contact.h"
#include "tracked_vehicle_dynamics/dynamics/ground_contact_forces.h"
#include "tracked_vehicle_dynamics/dynamics/ground_contact_monitor.h"
#include "tracked_vehicle_dynamics/dynamics/ground_tie_damping.h"
#include "tracked_vehicle_dynamics/dynamics/road_excitation.h"
#include "tracked_vehicle_dynamics/dynamics/simulator.h"
#include "tracked_vehicle_dynamics/dynamics/speed_profile.h"
#include "tracked_vehicle_dynamics/dynamics/speed_profile_io.h"
#include "tracked_vehicle_dynamics/dynamics/travel_inertia.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/json_writer.h"
#include "tracked_vehicle_dynamics/reduction/contact_groups.h"
#include "tracked_vehicle_dynamics/reduction/full_model_reference.h"
#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "tracked_vehicle_dynamics/terrain/terrain_io.h"
#include "tracked_vehicle_dynamics/terrain/terrain_lines.h"
#include "tracked_vehicle_dynamics/terrain/terrain_plausibility.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_geometry.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"
#include "vehicle_analysis.h"
#include "warning_list.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {

// A travel acceleration beyond 1 g is no tracked vehicle's (brakes give about 0.6-0.8 g).
constexpr double kPlausibleTravelAcceleration = kStandardGravity;  // types.h

using Clock = std::chrono::steady_clock;

struct SimulateOptions {
  std::string vehicle_file;
  std::string variant = "tracked";
  std::string track = "long_hill";
  double speed_kmh = 30.0;
  std::string speed_profile;  // CSV time_s,speed_kmh; replaces speed_kmh
  double dt = 1e-3;
  double lateral_offset = 0.0;
  std::string method = "modal";
  std::string model = "reduced";
  double max_mode_hz = -1.0;  // < 0: the Nyquist frequency 1 / (2 dt)
  ReducedModelFlags reduced;
  bool variant_given = false;
  std::string out_file;
  bool json = false;
  std::string ground_contact = "on";  // on | off
};

// The summary line: whether every contact stays in compression over the run.
void writeGroundContactText(std::ostream& out, const dynamics::GroundContactSummary& s) {
  out << std::setprecision(3);
  if (!s.anyTension()) {
    out << "  ground contact: all " << s.contacts << " contacts stay in compression, min "
        << s.min_contact_force * 1e-3 << " kN (within the linear model's range)\n";
    return;
  }
  out << "  ground contact: the linear model pulls on " << s.contactsEverInTension() << " of "
      << s.contacts << " contacts (up to " << s.max_in_tension << " at once, min "
      << s.min_contact_force * 1e-3 << " kN)";
  if (s.in_tension_at_rest > 0)
    out << "; " << s.in_tension_at_rest << " already at rest (its bonded statics)";
  if (s.first_new_tension_contact < 0) {
    out << "; none pressed at rest goes into tension\n";
    return;
  }
  out << (s.in_tension_at_rest > 0 ? ", contacts pressed at rest" : "")
      << " from t = " << s.first_new_tension_time << " s (x = " << s.first_new_tension_station
      << " m, " << s.newTensionFraction() * 100
      << " % of samples): beyond its range, a real vehicle would lift there";
  if (s.groups > 0) {
    if (s.first_new_group_tension >= 0)
      out << "; whole pads (up to " << s.max_groups_in_tension << " of " << s.groups
          << " at once) from t = " << s.first_new_group_tension_time
          << " s (x = " << s.first_new_group_tension_station << " m)";
    else
      out << "; no pad pressed at rest pulls as a whole (min " << s.min_group_force * 1e-3
          << " kN)";
  }
  out << "\n";
}

// The ground contact block of the JSON (ground_contact_monitor.h).
void writeGroundContactJson(io::JsonWriter& json, const dynamics::GroundContactSummary& s,
                            const std::vector<std::string>& labels, const Vector& stations,
                            const std::vector<dynamics::GroundContact>& contacts,
                            double static_total, double setup_seconds) {
  auto contact = [&](DofIndex i) {
    json.beginObject().field("index", static_cast<long long>(i));
    if (i >= 0) {
      const dynamics::GroundContact& c = contacts[static_cast<std::size_t>(i)];
      if (static_cast<std::size_t>(c.input) < labels.size())
        json.field("input", labels[static_cast<std::size_t>(c.input)]);
      json.field("side", dynamics::contactSideName(c.side));
      if (c.input < stations.size())
        json.field("x_m", stations(c.input));
      json.field("y_m", c.lateral);
    }
    json.endObject();
  };
  json.beginObject()
      .field("contacts", static_cast<long long>(s.contacts))
      // In range: no contact pressed at rest ever pulls. The bonded tracked model pulls on some
      // soles already at rest (its statics, counted apart); judging by those would put every
      // tracked run, even on flat ground, out of range.
      .field("in_range", s.first_new_tension_contact < 0)
      .field("in_range_at_rest", s.in_tension_at_rest == 0)
      .field("first_tension_time_s", s.first_tension_time)
      .field("first_tension_station_m", s.first_tension_station);
  json.key("first_tension_contact");
  if (s.first_tension_contact >= 0)
    contact(s.first_tension_contact);
  else
    json.value(std::numeric_limits<double>::quiet_NaN());  // null
  json.field("contacts_in_tension_at_rest", static_cast<long long>(s.in_tension_at_rest))
      .field("first_new_tension_time_s", s.first_new_tension_time)
      .field("first_new_tension_station_m", s.first_new_tension_station);
  json.key("first_new_tension_contact");
  if (s.first_new_tension_contact >= 0)
    contact(s.first_new_tension_contact);
  else
    json.value(std::numeric_limits<double>::quiet_NaN());  // null
  json.field("new_tension_sample_fraction", s.newTensionFraction())
      .field("max_contacts_in_tension", static_cast<long long>(s.max_in_tension))
      .field("contacts_ever_in_tension", static_cast<long long>(s.contactsEverInTension()))
      .field("tension_samples", static_cast<long long>(s.tension_samples))
      .field("tension_sample_fraction", s.tensionFraction())
      .field("min_contact_force_n", s.min_contact_force)
      .field("min_contact_force_time_s", s.min_contact_time);
  json.key("min_contact");
  contact(s.min_contact);
  json.field("static_ground_force_n", static_total)
      .field("peak_ground_force_left_n", s.peak_left)
      .field("min_ground_force_left_n", s.min_left)
      .field("peak_ground_force_right_n", s.peak_right)
      .field("min_ground_force_right_n", s.min_right)
      .field("setup_seconds", setup_seconds);
  json.key("pads")
      .beginObject()
      .field("count", static_cast<long long>(s.groups))
      .field("in_tension_at_rest", static_cast<long long>(s.groups_in_tension_at_rest))
      .field("max_in_tension", static_cast<long long>(s.max_groups_in_tension))
      .field("first_new_tension_time_s", s.first_new_group_tension_time)
      .field("first_new_tension_station_m", s.first_new_group_tension_station)
      .field("new_tension_sample_fraction", s.newGroupTensionFraction())
      .field("min_force_n", s.min_group_force)
      .endObject()
      .endObject();
}

void run(const SimulateOptions& opt) {
  vehicle::Variant variant = vehicle::parseVariant(opt.variant);
  if (!(opt.speed_kmh > 0) || opt.speed_kmh > dynamics::kMaxSpeedKmh)
    throw InputError("simulate: --speed-kmh must be in (0, " + brief(dynamics::kMaxSpeedKmh) +
                     "], got " + beyond(opt.speed_kmh, dynamics::kMaxSpeedKmh));
  if (opt.method != "modal" && opt.max_mode_hz >= 0 && opt.model != "full")
    throw InputError(
        "simulate: --max-mode-hz applies to --method modal only, or to --model full (the "
        "exact method integrates every mode of the reduced model)");
  std::optional<dynamics::SpeedProfile> profile;
  if (!opt.speed_profile.empty()) {
    profile = dynamics::loadSpeedProfile(opt.speed_profile);
    if (profile->maxSpeed() * kKmhPerMs > dynamics::kMaxSpeedKmh)
      throw InputError(opt.speed_profile + ": speeds above " + brief(dynamics::kMaxSpeedKmh) +
                       " km/h are outside the model's use (it reaches " +
                       beyond(profile->maxSpeed() * kKmhPerMs, dynamics::kMaxSpeedKmh) + " km/h)");
  }
  // Plausibility (terrain_plausibility.h): said before any work, run all the same.
  std::vector<std::string> warnings;  // printed on stderr as they arise, and in the JSON
  double jolt_at = 0.0;
  const double jolt = profile ? profile->maxAbsAcceleration(&jolt_at) : 0.0;
  if (jolt > kPlausibleTravelAcceleration) {
    warnings.push_back(
        opt.speed_profile + ": the speed changes at up to " + brief(jolt) + " m/s^2 (" +
        brief(jolt / kStandardGravity) + " g) from t = " + brief(jolt_at) +
        " s, more than a tracked vehicle's brakes or traction give (under 1 g): times in ms "
        "read as s? The model applies it as a travel acceleration on the hull");
  }
  const terrain::Terrain track = loadTrackOption("simulate", opt.track);
  for (std::string& w : terrain::terrainWarnings(opt.track, track))
    warnings.push_back(std::move(w));
  for (const std::string& w : warnings)
    std::cerr << "tvd: warning: " << w << "\n";
  // From the start of the track until the station has covered its length (paper: 30 m), or until
  // the speed profile ends. Checked before the model is obtained, which may take seconds.
  const double distance = track.endStation() - track.startStation();
  if (!(distance > 0))
    throw InputError(opt.track + ": the terrain has a single station; a track must cover a length");
  const Drive drive =
      profile ? Drive(track.startStation(), distance, opt.dt, *profile, opt.speed_profile)
              : Drive(track.startStation(), distance, opt.dt, opt.speed_kmh / kKmhPerMs);
  const long steps = drive.steps();

  // The reduced model (cached or from a file), or the full FE model in modal form with its
  // static residual.
  std::optional<ReducedModelSource> reduced;
  std::unique_ptr<reduction::FullModelReference> full;
  const vehicle::VehicleDescription description = loadVehicle(opt.vehicle_file, &warnings);
  refuseDrivingBesideTerrain(opt.track, track, description, opt.lateral_offset);
  if (opt.model == "full") {
    if (opt.max_mode_hz == 0 || opt.max_mode_hz > 100)
      throw InputError(
          "simulate: --model full needs --max-mode-hz in (0, 100] Hz (the full model's "
          "modes up to it are dynamic, the rest static; above 100 Hz the tracked "
          "model's chain-link modes take minutes to solve)");
    reduction::FullReferenceOptions ref_options;
    if (opt.max_mode_hz >= 0)
      ref_options.max_frequency_hz = opt.max_mode_hz;
    full = std::make_unique<reduction::FullModelReference>(
        reduction::buildVehicleReference(description, variant, ref_options));
  } else {
    reduced = obtainReducedModel(description, variant, opt.variant_given, "simulate", opt.reduced);
    variant = reduced->variant;  // a --reduced file's
  }
  const dynamics::SecondOrderSystem& model_sys = full ? full->modal : reduced->model.system;
  const Vector& gravity = full ? full->modal_gravity : reduced->model.gravity_load;
  // A varying speed accelerates the path frame the model lives in: the travel acceleration a(t)
  // rides as one more input (travel_inertia.h). At constant speed the model is run as it is,
  // so those runs are unchanged.
  const bool travel = profile.has_value();
  std::unique_ptr<reduction::FullModelReference> full_travel;
  dynamics::SecondOrderSystem reduced_travel;
  if (travel && full)
    full_travel = std::make_unique<reduction::FullModelReference>(full->withTravelInertia());
  else if (travel)
    reduced_travel = dynamics::withTravelInertia(model_sys, reduced->model.travel_load);
  const reduction::FullModelReference* full_run = full_travel ? full_travel.get() : full.get();
  const dynamics::SecondOrderSystem& sys = full_run ? full_run->modal
                                           : travel ? reduced_travel
                                                    : model_sys;
  const bool from_cache = reduced && reduced->kind == ReducedModelSource::Kind::Cache;

  dynamics::SimulatorOptions sim_options;
  sim_options.time_step = opt.dt;
  sim_options.hold = dynamics::InputHold::FirstOrder;  // the profile is piecewise linear in time
  // Discrete dampers coupling the modes: both methods keep the whole damping (the modal one
  // steps the coupled dynamic modes together, modal_engine.cpp).
  sim_options.method = dynamics::methodFromName(opt.method).value();  // CLI11 checked the name
  sim_options.quantities = {dynamics::OutputQuantity::Displacement,
                            dynamics::OutputQuantity::Velocity,
                            dynamics::OutputQuantity::Acceleration};
  sim_options.generalized_force = gravity;
  if (sim_options.method == dynamics::DiscretizationMethod::ModalDecoupled && !full)
    sim_options.max_mode_frequency_hz =
        opt.max_mode_hz < 0 ? dynamics::nyquistCutoff(opt.dt) : opt.max_mode_hz;
  const auto setup_start = Clock::now();
  // One modal decomposition for the run and, below, its ground contact forces.
  std::optional<dynamics::ModalSystem> modal;
  if (!full && sim_options.method == dynamics::DiscretizationMethod::ModalDecoupled)
    modal.emplace(sys);
  // The exact method's augmented exponential, likewise once for both (seconds on the tracked
  // model): the Simulator on it is the one Simulator(sys, sim_options) builds.
  std::optional<dynamics::StateSpace> discrete;
  if (!full && sim_options.method == dynamics::DiscretizationMethod::AugmentedExponential &&
      opt.ground_contact == "on")
    discrete = dynamics::exactDiscretization(sys, sim_options);
  dynamics::Simulator sim = modal      ? dynamics::Simulator(sys, *modal, sim_options)
                            : discrete ? dynamics::Simulator(*discrete)
                                       : dynamics::Simulator(sys, sim_options);
  const double setup_seconds = std::chrono::duration<double>(Clock::now() - setup_start).count();
  // Every modal run, the full model's included (0 for the exact method, which keeps all of C).
  warn(&warnings,
       dynamics::modalDampingCouplingWarning(
           sim.maxOffDiagonalDampingRatio(),
           full ? "--model full (its modes, each with its own damping)"
                : "--method modal (the default)",
           full ? "--method exact integrates the whole C"
                : "--method exact integrates the whole C (slower: seconds to set up on the "
                  "tracked model)"));
  // Ground contact (ground_contact.h): the force of every road input's spring, checked for
  // tension, the limit of the bonded linear model. Reduced model only: the full model's modal
  // coordinates carry no ground DOF (K_u = Phi^T K_u is not of the spring form), and its ground
  // DOFs' static residual is not among its outputs.
  const bool monitor_contact = !full && opt.ground_contact == "on";
  std::vector<dynamics::GroundContact> contacts;
  std::unique_ptr<dynamics::GroundContactForces> contact_forces;
  std::unique_ptr<dynamics::GroundContactMonitor> contact_monitor;
  double contact_setup_seconds = 0.0;
  if (monitor_contact) {
    const auto contact_start = Clock::now();
    contacts = dynamics::groundContacts(model_sys);  // the road inputs (not the travel input)
    reduction::groupContactsByAssembly(vehicle::buildVehicleModel(description, variant),
                                       reduced->model, &contacts);
    contact_forces = discrete ? std::make_unique<dynamics::GroundContactForces>(
                                    sys, contacts, sim_options, *discrete)
                              : std::make_unique<dynamics::GroundContactForces>(
                                    sys, contacts, sim_options, modal ? &*modal : nullptr);
    contact_monitor = std::make_unique<dynamics::GroundContactMonitor>(contacts);
    contact_setup_seconds = std::chrono::duration<double>(Clock::now() - contact_start).count();
    // Damped ground-tie modes integrated dynamically fill the contact forces with a damping
    // force no road exerts (ground_tie_damping.h): 3.4 times the default run's side peak on the
    // bundled tracked vehicle over the long hill at 30 km/h with --method exact.
    const std::string how = discrete               ? "--method exact integrates every mode"
                            : opt.max_mode_hz == 0 ? "--max-mode-hz 0 keeps every mode dynamic"
                            : opt.max_mode_hz > 0
                                ? "--max-mode-hz " + brief(opt.max_mode_hz)
                                : "--max-mode-hz defaults to the Nyquist frequency of --dt " +
                                      brief(opt.dt) + ", " +
                                      brief(dynamics::nyquistCutoff(opt.dt)) + " Hz";
    const std::string instead =
        discrete ? "run --method modal (the default) with --max-mode-hz below them (by default "
                   "the Nyquist frequency of --dt, 500 Hz at 1 ms), which keeps them quasi-static"
                 : "set --max-mode-hz below them (the ride modes lie far below), which keeps "
                   "them quasi-static";
    try {
      const std::string w =
          dynamics::groundTieDampingWarning(sys, contacts, modal ? &*modal : nullptr,
                                            sim_options.max_mode_frequency_hz, how, instead);
      warn(&warnings, w);
    } catch (const Error&) {
      // A diagnostic: a model not held by its ground springs alone has no tie to judge, and
      // the run goes on.
    }
  }

  // The road under the model's own inputs (the travel input reads none).
  const dynamics::RoadExcitation road(model_sys.input_stations, model_sys.input_lateral,
                                      opt.lateral_offset);
  const terrain::TerrainLines lines(track, road.inputY());  // the pad rows, precomputed
  warn(&warnings, terrainCoverageWarning(opt.track, track, road, opt.lateral_offset));

  const std::vector<std::string>& names = sim.outputNames();
  const SimulationLayout layout = simulationLayout(names, sys.output_names);
  // The road under each wheel centre, from its height at the start like the displacements.
  const std::vector<RoadUnderWheel> roads =
      roadUnderWheels(layout, vehicle::vehicleGeometry(description));
  auto roadHeight = [&](const RoadUnderWheel& r, long k) {
    return track.height(drive.station(k) + r.x, r.y + opt.lateral_offset);
  };
  Vector road0(static_cast<Eigen::Index>(roads.size()));
  for (std::size_t r = 0; r < roads.size(); ++r)
    road0(static_cast<Eigen::Index>(r)) = roadHeight(roads[r], 0);
  // Ride comfort at the hull's CoG and at every named point: ISO 2631-1 Wk and absorbed power
  // vertically, Wd in x and y, We of the hull's rotations.
  std::vector<std::string> comfort_points = {"hull"};
  comfort_points.insert(comfort_points.end(), layout.points.begin(), layout.points.end());
  std::vector<PointComfort> comfort;
  for (const std::string& point : comfort_points)
    comfort.emplace_back(point, comfortRows(names, point, "simulate"), opt.dt);

  constexpr int kFirstColumn = 2;  // after time and station
  const auto first_road = static_cast<Eigen::Index>(kFirstColumn + layout.columns.size());
  // Then the travel acceleration a(t) (0 at constant speed), then, when monitored, the ground
  // force per side and the contacts in tension (appended: the columns before are unchanged).
  const auto travel_column = first_road + static_cast<Eigen::Index>(roads.size());
  const auto contact_column = travel_column + 1;
  Matrix series(steps + 1, contact_column + (monitor_contact ? 3 : 0));
  // The model's accelerations are relative to the path frame; along x an accelerometer on the
  // hull also reads the frame's own acceleration: absolute x acceleration = relative + a(t), so
  // the x columns and ISO 2631's a_wx of a braking run include the braking.
  std::vector<DofIndex> x_accelerations;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i].size() > 7 && names[i].compare(names[i].size() - 7, 7, " ux/acc") == 0)
      x_accelerations.push_back(static_cast<DofIndex>(i));
  Eigen::RowVectorXd absolute(static_cast<Eigen::Index>(names.size()));
  Vector y0;
  const auto start = Clock::now();
  driveOver(
      sim, sys, gravity, drive, road, lines, full_run,
      [&](long k, const OutputRow& relative) {
        const double a = drive.acceleration(k);
        series(k, travel_column) = a;
        if (travel) {
          absolute = relative;
          for (const DofIndex r : x_accelerations)
            absolute(r) += a;
        }
        const OutputRow y = travel ? OutputRow(absolute) : relative;
        if (k == 0)
          y0 = y.transpose();
        series(k, 0) = k * opt.dt;
        series(k, 1) = drive.station(k);
        for (std::size_t c = 0; c < layout.columns.size(); ++c) {
          const SimulationColumn& col = layout.columns[c];
          series(k, kFirstColumn + c) =
              col.scale * (y(col.row) - (col.relative ? y0(col.row) : 0.0));
        }
        for (PointComfort& c : comfort)
          c.add(y);
      },
      contact_forces.get(),
      [&](long first, const Eigen::Ref<const Matrix>& forces) {
        Vector times(forces.rows()), stations(forces.rows());
        for (Eigen::Index j = 0; j < forces.rows(); ++j) {
          times(j) = (first + j) * opt.dt;
          stations(j) = drive.station(first + j);
        }
        contact_monitor->add(forces, times, stations);
      });
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();
  if (monitor_contact && contact_monitor->leftForce().size() != static_cast<std::size_t>(steps + 1))
    throw std::logic_error("simulate: the ground contact monitor saw " +
                           std::to_string(contact_monitor->leftForce().size()) +
                           " samples, the run " + std::to_string(steps + 1));
  if (monitor_contact)
    for (long k = 0; k <= steps; ++k) {
      const auto i = static_cast<std::size_t>(k);
      series(k, contact_column) = contact_monitor->leftForce()[i];
      series(k, contact_column + 1) = contact_monitor->rightForce()[i];
      series(k, contact_column + 2) = contact_monitor->contactsInTension()[i];
    }
  for (long k = 0; k <= steps; ++k)
    for (std::size_t r = 0; r < roads.size(); ++r) {
      const auto i = static_cast<Eigen::Index>(r);
      series(k, first_road + i) = roadHeight(roads[r], k) - road0(i);
    }
  const double simulated = steps * opt.dt;
  const double travelled = series(steps, 1) - track.startStation();
  if (travelled < distance * (1 - 1e-9)) {
    std::ostringstream w;
    w << "the speed profile ends after " << travelled << " m, before the track's " << distance
      << " m";
    warn(&warnings, w.str());
  }
  // The node's criterion (its "beyond the linear model's range" WARN): a whole pad pressed at
  // rest pulls on the road (without pads, a contact). Beyond it the run is the bonded model's,
  // not a vehicle's, however plausible its curves look: said where warnings are looked for.
  if (monitor_contact) {
    const dynamics::GroundContactSummary& s = contact_monitor->summary();
    const bool by_pads = s.groups > 0;
    if (by_pads ? s.first_new_group_tension >= 0 : s.first_new_tension_contact >= 0) {
      std::ostringstream w;
      w << std::fixed << std::setprecision(3) << "beyond the linear model's range from t = "
        << (by_pads ? s.first_new_group_tension_time : s.first_new_tension_time)
        << " s (x = " << (by_pads ? s.first_new_group_tension_station : s.first_new_tension_station)
        << " m): the bonded model pulls on the road with " << (by_pads ? "whole pads" : "contacts")
        << " pressed at rest (up to " << (by_pads ? s.max_groups_in_tension : s.max_in_tension)
        << " of " << (by_pads ? s.groups : s.contacts)
        << " at once), where a vehicle would lift them; the results after that are the linear "
           "model's (ground_contact in the JSON; README, \"Ground contact\")";
      warn(&warnings, w.str());
    }
  }

  auto peak = [&](const std::string& header) {
    return series.col(kFirstColumn + layout.column(header)).cwiseAbs().maxCoeff();
  };
  const double peak_heave = peak("hull_heave_m");
  const double peak_accel = peak("hull_vertical_accel_m_s2");
  const double peak_pitch = peak("hull_pitch_deg");
  const double peak_roll = peak("hull_roll_deg");
  const double peak_wheel =
      layout.wheel_count == 0
          ? 0.0
          : series.middleCols(kFirstColumn + layout.first_wheel, layout.wheel_count)
                .cwiseAbs()
                .maxCoeff();

  // The modes integrated, up to this (0: every mode); above it quasi-static.
  const double max_mode_hz = !full ? sim_options.max_mode_frequency_hz
                             : opt.max_mode_hz >= 0
                                 ? opt.max_mode_hz
                                 : reduction::FullReferenceOptions().max_frequency_hz;
  if (!opt.out_file.empty()) {
    std::vector<std::string> headers = {"time_s", "station_m"};
    for (const SimulationColumn& col : layout.columns)
      headers.push_back(col.header);
    for (const RoadUnderWheel& r : roads)
      headers.push_back(r.header);
    headers.push_back("travel_accel_m_s2");
    if (monitor_contact)
      for (const char* h : {"ground_force_left_n", "ground_force_right_n", "contacts_in_tension"})
        headers.push_back(h);
    Metadata metadata = {{"vehicle", description.name},
                         {"vehicle_file", opt.vehicle_file},
                         {"variant", vehicle::variantName(variant)},
                         {"track", track.name()},
                         {"track_argument", opt.track},
                         {"model", full ? "full" : "reduced"},
                         {"method", opt.method},
                         {"dt_s", opt.dt},
                         {"max_mode_hz", max_mode_hz},
                         {"lateral_offset_m", opt.lateral_offset}};
    if (!opt.reduced.reducedFile().empty())
      metadata.push_back({"reduced_model_file", opt.reduced.reducedFile()});
    if (profile)
      metadata.push_back({"speed_profile", opt.speed_profile});
    else
      metadata.push_back({"speed_kmh", opt.speed_kmh});
    writeTable(opt.out_file, headers, series, 9, metadata);
  }
  if (opt.json) {
    io::JsonWriter json(std::cout);
    json.beginObject()
        .field("vehicle", description.name)
        .field("vehicle_file", opt.vehicle_file)
        .field("variant", vehicle::variantName(variant))
        .field("track", track.name())
        .field("track_argument", opt.track)  // the file or built-in name given to --track
        .field("lateral_offset_m", opt.lateral_offset)
        .field("max_mode_hz", max_mode_hz);
    if (!opt.reduced.reducedFile().empty())
      json.field("reduced_model_file", opt.reduced.reducedFile());
    if (profile) {
      json.field("speed_profile", opt.speed_profile)
          .field("mean_speed_kmh", travelled / simulated * kKmhPerMs)
          .field("max_speed_kmh", profile->maxSpeed() * kKmhPerMs);
    } else {
      json.field("speed_kmh", opt.speed_kmh);
    }
    json.field("warnings", warnings)
        .field("travelled_m", travelled)
        .field("time_step_s", opt.dt)
        .field("model", full ? "full" : "reduced")
        .field("method", opt.method)
        .field(full ? "modal_coordinates" : "reduced_dofs", static_cast<long long>(sys.size()))
        .field("full_dofs",
               static_cast<long long>(full ? full->full_dofs : reduced->model.full_dof_count))
        .field("dynamic_modes", static_cast<long long>(sim.dynamicModeCount()))
        .field("quasi_static_modes", static_cast<long long>(sim.quasiStaticModeCount()))
        .field("model_from_cache", from_cache);
    if (reduced)
      writeReductionJson(json.key("reduction"), *reduced);
    json.field("peak_hull_heave_m", peak_heave)
        .field("peak_hull_vertical_accel_m_s2", peak_accel)
        .field("peak_pitch_deg", peak_pitch)
        .field("peak_roll_deg", peak_roll)
        .field("peak_wheel_displacement_m", peak_wheel)
        .field("peak_hull_heave_rate_m_s", peak("hull_heave_rate_m_s"))
        .field("peak_pitch_rate_deg_s", peak("hull_pitch_rate_deg_s"))
        .field("peak_roll_rate_deg_s", peak("hull_roll_rate_deg_s"))
        .field("peak_pitch_accel_deg_s2", peak("hull_pitch_accel_deg_s2"))
        .field("peak_roll_accel_deg_s2", peak("hull_roll_accel_deg_s2"))
        .field("peak_yaw_deg", peak("hull_yaw_deg"))
        .field("peak_yaw_rate_deg_s", peak("hull_yaw_rate_deg_s"))
        .field("peak_yaw_accel_deg_s2", peak("hull_yaw_accel_deg_s2"))
        .field("peak_travel_accel_m_s2", series.col(travel_column).cwiseAbs().maxCoeff());
    json.key("ground_contact");
    if (monitor_contact)
      writeGroundContactJson(
          json, contact_monitor->summary(), reduced->model.input_labels, model_sys.input_stations,
          contacts, contact_monitor->leftForce().front() + contact_monitor->rightForce().front(),
          contact_setup_seconds);
    else
      json.beginObject()
          .field("monitored", false)
          .field("reason", full ? "--model full: reduced model only (the full model's modal "
                                  "coordinates carry no ground DOF)"
                                : "--ground-contact off")
          .endObject();
    json.key("peaks_at_points").beginArray();
    for (const std::string& point : layout.points)
      json.beginObject()
          .field("point", point)
          .field("peak_vertical_displacement_m", peak(point + "_vertical_m"))
          .field("peak_vertical_accel_m_s2", peak(point + "_accel_z_m_s2"))
          .endObject();
    json.endArray().key("comfort");
    comfort.front().writeJson(json);
    json.key("comfort_at_points").beginArray();
    for (std::size_t i = 1; i < comfort.size(); ++i)
      comfort[i].writeJson(json);
    json.endArray()
        .field("simulated_seconds", simulated)
        .field("wall_seconds", wall)
        .field("setup_seconds", setup_seconds)
        .field("real_time_factor", simulated / wall);
    if (!opt.out_file.empty())
      json.field("out", opt.out_file);
    json.endObject();
    return;
  }
  std::cout << std::fixed << std::setprecision(3) << track.name();
  if (profile)
    std::cout << " with the speed profile " << opt.speed_profile << " (mean "
              << travelled / simulated * kKmhPerMs << " km/h, " << travelled << " m travelled"
              << (travelled < distance ? ", the profile ends before the track does" : "") << ")";
  else
    std::cout << " at " << opt.speed_kmh << " km/h";
  std::cout << ", " << vehicle::variantName(variant)
            << (full ? " full model (" + std::to_string(sys.size()) + " modes + static residual"
                     : " reduced model (" + std::to_string(sys.size()) + " DOFs")
            << (from_cache ? ", cached" : "") << "), dt " << opt.dt * 1e3 << " ms\n";
  if (reduced)
    std::cout << "  reduction: " << describeReduction(*reduced) << "\n";
  std::cout << "  peak hull heave " << peak_heave << " m, vertical acceleration " << peak_accel
            << " m/s^2, pitch " << peak_pitch << " deg, roll " << peak_roll << " deg\n"
            << "  peak road-wheel displacement " << peak_wheel << " m\n";
  if (travel)
    std::cout << "  peak travel acceleration " << series.col(travel_column).cwiseAbs().maxCoeff()
              << " m/s^2 (its inertia loads the model; x accelerations are absolute)\n";
  for (const std::string& point : layout.points)
    std::cout << "  peak at " << point << ": vertical displacement " << peak(point + "_vertical_m")
              << " m, vertical acceleration " << peak(point + "_accel_z_m_s2") << " m/s^2\n";
  std::cout << "  ride comfort (ISO 2631-1 a_w: Wk vertical, Wd horizontal, We rotational; "
               "absorbed power vertical):\n";
  for (const PointComfort& c : comfort)
    c.writeText(std::cout);
  if (monitor_contact)
    writeGroundContactText(std::cout, contact_monitor->summary());
  else
    std::cout << "  ground contact: not monitored ("
              << (full ? "--model full; the reduced model reports it" : "--ground-contact off")
              << ")\n";
  std::cout << "  simulated " << simulated << " s in " << wall * 1e3 << " ms (real-time factor "
            << std::setprecision(0) << simulated / wall << "), after a set-up of "
            << std::setprecision(3) << setup_seconds << " s (discretisation";
  if (monitor_contact)
    std::cout << ") and " << contact_setup_seconds << " s (ground-contact forces";
  std::cout << ")\n";
}

}  // namespace

void registerSimulateCommand(CLI::App& app) {
  auto opt = std::make_shared<SimulateOptions>();
  CLI::App* cmd =
      app.add_subcommand("simulate", "Time response of the reduced (or full) vehicle over a track");
  addVehicleOption(cmd, &opt->vehicle_file);
  CLI::Option* variant =
      addVariantOption(cmd, &opt->variant, "untracked | tracked (with --reduced: the file's)");
  cmd->add_option("--track", opt->track,
                  "long_hill | separated_waves | oop_waves | half_round:H (obstacle, H in m) | "
                  "terrain file (CSV/YAML); oop_waves is laid out for the paper's 1 m offset "
                  "towards +y: --lateral-offset adds to it");
  CLI::Option* speed =
      cmd->add_option("--speed-kmh", opt->speed_kmh, "constant speed [km/h], (0, 200]");
  cmd->add_option("--speed-profile", opt->speed_profile,
                  "speed varying in time instead: CSV time_s,speed_kmh (or speed_m_s), linear "
                  "between rows; the run ends at the track's end or the profile's; its "
                  "acceleration's inertia loads the model (braking pitches the nose down)")
      ->check(CLI::ExistingFile)
      ->excludes(speed);
  // Up to 10 ms: 100 Hz sampling still resolves the 0-30 Hz band, and ISO 2631's Wk weighting
  // needs more than 25 Hz.
  cmd->add_option("--dt", opt->dt, "time step [s] (1e-5 .. 0.01, default 0.001)")
      ->check(numberIn(1e-5, 0.01, "s"));
  cmd->add_option("--lateral-offset", opt->lateral_offset,
                  "lateral offset of the path [m] (y left) on the terrain's lines (oop_waves: "
                  "beyond the paper's 1 m, built into the track)")
      ->check(finiteNumber());
  cmd->add_option("--method", opt->method,
                  "discretisation: modal (the modes, fast; the default) | exact (augmented "
                  "exponential of the whole state)")
      ->check(CLI::IsMember({"modal", "exact"}));
  cmd->add_option("--max-mode-hz", opt->max_mode_hz,
                  "modal method: modes above this frequency [Hz] are quasi-static "
                  "(default: the Nyquist frequency 1/(2 dt); 0 keeps every mode dynamic); "
                  "--model full, either method: its modes up to it are kept, the rest static "
                  "(in (0, 100], default 100)")
      ->check(nonNegativeNumber())
      ->default_str("1/(2 dt)");
  cmd->add_option("--model", opt->model,
                  "reduced (Craig-Bampton: cached with the reduction options, or --reduced FILE) | "
                  "full (FE modes up to --max-mode-hz, default 100 Hz, plus static residual: the "
                  "reference)")
      ->check(CLI::IsMember({"reduced", "full"}));
  opt->reduced.addTo(cmd);
  cmd->add_option("--out", opt->out_file, "time series: CSV, or .mat (one variable per column)")
      ->check(outputFile({".csv", ".mat"}));
  cmd->add_flag("--json", opt->json, "print a JSON summary");
  CLI::Option* ground_contact =
      cmd->add_option("--ground-contact", opt->ground_contact,
                      "on | off: report where the linear model's ground springs pull the vehicle "
                      "down (F < 0: beyond its range); reduced model only")
          ->check(CLI::IsMember({"on", "off"}));
  cmd->callback([opt, variant, ground_contact]() {
    opt->reduced.check("simulate", opt->model);
    refuseOutputOverInput("simulate", "--out", opt->out_file,
                          {{"--vehicle", opt->vehicle_file},
                           {"--track", opt->track},
                           {"--speed-profile", opt->speed_profile},
                           {"--reduced", opt->reduced.reducedFile()}});
    if (ground_contact->count() > 0 && opt->model == "full")
      throw InputError(
          "simulate: --ground-contact applies to --model reduced only (the full "
          "model is the reference; the reduced model reports ground contact)");
    opt->variant_given = variant->count() > 0;
    run(*opt);
  });
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
