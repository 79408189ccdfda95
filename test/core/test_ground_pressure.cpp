// Ground loads of the vehicle at rest (vehicle/ground_pressure.h): per-assembly reactions from the
// static solution, checked by equilibrium, and the closed-form pressures (NGP, Rowland's MMP).
#include <gtest/gtest.h>

#include <cmath>

#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/vehicle/ground_pressure.h"
#include "tracked_vehicle_dynamics/vehicle/static_summary.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

#ifndef TVD_SOURCE_DIR
#define TVD_SOURCE_DIR "."
#endif

namespace veh = tracked_vehicle_dynamics::vehicle;
namespace fem = tracked_vehicle_dynamics::fem;

namespace {

const std::string kDescriptionFile =
    std::string(TVD_SOURCE_DIR) + "/config/vehicles/paper_vehicle.yaml";
constexpr double kGravity = 9.80665;  // [m/s^2], the models' gravity

struct AtRest {
  veh::VehicleDescription description;
  veh::VehicleModel model;
  veh::StaticSummary statics;
  veh::GroundPressure ground;
};

AtRest atRest(veh::Variant variant) {
  AtRest r;
  r.description = veh::loadVehicleDescription(kDescriptionFile);
  r.model = veh::buildVehicleModel(r.description, variant);
  const fem::System system = fem::assemble(r.model.model);
  r.statics = veh::computeStaticSummary(r.model, system);
  r.ground = veh::groundPressure(r.model, r.description, r.statics);
  return r;
}

/// What every variant satisfies: each assembly's rows add up, the assemblies carry the weight, both
/// sides alike (the vehicle is symmetric about x-z), ordered left then right, front to rear.
void expectConsistent(const AtRest& r, std::size_t assemblies_per_side) {
  const veh::GroundPressure& g = r.ground;
  ASSERT_EQ(g.assemblies.size(), 2 * assemblies_per_side);
  const double footprint = 0.62 * 0.1615;  // Table 1 width (B - b) x pitch (14,858 mm / 92) [m^2]
  double sum = 0.0;
  for (std::size_t k = 0; k < g.assemblies.size(); ++k) {
    const veh::AssemblyGroundLoad& a = g.assemblies[k];
    sum += a.load;
    EXPECT_NEAR(a.inner + a.outer, a.load, 1e-9 * r.statics.weight);
    EXPECT_NEAR(a.pressure * footprint, a.load, 1e-9 * r.statics.weight);
    EXPECT_EQ(a.side, k < assemblies_per_side ? 0 : 1);
    if (k % assemblies_per_side != 0) {
      EXPECT_LT(a.x, g.assemblies[k - 1].x) << k;
    }
    // Mirror image: assembly k on the right carries what assembly k on the left does.
    if (k < assemblies_per_side) {
      const veh::AssemblyGroundLoad& m = g.assemblies[k + assemblies_per_side];
      EXPECT_NEAR(m.x, a.x, 1e-12);
      EXPECT_NEAR(m.load, a.load, 1e-6 * r.statics.weight);
    }
  }
  EXPECT_NEAR(sum, r.statics.weight, 1e-6 * r.statics.weight);
  EXPECT_NEAR(g.side_load[0] + g.side_load[1], sum, 1e-9 * r.statics.weight);
  EXPECT_NEAR(g.side_load[0], g.side_load[1], 1e-6 * r.statics.weight);
  ASSERT_GE(g.peak, 0);
  // Mirror-image twins tie to round-off: the left one is reported.
  EXPECT_EQ(g.assemblies[static_cast<std::size_t>(g.peak)].side, 0);
  const double largest = g.assemblies[static_cast<std::size_t>(g.peak)].pressure;
  for (const veh::AssemblyGroundLoad& a : g.assemblies)
    EXPECT_LE(a.pressure, largest * (1.0 + 1e-9));
}

}  // namespace

TEST(GroundPressure, UntrackedAssemblyCarriesItsWheelAndItself) {
  const AtRest r = atRest(veh::Variant::Untracked);
  expectConsistent(r, 7);
  // Each assembly is held by its wheel's contact and the ground alone (the guide horn's contact
  // carries only lateral force): ground reaction = wheel load + its own weight (Table 1, 27 kg).
  const auto& wheels = r.model.layout.wheels;
  for (std::size_t i = 0; i < wheels.size(); ++i) {
    const veh::AssemblyGroundLoad& a = r.ground.assemblies[i];  // same order: left 1..7, right 1..7
    EXPECT_EQ(a.assembly, wheels[i].axle);
    EXPECT_NEAR(a.load, r.statics.wheel_loads[i] + 27.0 * kGravity, 1e-6 * a.load)
        << wheels[i].name;
    EXPECT_GT(a.load, 0.0);
    // One assembly under each wheel: the peak under it is that assembly's pressure.
    EXPECT_DOUBLE_EQ(r.ground.wheel_peak_pressure[i], a.pressure) << wheels[i].name;
    // The pads sit symmetrically under the wheel: inner and outer rows share its load.
    EXPECT_NEAR(a.inner, a.outer, 1e-6 * a.load) << wheels[i].name;
  }
  EXPECT_EQ(r.ground.lifting, 0);
}

TEST(GroundPressure, TrackedGroundRunCarriesTheWholeVehicle) {
  const AtRest r = atRest(veh::Variant::Tracked);
  expectConsistent(r, 30);  // §2: 30 assemblies per side on the ground
  EXPECT_NEAR(r.ground.side_load[0], 0.5 * 55668.0 * kGravity, 1e-6 * r.statics.weight);
  // The ground run spans its 4,845 mm (§2): 29 pitches between the first and last centres.
  const auto& a = r.ground.assemblies;
  EXPECT_NEAR(a.front().x - a[29].x, 29 * 0.1615, 1e-9);
  int lifting = 0;
  for (const auto& x : a)
    lifting += x.load < 0.0;
  EXPECT_EQ(r.ground.lifting, lifting);
  // The peak under each wheel is one of the assemblies under it (within 0.39 m) and no lower than
  // the nearest one; their mean is the FE mean maximum pressure.
  const auto& wheels = r.model.layout.wheels;
  ASSERT_EQ(r.ground.wheel_peak_pressure.size(), wheels.size());
  double mean = 0.0;
  for (std::size_t i = 0; i < wheels.size(); ++i) {
    const double x = 2.34 - 0.78 * wheels[i].axle;  // Table 1's 0.78 m axle spacing, centred
    const veh::AssemblyGroundLoad* nearest = nullptr;
    bool found = false;
    for (const auto& s : a) {
      if (s.side != wheels[i].side)
        continue;
      if (!nearest || std::abs(s.x - x) < std::abs(nearest->x - x))
        nearest = &s;
      if (std::abs(s.x - x) <= 0.39 && s.pressure == r.ground.wheel_peak_pressure[i])
        found = true;
    }
    EXPECT_TRUE(found) << wheels[i].name;
    EXPECT_GE(r.ground.wheel_peak_pressure[i], nearest->pressure) << wheels[i].name;
    mean += r.ground.wheel_peak_pressure[i] / wheels.size();
  }
  EXPECT_NEAR(r.ground.mean_peak_pressure, mean, 1e-9 * mean);
}

TEST(GroundPressure, NominalAndMeanMaximumPressureClosedForms) {
  const AtRest r = atRest(veh::Variant::Tracked);
  // NGP = W / (2 b L) with Table 1's b = 0.62 m and §2's L = 4.845 m.
  const double weight = 55668.0 * kGravity;
  EXPECT_NEAR(r.ground.nominal_pressure, weight / (2.0 * 0.62 * 4.845), 1e-6);
  EXPECT_NEAR(r.ground.nominal_pressure, 90.868e3, 1.0);
  // Rowland: 1.26 W / (2 n b sqrt(t D)), n = 7 wheels per side, t = 0.1615 m, D = 2 x 0.34 m.
  EXPECT_NEAR(r.ground.rowland_mean_maximum_pressure,
              1.26 * weight / (2.0 * 7 * 0.62 * std::sqrt(0.1615 * 0.68)), 1e-6);
  EXPECT_NEAR(r.ground.rowland_mean_maximum_pressure, 239.13e3, 10.0);
}

TEST(GroundPressure, PadRowsAndWheelReachOfGivenReactions) {
  // Reactions set by hand on the tracked model: each sole carries its distance from the vehicle
  // centre line [N], so an assembly's inner row (3 soles at 1.4 - 0.155 m) carries 3 x 1.245 and
  // its outer row 3 x 1.555; and left assembly 26 (x = 1.857 m) carries 1 N more per sole.
  AtRest r = atRest(veh::Variant::Tracked);
  const auto& inputs = r.model.layout.road_inputs;
  int spiked = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    const bool spike =
        inputs[i].side == 0 &&
        r.model.layout.assemblies[static_cast<std::size_t>(inputs[i].assembly)].index == 26;
    spiked += spike;
    r.statics.pad_loads[i] = std::abs(inputs[i].y) + (spike ? 1.0 : 0.0);
  }
  ASSERT_EQ(spiked, 6);
  const veh::GroundPressure g = veh::groundPressure(r.model, r.description, r.statics);
  const double footprint = 0.62 * 0.1615;
  for (const veh::AssemblyGroundLoad& a : g.assemblies) {
    const double extra = a.side == 0 && a.assembly == 26 ? 3.0 : 0.0;
    EXPECT_NEAR(a.inner, 3 * 1.245 + extra, 1e-9) << a.side << " " << a.assembly;
    EXPECT_NEAR(a.outer, 3 * 1.555 + extra, 1e-9) << a.side << " " << a.assembly;
  }
  // Assembly 26 lies 0.483 m behind wheel 1 (x = 2.34 m), beyond half the 0.78 m spacing, and
  // 0.297 m ahead of wheel 2 (x = 1.56 m): its peak is under wheel 2 only, on the left only.
  const double base = 3 * (1.245 + 1.555) / footprint;
  const double peak = base + 6.0 / footprint;
  const auto& wheels = r.model.layout.wheels;
  for (std::size_t i = 0; i < wheels.size(); ++i) {
    const bool under = wheels[i].side == 0 && wheels[i].axle == 1;
    EXPECT_NEAR(g.wheel_peak_pressure[i], under ? peak : base, 1e-9 * peak) << wheels[i].name;
  }
  EXPECT_NEAR(g.mean_peak_pressure, base + (peak - base) / wheels.size(), 1e-9 * peak);
  ASSERT_GE(g.peak, 0);
  EXPECT_EQ(g.assemblies[static_cast<std::size_t>(g.peak)].side, 0);
  EXPECT_EQ(g.assemblies[static_cast<std::size_t>(g.peak)].assembly, 26);
}

TEST(GroundPressure, MismatchedStaticSummaryIsALogicError) {
  AtRest r = atRest(veh::Variant::Untracked);
  r.statics.pad_loads.pop_back();
  EXPECT_THROW(veh::groundPressure(r.model, r.description, r.statics), std::logic_error);
}
