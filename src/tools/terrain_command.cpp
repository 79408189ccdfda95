// `tvd terrain`: writes a terrain file that `tvd simulate --track FILE` (and the ROS node's track
// player) read: one of the paper's built-in tracks, the NRMM half-round obstacle (half_round:H),
// or an ISO 8608 random road (classes A-H, seeded), which the paper does not use but ride
// engineers test on.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>

#include "commands.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/file_type.h"
#include "tracked_vehicle_dynamics/io/json_writer.h"
#include "tracked_vehicle_dynamics/terrain/interpolation_loss.h"
#include "tracked_vehicle_dynamics/terrain/iso8608.h"
#include "tracked_vehicle_dynamics/terrain/terrain.h"
#include "tracked_vehicle_dynamics/terrain/terrain_io.h"
#include "tracked_vehicle_dynamics/terrain/tracks.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {

struct TerrainOptions {
  std::string track;      // a built-in track ...
  std::string iso_class;  // ... or an ISO 8608 class A-H
  double length = 200.0;
  double width = terrain::kTrackWidth;
  double spacing = 0.05;
  std::uint64_t seed = 1;
  bool independent_sides = false;
  double taper = 5.0;
  double min_frequency = terrain::Iso8608Options{}.min_frequency;
  bool min_frequency_given = false;  // the note on a band cut by the length is for a chosen one
  double max_frequency = terrain::Iso8608Options{}.max_frequency;
  double waviness = terrain::Iso8608Options{}.waviness;
  std::string out_file;
  bool json = false;
};

// Root-mean-square height of every lateral line over the stations [first, last).
double rmsHeight(const terrain::Terrain& t, Eigen::Index first, Eigen::Index last) {
  const Matrix block = t.heights().middleCols(first, last - first);
  return std::sqrt(block.squaredNorm() / static_cast<double>(block.size()));
}

// `value` > 0 to `digits` significant digits, rounded down: a bound the user may type back as it
// is (brief() rounds 1/6 up to 0.166667, which the bound then refuses).
std::string roundedDown(double value, int digits = 6) {
  const double scale = std::pow(10.0, digits - 1 - std::floor(std::log10(value)));
  return brief(std::floor(value * scale) / scale);
}

// --width's bound [m]: a road's, with room for any vehicle and lateral offset.
constexpr double kMaxRoadWidth = 1000.0;
// --max-frequency's bound [cycles/m]: the Nyquist frequency of the finest --spacing.
constexpr double kMaxRoadFrequency = 0.5 / terrain::kMinTerrainSpacing;

// The share of the band top's PSD a simulation's linear interpolation must keep before a note.
constexpr double kKeptPowerShare = 0.8;

void run(TerrainOptions opt) {
  const bool iso = !opt.iso_class.empty();
  char road_class = 0;
  terrain::Iso8608Options iso_options;
  terrain::Terrain t = [&] {
    if (!iso)
      return terrain::makeTrack(opt.track);
    if (opt.iso_class.size() != 1 ||
        std::toupper(static_cast<unsigned char>(opt.iso_class[0])) < 'A' ||
        std::toupper(static_cast<unsigned char>(opt.iso_class[0])) > 'H')
      throw InputError("terrain: --iso8608 must be one road class A..H, got '" + opt.iso_class +
                       "'");
    road_class = static_cast<char>(std::toupper(static_cast<unsigned char>(opt.iso_class[0])));
    // The core's checks name its fields (taper_length, band); here they name the options.
    if (opt.taper > 0.5 * opt.length)
      throw InputError("terrain: --taper " + brief(opt.taper) +
                       " m must be at most half of --length (" + brief(opt.length) +
                       " m: at most " + brief(0.5 * opt.length) + " m)");
    if (opt.min_frequency >= opt.max_frequency)
      throw InputError("terrain: --min-frequency " + brief(opt.min_frequency) +
                       " cycles/m must be below --max-frequency " + brief(opt.max_frequency) +
                       " cycles/m");
    const double nyquist = 0.5 / opt.spacing;
    if (opt.max_frequency > nyquist)
      throw InputError("terrain: --max-frequency " + brief(opt.max_frequency) + " cycles/m" +
                       (opt.max_frequency == terrain::Iso8608Options{}.max_frequency
                            ? " (the default, ISO 8608's upper bound)"
                            : "") +
                       " is above what --spacing " + brief(opt.spacing) +
                       " m can hold, 1 / (2 spacing) = " + brief(nyquist) +
                       " cycles/m: give --spacing at most " + roundedDown(0.5 / opt.max_frequency) +
                       " m or a lower --max-frequency");
    // The road is L-periodic with its last station repeating the first (iso8608.h), which
    // needs L to be a whole number of steps: a length that is not is raised to the next one
    // (600 m at 0.17 m: 600.1 m), never cut short of what was asked for.
    const double steps = opt.length / opt.spacing;
    if (std::abs(steps - std::round(steps)) > 1e-9 * steps) {
      const double raised = std::ceil(steps) * opt.spacing;
      std::cerr << "tvd: note: --length " << brief(opt.length) << " m is not a whole number of "
                << "--spacing " << brief(opt.spacing) << " m steps: the road is " << brief(raised)
                << " m long\n";
      opt.length = raised;
    }
    iso_options.min_frequency = opt.min_frequency;
    iso_options.max_frequency = opt.max_frequency;
    iso_options.waviness = opt.waviness;
    iso_options.taper_length = opt.taper;
    iso_options.correlation = opt.independent_sides ? terrain::LateralCorrelation::IndependentSides
                                                    : terrain::LateralCorrelation::Uniform;
    return terrain::makeIso8608(road_class, opt.length, opt.width, opt.spacing, opt.seed,
                                iso_options);
  }();
  if (io::lowerExtension(opt.out_file) ==
      ".csv")  // else .yaml / .yml: checked by --out's validator
    terrain::saveTerrainCsv(t, opt.out_file);
  else
    terrain::saveTerrainYaml(t, opt.out_file);

  const Eigen::Index n = t.stations().size();
  // The ISO road is periodic over its length, its last station repeating the first: over one
  // period, untapered, its variance is exactly that of the PSD over the generated band
  // [max(n_min, 1/(2 L)), n_max] (iso8608.h).
  const double rms = rmsHeight(t, 0, iso ? n - 1 : n);
  double expected_rms = 0.0;
  // The band generated: a road of length L holds no wavelength longer than 2 L.
  const double n_low = std::max(opt.min_frequency, 0.5 / opt.length);
  if (iso) {
    expected_rms =
        std::sqrt(terrain::iso8608Variance(road_class, n_low, opt.max_frequency, opt.waviness));
    if (n_low > opt.min_frequency && opt.min_frequency_given)
      std::cerr << "tvd: note: --min-frequency " << brief(opt.min_frequency)
                << " cycles/m is below 1/(2 --length) = " << brief(n_low) << ": a road of "
                << brief(opt.length) << " m holds no longer wavelength, so its band starts there\n";
    else if (n_low > opt.min_frequency) {
      // The default band's longest waves (90 m) do not fit: the road is smoother than its class
      // over the default band. Said when that costs more than 1 % of the r.m.s. height.
      const double full_rms = std::sqrt(
          terrain::iso8608Variance(road_class, opt.min_frequency, opt.max_frequency, opt.waviness));
      if (expected_rms < 0.99 * full_rms) {
        const std::streamsize precision = std::cerr.precision();
        std::cerr << std::setprecision(3) << "tvd: note: a road of " << opt.length
                  << " m holds no wavelength longer than " << 2.0 * opt.length
                  << " m, so its band starts at " << n_low << " cycles/m, not the default "
                  << opt.min_frequency << ": r.m.s. height " << expected_rms * 1e3
                  << " mm against the class's " << full_rms * 1e3
                  << " mm over the default band (--length " << std::ceil(0.5 / opt.min_frequency)
                  << " or more keeps it)\n"
                  << std::setprecision(static_cast<int>(precision));
      }
    }
  }

  // What a simulation reads of the band's top: the stations are interpolated linearly, which
  // passes sinc^4(n dx) of the PSD (19 % at 2.83 cycles/m and 0.17 m, 88 % at the default
  // 0.05 m). Below 80 % the vehicle rides a visibly smoother road than the class (the crew
  // seat's absorbed power 48 % low at 15 km/h at 0.17 m), so it is said.
  const double top_share =
      iso ? terrain::interpolatedPowerShare(opt.max_frequency, opt.spacing) : 1.0;
  if (top_share < kKeptPowerShare) {
    std::cerr << "tvd: note: simulate interpolates the road linearly "
              << "between stations, which passes sinc^4(n spacing) of its PSD: at --spacing "
              << brief(opt.spacing) << " m only " << std::floor(100.0 * top_share)
              << " % at the band's top (" << brief(opt.max_frequency)
              << " cycles/m), so the vehicle rides a smoother road "
              << "than class " << road_class << "; ";
    // The share depends on n dx alone: the spacing keeping 80 % at the band's top, or, when that
    // is finer than any terrain's (1 um), the band's top keeping it at this spacing.
    const double spacing = terrain::spacingKeepingPowerShare(opt.max_frequency, kKeptPowerShare);
    if (spacing >= terrain::kMinTerrainSpacing)
      std::cerr << "--spacing " << roundedDown(spacing, 3) << " m or less keeps 80 %\n";
    else
      std::cerr << "--max-frequency "
                << roundedDown(
                       terrain::spacingKeepingPowerShare(1.0, kKeptPowerShare) / opt.spacing, 3)
                << " cycles/m or less keeps 80 % (--spacing cannot be finer than "
                << brief(terrain::kMinTerrainSpacing) << " m)\n";
  }

  if (opt.json) {
    io::JsonWriter json(std::cout);
    json.beginObject().field("name", t.name()).field("out", opt.out_file);
    if (iso)
      json.field("iso8608_class", std::string(1, road_class))
          .field("seed", static_cast<long long>(opt.seed))
          .field("psd_at_n0_m3", terrain::iso8608ReferencePsd(road_class))
          .field("waviness", opt.waviness)
          .field("band_cycles_per_m", std::vector<double>{n_low, opt.max_frequency})
          .field("taper_m", opt.taper)
          .field("band_rms_height_m", expected_rms)
          .field("interpolated_psd_share_at_band_top", top_share);
    json.field("stations", static_cast<long long>(n))
        .field("start_station_m", t.startStation())
        .field("end_station_m", t.endStation())
        .field("lateral_m", t.lateral())
        .field("min_height_m", t.heights().minCoeff())
        .field("max_height_m", t.heights().maxCoeff())
        .field("rms_height_m", rms)
        .endObject();
    return;
  }
  std::cout << std::setprecision(4) << t.name() << ": " << n << " stations, " << t.startStation()
            << " .. " << t.endStation() << " m, " << t.lateral().size() << " lateral lines; height "
            << t.heights().minCoeff() << " .. " << t.heights().maxCoeff() << " m, r.m.s. " << rms
            << " m";
  if (iso)
    std::cout << " (ISO 8608 class " << road_class
              << (opt.waviness != 2.0 ? ", waviness " + brief(opt.waviness) : std::string()) << ": "
              << expected_rms << " m r.m.s. in the band, untapered)";
  std::cout << "\n  wrote " << opt.out_file << "\n";
}

/// A built-in track name, half_round:H included (CLI::IsMember cannot take a parameterised
/// name): the core's own message for anything else, naming the known tracks or the spec's fault.
CLI::Validator builtInTrack() {
  return CLI::Validator(
      [](std::string& name) -> std::string {
        try {
          terrain::checkTrackName(name);
        } catch (const InputError& e) {
          return e.what();
        }
        return std::string();
      },
      "TRACK");
}

}  // namespace

void registerTerrainCommand(CLI::App& app) {
  auto opt = std::make_shared<TerrainOptions>();
  CLI::App* cmd = app.add_subcommand("terrain",
                                     "Write a terrain file: a built-in track or an ISO 8608 random "
                                     "road (for simulate --track FILE)");
  CLI::Option* track =
      cmd->add_option(
             "--track", opt->track,
             "built-in track: long_hill | separated_waves | oop_waves | half_round:H (the NRMM "
             "half-round obstacle, H its height in m, e.g. half_round:0.2); oop_waves is written "
             "with the paper's 1 m offset built in (lines at y -3.5 .. 1.5 m)")
          ->check(builtInTrack());
  CLI::Option* iso =
      cmd->add_option("--iso8608", opt->iso_class, "random road of ISO 8608 class A..H instead");
  track->excludes(iso);
  // The random road's options need --iso8608 (CLI11 names both when one comes without the other).
  for (CLI::Option* o :
       {cmd->add_option("--length", opt->length, "random road: length [m]")
            ->check(positiveNumber()),
        // At most 1 km: the lines carry a vehicle a few metres wide (a width in mm typed as m,
        // 5000, is refused); 1e20 m was refused by the terrain, naming its lateral line, not
        // --width.
        cmd->add_option("--width", opt->width, "random road: width [m], at most 1000")
            ->check(finiteNumberWhere([](double v) { return v > 0.0 && v <= kMaxRoadWidth; },
                                      "positive and at most 1000 m (a road's width)", "WIDTH")),
        cmd->add_option("--spacing", opt->spacing, "random road: station step [m], >= 1e-6")
            ->check(finiteNumberWhere([](double v) { return v >= terrain::kMinTerrainSpacing; },
                                      "at least 1e-06 m (terrain stations 1 um apart)", "SPACING")),
        // Up to 2^53: every seed is then exact in the JSON summary (a double in most readers).
        cmd->add_option("--seed", opt->seed, "random road: seed of the phases, 0 .. 2^53")
            ->check(unsignedIn(std::uint64_t{1} << 53)),
        cmd->add_flag("--independent-sides", opt->independent_sides,
                      "random road: left and right halves independent (default: one profile across "
                      "the width)"),
        cmd->add_option("--taper", opt->taper, "random road: raised-cosine taper at each end [m]")
            ->check(nonNegativeNumber()),
        cmd->add_option("--min-frequency", opt->min_frequency,
                        "random road: lowest spatial frequency [cycles/m]")
            ->check(positiveNumber()),
        // At most 1 / (2 x the finest --spacing): no grid holds more, and 1e308 once asked for
        // "--spacing at most nan m".
        cmd->add_option("--max-frequency", opt->max_frequency,
                        "random road: highest spatial frequency [cycles/m], at most 5e5")
            ->check(finiteNumberWhere(
                [](double v) { return v > 0.0 && v <= kMaxRoadFrequency; },
                "positive and at most 5e+05 cycles/m (1 / (2 x 1e-06 m), the finest --spacing)",
                "FREQUENCY")),
        // As ride --iso8608's (measured roads: 1.5 .. 3.5), so that a spectral ride has its
        // time-domain road.
        cmd->add_option("--waviness", opt->waviness,
                        "random road: PSD slope w in G_d(n0) (n/n0)^-w (ISO 8608: 2)")
            ->check(numberIn(0.5, 5.0))})
    o->needs(iso);
  cmd->add_option("--out", opt->out_file, "terrain file to write (.csv, .yaml or .yml)")
      ->required()
      ->check(outputFile({".csv", ".yaml", ".yml"}));
  cmd->add_flag("--json", opt->json, "print a JSON summary");
  cmd->callback([cmd, opt, track, iso]() {
    if (track->count() == 0 && iso->count() == 0)
      throw InputError("terrain: give --track NAME or --iso8608 CLASS");
    if (iso->count() > 0 && opt->iso_class.empty())
      throw InputError("terrain: --iso8608 must be one road class A..H, got ''");
    opt->min_frequency_given = cmd->get_option("--min-frequency")->count() > 0;
    run(*opt);
  });
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
