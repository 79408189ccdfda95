// `tvd statics`: the vehicle at rest under gravity (paper §2, issue 3): hull sag and attitude,
// road-wheel loads, and the ground reaction under every track assembly with the ground-pressure
// figures (vehicle/ground_pressure.h). Linear statics K x = f_g, no modal solve; with --accel a,
// the steady state of a constant forward acceleration, K x = f_g + a f_a (f_a = -M e_x, the
// travel inertia): braking's load transfer to the front and its nose-down pitch.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <numeric>
#include <utility>

#include "commands.h"
#include "mass_breakdown_report.h"
#include "output_files.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/io/json_writer.h"
#include "tracked_vehicle_dynamics/vehicle/contact_statics.h"
#include "tracked_vehicle_dynamics/vehicle/ground_pressure.h"
#include "tracked_vehicle_dynamics/vehicle/static_summary.h"
#include "tracked_vehicle_dynamics/vehicle/track_tension.h"
#include "tracked_vehicle_dynamics/vehicle/wheel_rate_estimate.h"
#include "vehicle_analysis.h"
#include "wheel_rate_report.h"

namespace tracked_vehicle_dynamics {
namespace tools {

namespace {

struct StaticsOptions {
  std::string vehicle_file;
  std::string variant = "tracked";
  std::string contact = "unilateral";
  double accel = 0.0;  ///< steady forward acceleration of the vehicle [m/s^2], braking < 0
  bool json = false;
  std::string out_file;
};

using vehicle::sideName;

/// `value` as printed with `decimals` fixed decimals, without the sign of a round-off residue
/// ("-0.0000" for a symmetric vehicle's roll of -1e-13 deg).
double printed(double value, int decimals) {
  return std::abs(value) < 0.5 * std::pow(10.0, -decimals) ? 0.0 : value;
}

void run(const StaticsOptions& opt) {
  const vehicle::VehicleDescription description = loadVehicle(opt.vehicle_file);
  const vehicle::Variant variant = vehicle::parseVariant(opt.variant);
  const auto t0 = std::chrono::steady_clock::now();
  const vehicle::VehicleModel built = vehicle::buildVehicleModel(description, variant);
  // Unilateral: the equilibrium of a modified model (the lifted contacts' springs removed).
  vehicle::ContactStatics contact;
  const bool unilateral = opt.contact == "unilateral";
  if (unilateral) {
    try {
      contact = vehicle::computeContactStatics(built, opt.accel);
    } catch (const fem::UnilateralFreeMotionError& e) {
      // Released contacts left a free motion; the bonded model (contacts that also pull) has none.
      throw SolverError(std::string(e.what()) +
                        "; --contact bilateral solves the bonded model at this load");
    }
  } else {
    contact.vehicle = built;
    contact.system = fem::assemble(built.model);
    contact.summary = vehicle::computeStaticSummary(built, contact.system, opt.accel);
    contact.iterations = 1;
    // Nothing released: one false flag per contact, so both modes report alike.
    contact.pad_lifted.assign(built.layout.road_inputs.size(), false);
    contact.wheel_lifted.assign(built.layout.wheels.size(), false);
    contact.chain_wheel_released.assign(built.layout.chain_wheel_contacts.size(), false);
  }
  const vehicle::VehicleModel& model = contact.vehicle;
  const fem::System& system = contact.system;
  const vehicle::StaticSummary& s = contact.summary;
  std::vector<std::string> warnings = vehicle::staticWarnings(s, description);
  const vehicle::WheelRateEstimate estimate = vehicle::wheelRateEstimate(description, variant);
  // At rest only: under --accel the sag is the load case's, not the suspension's.
  if (opt.accel == 0.0) {
    for (std::string& w : vehicle::restWarnings(s.hull_sag, s.hull_pitch, description, variant))
      warnings.push_back(std::move(w));
  }
  // A road wheel off the track at rest is a vehicle that does not stand on its wheels (a centre
  // of gravity far off the wheelbase, a chain stiff enough to carry the hull): said, not only
  // counted. Under --accel lifting wheels are the expected result.
  if (unilateral && opt.accel == 0.0) {
    std::string lifted;
    int n = 0;
    for (std::size_t i = 0; i < contact.wheel_lifted.size(); ++i)
      if (contact.wheel_lifted[i])
        lifted += std::string(n++ ? ", " : "") + built.layout.wheels[i].name;
    if (n > 0)
      warnings.push_back(
          std::to_string(n) + " of " + std::to_string(contact.wheel_lifted.size()) +
          " road wheels lift off " +
          (variant == vehicle::Variant::Tracked ? "the track" : "their track assemblies") +
          " at rest (" + lifted + "): the hull rests on the others" +
          (variant == vehicle::Variant::Tracked
               ? " and the chain; check hull.cog_x and the chain's bending "
                 "stiffness (track_assembly.link_member_bending_inertia)"
               : "; check hull.cog_x"));
  }
  for (const std::string& w : warnings)
    std::cerr << "tvd: warning: " << w << "\n";
  const vehicle::GroundPressure g = vehicle::groundPressure(model, description, s);
  const auto count = [](const std::vector<bool>& v) {
    return static_cast<int>(std::count(v.begin(), v.end(), true));
  };
  const int pads_lifted = count(contact.pad_lifted);
  const int wheels_lifted = count(contact.wheel_lifted);
  const std::vector<vehicle::ChainWheelContact>& chain_wheels = built.layout.chain_wheel_contacts;
  const vehicle::ChainWheel kChainWheels[] = {
      vehicle::ChainWheel::Sprocket, vehicle::ChainWheel::Idler, vehicle::ChainWheel::ReturnRoller};
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

  if (!opt.out_file.empty()) {
    Matrix table(static_cast<Eigen::Index>(g.assemblies.size()), 7);
    for (std::size_t k = 0; k < g.assemblies.size(); ++k) {
      const vehicle::AssemblyGroundLoad& a = g.assemblies[k];
      table.row(static_cast<Eigen::Index>(k)) << a.side, a.assembly, a.x, a.load, a.inner, a.outer,
          a.pressure;
    }
    writeTable(opt.out_file,
               {"side", "assembly", "x_m", "load_n", "inner_pad_n", "outer_pad_n", "pressure_pa"},
               table, 10,
               {{"vehicle", description.name},
                {"vehicle_file", opt.vehicle_file},
                {"variant", vehicle::variantName(variant)},
                {"contact", opt.contact},
                {"forward_acceleration_m_s2", opt.accel}});
  }
  const vehicle::AssemblyGroundLoad* peak =
      g.peak >= 0 ? &g.assemblies[static_cast<std::size_t>(g.peak)] : nullptr;

  if (opt.json) {
    io::JsonWriter json(std::cout);
    json.beginObject()
        .field("vehicle", description.name)
        .field("vehicle_file", opt.vehicle_file)
        .field("variant", vehicle::variantName(variant))
        .field("contact", opt.contact)
        .field("forward_acceleration_m_s2", opt.accel)
        .field("track_tension_n", vehicle::modelTrackTension(description, variant))
        .field("iterations", contact.iterations)
        .field("lifted_pads", pads_lifted)
        .field("lifted_wheels", wheels_lifted)
        .field("released_chain_wheel_contacts", count(contact.chain_wheel_released));
    // Per side and chain wheel kind: how many of its contacts with the links were released.
    json.key("released_chain_wheel_contacts_by_side").beginObject();
    for (int side = 0; side < 2; ++side) {
      json.key(sideName(side)).beginObject();
      for (const vehicle::ChainWheel wheel : kChainWheels)
        json.field(
            vehicle::chainWheelName(wheel),
            vehicle::chainWheelRelease(built.layout, contact.chain_wheel_released, side, wheel)
                .released);
      json.endObject();
    }
    json.endObject()
        .field("active_dofs", static_cast<long long>(system.size()))
        .field("mass_kg", model.model.totalMass());
    writeMassBreakdown(json, model.layout.mass);
    writeWheelRateEstimate(json, estimate);
    json.field("weight_n", s.weight)
        .field("hull_sag_m", s.hull_sag)
        .field("hull_pitch_deg", s.hull_pitch * kRadToDegree)
        .field("hull_roll_deg", s.hull_roll * kRadToDegree)
        .field("ground_reaction_sum_n", s.ground_reaction)
        .field("longitudinal_ground_reaction_sum_n", s.ground_reaction_x)
        .field("road_wheel_load_sum_n",
               std::accumulate(s.wheel_loads.begin(), s.wheel_loads.end(), 0.0))
        .field("chain_wheel_vertical_force_n", s.chain_wheel_vertical)
        .field("relative_balance_error", s.balanceError())
        .field("solve_residual", s.residual)
        .field("side_loads_n", std::vector<double>{g.side_load[0], g.side_load[1]})
        .field("nominal_ground_pressure_pa", g.nominal_pressure)
        .field("rowland_mean_maximum_pressure_pa", g.rowland_mean_maximum_pressure)
        .field("mean_peak_pressure_pa", g.mean_peak_pressure);
    json.key("peak_assembly_pressure").beginObject();
    if (peak)
      json.field("pressure_pa", peak->pressure)
          .field("side", sideName(peak->side))
          .field("x_m", peak->x);
    json.endObject().field("lifting_assemblies", g.lifting);
    json.key("road_wheels").beginArray();
    for (std::size_t i = 0; i < model.layout.wheels.size(); ++i) {
      const vehicle::WheelStation& w = model.layout.wheels[i];
      json.beginObject()
          .field("name", w.name)
          .field("x_m", g.wheel_x[i])
          .field("load_n", s.wheel_loads[i])
          .field("lifted", static_cast<bool>(contact.wheel_lifted[i]))
          .field("peak_pressure_pa", g.wheel_peak_pressure[i])
          .endObject();
    }
    json.endArray().key("chain_wheel_contacts").beginArray();
    for (std::size_t i = 0; i < chain_wheels.size(); ++i) {
      const vehicle::ChainWheelContact& c = chain_wheels[i];
      json.beginObject()
          .field("name", model.model.springs[c.spring].name)
          .field("wheel", vehicle::chainWheelName(c.wheel))
          .field("side", sideName(c.side))
          .field("assembly", model.layout.assemblies[static_cast<std::size_t>(c.assembly)].index)
          .field("load_n", s.chain_wheel_loads[i])
          .field("released", static_cast<bool>(contact.chain_wheel_released[i]))
          .endObject();
    }
    json.endArray().key("track_assemblies").beginArray();
    for (const vehicle::AssemblyGroundLoad& a : g.assemblies)
      json.beginObject()
          .field("name", vehicle::assemblyName(a.side, a.assembly))
          .field("side", sideName(a.side))
          .field("assembly", a.assembly)
          .field("x_m", a.x)
          .field("load_n", a.load)
          .field("inner_pad_n", a.inner)
          .field("outer_pad_n", a.outer)
          .field("pressure_pa", a.pressure)
          .endObject();
    json.endArray().key("warnings").beginArray();
    for (const std::string& w : warnings)
      json.value(w);
    json.endArray().field("seconds", seconds);
    if (!opt.out_file.empty())
      json.field("out", opt.out_file);
    json.endObject();
    return;
  }

  std::cout << std::fixed << "model: " << description.name << " (" << vehicle::variantName(variant)
            << ")   active DOFs: " << system.size() << "   mass: " << std::setprecision(1)
            << model.model.totalMass() << " kg   weight: " << std::setprecision(2) << s.weight / 1e3
            << " kN   solve: " << std::setprecision(3) << seconds << " s\n"
            << massBreakdownText(model.layout.mass) << "\n";
  if (unilateral)
    std::cout << "contacts: unilateral ("
              << (variant == vehicle::Variant::Tracked
                      ? "pads on the road, wheels on the links, links on the sprockets, idlers and "
                        "rollers"
                      : "pads on the road")
              << " push but cannot pull): " << pads_lifted << " of " << contact.pad_lifted.size()
              << " pad soles and " << wheels_lifted << " of " << contact.wheel_lifted.size()
              << " road wheels lifted, " << contact.iterations
              << (contact.iterations == 1 ? " solve\n" : " solves\n");
  else
    std::cout
        << "contacts: bilateral (the linear model: the equilibrium the dynamics start from)\n";
  if (!chain_wheels.empty()) {
    // Unilateral: the contacts released; bilateral: those the link pulls on (N < 0).
    std::vector<bool> shown = contact.chain_wheel_released;
    if (!unilateral)
      for (std::size_t i = 0; i < chain_wheels.size(); ++i)
        shown[i] = s.chain_wheel_loads[i] < 0.0;
    std::cout << (unilateral ? "chain wheel contacts released (the link has left the wheel):"
                             : "chain wheel contacts pulling (would leave the wheel):");
    for (int side = 0; side < 2; ++side) {
      std::cout << (side == 0 ? " " : "; ") << sideName(side);
      const char* separator = " ";
      for (const vehicle::ChainWheel wheel : kChainWheels) {
        const vehicle::ChainWheelRelease r =
            vehicle::chainWheelRelease(built.layout, shown, side, wheel);
        if (r.contacts == 0)
          continue;  // no return rollers: not "return_roller 0 of 0"
        std::cout << separator << vehicle::chainWheelName(wheel) << " " << r.released << " of "
                  << r.contacts;
        separator = ", ";
      }
    }
    std::cout << "\n";
  }
  if (const std::string tension = vehicle::trackTensionText(description, variant); !tension.empty())
    std::cout << tension << "\n";
  if (opt.accel != 0.0)
    std::cout << "steady forward acceleration " << std::setprecision(3) << opt.accel << " m/s^2 ("
              << std::setprecision(3) << std::abs(opt.accel) / kStandardGravity << " g, "
              << (opt.accel < 0.0 ? "braking" : "accelerating")
              << "): the road holds the vehicle with " << std::setprecision(2)
              << s.ground_reaction_x / 1e3 << " kN along x\n";
  std::cout
      << "\n"
      // hull_sag is the CoG's z displacement (z up, as in the JSON): a hull that settles
      // has a negative one, printed as a positive sag beside it.
      << (opt.accel == 0.0 ? "hull at rest: sag " : "hull: sag ") << std::setprecision(3)
      << -s.hull_sag * 1e3 << " mm (z " << s.hull_sag * 1e3 << " mm), pitch "
      << std::setprecision(4) << printed(s.hull_pitch * kRadToDegree, 4)
      << " deg (nose down +), roll " << printed(s.hull_roll * kRadToDegree, 4)
      << " deg (left up +)\n"
      << wheelRateEstimateText(estimate) << "\n\n"
      << "road wheels: normal force on the track [kN] (negative: pulling on it, would lift off);\n"
      << "the largest assembly pressure within half an axle spacing [kPa]\n"
      << "  wheel                   x [m]   load [kN]   peak pressure under it [kPa]\n";
  for (std::size_t i = 0; i < model.layout.wheels.size(); ++i) {
    const vehicle::WheelStation& w = model.layout.wheels[i];
    std::cout << "  " << std::left << std::setw(20) << w.name << std::right << std::setw(8)
              << std::setprecision(3) << g.wheel_x[i] << std::setw(12) << std::setprecision(2)
              << s.wheel_loads[i] / 1e3 << std::setw(20) << std::setprecision(1)
              << g.wheel_peak_pressure[i] / 1e3 << "\n";
  }
  const double wheel_sum = std::accumulate(s.wheel_loads.begin(), s.wheel_loads.end(), 0.0);
  // Why the wheel loads need not sum to the weight (StaticSummary::chain_wheel_vertical).
  std::cout << "  together " << std::setprecision(2) << wheel_sum / 1e3 << " kN ("
            << wheel_sum / s.weight << " x the weight)";
  if (model.layout.variant == vehicle::Variant::Tracked) {
    // Up: the loop hangs on them. Down: either bonded links pull on them (a contact in
    // tension), or, every contact pressing, a tensioned loop wraps round them where their
    // outward push points down (below a sprocket or idler centre).
    const bool any_pulling = std::any_of(s.chain_wheel_loads.begin(), s.chain_wheel_loads.end(),
                                         [](double n) { return n < 0.0; });
    const bool up = s.chain_wheel_vertical >= 0.0;
    std::cout << ": the chain lies between them and the ground with its own weight ("
              << model.layout.mass.track_assemblies * model.model.gravity.norm() / 1e3
              << " kN),\n  and the sprockets, idlers and rollers "
              << (up            ? "push it up"
                  : any_pulling ? "pull it down"
                                : "press it down")
              << " with " << std::abs(s.chain_wheel_vertical) / 1e3 << " kN, with which it "
              << (up            ? "pushes the hull down"
                  : any_pulling ? "pulls the hull up"
                                : "lifts the hull")
              << (up            ? " (the loop hanging on them under gravity)"
                  : any_pulling ? " (links bonded to them pulling on them)"
                                : " (the tensioned loop wrapped round them)");
  } else
    std::cout << ": the track assemblies under them add their own weight ("
              << model.layout.mass.track_assemblies * model.model.gravity.norm() / 1e3 << " kN)";
  std::cout << "\n";
  std::cout << "\ntrack assemblies on the ground: vertical reaction [kN] (inner / outer pad row), "
               "pressure = load / (width x pitch) [kPa]\n"
            << "  side   assembly    x [m]   load [kN]   inner   outer   pressure [kPa]\n";
  for (const vehicle::AssemblyGroundLoad& a : g.assemblies)
    std::cout << "  " << std::left << std::setw(5) << sideName(a.side) << std::right
              << std::setw(10) << a.assembly << std::setw(9) << std::setprecision(3) << a.x
              << std::setw(12) << std::setprecision(2) << a.load / 1e3 << std::setw(8)
              << a.inner / 1e3 << std::setw(8) << a.outer / 1e3 << std::setw(17)
              << std::setprecision(1) << a.pressure / 1e3 << "\n";
  std::cout << "\nground reactions " << std::setprecision(1) << s.ground_reaction << " N (left "
            << g.side_load[0] << ", right " << g.side_load[1] << ") = weight " << s.weight
            << " N, relative error " << std::scientific << std::setprecision(1) << s.balanceError()
            << std::fixed << "\n"
            << "nominal ground pressure W / (2 b L): " << std::setprecision(1)
            << g.nominal_pressure / 1e3 << " kPa\n"
            << "mean maximum pressure: " << g.mean_peak_pressure / 1e3
            << " kPa (mean of the peaks under the wheels); Rowland's empirical estimate "
            << g.rowland_mean_maximum_pressure / 1e3 << " kPa\n";
  if (peak)
    std::cout << "largest assembly pressure: " << peak->pressure / 1e3 << " kPa ("
              << sideName(peak->side) << ", x = " << std::setprecision(3) << peak->x << " m)";
  if (unilateral)
    std::cout << "\n";
  else
    std::cout << "; " << g.lifting
              << " assemblies pulled down (the linear model holds them on the "
                 "road; --contact unilateral lets them lift)\n";
  if (!opt.out_file.empty())
    std::cout << "  wrote " << opt.out_file << "\n";
}

}  // namespace

void registerStaticsCommand(CLI::App& app) {
  auto opt = std::make_shared<StaticsOptions>();
  CLI::App* cmd = app.add_subcommand("statics",
                                     "The vehicle at rest under gravity: hull sag, wheel loads, "
                                     "ground load and pressure under the track");
  addVehicleOption(cmd, &opt->vehicle_file);
  addVariantOption(cmd, &opt->variant, "untracked | tracked");
  cmd->add_option(
         "--out", opt->out_file,
         "CSV (or .mat: one variable per column), one row per assembly on the ground: side "
         "(0 left, 1 right), assembly, x_m, load_n, inner_pad_n, outer_pad_n, pressure_pa")
      ->check(outputFile({".csv", ".mat"}));
  cmd->add_option("--contact", opt->contact,
                  "unilateral: pads, road wheels and the links on the sprockets, idlers and "
                  "return rollers push but cannot pull, those in tension lift off | bilateral: "
                  "the linear model, every contact bonded (the equilibrium the dynamics start "
                  "from, as tvd modes reports)")
      ->check(CLI::IsMember({"unilateral", "bilateral"}));
  cmd->add_option("--accel", opt->accel,
                  "steady forward acceleration of the vehicle [m/s^2], braking negative (e.g. "
                  "-2.94 for 0.3 g): the travel inertia -m a at every mass moves the load to the "
                  "front pads and pitches the nose down; -15 .. 15; 0 (default): at rest")
      ->check(numberIn(-15.0, 15.0, "m/s^2"));
  cmd->add_flag("--json", opt->json, "print a JSON document instead of the tables");
  cmd->callback([opt]() {
    refuseOutputOverInput("statics", "--out", opt->out_file, {{"--vehicle", opt->vehicle_file}});
    run(*opt);
  });
}

}  // namespace tools
}  // namespace tracked_vehicle_dynamics
