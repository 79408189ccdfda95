// The spectral method of `tvd ride`: a linear model on a stationary random road has the output
// PSD S_a = Σ_sides |H_v,side|^2 S_h (dynamics/spectral_ride.h), so the absorbed power and the
// ISO 2631-1 a_wz at a speed come from the travelled FRF and the road's PSD, with no road
// realisation, no run-in and no statistical scatter: milliseconds per speed where a time-domain
// run takes a second. The peak (2.5 g) criterion has no spectral counterpart and is not computed.
#include "ride_spectral.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "output_files.h"
#include "ride_report.h"
#include "simulation_layout.h"
#include "speed_sweep.h"
#include "tracked_vehicle_dynamics/dynamics/comfort.h"
#include "tracked_vehicle_dynamics/dynamics/limit_crossing.h"
#include "tracked_vehicle_dynamics/dynamics/modal_system.h"
#include "tracked_vehicle_dynamics/dynamics/spectral_ride.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/json_writer.h"
#include "vehicle_analysis.h"
#include "warning_list.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {

// How the two sides' profiles relate, as the JSON and the .mat files name it.
std::string lateralCorrelationName(bool independent_sides) {
  return independent_sides ? "independent_sides" : "uniform";
}

using Clock = std::chrono::steady_clock;

// What the time-domain method reports and this one does not: a PSD gives the variance of a
// Gaussian response, not the peaks (nor the fourth-power VDV) of one road.
const std::vector<std::string> kNotComputed = {"peak_acceleration", "peak_up_g", "peak_abs_g",
                                               "vdv_z_m_s1_75"};

// The outputs rated, as SpectralRide takes them: per point its z (Wk), x and y (Wd)
// accelerations, then the hull's roll, pitch and yaw (We), which the rigid hull gives every point.
struct RatedOutputs {
  static constexpr std::size_t kPerPoint = 3;  // z, x, y
  std::vector<DofIndex> rows;
  std::vector<dynamics::Weighting> weightings;
  std::size_t rotations = 0;  // index of the roll output

  RatedOutputs(const dynamics::SecondOrderSystem& sys, const std::vector<std::string>& points) {
    const auto add = [&](const std::string& name, dynamics::Weighting weighting) {
      rows.push_back(outputRow(sys.output_names, name, "ride"));
      weightings.push_back(weighting);
    };
    for (const std::string& p : points) {
      add(p + " uz", dynamics::Weighting::Wk);
      add(p + " ux", dynamics::Weighting::Wd);
      add(p + " uy", dynamics::Weighting::Wd);
    }
    rotations = rows.size();
    for (const char* r : {"hull rx", "hull ry", "hull rz"})
      add(r, dynamics::Weighting::We);
  }
  static std::size_t vertical(std::size_t point) { return kPerPoint * point; }
};

// One point's metrics at one speed.
struct PointRide {
  dynamics::SpectralOutput z;             // P, a_wz, a_rms of the vertical acceleration
  double weighted_rms_x = 0.0;            // Wd [m/s^2]
  double weighted_rms_y = 0.0;            // Wd [m/s^2]
  double total_value = 0.0;               // a_v [m/s^2]
  double seat_surface_total_value = 0.0;  // sqrt(a_v^2 + a_r^2) [m/s^2]
};

struct Run {
  bool in_sweep = false;
  Eigen::Index frequencies = 0;
  double low_hz = 0.0, high_hz = 0.0;
  std::vector<PointRide> points;              // as the chosen points
  double roll = 0.0, pitch = 0.0, yaw = 0.0;  // We [rad/s^2]
  double rotational_total_value = 0.0;        // a_r [m/s^2]
};

Run runOf(const dynamics::SpectralRideResult& r, const RatedOutputs& rated, std::size_t points) {
  Run run;
  const std::size_t k = rated.rotations;
  run.roll = r.outputs[k].weighted_rms;
  run.pitch = r.outputs[k + 1].weighted_rms;
  run.yaw = r.outputs[k + 2].weighted_rms;
  run.rotational_total_value = dynamics::seatRotationalTotalValue(run.roll, run.pitch, run.yaw);
  for (std::size_t i = 0; i < points; ++i) {
    const std::size_t o = RatedOutputs::vertical(i);
    PointRide p;
    p.z = r.outputs[o];
    p.weighted_rms_x = r.outputs[o + 1].weighted_rms;
    p.weighted_rms_y = r.outputs[o + 2].weighted_rms;
    p.total_value =
        dynamics::seatTranslationalTotalValue(p.weighted_rms_x, p.weighted_rms_y, p.z.weighted_rms);
    p.seat_surface_total_value = std::hypot(p.total_value, run.rotational_total_value);
    run.points.push_back(p);
  }
  return run;
}

dynamics::RoadSpectrum roadOf(const RideOptions& opt) {
  const std::string& c = opt.iso_class;
  const char upper =
      c.size() == 1 ? static_cast<char>(std::toupper(static_cast<unsigned char>(c[0]))) : 0;
  if (upper < 'A' || upper > 'H')
    throw InputError("ride: --iso8608 must be one road class A..H, got '" + c + "'");
  if (!(opt.min_frequency < opt.max_frequency)) {
    std::ostringstream m;
    m << "ride: --min-frequency " << opt.min_frequency << " must be below --max-frequency "
      << opt.max_frequency << " cycles/m";
    throw InputError(m.str());
  }
  dynamics::RoadSpectrum road;
  road.road_class = upper;
  road.min_frequency = opt.min_frequency;
  road.max_frequency = opt.max_frequency;
  road.waviness = opt.waviness;
  road.correlation = opt.independent_sides ? terrain::LateralCorrelation::IndependentSides
                                           : terrain::LateralCorrelation::Uniform;
  return road;
}

// The PSDs behind the metrics at each speed of the sweep, as one long table: a row per speed and
// frequency of that speed's grid (the grids differ: [v n_min, v n_max]). Per point the raw
// acceleration PSD S_a, the ISO 2631-1 weighted |W_k|^2 S_a and the absorbed-power density K S_a,
// so that the trapezoid over one speed's rows gives that run's a_rms^2, a_wz^2 and P (the
// integrals SpectralRide::evaluate takes on the same grid); then per point the raw PSDs of its x
// and y accelerations, and last those of the hull's roll, pitch and yaw accelerations
// [(rad/s^2)^2/Hz] (after the vertical ones, so that those keep their places).
std::vector<std::string> psdHeaders(const std::vector<std::string>& points) {
  std::vector<std::string> headers = {"speed_kmh", "frequency_hz", "road_psd_m2_hz"};
  for (const std::string& p : points)
    for (const char* q : {"_psd_z_m2_s4_hz", "_wk_psd_z_m2_s4_hz", "_power_density_z_w_hz"})
      headers.push_back(p + q);
  for (const std::string& p : points)
    for (const char* q : {"_psd_x_m2_s4_hz", "_psd_y_m2_s4_hz"})
      headers.push_back(p + q);
  for (const char* r :
       {"hull_psd_roll_rad2_s4_hz", "hull_psd_pitch_rad2_s4_hz", "hull_psd_yaw_rad2_s4_hz"})
    headers.push_back(r);
  return headers;
}

// The --out table's columns: speed, whether in the sweep, three metrics per point, then each
// point's two totals (added last, so that the earlier columns keep their places).
std::vector<std::string> rideHeaders(const std::vector<std::string>& points) {
  std::vector<std::string> headers = {"speed_kmh", "in_sweep"};
  for (const std::string& p : points)
    for (const char* q : {"_absorbed_power_w", "_weighted_rms_z_m_s2", "_rms_z_m_s2"})
      headers.push_back(p + q);
  for (const std::string& p : points)
    for (const char* q : {"_vibration_total_value_m_s2", "_seat_surface_total_value_m_s2"})
      headers.push_back(p + q);
  return headers;
}

void writePsdTable(const std::string& path, const RideOptions& opt,
                   const dynamics::SpectralRide& ride, const std::vector<double>& speeds,
                   const std::vector<std::string>& points, const RatedOutputs& rated,
                   const std::string& vehicle_name, const std::string& variant,
                   const std::string& road_name) {
  const std::vector<std::string> headers = psdHeaders(points);
  std::vector<dynamics::SpectralRideResult> results;
  Eigen::Index rows = 0;
  for (double speed_kmh : speeds) {
    results.push_back(ride.evaluate(speed_kmh / kKmhPerMs));
    rows += results.back().frequencies_hz.size();
  }
  const std::vector<dynamics::AnalogSection> power_filter =
      dynamics::absorbedPowerVerticalSections();
  Matrix table(rows, static_cast<Eigen::Index>(headers.size()));
  Eigen::Index row = 0;
  for (std::size_t k = 0; k < speeds.size(); ++k) {
    const dynamics::SpectralRideResult& r = results[k];
    for (Eigen::Index i = 0; i < r.frequencies_hz.size(); ++i, ++row) {
      const double f = r.frequencies_hz(i);
      const double wk = std::norm(dynamics::iso2631Response(dynamics::Weighting::Wk, f));
      const double power = std::norm(dynamics::analogResponse(power_filter, f));
      table(row, 0) = speeds[k];
      table(row, 1) = f;
      table(row, 2) = r.road_psd(i);
      Eigen::Index c = 3;
      for (std::size_t p = 0; p < points.size(); ++p, c += 3) {
        const auto o = static_cast<Eigen::Index>(RatedOutputs::vertical(p));
        table.block(row, c, 1, 3) << r.psd(i, o), wk * r.psd(i, o), power * r.psd(i, o);
      }
      for (std::size_t p = 0; p < points.size(); ++p, c += 2) {
        const auto o = static_cast<Eigen::Index>(RatedOutputs::vertical(p));
        table.block(row, c, 1, 2) << r.psd(i, o + 1), r.psd(i, o + 2);
      }
      const auto k = static_cast<Eigen::Index>(rated.rotations);
      table.block(row, c, 1, 3) << r.psd(i, k), r.psd(i, k + 1), r.psd(i, k + 2);
    }
  }
  writeTable(path, headers, table, 12,
             {{"vehicle", vehicle_name},
              {"vehicle_file", opt.vehicle_file},
              {"variant", variant},
              {"road", road_name},
              {"lateral_correlation", lateralCorrelationName(opt.independent_sides)}});
}

// ISO 8608 classifies a road by its PSD over 0.011..2.83 cycles/m; the road does not end there.
// At speed v the band reaches v n_max only (3.9 Hz at 5 km/h, below the hull's bounce), so at low
// speed the figures leave out whatever the shorter waves excite. Were the class's PSD to go on to
// kBandCheckFrequency (waves of 0.1 m, shorter than the pads, which average them), this says
// where that changes the absorbed power by more than kBandCheckShare: a sensitivity, not a
// correction (what a real road holds beyond n_max is the user's to give, --max-frequency).
constexpr double kBandCheckFrequency = 10.0;  // [cycles/m]
constexpr double kBandCheckShare = 0.1;

// A damping ratio at or below which a mode counts as undamped (round-off of a zero damping).
constexpr double kUndampedRatio = 1e-9;

// runs: the sweep's results on the road's own band, by speed.
std::optional<std::string> bandCutWarning(const RideOptions& opt,
                                          const dynamics::SpectralRide& ride,
                                          const std::vector<std::string>& points,
                                          const RatedOutputs& rated,
                                          const dynamics::RoadSpectrum& road,
                                          const std::vector<double>& sweep,
                                          const std::map<double, Run>& runs) {
  if (opt.max_frequency_given || !(road.max_frequency < kBandCheckFrequency))
    return std::nullopt;
  // The wider band may hold an undamped mode the run's band does not: no integral exists there.
  const double wide_low =
      *std::min_element(sweep.begin(), sweep.end()) / kKmhPerMs * road.min_frequency;
  const double wide_high =
      *std::max_element(sweep.begin(), sweep.end()) / kKmhPerMs * kBandCheckFrequency;
  for (const auto& mode : ride.modeDamping())
    if (mode.ratio <= kUndampedRatio && mode.frequency_hz >= wide_low &&
        mode.frequency_hz <= wide_high) {
      std::ostringstream m;
      m << std::setprecision(3) << "the road's band ends at " << road.max_frequency
        << " cycles/m (ISO 8608's classification band); what a band reaching "
        << kBandCheckFrequency << " cycles/m would add is not estimated: a mode without damping ("
        << mode.frequency_hz << " Hz) lies in it, across which the PSD has no finite integral. "
        << "--max-frequency sets the band your road has";
      return m.str();
    }
  dynamics::SpectralRideOptions options;
  options.points_per_decade = opt.points_per_decade;
  options.weightings = rated.weightings;
  // The same model (its complex modes too, when dampers couple them: the same solution as the
  // run's) on the wider band.
  const dynamics::SpectralRide wide = ride.withMaxFrequency(kBandCheckFrequency, options);
  // The worst point at the lowest speed, and the fastest speed of the sweep still over the share.
  double worst_ratio = 0.0, worst_base = 0.0, worst_wide = 0.0, fastest = 0.0;
  std::size_t worst_point = 0;
  for (double speed_kmh : sweep) {
    const std::vector<PointRide>& base = runs.at(speed_kmh).points;
    const dynamics::SpectralRideResult more = wide.evaluate(speed_kmh / kKmhPerMs);
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double p = base[i].z.absorbed_power,
                   q = more.outputs[RatedOutputs::vertical(i)].absorbed_power;
      if (!(q > (1.0 + kBandCheckShare) * p))
        continue;
      fastest = speed_kmh;
      if (speed_kmh == sweep.front() && q / p > worst_ratio) {
        worst_ratio = q / p;
        worst_base = p;
        worst_wide = q;
        worst_point = i;
      }
    }
  }
  if (fastest == 0.0)
    return std::nullopt;
  std::ostringstream m;
  m << std::setprecision(3) << "the road's band ends at " << road.max_frequency
    << " cycles/m (ISO 8608's classification band), which at " << sweep.front() << " km/h is "
    << road.max_frequency * sweep.front() / kKmhPerMs << " Hz: were the class's PSD to go on to "
    << kBandCheckFrequency << " cycles/m (waves of " << 1.0 / kBandCheckFrequency << " m), ";
  if (worst_ratio > 0.0)
    m << points[worst_point] << " would absorb " << worst_wide << " W at " << sweep.front()
      << " km/h, not " << worst_base << " W; ";
  m << "over " << 100.0 * kBandCheckShare << " % more power at the sweep's speeds up to " << fastest
    << " km/h, less above. --max-frequency sets the band your road has";
  return m.str();
}

// The modes in [low, high] Hz, their damping ratio below `below`, listed "f Hz (zeta)" with
// repeated ones (a left and a right mode) once, "x2".
std::string listModes(const std::vector<dynamics::SpectralRide::ModeDamping>& modes, double below,
                      double low, double high, std::size_t* count) {
  constexpr std::size_t kListed = 5;
  std::vector<std::pair<std::string, int>> listed;
  *count = 0;
  for (const auto& mode : modes) {
    if (!(mode.frequency_hz >= low && mode.frequency_hz <= high && mode.ratio < below))
      continue;
    ++*count;
    std::ostringstream one;
    // Round-off ratios of undamped modes (1e-14, -1e-13) print as 0, so that repeats merge.
    one << std::setprecision(3) << mode.frequency_hz << " Hz ("
        << (std::abs(mode.ratio) <= kUndampedRatio ? 0.0 : mode.ratio) << ")";
    if (!listed.empty() && listed.back().first == one.str())
      ++listed.back().second;
    else
      listed.emplace_back(one.str(), 1);
  }
  std::ostringstream m;
  for (std::size_t i = 0; i < std::min(listed.size(), kListed); ++i)
    m << (i ? ", " : "") << listed[i].first << (listed[i].second > 1 ? " x" : "")
      << (listed[i].second > 1 ? std::to_string(listed[i].second) : "");
  if (listed.size() > kListed)
    m << " and more";
  return m.str();
}

// A mode without damping in the band [low, high] Hz of the sweep's speeds: across its resonance
// S_a has no finite integral, so any figure there would be the grid's, not the model's (and so
// would the limits found between them). Refused before the sweep, naming the modes.
void refuseUndampedModes(const dynamics::SpectralRide& ride, double low, double high) {
  std::size_t count = 0;
  const std::string listed = listModes(ride.modeDamping(), kUndampedRatio, low, high, &count);
  if (count == 0)
    return;
  std::ostringstream m;
  m << std::setprecision(3) << "ride: " << count << " mode(s) without damping lie in the band of "
    << "the speeds asked for (" << low << " .. " << high << " Hz): " << listed
    << ". Across an undamped resonance the PSD has no finite integral, so no figure could be "
       "given: give the vehicle damping (damping.modal_ratio, or Rayleigh damping) where its "
       "dampers do not reach, or rate it in the time domain (--track)";
  throw InputError(m.str());
}

// With independent sides the left and right profiles meet at the road's centre line: an offset
// that carries inputs across it puts them on the other track's profile.
std::optional<std::string> sideCrossingWarning(const RideOptions& opt,
                                               const dynamics::SecondOrderSystem& sys) {
  if (!opt.independent_sides || opt.lateral_offset == 0.0)
    return std::nullopt;
  Eigen::Index crossed = 0;
  for (Eigen::Index q = 0; q < sys.input_lateral.size(); ++q) {
    const double y = sys.input_lateral(q);
    if (y != 0.0 && (y > 0.0) != (y + opt.lateral_offset > 0.0))
      ++crossed;
  }
  if (crossed == 0)
    return std::nullopt;
  std::ostringstream m;
  m << "--lateral-offset " << opt.lateral_offset << " m carries " << crossed << " of "
    << sys.input_lateral.size()
    << " road inputs across the road's centre line, where --independent-sides joins its left and "
       "right profiles: they ride the other side's profile";
  return m.str();
}

}  // namespace

void runSpectralRide(const RideOptions& opt) {
  const std::vector<double> sweep = parseSpeedSweep(opt.speeds);
  const dynamics::RoadSpectrum road = roadOf(opt);
  dynamics::SpectralRideOptions spectral;
  spectral.points_per_decade = opt.points_per_decade;
  spectral.keep_psd = !opt.psd_out.empty();
  dynamics::checkSpectralInput(road, spectral);
  std::vector<std::string> warnings;
  const RideModel model = loadRideModel(opt, nullptr, &warnings);
  const std::vector<std::string>& points = model.points;
  const ReducedModelSource& reduced = model.reduced;
  const vehicle::Variant variant = reduced.variant;
  const dynamics::SecondOrderSystem& sys = reduced.model.system;
  // A long point name's columns would fail a .mat file after the sweep: refused before it.
  checkMatColumns("out", opt.out_file, rideHeaders(points));
  checkMatColumns("psd-out", opt.psd_out, psdHeaders(points));
  const RatedOutputs rated(sys, points);
  spectral.weightings = rated.weightings;

  // The modes and the grouped modal input matrices, once for every speed.
  const auto start = Clock::now();
  const dynamics::ModalSystem modal(sys);
  const Vector lateral = sys.input_lateral.array() + opt.lateral_offset;
  // Discrete dampers coupling the modes: the whole Phi^T C Phi, by complex modes (exact; one
  // non-symmetric eigen-solve, seconds on the tracked model) instead of eq. 20's diagonal.
  const dynamics::SpectralRide ride(modal, lateral, rated.rows, road, spectral,
                                    dynamics::modalDamping(modal, sys));
  const double setup = std::chrono::duration<double>(Clock::now() - start).count();
  const double damping_coupling = modal.maxOffDiagonalDampingRatio();
  warn(&warnings, sideCrossingWarning(opt, sys));
  // The band every speed of the sweep (and of a bisection between them) excites.
  const double band_low =
      *std::min_element(sweep.begin(), sweep.end()) / kKmhPerMs * road.min_frequency;
  const double band_high =
      *std::max_element(sweep.begin(), sweep.end()) / kKmhPerMs * road.max_frequency;
  refuseUndampedModes(ride, band_low, band_high);

  RideRuns<Run> rate([&](double speed_kmh) {
    const dynamics::SpectralRideResult r = ride.evaluate(speed_kmh / kKmhPerMs);
    Run run = runOf(r, rated, points.size());
    const Vector f = ride.grid(speed_kmh / kKmhPerMs);
    run.frequencies = f.size();
    run.low_hz = f(0);
    run.high_hz = f(f.size() - 1);
    return run;
  });
  rate.sweep(sweep);
  std::vector<RideCriterion<Run>> criteria;
  for (std::size_t i = 0; i < points.size(); ++i)
    criteria.push_back(
        {[i](const Run& r) { return r.points[i].z.absorbed_power; }, opt.power_limit_w});
  const std::vector<dynamics::LimitCrossing> limits = rate.limits(criteria, opt.tolerance_kmh);
  const std::map<double, Run>& runs = rate.all();
  const double wall = std::chrono::duration<double>(Clock::now() - start).count() - setup;
  warn(&warnings, bandCutWarning(opt, ride, points, rated, road, sweep, runs));

  const std::string road_name = std::string("iso8608_") + road.road_class + "_psd";
  const bool sides = road.correlation == terrain::LateralCorrelation::IndependentSides;
  const double rms_height = std::sqrt(terrain::iso8608Variance(road.road_class, road.min_frequency,
                                                               road.max_frequency, road.waviness));

  const std::vector<std::string> headers = rideHeaders(points);
  Matrix table(static_cast<Eigen::Index>(runs.size()), static_cast<Eigen::Index>(headers.size()));
  Eigen::Index row = 0;
  for (const auto& [speed, r] : runs) {
    table(row, 0) = speed;
    table(row, 1) = r.in_sweep ? 1.0 : 0.0;
    const auto n = static_cast<Eigen::Index>(points.size());
    for (Eigen::Index i = 0; i < n; ++i) {
      const PointRide& p = r.points[static_cast<std::size_t>(i)];
      table.block(row, 2 + 3 * i, 1, 3) << p.z.absorbed_power, p.z.weighted_rms, p.z.rms;
      table.block(row, 2 + 3 * n + 2 * i, 1, 2) << p.total_value, p.seat_surface_total_value;
    }
    ++row;
  }
  // Both files or neither (a failed --psd-out does not leave a new --out beside an old PSD).
  OutputFileSet written;
  if (!opt.out_file.empty())
    written.write(opt.out_file, [&](const std::string& path) {
      writeTable(path, headers, table, 9,
                 {{"vehicle", model.vehicle_name},
                  {"vehicle_file", opt.vehicle_file},
                  {"variant", vehicle::variantName(variant)},
                  {"road", road_name},
                  {"lateral_correlation", lateralCorrelationName(opt.independent_sides)}});
    });
  if (!opt.psd_out.empty())
    written.write(opt.psd_out, [&](const std::string& path) {
      writePsdTable(path, opt, ride, sweep, points, rated, model.vehicle_name,
                    vehicle::variantName(variant), road_name);
    });
  written.commit();

  if (opt.json) {
    io::JsonWriter json(std::cout);
    json.beginObject()
        .field("vehicle", model.vehicle_name)
        .field("vehicle_file", opt.vehicle_file)
        .field("variant", vehicle::variantName(variant))
        .field("method", std::string("spectral"));
    json.key("road")
        .beginObject()
        .field("name", road_name)
        .field("iso8608_class", std::string(1, road.road_class))
        .field("psd_at_n0_m3", terrain::iso8608ReferencePsd(road.road_class))
        .field("waviness", road.waviness)
        .field("band_cycles_per_m", std::vector<double>{road.min_frequency, road.max_frequency})
        .field("lateral_correlation", lateralCorrelationName(sides))
        .field("band_rms_height_m", rms_height)
        .endObject();
    json.field("warnings", warnings)
        .field("points_per_decade", opt.points_per_decade)
        .field("lateral_offset_m", opt.lateral_offset);
    if (!opt.reduced.reducedFile().empty())
      json.field("reduced_model_file", opt.reduced.reducedFile());
    json.field("power_limit_w", opt.power_limit_w)
        .field("tolerance_kmh", opt.tolerance_kmh)
        .field("reduced_dofs", static_cast<long long>(sys.size()))
        .field("solution", std::string(ride.complexModes() ? "complex_modes" : "modal"))
        .field("damping_coupling", damping_coupling);
    writeReductionJson(json.key("reduction"), reduced);
    json.field("points", points).field("speeds_kmh", sweep);
    json.key("runs").beginArray();
    for (const auto& [speed, r] : runs) {
      json.beginObject()
          .field("speed_kmh", speed)
          .field("in_sweep", r.in_sweep)
          .field("frequency_band_hz", std::vector<double>{r.low_hz, r.high_hz})
          .field("frequencies", static_cast<long long>(r.frequencies))
          .field("weighted_rms_roll_rad_s2", r.roll)
          .field("weighted_rms_pitch_rad_s2", r.pitch)
          .field("weighted_rms_yaw_rad_s2", r.yaw)
          .field("rotational_total_value_m_s2", r.rotational_total_value)
          .key("points")
          .beginArray();
      for (std::size_t i = 0; i < points.size(); ++i) {
        const PointRide& p = r.points[i];
        json.beginObject()
            .field("point", points[i])
            .field("absorbed_power_w", p.z.absorbed_power)
            .field("weighted_rms_z_m_s2", p.z.weighted_rms)
            .field("rms_z_m_s2", p.z.rms)
            .field("weighted_rms_x_m_s2", p.weighted_rms_x)
            .field("weighted_rms_y_m_s2", p.weighted_rms_y)
            .field("vibration_total_value_m_s2", p.total_value)
            .field("seat_surface_total_value_m_s2", p.seat_surface_total_value)
            .endObject();
      }
      json.endArray().endObject();
    }
    json.endArray().key("limits").beginArray();
    for (std::size_t i = 0; i < points.size(); ++i) {
      json.beginObject().field("point", points[i]).key("absorbed_power");
      writeLimitJson(json, limits[i], opt.power_limit_w, "W");
      json.endObject();
    }
    json.endArray()
        .field("not_computed", kNotComputed)
        .field("evaluations", static_cast<long long>(runs.size()))
        .field("setup_seconds", setup)
        .field("wall_seconds", wall);
    if (!opt.out_file.empty())
      json.field("out", opt.out_file);
    if (!opt.psd_out.empty())
      json.field("psd_out", opt.psd_out);
    json.endObject();
    return;
  }

  std::ostringstream coupling;
  coupling << std::setprecision(3) << damping_coupling;
  std::cout << std::defaultfloat << std::setprecision(4) << "ride limits on the ISO 8608 class "
            << road.road_class << " road spectrum (G_d(n0) "
            << terrain::iso8608ReferencePsd(road.road_class) << " m^3, waviness " << road.waviness
            << ", " << road.min_frequency << ".." << road.max_frequency << " cycles/m, "
            << rms_height * 1e3 << " mm r.m.s.; "
            << (sides ? "left and right independent" : "one profile across the width") << "), "
            << vehicle::variantName(variant) << " reduced model (" << sys.size()
            << " DOFs), spectral (" << opt.points_per_decade
            << " frequencies per decade)\n  reduction: " << describeReduction(reduced)
            << (ride.complexModes()
                    ? "\n  solved by complex modes: the damping couples the modes (off-diagonal "
                      "Phi^T C Phi up to " +
                          coupling.str() +
                          " of the diagonal), which eq. 20's modal damping would drop"
                    : "")
            << "\n  absorbed power P [W], ISO 2631-1 weighted r.m.s. a_wz [m/s^2] (vertical) and "
               "the seat surface's total over six axes [m/s^2] (Wk, Wd, We of the hull's "
               "rotations) per speed:\n"
            << "  speed km/h";
  for (const std::string& p : points)
    std::cout << std::setw(22) << p + " P" << std::setw(12) << "a_wz" << std::setw(12) << "seat";
  std::cout << "\n" << std::fixed;
  for (const auto& [speed, r] : runs) {
    std::cout << "  " << std::setw(9) << std::setprecision(2) << speed << (r.in_sweep ? " " : "*");
    for (const PointRide& m : r.points)
      std::cout << std::setw(22) << std::setprecision(3) << m.z.absorbed_power << std::setw(12)
                << m.z.weighted_rms << std::setw(12) << m.seat_surface_total_value;
    std::cout << "\n";
  }
  if (std::any_of(runs.begin(), runs.end(), [](const auto& run) { return !run.second.in_sweep; }))
    std::cout << "  (* speeds the bisection added)\n";
  std::ostringstream power_limit;
  power_limit << std::defaultfloat << opt.power_limit_w << " W";
  for (std::size_t i = 0; i < points.size(); ++i)
    std::cout << "  " << points[i] << ": " << describeLimit(limits[i], power_limit.str()) << "\n";
  std::cout
      << "  peak acceleration: not computed (a PSD gives variances, not the peaks of one road or "
         "obstacle: use --track)\n"
      << std::setprecision(3) << "  " << runs.size() << " speeds evaluated in " << wall
      << " s (modes and input matrices: " << setup << " s)\n";
  if (!opt.psd_out.empty())
    std::cout << "  PSDs at the " << sweep.size() << " speeds of --speeds written to "
              << opt.psd_out << "\n";
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
