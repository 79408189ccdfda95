// `tvd frf`: comfort FRFs per unit road height (paper §4.1, eqs. 15-25) of the full or reduced
// vehicle, synchronous or travelled at a speed (the wheelbase filter), at the hull, the wheels
// and (--points) the description's named points, there also ISO 2631-1 Wk-weighted.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>

#include "commands.h"
#include "output_files.h"
#include "point_list.h"
#include "reduction_options.h"
#include "tracked_vehicle_dynamics/dynamics/comfort.h"
#include "tracked_vehicle_dynamics/dynamics/frf.h"
#include "tracked_vehicle_dynamics/dynamics/frf_state_space.h"
#include "tracked_vehicle_dynamics/dynamics/speed_profile.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/io/json_writer.h"
#include "tracked_vehicle_dynamics/reduction/full_model_reference.h"
#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "vehicle_analysis.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {

struct FrfOptions {
  std::string vehicle_file;
  std::string variant = "tracked";
  std::string model = "reduced";
  double speed_kmh = 0.0;  // 0: synchronous (tau = 1)
  /// in_phase (the paper's: both tracks' roads alike) | anti_phase (opposite, input_delay.h).
  std::string sides = "in_phase";
  double max_hz = 50.0;
  double step_hz = 0.05;
  double max_mode_hz = 100.0;  // full model: dynamic modes up to here
  ReducedModelFlags reduced;
  bool variant_given = false;
  std::string out_file;
  bool json = false;
  std::vector<std::string> points;  ///< named points of the description (--points)
};

// One output of the FRF matrix as written: the paper's comfort outputs (Figs. 13-16: hull
// vertical and pitch, front and rear left wheel) and the named points' vertical accelerations.
struct NamedColumn {
  std::string column;
  std::string output;
  std::string unit;
  DofIndex index = -1;  ///< column of the FRF matrix
  /// Also |H(f)| |Wk(f)|: the ISO 2631-1 weighting of vertical acceleration at a seat, which
  /// ride engineers compare designs with (a named point's column).
  bool wk_weighted = false;
};

DofIndex outputIndex(const std::vector<std::string>& names, const std::string& output) {
  const auto it = std::find(names.begin(), names.end(), output);
  if (it == names.end())
    throw InputError("frf: the model has no output '" + output + "'");
  return static_cast<DofIndex>(it - names.begin());
}

std::vector<NamedColumn> comfortOutputs(const std::vector<std::string>& names) {
  int rear = 0;
  for (const std::string& n : names)
    if (n.rfind("road_wheel_left_", 0) == 0)
      rear = std::max(rear, std::atoi(n.c_str() + std::string("road_wheel_left_").size()));
  std::vector<NamedColumn> out = {{"hull_vertical_acc", "hull uz", "(m/s^2)/m"},
                                  {"hull_pitch_acc", "hull ry", "(rad/s^2)/m"},
                                  {"front_wheel_acc", "road_wheel_left_1 uz", "(m/s^2)/m"}};
  if (rear > 1)
    out.push_back(
        {"rear_wheel_acc", "road_wheel_left_" + std::to_string(rear) + " uz", "(m/s^2)/m"});
  for (NamedColumn& c : out)
    c.index = outputIndex(names, c.output);
  return out;
}

// --points, checked against the description before any work: each a named point, none twice.
void checkPoints(const std::vector<std::string>& points,
                 const vehicle::VehicleDescription& description) {
  std::string known;
  for (const vehicle::NamedPoint& p : description.named_points)
    known += (known.empty() ? "" : ", ") + p.name;
  for (auto it = points.begin(); it != points.end(); ++it) {
    const bool named = std::any_of(description.named_points.begin(), description.named_points.end(),
                                   [&](const vehicle::NamedPoint& p) { return p.name == *it; });
    if (*it == "hull")  // ride's --points takes it; here its column is always there
      throw InputError(
          "frf: --points: the hull (its CoG) is always in the table, as "
          "hull_vertical_acc; --points adds the description's "
          "named points: " +
          (known.empty() ? std::string("it has none") : known));
    if (!named)
      throw InputError("frf: --points: unknown point '" + *it + "' (the vehicle has: " +
                       (known.empty() ? std::string("no named points") : known) + ")");
    if (std::find(points.begin(), it, *it) != it)
      throw InputError("frf: --points: point '" + *it + "' is listed twice");
  }
}

// Anti-phase roads roll, sway and yaw the hull (a stabiliser's disturbance): those outputs too.
std::vector<NamedColumn> rollOutputs(const std::vector<std::string>& names) {
  std::vector<NamedColumn> out = {{"hull_lateral_acc", "hull uy", "(m/s^2)/m"},
                                  {"hull_roll_acc", "hull rx", "(rad/s^2)/m"},
                                  {"hull_yaw_acc", "hull rz", "(rad/s^2)/m"}};
  for (NamedColumn& c : out)
    c.index = outputIndex(names, c.output);
  return out;
}

// Every model has the outputs "<point> ux|uy|uz" of each named point (vehicleOutputs()); the
// vertical one is what a seat transmits to the crew, and under anti-phase roads the lateral one
// what the roll adds at a point above the CoG.
std::vector<NamedColumn> pointOutputs(const std::vector<std::string>& names,
                                      const std::vector<std::string>& points, bool lateral) {
  std::vector<NamedColumn> out;
  for (const std::string& point : points) {
    NamedColumn c{point + "_vertical_acc", point + " uz", "(m/s^2)/m"};
    c.index = outputIndex(names, c.output);
    c.wk_weighted = true;
    out.push_back(c);
    if (lateral) {
      NamedColumn y{point + "_lateral_acc", point + " uy", "(m/s^2)/m"};
      y.index = outputIndex(names, y.output);
      out.push_back(y);
    }
  }
  return out;
}

// 0, step, 2 step, ... up to max, and max itself when it is not a multiple of step (the band
// asked for is covered to its edge). A last multiple within 0.1 % of a step of max is max (no
// second point next to it: --max-hz 1 --step-hz 0.3333333 ends 0.667, 1). Throws InputError
// when step > max: one frequency (0 Hz, where every FRF is 0) has no peak and no band.
Vector frequencyGrid(double max_hz, double step_hz) {
  const auto steps = static_cast<Eigen::Index>(std::floor(max_hz / step_hz + 1e-9));
  if (steps < 1)
    throw InputError("frf: --step-hz " + brief(step_hz) + " is larger than --max-hz " +
                     brief(max_hz) + ": the grid needs at least 2 frequencies (0 and max)");
  const bool partial = max_hz - steps * step_hz > 1e-3 * step_hz;
  Vector hz(steps + 1 + (partial ? 1 : 0));
  hz.head(steps + 1) = Vector::LinSpaced(steps + 1, 0.0, steps * step_hz);
  hz(hz.size() - 1) = max_hz;
  return hz;
}

void run(const FrfOptions& opt) {
  vehicle::Variant variant = vehicle::parseVariant(opt.variant);
  // The travelled excitation delays each input by L_q / v. Slower than 0.01 km/h (3 mm/s) a
  // vehicle is at rest for any ride question, and the delay (1700 s over the paper's 4.7 m) only
  // grows until e^(-j omega L / v) stops being a number: 1e-300 km/h gave another FRF (the phase
  // lost to round-off), 1e-308 an infinite delay ("an undamped mode lies on the grid").
  constexpr double kMinTravelKmh = 0.01;
  if (!(opt.speed_kmh >= 0) || opt.speed_kmh > dynamics::kMaxSpeedKmh ||
      (opt.speed_kmh > 0 && opt.speed_kmh < kMinTravelKmh))
    throw InputError("frf: --speed-kmh must be 0 (synchronous) or in [" + brief(kMinTravelKmh) +
                     ", " + brief(dynamics::kMaxSpeedKmh) + "], got " +
                     (opt.speed_kmh < kMinTravelKmh
                          ? beyond(opt.speed_kmh, kMinTravelKmh)
                          : beyond(opt.speed_kmh, dynamics::kMaxSpeedKmh)));
  if (!(opt.max_hz > 0) || !std::isfinite(opt.max_hz))
    throw InputError("frf: --max-hz must be positive and finite, got " + brief(opt.max_hz));
  if (!(opt.step_hz > 0))
    throw InputError("frf: --step-hz must be positive, got " + brief(opt.step_hz));
  if (opt.max_hz / opt.step_hz > 1e6)
    throw InputError("frf: --max-hz " + brief(opt.max_hz) + " at --step-hz " + brief(opt.step_hz) +
                     " gives " + brief(std::floor(opt.max_hz / opt.step_hz) + 1) +
                     " frequencies; at most 1e6");
  const Vector hz = frequencyGrid(opt.max_hz, opt.step_hz);

  // The model: its outputs, input stations and a way to evaluate the FRF.
  std::vector<std::string> names;
  Vector stations;
  dynamics::ComplexMatrix h;
  DofIndex dofs = 0, full_dofs = 0;
  std::string source;
  std::optional<ReducedModelSource> reduced;
  std::string solution = "modal";  // eq. 20, or "direct" (eq. 18)
  double damping_coupling = 0.0;   // max |c_rs| / sqrt(c_rr c_ss), c = Phi^T C Phi (reduced)
  const bool anti_phase = opt.sides == "anti_phase";
  auto delayFor = [&](const Vector& x, const Vector& y) {
    const dynamics::InputDelay delay =
        opt.speed_kmh > 0 ? dynamics::InputDelay::travelling(x, opt.speed_kmh / kKmhPerMs)
                          : dynamics::InputDelay::synchronous();
    return anti_phase ? delay.scaled(dynamics::InputDelay::antiPhaseFactors(y)) : delay;
  };
  const vehicle::VehicleDescription description = loadVehicle(opt.vehicle_file);
  checkPoints(opt.points, description);
  if (opt.model == "reduced") {
    reduced = obtainReducedModel(description, variant, opt.variant_given, "frf", opt.reduced);
    variant = reduced->variant;  // a --reduced file's
    const reduction::ReducedModel& model = reduced->model;
    names = model.system.output_names;
    // Eq. 20's modal damping is exact only when Phi^T C Phi is diagonal (proportional or modal
    // damping). Discrete dampers (suspension.arm_damping) couple the modes, and dropping the
    // coupling moved a wheel's peak by 105 % (two 20 kN m s/rad arm dampers, un-tracked): then
    // eq. 18 is solved exactly: one Hessenberg reduction of the state matrix, then O(n^2) per
    // frequency (frf_state_space.h; a dense LU per frequency takes 6-7x longer, bench_frf).
    const dynamics::ModalSystem modal(model.system);
    damping_coupling = modal.maxOffDiagonalDampingRatio();
    const dynamics::InputDelay delay =
        delayFor(model.system.input_stations, model.system.input_lateral);
    bool used_modal = false;
    h = dynamics::frfExact(model.system, modal, hz, delay, dynamics::OutputQuantity::Acceleration,
                           &used_modal);
    solution = used_modal ? "modal" : "direct";
    dofs = model.size();
    full_dofs = model.full_dof_count;
    source = reduced->kind == ReducedModelSource::Kind::Cache  ? "reduced (cached)"
             : reduced->kind == ReducedModelSource::Kind::File ? "reduced (file)"
                                                               : "reduced";
  } else {
    reduction::FullReferenceOptions ref_options;
    ref_options.max_frequency_hz = opt.max_mode_hz;
    const reduction::FullModelReference ref =
        reduction::buildVehicleReference(description, variant, ref_options);
    names = ref.modal.output_names;
    // Discrete dampers coupling its modes: eq. 18 in its modal coordinates, as the reduced
    // model's (FullModelReference::frf).
    damping_coupling = ref.dampingCoupling();
    solution = ref.dampingCouplesModes() ? "direct" : "modal";
    h = ref.frf(hz, delayFor(ref.modal.input_stations, ref.modal.input_lateral),
                dynamics::OutputQuantity::Acceleration);
    dofs = ref.full_dofs;
    full_dofs = ref.full_dofs;
    source = "full (" + std::to_string(ref.frequencies_hz.size()) + " modes up to " +
             std::to_string(static_cast<int>(opt.max_mode_hz)) + " Hz + static residual)";
  }
  // An undamped mode exactly on the grid divides by zero (eq. 20): said, not written as NaN
  // into the table and the peaks.
  for (Eigen::Index c = 0; c < h.cols(); ++c)
    for (Eigen::Index i = 0; i < h.rows(); ++i)
      if (!std::isfinite(h(i, c).real()) || !std::isfinite(h(i, c).imag()))
        throw SolverError("the FRF of " + names[static_cast<std::size_t>(c)] +
                          " is not finite at " + brief(hz(i)) +
                          " Hz: an undamped mode lies on the frequency grid (give the vehicle "
                          "damping, or shift the grid with --step-hz)");
  std::vector<NamedColumn> columns = comfortOutputs(names);
  if (anti_phase) {
    const std::vector<NamedColumn> roll = rollOutputs(names);
    columns.insert(columns.end(), roll.begin(), roll.end());
  }
  const std::vector<NamedColumn> point_columns = pointOutputs(names, opt.points, anti_phase);
  columns.insert(columns.end(), point_columns.begin(), point_columns.end());
  // |Wk(j 2 pi f)| on the grid (0 at 0 Hz: the weighting's high-pass).
  Vector wk(hz.size());
  for (Eigen::Index i = 0; i < hz.size(); ++i)
    wk(i) = std::abs(dynamics::iso2631Response(dynamics::Weighting::Wk, hz(i)));
  auto magnitude = [&](const NamedColumn& c) -> Vector { return h.col(c.index).cwiseAbs(); };
  auto weighted = [&](const NamedColumn& c) -> Vector { return magnitude(c).cwiseProduct(wk); };

  if (!opt.out_file.empty()) {
    std::vector<std::string> headers = {"frequency_hz"};
    std::vector<Vector> data = {hz};
    for (const NamedColumn& c : columns) {
      Vector phase(hz.size());
      for (Eigen::Index i = 0; i < hz.size(); ++i)
        phase(i) = std::arg(h(i, c.index)) * kRadToDegree;
      headers.push_back(c.column + "_mag");
      data.push_back(magnitude(c));
      headers.push_back(c.column + "_phase_deg");
      data.push_back(phase);
      if (c.wk_weighted) {
        headers.push_back(c.column + "_wk_mag");
        data.push_back(weighted(c));
      }
    }
    Matrix table(hz.size(), static_cast<Eigen::Index>(data.size()));
    for (std::size_t k = 0; k < data.size(); ++k)
      table.col(static_cast<Eigen::Index>(k)) = data[k];
    Metadata metadata = {{"vehicle", description.name},
                         {"vehicle_file", opt.vehicle_file},
                         {"variant", vehicle::variantName(variant)},
                         {"model", opt.model},
                         {"excitation", opt.speed_kmh > 0 ? "travelled" : "synchronous"},
                         {"sides", opt.sides},
                         {"speed_kmh", opt.speed_kmh}};
    // Which model file the FRF is of, as simulate records it (review 123: it was not said).
    if (!opt.reduced.reducedFile().empty())
      metadata.push_back({"reduced_model_file", opt.reduced.reducedFile()});
    writeTable(opt.out_file, headers, table, 10, metadata);
  }

  // Per output: the largest peak and the resonances, the local maxima of the FRF at or above
  // 10 % of that peak and those of |FRF| / omega^2 (the displacement it stands for) at or above
  // 10 % of its largest, merged: an acceleration FRF grows as omega^2, so a body mode at 2 Hz is
  // a few % of a wheel hop at 25 Hz while its displacement is the larger (a light vehicle: 490
  // against 8,100 (m/s^2)/m), and a well-damped body mode may be no maximum of the acceleration
  // at all.
  auto peaks = [&](const Vector& mag) {
    Eigen::Index top = 0;
    mag.maxCoeff(&top);
    Vector displacement = Vector::Zero(mag.size());
    for (Eigen::Index i = 0; i < mag.size(); ++i)
      if (hz(i) > 0.0)
        displacement(i) = mag(i) / std::pow(kTwoPi * hz(i), 2);
    const double top_displacement = displacement.maxCoeff();
    // Rising into it, not falling out of it: a plateau counts once, at its start.
    const auto maximum = [](const Vector& v, Eigen::Index i, double floor) {
      return v(i) > v(i - 1) && v(i) >= v(i + 1) && v(i) >= floor;
    };
    // A displacement maximum and the acceleration maximum just above it (the FRF still rising
    // to it, within 25 % in frequency) are one resonance, listed where the FRF peaks.
    const auto climb = [&](Eigen::Index i) {
      Eigen::Index k = i;
      while (k + 2 < mag.size() && mag(k + 1) > mag(k))
        ++k;
      return k + 1 < mag.size() && hz(k) <= 1.25 * hz(i) && maximum(mag, k, 0.0) ? k : i;
    };
    std::vector<Eigen::Index> at;
    for (Eigen::Index i = 1; i + 1 < mag.size(); ++i) {
      if (maximum(mag, i, 0.1 * mag(top)))
        at.push_back(i);
      // |H| / omega^2 has no value at 0 Hz (0 / 0; the zero above stands in for it): the first
      // frequency after it is the quasi-static limit, 1 for a heave FRF, and a travelled road's
      // falls from there, which is no maximum (it listed 0.05 Hz as a resonance).
      if (hz(i - 1) > 0.0 && maximum(displacement, i, 0.1 * top_displacement))
        at.push_back(climb(i));
    }
    std::sort(at.begin(), at.end());
    at.erase(std::unique(at.begin(), at.end()), at.end());
    std::vector<std::pair<double, double>> local;
    for (const Eigen::Index i : at)
      local.emplace_back(hz(i), mag(i));
    return std::make_pair(top, local);
  };
  if (opt.json) {
    io::JsonWriter json(std::cout);
    json.beginObject()
        .field("vehicle", description.name)
        .field("vehicle_file", opt.vehicle_file)
        .field("variant", vehicle::variantName(variant))
        .field("model", opt.model)  // reduced | full, as simulate's
        .field("model_description", source);
    if (!opt.reduced.reducedFile().empty())
      json.field("reduced_model_file", opt.reduced.reducedFile());
    json.field("dofs", static_cast<long long>(dofs))
        .field("full_dofs", static_cast<long long>(full_dofs))
        .field("excitation", opt.speed_kmh > 0 ? "travelled" : "synchronous")
        .field("sides", opt.sides)
        .field("speed_kmh", opt.speed_kmh)
        .field("frequencies", static_cast<long long>(hz.size()))
        .field("max_hz", hz(hz.size() - 1));
    // How the FRF was solved: modal superposition (eq. 20) when the damping is diagonal in the
    // modes (the full model always), else directly (eq. 18, the reduced model).
    json.field("solution", solution).field("damping_coupling", damping_coupling);
    if (reduced)
      writeReductionJson(json.key("reduction"), *reduced);
    json.key("outputs").beginArray();
    for (const NamedColumn& c : columns) {
      const auto [top, local] = peaks(magnitude(c));
      json.beginObject()
          .field("column", c.column)
          .field("output", c.output)
          .field("unit", c.unit)
          .field("peak_hz", hz(top))
          .field("peak_magnitude", std::abs(h(top, c.index)))
          // The largest value at the last frequency is the band's edge, not a resonance: the
          // response still rises there (resonances_hz lists the local maxima).
          .field("peak_at_band_edge", top == hz.size() - 1)
          .key("resonances_hz")
          .beginArray();
      for (const auto& [f, m] : local)
        json.value(f);
      json.endArray();
      if (c.wk_weighted) {
        const Vector w = weighted(c);
        const Eigen::Index wk_top = peaks(w).first;
        json.field("wk_peak_hz", hz(wk_top))
            .field("wk_peak_magnitude", w(wk_top))
            .field("wk_peak_at_band_edge", wk_top == hz.size() - 1);
      }
      json.endObject();
    }
    json.endArray();
    if (!opt.out_file.empty())
      json.field("out", opt.out_file);
    json.endObject();
    return;
  }
  std::cout << vehicle::variantName(variant) << " vehicle, " << source << " model (" << dofs
            << " DOFs), "
            << (opt.speed_kmh > 0 ? "travelled at " + brief(opt.speed_kmh) + " km/h"
                                  : std::string("synchronous excitation"))
            << (anti_phase ? ", the tracks' roads in anti-phase" : "") << ", 0-"
            << hz(hz.size() - 1) << " Hz\n";
  if (reduced)
    std::cout << "  reduction: " << describeReduction(*reduced) << "\n";
  if (solution == "direct")
    std::cout << "  solved directly (eq. 18" << (reduced ? "" : ", in the modal coordinates")
              << "): the damping couples the modes (off-diagonal Phi^T C Phi up to "
              << std::setprecision(3) << damping_coupling
              << " of the diagonal), which eq. 20's modal damping would drop\n";
  for (const NamedColumn& c : columns) {
    const auto [top, local] = peaks(magnitude(c));
    std::cout << "  " << std::left << std::setw(18) << c.column << std::right << " peak "
              << std::setprecision(4) << std::abs(h(top, c.index)) << " " << c.unit << " at "
              << hz(top) << " Hz" << (top == hz.size() - 1 ? " (band edge)" : "")
              << "; resonances [Hz]:";
    for (const auto& [f, m] : local)
      std::cout << " " << f;
    if (c.wk_weighted) {
      const Vector w = weighted(c);
      const Eigen::Index wk_top = peaks(w).first;
      std::cout << "; Wk-weighted peak " << w(wk_top) << " " << c.unit << " at " << hz(wk_top)
                << " Hz" << (wk_top == hz.size() - 1 ? " (band edge)" : "");
    }
    std::cout << "\n";
  }
  if (!opt.out_file.empty())
    std::cout << "  wrote " << opt.out_file << "\n";
}

}  // namespace

void registerFrfCommand(CLI::App& app) {
  auto opt = std::make_shared<FrfOptions>();
  CLI::App* cmd = app.add_subcommand(
      "frf",
      "Acceleration FRFs per unit road height (hull vertical/pitch, front/rear wheel, "
      "named points)");
  addVehicleOption(cmd, &opt->vehicle_file);
  CLI::Option* variant =
      addVariantOption(cmd, &opt->variant, "untracked | tracked (with --reduced: the file's)");
  cmd->add_option("--model", opt->model,
                  "reduced (Craig-Bampton: cached with the reduction options, or --reduced FILE) | "
                  "full (FE modes + static residual)")
      ->check(CLI::IsMember({"reduced", "full"}));
  cmd->add_option("--speed-kmh", opt->speed_kmh,
                  "travelled excitation at this speed [km/h] (wheelbase filter), 0.01 .. 200; 0: "
                  "synchronous");
  cmd->add_option("--sides", opt->sides,
                  "in_phase: both tracks' roads alike (the paper's) | anti_phase: left +h, "
                  "right -h, which rolls the hull (adds hull_lateral_acc, hull_roll_acc, "
                  "hull_yaw_acc and each point's _lateral_acc)")
      ->check(CLI::IsMember({"in_phase", "anti_phase"}))
      ->capture_default_str();
  cmd->add_option("--max-hz", opt->max_hz, "highest frequency [Hz]")->check(positiveNumber());
  cmd->add_option("--step-hz", opt->step_hz,
                  "frequency step [Hz] (at most --max-hz; when --max-hz is not a "
                  "multiple of it, the grid ends with --max-hz itself)")
      ->check(positiveNumber());
  // Up to 100 Hz (twice the FRF band): the modes above enter statically, and above 100 Hz the
  // tracked model's chain-link modes make the Lanczos run take minutes (200 Hz: > 4 min).
  CLI::Option* max_mode =
      cmd->add_option("--max-mode-hz", opt->max_mode_hz,
                      "full model: dynamic modes up to this frequency [Hz] (at most 100)")
          ->check(finiteNumberWhere([](double v) { return v > 0.0 && v <= 100.0; },
                                    "a number in (0, 100] Hz", "NUMBER"));
  opt->reduced.addTo(cmd);
  cmd->add_option("--points", opt->points,
                  "named points of the description (e.g. crew_seat), comma-separated or repeated: "
                  "adds <point>_vertical_acc (output '<point> uz') with its ISO 2631-1 "
                  "Wk-weighted magnitude <point>_vertical_acc_wk_mag")
      ->type_name("NAME[,NAME...]")
      ->default_str("")
      ->expected(1)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd->add_option("--out", opt->out_file,
                  "CSV (or .mat: one variable per column): frequency_hz, then <output>_mag "
                  "(linear, not dB: (m/s^2)/m, pitch (rad/s^2)/m) and <output>_phase_deg (a "
                  "point's also <point>_vertical_acc_wk_mag)")
      ->check(outputFile({".csv", ".mat"}));
  cmd->add_flag("--json", opt->json, "print a JSON summary");
  cmd->callback([opt, max_mode, variant]() {
    if (max_mode->count() > 0 && opt->model != "full")
      throw InputError("frf: --max-mode-hz applies to --model full only");
    opt->reduced.check("frf", opt->model);
    refuseOutputOverInput(
        "frf", "--out", opt->out_file,
        {{"--vehicle", opt->vehicle_file}, {"--reduced", opt->reduced.reducedFile()}});
    opt->points = splitPointList("frf", opt->points);  // split here: CLI11 drops empty names
    opt->variant_given = variant->count() > 0;
    run(*opt);
  });
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
