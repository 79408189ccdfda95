// `tvd ride`: ride-limiting speeds. The reduced vehicle drives a track at each speed of a sweep;
// at each chosen point of the hull the run gives the vertical absorbed power (comfort.h) and the
// peak low-passed vertical acceleration (shock_meter.h), with the ISO 2631-1 values beside them.
// The lowest speed at which each reaches its limit, 6 W and 2.5 g by default (the mobility
// models' "6 W speed" on a rough course and "2.5 g speed" over an obstacle), is bracketed by the
// sweep and narrowed by bisection (limit_crossing.h). With --iso8608 CLASS instead of a track,
// the road is that class's PSD and every speed is evaluated spectrally (ride_spectral.cpp).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "commands.h"
#include "drive.h"
#include "drive_over.h"
#include "output_files.h"
#include "point_comfort.h"
#include "reduction_options.h"
#include "ride_options.h"
#include "ride_report.h"
#include "ride_spectral.h"
#include "simulation_layout.h"
#include "speed_sweep.h"
#include "terrain_coverage.h"
#include "track_option.h"
#include "tracked_vehicle_dynamics/dynamics/limit_crossing.h"
#include "tracked_vehicle_dynamics/dynamics/road_excitation.h"
#include "tracked_vehicle_dynamics/dynamics/shock_meter.h"
#include "tracked_vehicle_dynamics/dynamics/simulator.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/json_writer.h"
#include "tracked_vehicle_dynamics/terrain/terrain_io.h"
#include "tracked_vehicle_dynamics/terrain/terrain_lines.h"
#include "tracked_vehicle_dynamics/terrain/terrain_plausibility.h"
#include "vehicle_analysis.h"
#include "warning_list.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {

using Clock = std::chrono::steady_clock;

/// What one run gives at one point.
struct PointRide {
  double absorbed_power = 0.0;      ///< [W]
  double weighted_rms_z = 0.0;      ///< a_wz [m/s^2]
  double vdv_z = 0.0;               ///< [m/s^1.75]
  double total_value = 0.0;         ///< a_v [m/s^2]
  double seat_surface_total = 0.0;  ///< a_v with the rotations, six axes [m/s^2]
  double peak_up_g = 0.0;           ///< low-passed [g]
  double peak_abs_g = 0.0;          ///< low-passed [g]
  double weighted_rms_x = 0.0;      ///< a_wx (Wd) [m/s^2]
  double weighted_rms_y = 0.0;      ///< a_wy (Wd) [m/s^2]
};

struct Run {
  bool in_sweep = false;
  std::vector<PointRide> points;              // as RideSetup::points
  double roll = 0.0, pitch = 0.0, yaw = 0.0;  // the hull's, We [rad/s^2]
  double rotational_total_value = 0.0;        // a_r [m/s^2]
};

// The --out table's columns: speed, whether in the sweep, six metrics per point, then each
// point's seat-surface total (added last, so that the earlier columns keep their places).
std::vector<std::string> rideHeaders(const std::vector<std::string>& points) {
  std::vector<std::string> headers = {"speed_kmh", "in_sweep"};
  for (const std::string& p : points)
    for (const char* q : {"_absorbed_power_w", "_weighted_rms_z_m_s2", "_vdv_z_m_s1_75",
                          "_vibration_total_value_m_s2", "_peak_up_g", "_peak_abs_g"})
      headers.push_back(p + q);
  for (const std::string& p : points)
    headers.push_back(p + "_seat_surface_total_value_m_s2");
  return headers;
}

void run(const RideOptions& opt) {
  const std::vector<double> sweep = parseSpeedSweep(opt.speeds);
  const terrain::Terrain track = loadTrackOption("ride", opt.track);
  const double distance = track.endStation() - track.startStation();
  if (!(distance > 0))
    throw InputError(opt.track + ": the terrain has a single station; a track must cover a length");

  // The slowest run is the longest; the bisections only run faster ones. Checked before any work.
  const double longest = std::ceil(distance / (sweep.front() / kKmhPerMs) / opt.dt);
  if (longest > Drive::kMaxSteps) {
    std::ostringstream m;
    m << "ride: --speeds: " << distance << " m at " << sweep.front() << " km/h take " << longest
      << " time steps of " << opt.dt << " s; at most " << Drive::kMaxSteps
      << " (raise the lowest speed)";
    throw InputError(m.str());
  }
  // The shock criterion's low-pass is 30 Hz; below 0.1 Hz its settling (several 1 / f_c, tens of
  // seconds) outlasts a run over an obstacle, so the peak read would be the filter's own start,
  // and toward 1e-308 Hz the analogue design's w_c^2 underflowed to a zero numerator ("weighting
  // filter section 0: numerator is zero", naming no option). 0 keeps its meaning: unfiltered.
  constexpr double kMinLowpassHz = 0.1;
  if (opt.lowpass_hz > 0.0 && opt.lowpass_hz < kMinLowpassHz)
    throw InputError("ride: --lowpass-hz " + brief(opt.lowpass_hz) +
                     " must be 0 (unfiltered) or at least " + brief(kMinLowpassHz) + " Hz");
  if (opt.lowpass_hz >= 0.5 / opt.dt) {
    std::ostringstream m;
    m << "ride: --lowpass-hz " << opt.lowpass_hz
      << " must be below the Nyquist frequency 1/(2 dt) = " << 0.5 / opt.dt << " Hz";
    throw InputError(m.str());
  }
  std::vector<std::string> warnings;
  for (const std::string& w : terrain::terrainWarnings(opt.track, track))
    warn(&warnings, w);
  const RideModel model = loadRideModel(opt, &track, &warnings);
  const std::vector<std::string>& points = model.points;
  checkMatColumns("out", opt.out_file, rideHeaders(points));
  const ReducedModelSource& reduced = model.reduced;
  const vehicle::Variant variant = reduced.variant;
  const dynamics::SecondOrderSystem& sys = reduced.model.system;

  dynamics::SimulatorOptions sim_options;
  sim_options.time_step = opt.dt;
  sim_options.hold = dynamics::InputHold::FirstOrder;
  sim_options.method = dynamics::DiscretizationMethod::ModalDecoupled;
  sim_options.max_mode_frequency_hz = dynamics::nyquistCutoff(opt.dt);  // as tvd simulate
  sim_options.quantities = {dynamics::OutputQuantity::Acceleration};
  sim_options.generalized_force = reduced.model.gravity_load;
  dynamics::Simulator sim(sys, sim_options);
  warn(&warnings, dynamics::modalDampingCouplingWarning(
                      sim.maxOffDiagonalDampingRatio(), "tvd ride's modal integration",
                      "tvd simulate --method exact gives the exact run at a speed"));

  const dynamics::RoadExcitation road(sys.input_stations, sys.input_lateral, opt.lateral_offset);
  const terrain::TerrainLines lines(track, road.inputY());
  warn(&warnings, terrainCoverageWarning(opt.track, track, road, opt.lateral_offset));
  const std::vector<std::string>& names = sim.outputNames();
  dynamics::ShockOptions shock;
  shock.lowpass_corner_hz = opt.lowpass_hz;

  // One run per speed, kept by speed: the sweep's, then those the bisections ask for (a speed
  // both limits of several points want is simulated once).
  double simulated = 0.0;
  const auto start = Clock::now();
  RideRuns<Run> ride([&](double speed_kmh) {
    const Drive drive(track.startStation(), distance, opt.dt, speed_kmh / kKmhPerMs);
    std::vector<PointComfort> comfort;
    std::vector<dynamics::ShockMeter> peaks;
    std::vector<DofIndex> z_rows;
    for (const std::string& p : points) {
      comfort.emplace_back(p, comfortRows(names, p, "ride"), opt.dt);
      peaks.emplace_back(1.0 / opt.dt, shock);
      z_rows.push_back(outputRow(names, p + " uz/acc", "ride"));
    }
    driveOver(sim, sys, reduced.model.gravity_load, drive, road, lines, nullptr,
              [&](long, const OutputRow& y) {
                for (std::size_t i = 0; i < points.size(); ++i) {
                  comfort[i].add(y);
                  peaks[i].add(y(z_rows[i]));
                }
              });
    simulated += drive.steps() * opt.dt;
    Run r;
    // The rigid hull's rotations, which every point shares.
    r.roll = comfort.front().meter().roll().weightedRms();
    r.pitch = comfort.front().meter().pitch().weightedRms();
    r.yaw = comfort.front().meter().yaw().weightedRms();
    r.rotational_total_value = comfort.front().meter().rotationalTotalValue();
    for (std::size_t i = 0; i < points.size(); ++i) {
      const dynamics::ComfortMeter& z = comfort[i].meter().vertical();
      r.points.push_back(
          {z.absorbedPower().value_or(0.0), z.weightedRms(), z.vibrationDoseValue(),
           comfort[i].meter().translationalTotalValue(), comfort[i].meter().seatSurfaceTotalValue(),
           peaks[i].peakUp() / kStandardGravity, peaks[i].peakAbsolute() / kStandardGravity,
           comfort[i].meter().longitudinal().weightedRms(),
           comfort[i].meter().lateral().weightedRms()});
    }
    return r;
  });
  ride.sweep(sweep);

  // Per point its absorbed-power limit, then its peak limit.
  std::vector<RideCriterion<Run>> criteria;
  for (std::size_t i = 0; i < points.size(); ++i) {
    criteria.push_back(
        {[i](const Run& r) { return r.points[i].absorbed_power; }, opt.power_limit_w});
    criteria.push_back({[i](const Run& r) { return r.points[i].peak_up_g; }, opt.peak_limit_g});
  }
  const std::vector<dynamics::LimitCrossing> found = ride.limits(criteria, opt.tolerance_kmh);
  struct Limits {
    dynamics::LimitCrossing power, peak;
  };
  std::vector<Limits> limits;
  for (std::size_t i = 0; i < points.size(); ++i)
    limits.push_back({found[2 * i], found[2 * i + 1]});
  const std::map<double, Run>& runs = ride.all();
  const double wall = std::chrono::duration<double>(Clock::now() - start).count();

  // Every run, by speed: the table's rows (headers as checked before the sweep).
  const std::vector<std::string> headers = rideHeaders(points);
  Matrix table(static_cast<Eigen::Index>(runs.size()), static_cast<Eigen::Index>(headers.size()));
  Eigen::Index row = 0;
  for (const auto& [speed, r] : runs) {
    table(row, 0) = speed;
    table(row, 1) = r.in_sweep ? 1.0 : 0.0;
    const auto n = static_cast<Eigen::Index>(points.size());
    for (Eigen::Index i = 0; i < n; ++i) {
      const PointRide& m = r.points[static_cast<std::size_t>(i)];
      table.block(row, 2 + 6 * i, 1, 6) << m.absorbed_power, m.weighted_rms_z, m.vdv_z,
          m.total_value, m.peak_up_g, m.peak_abs_g;
      table(row, 2 + 6 * n + i) = m.seat_surface_total;
    }
    ++row;
  }
  if (!opt.out_file.empty())
    writeTable(opt.out_file, headers, table, 9,
               {{"vehicle", model.vehicle_name},
                {"vehicle_file", opt.vehicle_file},
                {"variant", vehicle::variantName(variant)},
                {"track", track.name()},
                {"track_argument", opt.track},
                {"dt_s", opt.dt},
                {"lateral_offset_m", opt.lateral_offset}});

  if (opt.json) {
    io::JsonWriter json(std::cout);
    json.beginObject()
        .field("vehicle", model.vehicle_name)
        .field("vehicle_file", opt.vehicle_file)
        .field("variant", vehicle::variantName(variant))
        .field("track", track.name())
        .field("track_argument", opt.track)  // the file or built-in name given to --track
        .field("lateral_offset_m", opt.lateral_offset);
    if (!opt.reduced.reducedFile().empty())
      json.field("reduced_model_file", opt.reduced.reducedFile());
    json.field("travelled_m", distance)
        .field("warnings", warnings)
        .field("time_step_s", opt.dt)
        .field("power_limit_w", opt.power_limit_w)
        .field("peak_limit_g", opt.peak_limit_g)
        .field("peak_lowpass_hz", opt.lowpass_hz)
        // 0 with --lowpass-hz 0: the peaks are of the unfiltered acceleration.
        .field("peak_lowpass_order",
               static_cast<long long>(opt.lowpass_hz > 0.0 ? shock.lowpass_order : 0))
        .field("tolerance_kmh", opt.tolerance_kmh)
        .field("reduced_dofs", static_cast<long long>(sys.size()));
    writeReductionJson(json.key("reduction"), reduced);
    json.field("points", points).field("speeds_kmh", sweep);
    json.key("runs").beginArray();
    for (const auto& [speed, r] : runs) {
      json.beginObject()
          .field("speed_kmh", speed)
          .field("in_sweep", r.in_sweep)
          .field("weighted_rms_roll_rad_s2", r.roll)
          .field("weighted_rms_pitch_rad_s2", r.pitch)
          .field("weighted_rms_yaw_rad_s2", r.yaw)
          .field("rotational_total_value_m_s2", r.rotational_total_value)
          .key("points")
          .beginArray();
      for (std::size_t i = 0; i < points.size(); ++i) {
        const PointRide& m = r.points[i];
        json.beginObject()
            .field("point", points[i])
            .field("absorbed_power_w", m.absorbed_power)
            .field("weighted_rms_z_m_s2", m.weighted_rms_z)
            .field("vdv_z_m_s1_75", m.vdv_z)
            .field("weighted_rms_x_m_s2", m.weighted_rms_x)
            .field("weighted_rms_y_m_s2", m.weighted_rms_y)
            .field("vibration_total_value_m_s2", m.total_value)
            .field("seat_surface_total_value_m_s2", m.seat_surface_total)
            .field("peak_up_g", m.peak_up_g)
            .field("peak_abs_g", m.peak_abs_g)
            .endObject();
      }
      json.endArray().endObject();
    }
    json.endArray().key("limits").beginArray();
    for (std::size_t i = 0; i < points.size(); ++i) {
      json.beginObject().field("point", points[i]).key("absorbed_power");
      writeLimitJson(json, limits[i].power, opt.power_limit_w, "W");
      json.key("peak_acceleration");
      writeLimitJson(json, limits[i].peak, opt.peak_limit_g, "g");
      json.endObject();
    }
    json.endArray()
        .field("simulations", static_cast<long long>(runs.size()))
        .field("simulated_seconds", simulated)
        .field("wall_seconds", wall);
    if (!opt.out_file.empty())
      json.field("out", opt.out_file);
    json.endObject();
    return;
  }

  std::cout << std::fixed << std::setprecision(3) << "ride limits on " << track.name() << " ("
            << distance << " m), " << vehicle::variantName(variant) << " reduced model ("
            << sys.size() << " DOFs), dt " << opt.dt * 1e3
            << " ms\n  reduction: " << describeReduction(reduced) << "\n"
            << "  absorbed power P [W] (vertical) and peak upward acceleration a [g] (";
  if (opt.lowpass_hz > 0)
    std::cout << std::defaultfloat << opt.lowpass_hz << " Hz low-pass" << std::fixed;
  else
    std::cout << "unfiltered";
  std::cout << ") per speed:\n  speed km/h";
  for (const std::string& p : points)
    std::cout << std::setw(22) << p + " P" << std::setw(12) << "a";
  std::cout << "\n";
  for (const auto& [speed, r] : runs) {
    std::cout << "  " << std::setw(9) << std::setprecision(2) << speed << (r.in_sweep ? " " : "*");
    for (const PointRide& m : r.points)
      std::cout << std::setw(22) << std::setprecision(3) << m.absorbed_power << std::setw(12)
                << m.peak_up_g;
    std::cout << "\n";
  }
  if (std::any_of(runs.begin(), runs.end(), [](const auto& run) { return !run.second.in_sweep; }))
    std::cout << "  (* speeds the bisection added)\n";
  std::ostringstream power_limit, peak_limit;
  power_limit << std::defaultfloat << opt.power_limit_w << " W";
  peak_limit << std::defaultfloat << opt.peak_limit_g << " g";
  for (std::size_t i = 0; i < points.size(); ++i)
    std::cout << "  " << points[i] << ": " << describeLimit(limits[i].power, power_limit.str())
              << "; " << describeLimit(limits[i].peak, peak_limit.str()) << "\n";
  std::cout << std::setprecision(3) << "  " << runs.size()
            << (runs.size() == 1 ? " run, " : " runs, ") << simulated << " s simulated in " << wall
            << " s\n";
}

}  // namespace

void registerRideCommand(CLI::App& app) {
  auto opt = std::make_shared<RideOptions>();
  CLI::App* cmd = app.add_subcommand(
      "ride",
      "Ride-limiting speeds: absorbed power and peak acceleration over a speed sweep (6 W / 2.5 "
      "g), simulated "
      "over a --track, or the absorbed power spectrally on an ISO 8608 class (--iso8608)");
  addVehicleOption(cmd, &opt->vehicle_file);
  CLI::Option* variant =
      addVariantOption(cmd, &opt->variant, "untracked | tracked (with --reduced: the file's)");
  CLI::Option* track = cmd->add_option("--track", opt->track,
                                       "built-in track (e.g. half_round:0.2, an obstacle H = 0.2 "
                                       "m) or terrain file (CSV/YAML), e.g. an "
                                       "ISO 8608 road from tvd terrain: "
                                       "simulated in time at every speed");
  CLI::Option* iso = cmd->add_option("--iso8608", opt->iso_class,
                                     "instead of --track: the PSD of ISO 8608 road class A..H, "
                                     "evaluated spectrally at every speed "
                                     "(absorbed power, a_wz, r.m.s., every axis and the totals; "
                                     "no peaks, no VDV)");
  cmd->add_option("--speeds", opt->speeds,
                  "speeds [km/h]: FIRST:LAST:STEP (STEP must land on LAST) or a list 5,10,20");
  CLI::Option* points =
      cmd->add_option("--points", opt->points,
                      "points of the hull, comma-separated or repeated (as frf's): hull (the CoG) "
                      "and the description's named points (default: all)")
          ->type_name("NAME[,NAME...]")
          ->expected(1)
          ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--power-limit-w", opt->power_limit_w, "absorbed-power limit [W]")
      ->check(positiveNumber());
  // The time-domain run's own options, refused with --iso8608.
  const std::vector<CLI::Option*> time_only = {
      cmd->add_option("--peak-limit-g", opt->peak_limit_g, "peak upward acceleration limit [g]")
          ->check(positiveNumber()),
      cmd->add_option("--lowpass-hz", opt->lowpass_hz,
                      "Butterworth (4th order) low-pass before the peak is read [Hz], >= 0.1; 0: "
                      "unfiltered")
          ->check(nonNegativeNumber()),
      // At most 2 ms: the 30 Hz low-pass and the absorbed-power filter (peaking at 4.5 Hz, K up
      // to 80 Hz) need fs well above 60 Hz.
      cmd->add_option("--dt", opt->dt, "time step [s] (1e-4 .. 0.002)")
          ->check(numberIn(1e-4, 0.002, "s"))};
  cmd->add_option("--tolerance-kmh", opt->tolerance_kmh,
                  "bisection stops at this bracket width [km/h] (0.001 .. 10)")
      ->check(numberIn(1e-3, 10.0, "km/h"));
  cmd->add_option("--lateral-offset", opt->lateral_offset,
                  "lateral offset of the path [m] (y left) on the terrain's lines (oop_waves: "
                  "beyond the paper's 1 m, built into the track)")
      ->check(finiteNumber());
  // The road spectrum's options (those of tvd terrain --iso8608, and the grid), refused without
  // --iso8608.
  const std::vector<CLI::Option*> spectral_only = {
      cmd->add_flag(
          "--independent-sides", opt->independent_sides,
          "--iso8608: left and right tracks on independent profiles (default: one profile "
          "across the width)"),
      // Roads measured in the field have slopes w of 1.5 to 3.5 (ISO 8608 takes 2); the band
      // reaches from 1 km waves (the vehicle rides them quasi-statically) to 1 cm (finer than
      // its 0.16 m pads can feel): beyond, a number is a slip, not a road.
      cmd->add_option("--waviness", opt->waviness, "--iso8608: PSD slope w in G_d(n0) (n/n0)^-w")
          ->check(numberIn(0.5, 5.0)),
      cmd->add_option("--min-frequency", opt->min_frequency,
                      "--iso8608: lowest spatial frequency [cycles/m]")
          ->check(numberIn(1e-3, 100.0, "cycles/m")),
      cmd->add_option("--max-frequency", opt->max_frequency,
                      "--iso8608: highest spatial frequency [cycles/m]")
          ->check(numberIn(1e-3, 100.0, "cycles/m")),
      cmd->add_option("--points-per-decade", opt->points_per_decade,
                      "--iso8608: frequencies per decade of the integration grid (10 .. 1e5)")
          ->check(numberIn(10.0, 1e5)),
      cmd->add_option(
             "--psd-out", opt->psd_out,
             "--iso8608: the acceleration PSDs at every speed of --speeds, one row per speed and "
             "frequency (road; per point the vertical raw, Wk-weighted and absorbed-power "
             "density; per point x and y; the hull's roll, pitch and yaw): CSV, or .mat")
          ->check(outputFile({".csv", ".mat"}))};
  opt->reduced.addTo(cmd);
  cmd->add_option("--out", opt->out_file,
                  "every run, by speed: CSV, or .mat (one variable per column)")
      ->check(outputFile({".csv", ".mat"}));
  cmd->add_flag("--json", opt->json, "print a JSON summary");
  cmd->callback([cmd, opt, variant, track, iso, time_only, spectral_only, points]() {
    const bool spectral = iso->count() > 0;
    if (spectral && track->count() > 0)
      throw InputError(
          "ride: --track and --iso8608 exclude each other: give a terrain to simulate over, "
          "or an ISO 8608 class to evaluate spectrally");
    if (!spectral && track->count() == 0)
      throw InputError(
          "ride: --track is required (a terrain to simulate over), or --iso8608 CLASS for "
          "the spectral method");
    for (const CLI::Option* o : spectral ? time_only : spectral_only)
      if (o->count() > 0)
        throw InputError("ride: " + o->get_name() +
                         (spectral
                              ? " applies to a --track simulation, not to the spectral --iso8608"
                              : " applies to --iso8608 (the spectral method) only"));
    opt->reduced.check("ride", "reduced");
    for (const auto& [name, out] :
         {std::make_pair("--out", opt->out_file), std::make_pair("--psd-out", opt->psd_out)})
      refuseOutputOverInput("ride", name, out,
                            {{"--vehicle", opt->vehicle_file},
                             {"--track", opt->track},
                             {"--reduced", opt->reduced.reducedFile()}});
    if (!opt->psd_out.empty() && !opt->out_file.empty() &&
        sameOutputFile(opt->psd_out, opt->out_file))
      throw InputError("ride: --psd-out and --out name the same file " + opt->out_file);
    opt->variant_given = variant->count() > 0;
    opt->points_given = points->count() > 0;
    opt->max_frequency_given = cmd->get_option("--max-frequency")->count() > 0;
    if (spectral)
      runSpectralRide(*opt);
    else
      run(*opt);
  });
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
