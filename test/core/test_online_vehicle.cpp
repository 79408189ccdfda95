// The node's ROS-free engine (OnlineVehicle, RoadInputSampler) on a toy half car: static
// equilibrium at rest, identity with an offline Simulator run on the same terrain, terrain gaps,
// rejected input, and no allocation per step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "toy_vehicle.h"
#include "tracked_vehicle_dynamics/dynamics/road_excitation.h"
#include "tracked_vehicle_dynamics/dynamics/simulator.h"
#include "tracked_vehicle_dynamics/dynamics/static_equilibrium.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/online/online_vehicle.h"
#include "tracked_vehicle_dynamics/online/road_input_sampler.h"
#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "tracked_vehicle_dynamics/terrain/terrain.h"
#include "tracked_vehicle_dynamics/terrain/terrain_buffer.h"
#include "tracked_vehicle_dynamics/terrain/tracks.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"

#include "count_allocations.h"
#include "expect_input_error.h"

using namespace tracked_vehicle_dynamics;
using namespace tracked_vehicle_dynamics::online;

namespace {

constexpr double kAtRest = 1e-12;  // drift from equilibrium over many steps [m, rad]
// Online vs offline on the same terrain, of the peak (rounding only). Where a contact stands on a
// terrain station dh/dx jumps, and a station one rounding away takes the other cell: the speed
// of OnlineVersusOffline keeps the contacts >= 1e-5 m off the stations.
constexpr double kOfflineAgreement = 1e-9;
constexpr double kRate = 1000.0;  // [Hz]

/// A smooth bump 0.1 m high from x = 2 to 4 m, two lateral lines, sampled every 0.05 m.
terrain::Terrain bump() {
  const int n = 301;  // -5 .. 10 m
  Vector x = Vector::LinSpaced(n, -5.0, 10.0);
  Vector y(2);
  y << -1.0, 1.0;
  Matrix h = Matrix::Zero(2, n);
  for (int i = 0; i < n; ++i) {
    if (x(i) > 2.0 && x(i) < 4.0)
      h.col(i).setConstant(0.05 * (1.0 - std::cos(M_PI * (x(i) - 2.0))));
  }
  return terrain::Terrain(x, y, h, "bump");
}

/// The terrain as consecutive patches of `per_patch` samples (gap of one spacing between them).
std::vector<TerrainPatch> patches(const terrain::Terrain& t, int per_patch) {
  std::vector<TerrainPatch> out;
  for (Eigen::Index k0 = 0; k0 < t.stations().size(); k0 += per_patch) {
    const Eigen::Index n = std::min<Eigen::Index>(per_patch, t.stations().size() - k0);
    TerrainPatch p;
    p.start_station = t.stations()(k0);
    p.spacing = t.spacing();
    p.lateral = t.lateral();
    p.heights = t.heights().middleCols(k0, n);
    out.push_back(p);
  }
  return out;
}

/// Drives `vehicle` at 10 m/s over the bump for `steps` steps: a state away from rest.
void driveOverBump(OnlineVehicle& vehicle, int steps) {
  for (const TerrainPatch& p : patches(bump(), 50))
    vehicle.addTerrain(p);
  vehicle.setSpeed(10.0);
  for (int k = 0; k < steps; ++k)
    vehicle.step();
}

OnlineVehicleOptions options(dynamics::DiscretizationMethod method) {
  OnlineVehicleOptions o;
  o.rate = kRate;
  o.method = method;
  o.comfort_point = "crew_seat";
  return o;
}

/// Flat ground (height 0) from `from` to `to` [m] every `spacing`, on two lines at y =
/// +-half_width.
TerrainPatch flatPatch(double from, double to, double spacing, double half_width) {
  TerrainPatch flat;
  flat.start_station = from;
  flat.spacing = spacing;
  flat.lateral = Eigen::Vector2d(-half_width, half_width);
  flat.heights = Matrix::Zero(2, std::lround((to - from) / spacing) + 1);
  return flat;
}

}  // namespace

TEST(OnlineVehicle, AtRestOnFlatTerrainStaysInStaticEquilibrium) {
  const reduction::ReducedModel model = test::toyModel();
  OnlineVehicle vehicle(model, test::toyGeometry(),
                        options(dynamics::DiscretizationMethod::ModalDecoupled));
  vehicle.addTerrain(flatPatch(-5.0, 5.0, 0.1, 1.0));  // 101 samples
  const Vector6 start = vehicle.hullDisplacement();
  // Equilibrium: K q0 = f_g; the hull sinks by g (M + 2 m) / (2 k_t) + g M / (2 k_s).
  using T = test::ToyVehicle;
  const double sink = kStandardGravity * (T::kHullMass + 2 * T::kWheelMass) / (2 * T::kTyre) +
                      kStandardGravity * T::kHullMass / (2 * T::kSuspension);
  EXPECT_NEAR(start(2), -sink, 1e-12);
  for (int k = 0; k < 2000; ++k)
    ASSERT_EQ(vehicle.step().uncovered, 0);
  EXPECT_NEAR((vehicle.hullDisplacement() - start).norm(), 0.0, kAtRest);
  for (const WheelState& w : vehicle.wheels()) {
    EXPECT_NEAR(w.displacement, 0.0, kAtRest) << w.name;
    EXPECT_NEAR(w.acceleration, 0.0, 1e-9) << w.name;
  }
  EXPECT_NEAR(vehicle.comfort().weightedRms(), 0.0, 1e-9);
  EXPECT_DOUBLE_EQ(vehicle.station(), 0.0);
  // Frames: base_link at rest has no pitch; wheel centres keep x, y and sit on their tyres.
  const RigidPose pose = vehicle.hullPose();
  EXPECT_NEAR(pose.translation.x(), 0.0, 1e-12);
  EXPECT_NEAR(pose.translation.z(), -sink, 1e-12);
  const Vector3 front = vehicle.wheelPosition(0);
  EXPECT_DOUBLE_EQ(front.x(), T::kWheelX[0]);
  EXPECT_NEAR(vehicle.pointPosition(0).z(), 1.5, 1e-12);
}

class OnlineVersusOffline : public ::testing::TestWithParam<dynamics::DiscretizationMethod> {};

TEST_P(OnlineVersusOffline, SameResponseAsTheSimulatorOnTheWholeTerrain) {
  const reduction::ReducedModel model = test::toyModel();
  const terrain::Terrain terrain = bump();
  const double v = 7.31;  // [m/s]: k v h stays >= 1e-5 m away from the 0.05 m grid
  OnlineVehicle online(model, test::toyGeometry(), options(GetParam()));
  for (const TerrainPatch& p : patches(terrain, 40))
    online.addTerrain(p);
  online.setSpeed(v);

  // Offline: the same simulator configuration, inputs from the whole Terrain.
  dynamics::SimulatorOptions sim;
  sim.time_step = 1.0 / kRate;
  sim.hold = dynamics::InputHold::FirstOrder;
  sim.method = GetParam();
  sim.quantities = {dynamics::OutputQuantity::Displacement, dynamics::OutputQuantity::Velocity,
                    dynamics::OutputQuantity::Acceleration};
  sim.generalized_force = model.gravity_load;
  dynamics::Simulator offline(model.system, sim);
  const Vector u0 = Vector::Zero(2);
  offline.reset(dynamics::staticEquilibrium(model.system, u0, model.gravity_load), Vector::Zero(4));
  const Vector& xq = model.system.input_stations;
  Vector w(4);
  double peak = 0.0, worst = 0.0;
  const int steps = static_cast<int>(7.0 / (v / kRate));  // front wheel to x = 8 m
  for (int k = 1; k <= steps; ++k) {
    const double s = k * v / kRate;
    for (int q = 0; q < 2; ++q) {
      w(q) = terrain.height(s + xq(q), 0.0);
      w(2 + q) = v * terrain.slope(s + xq(q), 0.0);
    }
    offline.step(w);
    ASSERT_EQ(online.step().uncovered, 0) << "step " << k;
    ASSERT_NEAR(online.station(), s, 1e-9);
    const Vector& a = online.simulator().outputs();
    const Vector& b = offline.outputs();
    peak = std::max(peak, b.segment(0, 11).cwiseAbs().maxCoeff());
    worst = std::max(worst, (a - b).segment(0, 11).cwiseAbs().maxCoeff());
  }
  EXPECT_LE(worst, kOfflineAgreement * peak) << "worst " << worst << " of peak " << peak;
  // The bump moved the hull.
  EXPECT_GT(online.comfort().weightedRms(), 0.01);
  EXPECT_GT(online.peakAcceleration(), 0.1);
  // The built-in absorbed-power filter runs in the node's meter.
  ASSERT_TRUE(online.comfort().absorbedPower().has_value());
  EXPECT_GT(*online.comfort().absorbedPower(), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Methods, OnlineVersusOffline,
                         ::testing::Values(dynamics::DiscretizationMethod::ModalDecoupled,
                                           dynamics::DiscretizationMethod::AugmentedExponential));

// The bundled vehicle has no ground damping (C_u = 0), and its ground ties' modes (9 kHz and up)
// are quasi-static at 1 kHz: they move at H Phi_t Omega_t^-2 Phi_t^T K_u u', so every contact's
// u' reaches the velocities though none reaches a force. On the out-of-phase waves at 20 km/h
// (contacts on terrain stations every 9 steps, laterally blended lines) the node's engine must
// give the offline run's velocities and accelerations, not only its displacements: with u' left
// at 0 where C_u is zero the hull's roll rate was off by 0.2 % of its peak.
TEST(OnlineVehicle, PaperVehicleVelocitiesAreTheOfflineRunsWithQuasiStaticModes) {
  const vehicle::VehicleDescription description = vehicle::loadVehicleDescription(
      std::string(TVD_SOURCE_DIR) + "/config/vehicles/paper_vehicle.yaml");
  const reduction::ReducedModel model =
      reduction::reduceVehicle(description, vehicle::Variant::Untracked, {});
  ASSERT_TRUE(model.system.input_damping.isZero(0.0));
  const OnlineVehicleOptions o = options(dynamics::DiscretizationMethod::ModalDecoupled);
  OnlineVehicle online(model, vehicleGeometry(description), o);
  ASSERT_GT(online.simulator().quasiStaticModeCount(), 0);
  const terrain::Terrain track = terrain::makeTrack("oop_waves");
  // One patch: its stations are the track's (start + k spacing). Patches of their own start
  // put a grid node an ulp away from the track's, and the station, a compensated sum within
  // ulps of k v h, then falls on either side of a node in the two (the patched buffer's cells
  // are SameResponseAsTheSimulatorOnTheWholeTerrain's to check, off the grid).
  for (const TerrainPatch& p : patches(track, static_cast<int>(track.stations().size())))
    online.addTerrain(p);
  const double v = 20.0 / 3.6;  // [m/s]
  online.setSpeed(v);

  dynamics::Simulator offline(model.system, simulatorOptions(model, o));
  const Eigen::Index n_u = model.system.inputCount();
  offline.reset(dynamics::staticEquilibrium(model.system, Vector::Zero(n_u), model.gravity_load),
                Vector::Zero(2 * n_u));
  const dynamics::RoadExcitation road(model.system.input_stations, model.system.input_lateral);
  const auto n_y = static_cast<Eigen::Index>(model.system.output_names.size());
  ASSERT_EQ(offline.outputs().size(), 3 * n_y);  // displacement, velocity, acceleration
  Vector w(2 * n_u), peak = Vector::Zero(3), worst = Vector::Zero(3);
  for (int k = 1; k * v / kRate < 20.0; ++k) {
    online.step();
    // At the node's own station: on a terrain station the slope is the cell ahead's in both,
    // and a station one rounding away would take the other cell.
    road.sample(track, online.station(), v, w);
    offline.step(w);
    const Vector& a = online.simulator().outputs();
    const Vector& b = offline.outputs();
    for (int block = 0; block < 3; ++block) {
      peak(block) = std::max(peak(block), b.segment(block * n_y, n_y).cwiseAbs().maxCoeff());
      worst(block) =
          std::max(worst(block), (a - b).segment(block * n_y, n_y).cwiseAbs().maxCoeff());
    }
  }
  for (int block = 0; block < 3; ++block)
    EXPECT_LE(worst(block), kOfflineAgreement * peak(block))
        << "block " << block << ": worst " << worst(block) << " of peak " << peak(block);
  EXPECT_GT(peak(1), 0.1);  // the waves moved it
}

TEST(OnlineVehicle, TerrainGapHoldsTheLastHeightAndStaysFinite) {
  OnlineVehicle vehicle(test::toyModel(), test::toyGeometry(),
                        options(dynamics::DiscretizationMethod::ModalDecoupled));
  TerrainPatch p;
  p.spacing = 0.1;
  p.lateral = Eigen::Vector2d(-1.0, 1.0);
  p.start_station = -2.0;
  p.heights = Matrix::Constant(2, 41, 0.05);  // -2 .. 2 m at 5 cm
  vehicle.addTerrain(p);
  vehicle.setSpeed(10.0);
  int uncovered_steps = 0;
  for (int k = 0; k < 800; ++k) {  // 8 m: the front wheel leaves the patch at station 1 m
    const StepResult r = vehicle.step();
    uncovered_steps += r.uncovered > 0;
    ASSERT_FALSE(r.diverged);
    ASSERT_TRUE(vehicle.simulator().outputs().allFinite());
  }
  EXPECT_GT(uncovered_steps, 0);
  EXPECT_DOUBLE_EQ(vehicle.sampler().held()(0), 0.05);  // last height held
}

// A model whose outputs overflow (a hull with negative damping, its motion growing e^100-fold a
// step) is reset when they do, to equilibrium where it is: on the terrain under it, 5 cm high
// here, not on flat ground, from which the next step would lift every contact 5 cm at once.
TEST(OnlineVehicle, ADivergedVehicleRestartsAtRestOnTheTerrainUnderIt) {
  reduction::ReducedModel unstable = test::toyModel();
  unstable.system.damping(0, 0) -= 1e8;  // sigma = 1e8 / (2 m) = 5e4 /s at 1 kHz
  OnlineVehicle vehicle(unstable, test::toyGeometry(),
                        options(dynamics::DiscretizationMethod::AugmentedExponential));
  TerrainPatch p;
  p.spacing = 0.1;
  p.lateral = Eigen::Vector2d(-1.0, 1.0);
  p.start_station = -2.0;
  p.heights = Matrix::Constant(2, 41, 0.05);
  vehicle.addTerrain(p);
  const Eigen::Index uz = 2;  // hull uz, the toy's output row
  const double flat = vehicle.simulator().outputs()(uz);
  vehicle.setSpeed(1.0);
  int k = 0;
  StepResult r;
  for (; k < 100 && !r.diverged; ++k)
    r = vehicle.step();
  ASSERT_TRUE(r.diverged) << "no divergence in 100 steps";
  ASSERT_TRUE(vehicle.simulator().outputs().allFinite());
  // At rest on a uniform 5 cm: the toy rigidly 5 cm above its flat-ground equilibrium, its
  // inputs the terrain's.
  EXPECT_NEAR(vehicle.simulator().outputs()(uz) - flat, 0.05, 1e-9);
  EXPECT_NEAR(vehicle.simulator().input()(0), 0.05, 1e-15);
  EXPECT_NEAR(vehicle.simulator().input()(1), 0.05, 1e-15);
  EXPECT_EQ(vehicle.speed(), 1.0);  // the speed is kept

  // Slewing: the restart is at rest, so no travel acceleration rides along with the state solved
  // without it (input w = [u; a; u'; 0]: a is entry 2 of the toy's).
  OnlineVehicleOptions slew = options(dynamics::DiscretizationMethod::AugmentedExponential);
  slew.max_acceleration = slew.max_deceleration = 1.0;
  OnlineVehicle speeding(unstable, test::toyGeometry(), slew);
  speeding.addTerrain(p);
  speeding.setSpeed(10.0);
  r = StepResult();
  for (k = 0; k < 100 && !r.diverged; ++k)
    r = speeding.step();
  ASSERT_TRUE(r.diverged) << "no divergence in 100 steps";
  EXPECT_EQ(speeding.travelAcceleration(), 0.0);
  ASSERT_EQ(speeding.simulator().input().size(), 6);
  EXPECT_EQ(speeding.simulator().input()(2), 0.0);
  EXPECT_GT(speeding.speed(), 0.0);
  EXPECT_LT(speeding.speed(), 10.0);
}

// A speed that should have applied 3 steps ago, to a vehicle at rest on level ground since:
// setSpeedSince leaves it where, and as, the steps with that speed would have (the node's late
// stamped speed from a standstill, vehicle_dynamics_node_speed.cpp); then both drive on alike,
// over the bump too. A moving or slewing vehicle is refused.
TEST(OnlineVehicle, ASpeedSinceStepsAgoFromRestIsTheOnTimeRun) {
  const reduction::ReducedModel model = test::toyModel();
  const OnlineVehicleOptions o = options(dynamics::DiscretizationMethod::ModalDecoupled);
  OnlineVehicle on_time(model, test::toyGeometry(), o), late(model, test::toyGeometry(), o);
  for (OnlineVehicle* v : {&on_time, &late})
    for (const TerrainPatch& patch : patches(bump(), 50))
      v->addTerrain(patch);
  on_time.setSpeed(4.0);
  for (int k = 0; k < 3; ++k) {
    on_time.step();
    late.step();
  }
  late.setSpeedSince(4.0, 3);
  EXPECT_EQ(late.station(), on_time.station());
  EXPECT_EQ(late.speed(), 4.0);
  double worst = 0.0;
  for (int k = 0; k < 1500; ++k) {  // 6 m, over the bump
    on_time.step();
    late.step();
    worst = std::max(worst, (late.hullDisplacement() - on_time.hullDisplacement()).norm());
  }
  EXPECT_EQ(late.station(), on_time.station());
  EXPECT_GT(on_time.hullDisplacement().norm(), 0.0);
  EXPECT_LT(worst, 1e-12);

  EXPECT_THROW(late.setSpeedSince(2.0, 1), InputError);  // moving
  OnlineVehicleOptions slewing = o;
  slewing.max_acceleration = 1.0;
  OnlineVehicle slewed(model, test::toyGeometry(), slewing);
  EXPECT_THROW(slewed.setSpeedSince(2.0, 1), InputError);
  EXPECT_EQ(slewed.commandedSpeed(), 0.0);
  OnlineVehicle standing(model, test::toyGeometry(), o);
  EXPECT_THROW(standing.setSpeedSince(2.0, -1), InputError);
  EXPECT_THROW(standing.setSpeedSince(-2.0, 1), InputError);
  EXPECT_EQ(standing.station(), 0.0);
  EXPECT_EQ(standing.commandedSpeed(), 0.0);
}

// The station is a compensated sum of the steps' advances: 360 000 steps of 20 m/s from 9.9e6 m
// (six minutes at 1 kHz) end within a few ulps of s0 + n fl(v h); the plain sum was 1.6e-4 m
// short (every addition rounded alike), 1.6 cm after ten hours.
TEST(OnlineVehicle, TheStationDoesNotDriftOverManySteps) {
  OnlineVehicle vehicle(test::toyModel(), test::toyGeometry(),
                        options(dynamics::DiscretizationMethod::ModalDecoupled));
  const double s0 = 9.9e6, v = 20.0;
  vehicle.resetTo(s0, v, ResetTerrain::Clear);
  const long n = 360000;
  for (long k = 0; k < n; ++k)
    vehicle.step();
  const long double exact =
      static_cast<long double>(s0) + n * static_cast<long double>(v * (1.0 / kRate));
  EXPECT_LE(std::abs(static_cast<long double>(vehicle.station()) - exact),
            4 * std::numeric_limits<double>::epsilon() * exact);
}

TEST(OnlineVehicle, InvalidTerrainAndSpeedAreRejectedWithoutChange) {
  OnlineVehicle vehicle(test::toyModel(), test::toyGeometry(),
                        options(dynamics::DiscretizationMethod::ModalDecoupled));
  TerrainPatch p;
  p.start_station = 0.0;
  p.spacing = 0.1;
  p.lateral = Eigen::Vector2d(-1.0, 1.0);
  p.heights = Matrix::Zero(2, 10);
  p.heights(1, 3) = std::nan("");
  EXPECT_THROW(vehicle.addTerrain(p), InputError);
  EXPECT_TRUE(vehicle.terrain().empty());
  p.heights(1, 3) = 0.0;
  p.spacing = -0.1;
  EXPECT_THROW(vehicle.addTerrain(p), InputError);
  p.spacing = 0.1;
  p.lateral = (Eigen::VectorXd(2) << 1.0, -1.0).finished();  // lateral positions decreasing
  EXPECT_THROW(vehicle.addTerrain(p), InputError);
  EXPECT_TRUE(vehicle.terrain().empty());
  vehicle.setSpeed(3.0);
  EXPECT_THROW(vehicle.setSpeed(-1.0), InputError);
  EXPECT_THROW(vehicle.setSpeed(std::numeric_limits<double>::infinity()), InputError);
  // 200 km/h is the bound, as tvd's and the node's; 30 km/h given as 30 m/s passes, 300 not.
  vehicle.setSpeed(200.0 / 3.6);
  EXPECT_THROW(vehicle.setSpeed(std::nextafter(200.0 / 3.6, 100.0)), InputError);
  vehicle.setSpeed(3.0);
  EXPECT_THROW(vehicle.setSpeed(300.0), InputError);
  EXPECT_THROW(vehicle.resetTo(0.0, 300.0, ResetTerrain::Keep), InputError);
  EXPECT_EQ(vehicle.speed(), 3.0);
}

TEST(OnlineVehicle, PatchWhollyBehindTheKeptTerrainIsReportedDropped) {
  OnlineVehicleOptions o = options(dynamics::DiscretizationMethod::ModalDecoupled);
  o.terrain_keep_behind = 2.0;
  OnlineVehicle vehicle(test::toyModel(), test::toyGeometry(), o);
  const double keep_from = vehicle.rearContactStation() - 2.0;
  TerrainPatch p;
  p.spacing = 0.1;
  p.lateral = Eigen::Vector2d(-1.0, 1.0);
  p.heights = Matrix::Constant(2, 11, 0.02);  // 1 m long
  // Ends two spacings before the kept terrain, beyond the bridged gap (1.5 spacings): dropped.
  p.start_station = keep_from - 0.2 - 1.0;
  EXPECT_FALSE(vehicle.addTerrain(p));
  EXPECT_TRUE(vehicle.terrain().empty());
  // Ending one spacing before it, it still anchors the bridge to the kept terrain: stored.
  p.start_station = keep_from - 0.1 - 1.0;
  EXPECT_TRUE(vehicle.addTerrain(p));
  EXPECT_DOUBLE_EQ(vehicle.terrain().coveredUntil(), keep_from - 0.1);
  // Straddling keep_from: stored, cut to what lies ahead.
  p.start_station = keep_from - 0.5;
  EXPECT_TRUE(vehicle.addTerrain(p));
  EXPECT_DOUBLE_EQ(vehicle.terrain().coveredUntil(), keep_from + 0.5);
}

// terrain_max_memory_mb bounds the stored terrain: a patch beyond it is refused, nothing
// changes; what lies behind the vehicle is freed before the patch is judged.
TEST(OnlineVehicle, TerrainMemoryLimitRefusesAPatchBeyondItAfterFreeingWhatLiesBehind) {
  OnlineVehicleOptions o = options(dynamics::DiscretizationMethod::ModalDecoupled);
  for (double bad : {0.5, 2e9, std::numeric_limits<double>::quiet_NaN()}) {
    o.terrain_max_memory_mb = bad;
    EXPECT_THROW(OnlineVehicle(test::toyModel(), test::toyGeometry(), o), InputError) << bad;
  }
  o.terrain_max_memory_mb = 1.0;
  OnlineVehicle vehicle(test::toyModel(), test::toyGeometry(), o);
  EXPECT_EQ(vehicle.terrain().memoryLimit(), 1000000u);
  TerrainPatch p;
  p.spacing = 0.001;
  p.lateral = Eigen::Vector2d(-1.0, 1.0);
  p.heights = Matrix::Zero(2, 30000);  // 30 m: 8 (3 x 30000 + 2) bytes = 720 kB
  p.start_station = -5.0;
  ASSERT_TRUE(vehicle.addTerrain(p));
  EXPECT_EQ(vehicle.terrain().storedBytes(), terrain::TerrainBuffer::patchBytes(2, 30000));
  p.start_station = 100.0;
  expectInputError([&] { vehicle.addTerrain(p); },
                   "720 kB with the 720 kB stored (stations -5 .. 24.999 m) exceed the terrain "
                   "buffer's limit of 1 MB");
  EXPECT_NEAR(vehicle.terrain().coveredUntil(), 24.999, 1e-9);
  EXPECT_FALSE(vehicle.terrain().covers(100.5));
  // The vehicle moved on past the first patch: it is freed before the second one is judged.
  vehicle.resetTo(60.0, 0.0, ResetTerrain::Keep);
  ASSERT_GT(vehicle.rearContactStation() - o.terrain_keep_behind, 25.0);
  EXPECT_TRUE(vehicle.addTerrain(p));
  EXPECT_EQ(vehicle.terrain().patchCount(), 1u);
  EXPECT_TRUE(vehicle.terrain().covers(100.5));
}

TEST(OnlineVehicle, UnknownOutputsAreNamed) {
  reduction::ReducedModel model = test::toyModel();
  model.system.output_names[7] = "road_wheel_left_9 uz";
  try {
    OnlineVehicle vehicle(model, test::toyGeometry());
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("road_wheel_left_2 uz"), std::string::npos) << e.what();
  }
  OnlineVehicleOptions o;
  o.comfort_point = "driver_seat";
  EXPECT_THROW(OnlineVehicle(test::toyModel(), test::toyGeometry(), o), InputError);
}

// The default comfort point is the crew seat where the vehicle has one, else the hull: a vehicle
// of one's own without a crew seat runs with default options (it used to throw, the default
// naming "crew_seat"). A point named explicitly that the vehicle lacks is refused, listing those
// it has.
TEST(OnlineVehicle, DefaultComfortPointIsTheCrewSeatWhenPresentElseTheHull) {
  EXPECT_EQ(OnlineVehicle(test::toyModel(), test::toyGeometry()).comfortPoint(), "crew_seat");
  // The toy vehicle with its point renamed, in the geometry and in the model's outputs.
  reduction::ReducedModel model = test::toyModel();
  for (std::string& name : model.system.output_names)
    if (name.rfind("crew_seat ", 0) == 0)
      name.replace(0, 9, "driver_seat");
  VehicleGeometry geometry = test::toyGeometry();
  geometry.points[0].name = "driver_seat";
  OnlineVehicle seatless(model, geometry);
  EXPECT_EQ(seatless.comfortPoint(), "hull");
  OnlineVehicleOptions o;
  o.comfort_point = "crew_seat";
  expectInputError(
      [&] { OnlineVehicle(model, geometry, o); },
      {"comfort_point: unknown point 'crew_seat' (the vehicle has: hull, driver_seat)"});
  o.comfort_point = "driver_seat";
  EXPECT_EQ(OnlineVehicle(model, geometry, o).comfortPoint(), "driver_seat");
  // The rule itself, as the node applies it before its reduction.
  EXPECT_EQ(resolveComfortPoint("", {"sensor_mount", "crew_seat"}), "crew_seat");
  EXPECT_EQ(resolveComfortPoint("", {"sensor_mount"}), "hull");
  EXPECT_EQ(resolveComfortPoint("", {}), "hull");
  EXPECT_EQ(resolveComfortPoint("hull", {"crew_seat"}), "hull");
  expectInputError([] { resolveComfortPoint("seat", {}); },
                   {"unknown point 'seat' (the vehicle has: hull)"});
}

// An index past the wheels or named points is an InputError naming it and the count (it was
// .at()'s std::out_of_range, which names neither and which the node's handlers do not catch).
TEST(OnlineVehicle, OutOfRangeWheelAndPointIndicesAreNamed) {
  const OnlineVehicle vehicle(test::toyModel(), test::toyGeometry());  // 2 wheels, 1 point
  expectInputError([&] { vehicle.wheelPosition(2); },
                   {"wheelPosition: road wheel index 2 is out of range: the vehicle has 2 road "
                    "wheels (0 .. 1)"});
  expectInputError([&] { vehicle.pointPosition(1); },
                   {"pointPosition: named point index 1 is out of range: the vehicle has 1 named "
                    "point (index 0)"});
  expectInputError([&] { vehicle.pointAcceleration(7); },
                   {"pointAcceleration: named point index 7"});
  VehicleGeometry pointless = test::toyGeometry();
  pointless.points.clear();
  expectInputError([&] { OnlineVehicle(test::toyModel(), pointless).pointPosition(0); },
                   {"pointPosition: named point index 0 is out of range: the vehicle has none"});
  expectInputError([&] { vehicle.pointIsRigid(1); }, {"pointIsRigid: named point index 1"});
  EXPECT_NO_THROW(vehicle.wheelPosition(1));
  EXPECT_NO_THROW(vehicle.pointAcceleration(0));
}

// comfort_point "hull" (the node's default for a vehicle without a crew seat): the meter reads
// the hull's vertical acceleration, sample for sample, not a named point's.
TEST(OnlineVehicle, HullComfortPointWeighsTheHullsVerticalAcceleration) {
  OnlineVehicleOptions o = options(dynamics::DiscretizationMethod::ModalDecoupled);
  o.comfort_point = "hull";
  OnlineVehicle vehicle(test::toyModel(), test::toyGeometry(), o);
  OnlineVehicle seat(test::toyModel(), test::toyGeometry(),
                     options(dynamics::DiscretizationMethod::ModalDecoupled));
  EXPECT_EQ(vehicle.comfortPoint(), "hull");
  dynamics::ComfortMeter expected(kRate);  // Wk, as the vehicle's (VDV needs no more)
  // Every axis of the seat meter: the hull's accelerations, translations and rotations.
  dynamics::SeatComfortMeter expected_seat(kRate);
  for (OnlineVehicle* v : {&vehicle, &seat}) {
    for (const TerrainPatch& p : patches(bump(), 50))
      v->addTerrain(p);
    v->setSpeed(10.0);
  }
  for (int k = 0; k < 600; ++k) {
    vehicle.step();
    seat.step();
    const Vector6 a = vehicle.hullAcceleration();
    expected.add(a(2));
    expected_seat.add({a(0), a(1), a(2), a(3), a(4), a(5)});
  }
  EXPECT_GT(expected.vibrationDoseValue(), 0.1);
  EXPECT_NEAR(vehicle.comfort().vibrationDoseValue(), expected.vibrationDoseValue(),
              1e-12 * expected.vibrationDoseValue());
  const dynamics::SeatComfortMeter& got = vehicle.seatComfort();
  EXPECT_GT(expected_seat.pitch().weightedRms(), 1e-3);
  for (const auto& [mine, theirs] : {std::pair(&got.longitudinal(), &expected_seat.longitudinal()),
                                     std::pair(&got.lateral(), &expected_seat.lateral()),
                                     std::pair(&got.roll(), &expected_seat.roll()),
                                     std::pair(&got.pitch(), &expected_seat.pitch()),
                                     std::pair(&got.yaw(), &expected_seat.yaw())})
    EXPECT_NEAR(mine->weightedRms(), theirs->weightedRms(),
                1e-12 * (theirs->weightedRms() + 1e-30));
  EXPECT_NEAR(got.seatSurfaceTotalValue(), expected_seat.seatSurfaceTotalValue(),
              1e-12 * expected_seat.seatSurfaceTotalValue());
  // The seat's rotations are the hull's; its translations are not.
  EXPECT_EQ(seat.seatComfort().pitch().weightedRms(), got.pitch().weightedRms());
  EXPECT_NE(seat.seatComfort().longitudinal().weightedRms(), got.longitudinal().weightedRms());
  // The crew seat lies ahead of the CoG: pitch makes its dose another one.
  EXPECT_GT(std::abs(seat.comfort().vibrationDoseValue() - expected.vibrationDoseValue()),
            1e-3 * expected.vibrationDoseValue());
}

TEST(OnlineVehicle, ResetReturnsToEquilibriumAtStationZero) {
  OnlineVehicle vehicle(test::toyModel(), test::toyGeometry());
  const Vector6 rest = vehicle.hullDisplacement();
  driveOverBump(vehicle, 300);
  EXPECT_GT((vehicle.hullDisplacement() - rest).norm(), 1e-4);
  vehicle.reset();
  EXPECT_EQ(vehicle.station(), 0.0);
  EXPECT_EQ(vehicle.speed(), 0.0);
  EXPECT_TRUE(vehicle.terrain().empty());
  EXPECT_NEAR((vehicle.hullDisplacement() - rest).norm(), 0.0, 1e-15);
  EXPECT_EQ(vehicle.comfort().sampleCount(), 0u);
}

// resetTo(s, v, Keep): at rest in static equilibrium on the terrain sampled at s, K q0 = f_g +
// K_u u(s), and it stays there; contacts off the terrain hold their last height; Clear: flat
// ground at s; an invalid request throws and changes nothing.
TEST(OnlineVehicle, ResetToStandsInEquilibriumOnTheTerrainAtTheStation) {
  const reduction::ReducedModel model = test::toyModel();
  OnlineVehicle vehicle(model, test::toyGeometry(),
                        options(dynamics::DiscretizationMethod::ModalDecoupled));
  const Vector6 rest = vehicle.hullDisplacement();
  driveOverBump(vehicle, 100);

  // Front contact (x = +1) on the bump's crest at 3 m, rear one (x = -1) on flat ground at 1 m.
  EXPECT_EQ(vehicle.resetTo(2.0, 0.0, ResetTerrain::Keep), 0);
  EXPECT_EQ(vehicle.station(), 2.0);
  EXPECT_EQ(vehicle.speed(), 0.0);
  EXPECT_EQ(vehicle.stepCount(), 0);
  EXPECT_EQ(vehicle.comfort().sampleCount(), 0u);
  EXPECT_FALSE(vehicle.terrain().empty());
  const Vector u = Eigen::Vector2d(0.1, 0.0);
  const Vector z0 = dynamics::staticEquilibrium(model.system, u, model.gravity_load);
  EXPECT_LT((vehicle.simulator().state() - z0).cwiseAbs().maxCoeff(), 1e-12);
  const Vector6 on_bump = vehicle.hullDisplacement();
  EXPECT_GT(on_bump(2), rest(2));  // heave up
  EXPECT_LT(on_bump(4), 0.0);      // nose up (REP-103: positive pitch is nose down)
  EXPECT_NEAR(vehicle.wheels()[0].displacement, 0.1, 1e-4);  // the tyre is stiff
  for (int k = 0; k < 200; ++k)
    vehicle.step();
  EXPECT_LT((vehicle.hullDisplacement() - on_bump).cwiseAbs().maxCoeff(), kAtRest);
  EXPECT_EQ(vehicle.station(), 2.0);

  // Off the terrain (it ends at 10 m): both contacts hold the heights they had, so the
  // equilibrium is the same.
  EXPECT_EQ(vehicle.resetTo(20.0, 0.0, ResetTerrain::Keep), 2);
  EXPECT_LT((vehicle.simulator().state() - z0).cwiseAbs().maxCoeff(), 1e-12);

  // Invalid: nothing changes.
  EXPECT_THROW(vehicle.resetTo(std::nan(""), 0.0, ResetTerrain::Clear), InputError);
  EXPECT_THROW(vehicle.resetTo(1e300, 0.0, ResetTerrain::Clear), InputError);
  EXPECT_THROW(vehicle.resetTo(-2.0 * kMaxResetStation, 0.0, ResetTerrain::Clear), InputError);
  EXPECT_THROW(vehicle.resetTo(5.0, -1.0, ResetTerrain::Clear), InputError);
  EXPECT_THROW(vehicle.resetTo(5.0, std::numeric_limits<double>::infinity(), ResetTerrain::Clear),
               InputError);
  EXPECT_EQ(vehicle.station(), 20.0);
  EXPECT_FALSE(vehicle.terrain().empty());
  EXPECT_LT((vehicle.simulator().state() - z0).cwiseAbs().maxCoeff(), 1e-12);

  // Clear: flat ground at the station, moving on at the requested speed.
  EXPECT_EQ(vehicle.resetTo(5.0, 3.0, ResetTerrain::Clear), 0);
  EXPECT_TRUE(vehicle.terrain().empty());
  EXPECT_NEAR((vehicle.hullDisplacement() - rest).norm(), 0.0, 1e-15);
  vehicle.step();
  EXPECT_NEAR(vehicle.station(), 5.0 + 3.0 / kRate, 1e-12);
  EXPECT_LT((vehicle.hullDisplacement() - rest).cwiseAbs().maxCoeff(), kAtRest);
}

// ~lateral_offset: every contact reads the terrain at y + offset. On a plane sloping across the
// path, h = a y, the toy's contacts (put at y = +-0.5 m here: the toy has them on its centre line)
// stand in static equilibrium on u_i = a (y_i + d); an offset d raises every contact by a d, so
// the vehicle stands and drives a d higher, rigidly: every wheel and the hull's heave up by a d,
// its attitude and station unchanged (the model's ground inputs moved alike are a rigid
// translation: K T = K_u 1).
TEST(OnlineVehicle, LateralOffsetReadsTheTerrainThatFarToTheLeft) {
  reduction::ReducedModel model = test::toyModel();
  model.system.input_lateral = (Vector(2) << 0.5, -0.5).finished();
  const double a = 0.1, d = 0.4;  // [m/m], [m]
  TerrainPatch plane = flatPatch(-5.0, 10.0, 0.05, 3.0);
  plane.heights.row(0).setConstant(-3.0 * a);
  plane.heights.row(1).setConstant(3.0 * a);
  OnlineVehicleOptions o = options(dynamics::DiscretizationMethod::ModalDecoupled);
  OnlineVehicle centred(model, test::toyGeometry(), o);
  o.lateral_offset = d;
  OnlineVehicle offset(model, test::toyGeometry(), o);
  for (OnlineVehicle* v : {&centred, &offset}) {
    v->addTerrain(plane);
    ASSERT_EQ(v->resetTo(0.0, 0.0, ResetTerrain::Keep), 0);
  }
  for (const auto& [vehicle, shift] : {std::pair<OnlineVehicle*, double>{&centred, 0.0},
                                       std::pair<OnlineVehicle*, double>{&offset, d}}) {
    const Vector u = a * (model.system.input_lateral.array() + shift).matrix();
    const Vector z0 = dynamics::staticEquilibrium(model.system, u, model.gravity_load);
    EXPECT_LT((vehicle->simulator().state() - z0).cwiseAbs().maxCoeff(), 1e-12) << shift;
    vehicle->setSpeed(5.0);
  }
  Vector6 rise = Vector6::Zero();
  rise(2) = a * d;
  for (int k = 0; k <= 500; ++k) {
    ASSERT_EQ(offset.station(), centred.station());
    EXPECT_LT((offset.hullDisplacement() - centred.hullDisplacement() - rise).cwiseAbs().maxCoeff(),
              1e-12)
        << "step " << k;
    ASSERT_EQ(offset.wheels().size(), centred.wheels().size());
    for (std::size_t i = 0; i < centred.wheels().size(); ++i)
      EXPECT_NEAR(offset.wheels()[i].displacement - centred.wheels()[i].displacement, a * d, 1e-12)
          << "wheel " << i << ", step " << k;
    centred.step();
    offset.step();
  }
  EXPECT_GT(offset.station(), 2.0);
}

// resetTo(s, v > 0, Keep): the first step interpolates from w = [u; u'] with u' = v dh/dx, as a
// step at s samples it, and the state is the equilibrium on u alone (q0' = 0). The front contact
// (x = +1) at 2.525 m is mid-cell on the bump's rising flank: bilinear, u = the mean of the
// samples at 2.5 and 2.55 m and dh/dx = their difference / 0.05 m; the rear one is on flat ground.
TEST(OnlineVehicle, ResetToAtASpeedStartsFromTheSampledInputRate) {
  const reduction::ReducedModel model = test::toyModel();
  OnlineVehicle vehicle(model, test::toyGeometry(),
                        options(dynamics::DiscretizationMethod::ModalDecoupled));
  for (const TerrainPatch& p : patches(bump(), 50))
    vehicle.addTerrain(p);
  const double v = 4.0;  // [m/s]
  const auto h = [](double x) { return 0.05 * (1.0 - std::cos(M_PI * (x - 2.0))); };
  EXPECT_EQ(vehicle.resetTo(1.525, v, ResetTerrain::Keep), 0);
  const Vector& w = vehicle.simulator().input();
  ASSERT_EQ(w.size(), 4);
  const double rate = v * (h(2.55) - h(2.5)) / 0.05;
  ASSERT_GT(rate, 0.5);  // [m/s]: a sampler that dropped u' fails below
  EXPECT_NEAR(w(0), 0.5 * (h(2.5) + h(2.55)), 1e-12);
  EXPECT_NEAR(w(1), 0.0, 1e-12);
  EXPECT_NEAR(w(2), rate, 1e-8);  // central difference of +-1e-6 m: rounding / 2e-6
  EXPECT_NEAR(w(3), 0.0, 1e-12);
  const Vector z0 = dynamics::staticEquilibrium(model.system, w.head(2), model.gravity_load);
  EXPECT_LT((vehicle.simulator().state() - z0).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(vehicle.speed(), v);
}

TEST(OnlineVehicle, PointAccelerationIsTheHullsRigidMotionAtThePoint) {
  // The toy's crew seat rows are the hull's rigid motion (no elastic part), so the acceleration
  // the node's imu/<point> reads, less gravity, is the exact rigid-body acceleration of the point
  // from the hull's rows (vehicle_frames.h; checked there against the published pose).
  const reduction::ReducedModel model = test::toyModel();
  OnlineVehicle vehicle(model, test::toyGeometry(),
                        options(dynamics::DiscretizationMethod::ModalDecoupled));
  double peak = 0.0, worst = 0.0, centripetal = 0.0;
  for (const TerrainPatch& p : patches(bump(), 50))
    vehicle.addTerrain(p);
  vehicle.setSpeed(10.0);
  const Vector3 point = vehicle.geometry().points[0].position;
  const Vector3 arm = point - vehicle.geometry().cog;
  for (int k = 0; k < 600; ++k) {
    vehicle.step();
    const Vector6 u = vehicle.hullDisplacement(), du = vehicle.hullVelocity();
    const Vector6 a = vehicle.hullAcceleration();
    const Vector3 rigid = rigidPointAcceleration(vehicle.geometry().cog, u, du, a, point);
    peak = std::max(peak, rigid.norm());
    worst = std::max(worst, (vehicle.pointAcceleration(0) - rigid).norm());
    // How far the exact rigid motion is from the linear model's u_G'' + theta'' x r.
    centripetal = std::max(centripetal, (rigid - (a.head<3>() + a.tail<3>().cross(arm))).norm());
  }
  EXPECT_GT(peak, 1.0);  // the bump shook the seat
  EXPECT_LE(worst, 1e-9 * peak);
  EXPECT_GT(centripetal, 1e-6 * peak);  // the exact kinematics is not the linear one
}

namespace {

OnlineVehicleOptions slewing(double max_acceleration, double max_deceleration) {
  OnlineVehicleOptions o = options(dynamics::DiscretizationMethod::ModalDecoupled);
  o.max_acceleration = max_acceleration;
  o.max_deceleration = max_deceleration;
  return o;
}

}  // namespace

TEST(OnlineVehicle, WithoutSlewASpeedAppliesAtOnceWithoutTravelInertia) {
  OnlineVehicle vehicle(test::toyModel(), test::toyGeometry(), slewing(0.0, 0.0));
  EXPECT_FALSE(vehicle.slews());
  EXPECT_EQ(vehicle.simulator().inputCount(), 4);  // [u; u'] of the two contacts
  vehicle.setSpeed(10.0);
  EXPECT_EQ(vehicle.speed(), 10.0);
  vehicle.step();
  EXPECT_EQ(vehicle.travelAcceleration(), 0.0);
  EXPECT_DOUBLE_EQ(vehicle.station(), 10.0 / kRate);
}

TEST(OnlineVehicle, SlewReachesTheCommandedSpeedAlongUniformlyAcceleratedMotion) {
  constexpr double kAccel = 2.0, kDecel = 4.0;  // [m/s^2]
  OnlineVehicle vehicle(test::toyModel(), test::toyGeometry(), slewing(kAccel, kDecel));
  EXPECT_TRUE(vehicle.slews());
  EXPECT_EQ(vehicle.simulator().inputCount(), 6);  // [u; a; u'; 0]
  vehicle.addTerrain(flatPatch(-5.0, 195.0, 0.5, 1.0));
  const double h = 1.0 / kRate;
  // 0 -> 10 m/s at 2 m/s^2: 5 s = 5000 steps, s = a t^2 / 2.
  vehicle.setSpeed(10.0);
  EXPECT_EQ(vehicle.speed(), 0.0);  // from the next step on
  EXPECT_EQ(vehicle.commandedSpeed(), 10.0);
  const long rise = std::lround(10.0 / kAccel / h);
  for (long k = 1; k <= rise; ++k) {
    vehicle.step();
    const double t = k * h;
    ASSERT_NEAR(vehicle.speed(), std::min(kAccel * t, 10.0), 1e-9) << k;
    ASSERT_NEAR(vehicle.station(), 0.5 * kAccel * t * t, 1e-9) << k;
    ASSERT_NEAR(vehicle.travelAcceleration(), kAccel, 1e-6) << k;
  }
  // Reached at |dv| / a_max (to rounding: the last step may leave 1e-12 m/s to the next one),
  // then held exactly.
  EXPECT_NEAR(vehicle.speed(), 10.0, 1e-9);
  vehicle.step();
  EXPECT_EQ(vehicle.speed(), 10.0);
  EXPECT_NEAR(vehicle.travelAcceleration(), 0.0, 1e-6);
  EXPECT_NEAR(vehicle.station(), 25.0 + 10.0 * h, 1e-9);
  vehicle.step();
  EXPECT_EQ(vehicle.travelAcceleration(), 0.0);
  // 10 -> 2 m/s at 4 m/s^2: 2 s, s = s_0 + v_0 t - d t^2 / 2.
  const double s0 = vehicle.station();
  vehicle.setSpeed(2.0);
  const long fall = std::lround(8.0 / kDecel / h);
  for (long k = 1; k <= fall; ++k) {
    vehicle.step();
    const double t = k * h;
    ASSERT_NEAR(vehicle.speed(), 10.0 - kDecel * t, 1e-9) << k;
    ASSERT_NEAR(vehicle.station(), s0 + 10.0 * t - 0.5 * kDecel * t * t, 1e-9) << k;
    ASSERT_NEAR(vehicle.travelAcceleration(), -kDecel, 1e-6) << k;
  }
  EXPECT_NEAR(vehicle.speed(), 2.0, 1e-9);
  vehicle.step();
  EXPECT_EQ(vehicle.speed(), 2.0);
  // reset_to sets the speed at once, at rest relative to it (a = 0).
  vehicle.resetTo(3.0, 7.0, ResetTerrain::Keep);
  EXPECT_EQ(vehicle.speed(), 7.0);
  EXPECT_EQ(vehicle.commandedSpeed(), 7.0);
  EXPECT_EQ(vehicle.travelAcceleration(), 0.0);
  vehicle.step();
  EXPECT_EQ(vehicle.speed(), 7.0);
  EXPECT_EQ(vehicle.travelAcceleration(), 0.0);
}

TEST(OnlineVehicle, OneSlewRateSetBoundsBothDirections) {
  for (const auto& [accel, decel] : {std::pair<double, double>{3.0, 0.0}, {0.0, 3.0}}) {
    OnlineVehicle vehicle(test::toyModel(), test::toyGeometry(), slewing(accel, decel));
    EXPECT_TRUE(vehicle.slews());
    vehicle.setSpeed(6.0);
    vehicle.step();
    EXPECT_NEAR(vehicle.travelAcceleration(), 3.0, 1e-9);
    vehicle.resetTo(0.0, 6.0, ResetTerrain::Clear);
    vehicle.setSpeed(0.0);
    vehicle.step();
    EXPECT_NEAR(vehicle.travelAcceleration(), -3.0, 1e-9);
  }
  EXPECT_THROW(OnlineVehicle(test::toyModel(), test::toyGeometry(), slewing(-1.0, 0.0)),
               InputError);
  EXPECT_THROW(OnlineVehicle(test::toyModel(), test::toyGeometry(), slewing(0.0, NAN)), InputError);
  reduction::ReducedModel without = test::toyModel();
  without.travel_load.resize(0);
  EXPECT_THROW(OnlineVehicle(without, test::toyGeometry(), slewing(1.0, 1.0)), InputError);
  EXPECT_NO_THROW(OnlineVehicle(without, test::toyGeometry(), slewing(0.0, 0.0)));
}

TEST(OnlineVehicle, ConstantBrakingPitchesToTheStaticValueAndTheImuReadsTheBraking) {
  // 0.3 g from 20 m/s on flat ground: 6.8 s of braking; the toy's damped pitch settles within 2 s.
  constexpr double kBraking = 0.3 * kStandardGravity;
  const reduction::ReducedModel model = test::toyModel();
  OnlineVehicle vehicle(model, test::toyGeometry(), slewing(1.0, kBraking));
  vehicle.addTerrain(flatPatch(-5.0, 195.0, 0.5, 1.0));
  vehicle.resetTo(0.0, 20.0, ResetTerrain::Keep);
  const Vector6 rest = vehicle.hullDisplacement();
  vehicle.setSpeed(0.0);
  for (int k = 0; k < 6000; ++k)
    vehicle.step();
  ASSERT_NEAR(vehicle.travelAcceleration(), -kBraking, 1e-6);
  // Static pitch: K q = f_a a (u = 0); the hull's row of H picks theta.
  const Vector q = model.system.stiffness.ldlt().solve(model.travel_load * -kBraking);
  const double pitch = (model.system.output * q)(4);
  EXPECT_GT(pitch, 0.0);  // nose down (REP-103)
  EXPECT_NEAR(vehicle.hullDisplacement()(4) - rest(4), pitch, 1e-2 * pitch);
  // The IMU at the crew seat: the point's acceleration in odom is the braking itself (settled),
  // and its specific force in the hull's axes f = R^T (a - g) reads, with the hull pitched by
  // theta about y, f_x = a cos(theta) - g sin(theta), f_z = a sin(theta) + g cos(theta).
  const Vector3 acceleration = vehicle.pointAcceleration(0);
  EXPECT_NEAR(acceleration.x(), -kBraking, 1e-3 * kBraking);
  EXPECT_NEAR(acceleration.z(), 0.0, 1e-3 * kBraking);
  const double theta = vehicle.hullDisplacement()(4);
  const Vector3 f = specificForce(vehicle.hullPose().rotation, acceleration);
  EXPECT_NEAR(f.x(), -kBraking * std::cos(theta) - kStandardGravity * std::sin(theta),
              1e-3 * kBraking);
  EXPECT_NEAR(f.z(), -kBraking * std::sin(theta) + kStandardGravity * std::cos(theta),
              1e-3 * kBraking);
  EXPECT_LT(f.x(), -kBraking);  // the nose-down pitch adds gravity's share to the braking
  // Stopped: the acceleration ends and the pitch returns.
  for (int k = 0; k < 4000; ++k)
    vehicle.step();
  EXPECT_EQ(vehicle.speed(), 0.0);
  EXPECT_EQ(vehicle.travelAcceleration(), 0.0);
  EXPECT_NEAR(vehicle.hullDisplacement()(4), rest(4), 1e-2 * pitch);
}

TEST(OnlineVehicle, BrakingPaperVehicleSettlesToTheReducedModelsStaticPitch) {
  // The bundled vehicle (un-tracked, reduced as the node reduces it) braking at 1 m/s^2 from
  // 25 m/s for 20 s on flat ground: its hull pitch settles to a H K_R^-1 travel_load, the steady
  // value of tvd simulate and test_travel_inertia (5 % modal damping: the onset's transient is
  // below 0.1 % after 20 s), nose down.
  const vehicle::VehicleDescription description = vehicle::loadVehicleDescription(
      std::string(TVD_SOURCE_DIR) + "/config/vehicles/paper_vehicle.yaml");
  const reduction::ReducedModel model =
      reduction::reduceVehicle(description, vehicle::Variant::Untracked, {});
  constexpr double kBraking = 1.0;  // [m/s^2]
  OnlineVehicle vehicle(model, vehicleGeometry(description), slewing(1.0, kBraking));
  vehicle.addTerrain(flatPatch(-10.0, 389.0, 1.0, 3.0));  // 400 samples
  vehicle.resetTo(0.0, 25.0, ResetTerrain::Keep);
  const double rest = vehicle.hullDisplacement()(4);
  vehicle.setSpeed(0.0);
  for (int k = 0; k < 20000; ++k)
    ASSERT_EQ(vehicle.step().uncovered, 0) << k;
  ASSERT_NEAR(vehicle.travelAcceleration(), -kBraking, 1e-6);
  const auto& names = model.system.output_names;
  const auto ry = std::find(names.begin(), names.end(), "hull ry") - names.begin();
  const double pitch = -kBraking * (model.system.output *
                                    model.system.stiffness.ldlt().solve(model.travel_load))(ry);
  EXPECT_GT(pitch, 0.0);  // nose down
  EXPECT_NEAR(vehicle.hullDisplacement()(4) - rest, pitch, 1e-2 * pitch);
  // Settled, the crew seat's accelerometer reads the braking along the path's x.
  EXPECT_NEAR(vehicle.pointAcceleration(0).x(), -kBraking, 1e-2 * kBraking);
}

TEST(OnlineVehicle, DampedGroundTiesIntegratedDynamicallyAreSaid) {
  // The bundled vehicle's 2e10 N/m ground ties make modes at 9.1 kHz and up, which its 5 % modal
  // damping holds to an inertial frame (dynamics/ground_tie_damping.h): quasi-static under the
  // default cut-off (rate / 2), dynamic with the exact method or a cut-off above them.
  const vehicle::VehicleDescription description = vehicle::loadVehicleDescription(
      std::string(TVD_SOURCE_DIR) + "/config/vehicles/paper_vehicle.yaml");
  const reduction::ReducedModel model =
      reduction::reduceVehicle(description, vehicle::Variant::Untracked, {});
  OnlineVehicleOptions o = options(dynamics::DiscretizationMethod::ModalDecoupled);
  EXPECT_EQ(OnlineVehicle(model, vehicleGeometry(description), o).groundTieDampingWarning(), "");
  o.max_mode_frequency_hz = 5000.0;
  EXPECT_EQ(OnlineVehicle(model, vehicleGeometry(description), o).groundTieDampingWarning(), "");
  o.max_mode_frequency_hz = 0.0;
  const std::string all =
      OnlineVehicle(model, vehicleGeometry(description), o).groundTieDampingWarning();
  EXPECT_NE(all.find("the ground-tie modes (9139 to 58125 Hz"), std::string::npos) << all;
  EXPECT_NE(all.find("max_mode_frequency 0 keeps every mode dynamic"), std::string::npos) << all;
  const std::string exact =
      OnlineVehicle(model, vehicleGeometry(description),
                    options(dynamics::DiscretizationMethod::AugmentedExponential))
          .groundTieDampingWarning();
  EXPECT_NE(exact.find("method exact integrates every mode"), std::string::npos) << exact;
  // The toy's tyres hop at 10.8 Hz, a ride mode the step resolves, and are damped relative to
  // the road: nothing to say.
  EXPECT_EQ(OnlineVehicle(test::toyModel(), test::toyGeometry(),
                          options(dynamics::DiscretizationMethod::AugmentedExponential))
                .groundTieDampingWarning(),
            "");
}

// The toy's crew seat (outputs u_G + theta x r) is rigid with the hull, and a wheel centre keeps
// its base_link x and y while the hull pitches (only its uz is a model output).
TEST(OnlineVehicle, RigidPointsAndWheelCentresStayWhereTheGeometryPutsThem) {
  OnlineVehicle vehicle(test::toyModel(), test::toyGeometry(),
                        options(dynamics::DiscretizationMethod::ModalDecoupled));
  EXPECT_TRUE(vehicle.pointIsRigid(0));
  driveOverBump(vehicle, 300);
  EXPECT_GT(std::abs(vehicle.hullDisplacement()(4)), 1e-4);  // pitched
  for (std::size_t i = 0; i < vehicle.geometry().wheels.size(); ++i) {
    const Vector3 at = vehicle.wheelPosition(i), rest = vehicle.geometry().wheels[i].position;
    EXPECT_EQ(at.x(), rest.x()) << i;
    EXPECT_EQ(at.y(), rest.y()) << i;
  }
}

// peakAcceleration() is the largest |vertical acceleration| at the comfort point: over a bump
// and over a dip alike (a dip's largest is downward). The toy's crew seat at r = (0.5, 0.3, .)
// from the CoG, with no roll: a_z = a_Gz - 0.5 theta_y''.
TEST(OnlineVehicle, PeakAccelerationIsTheLargestMagnitudeUpOrDown) {
  for (const double amplitude : {0.05, -0.05}) {
    SCOPED_TRACE(amplitude);
    OnlineVehicle vehicle(test::toyModel(), test::toyGeometry(),
                          options(dynamics::DiscretizationMethod::ModalDecoupled));
    TerrainPatch bump = flatPatch(-5.0, 15.0, 0.05, 1.0);
    for (Eigen::Index j = 0; j < bump.heights.cols(); ++j) {
      const double x = -5.0 + 0.05 * static_cast<double>(j);
      if (x > 2.0 && x < 2.5)
        bump.heights.col(j).setConstant(amplitude * std::sin(kPi * (x - 2.0) / 0.5));
    }
    vehicle.addTerrain(bump);
    vehicle.setSpeed(5.0);
    double peak = 0.0;
    for (int k = 0; k < 1200; ++k) {
      vehicle.step();
      const Vector6 a = vehicle.hullAcceleration();
      peak = std::max(peak, std::abs(a(2) - 0.5 * a(4)));
    }
    EXPECT_GT(peak, 1.0);
    EXPECT_NEAR(vehicle.peakAcceleration(), peak, 1e-12 * peak);
  }
}

// The road rate u' = v dh/dx at the first covered station (nothing behind it: its cell's slope)
// and at the last station of a flat run, where the rise ahead starts: the cell ahead, also when
// the run's cached heights served the step before.
TEST(RoadInputSampler, RateAtTheEdgeOfCoverageAndAtTheEndOfAFlatRun) {
  Vector w(2);
  terrain::TerrainBuffer ramp;
  Matrix rising(2, 11);
  for (int j = 0; j <= 10; ++j)
    rising.col(j).setConstant(0.01 * j);  // 0.1 m/m from station 0
  ramp.addPatch(0.0, 0.1, Eigen::Vector2d(-1.0, 1.0), rising);
  RoadInputSampler at_edge(Vector::Zero(1), Vector::Zero(1));
  at_edge.sample(ramp, 0.0, 4.0, 0.0, &w);
  EXPECT_NEAR(w(1), 0.4, 1e-6);

  terrain::TerrainBuffer flat_then_ramp;
  Matrix heights(2, 101);
  for (int j = 0; j <= 100; ++j)
    heights.col(j).setConstant(j <= 50 ? 0.0 : 0.01 * (j - 50));  // flat to 5 m, then 0.1 m/m
  flat_then_ramp.addPatch(0.0, 0.1, Eigen::Vector2d(-1.0, 1.0), heights);
  RoadInputSampler sampler(Vector::Zero(1), Vector::Zero(1));
  sampler.sample(flat_then_ramp, 2.0, 4.0, 0.0, &w);  // inside the flat run: u' = 0
  EXPECT_EQ(w(1), 0.0);
  sampler.sample(flat_then_ramp, 5.0, 4.0, 0.0, &w);  // its last station: the cell ahead, 0.1
  EXPECT_NEAR(w(1), 0.4, 1e-12);
  // The same through the flat run's shortcut: in the run, then at its end.
  RoadInputSampler through_run(Vector::Zero(1), Vector::Zero(1));
  through_run.sample(flat_then_ramp, 4.9, 4.0, 0.0, &w);
  EXPECT_EQ(w(1), 0.0);
  through_run.sample(flat_then_ramp, 5.0, 4.0, 0.0, &w);
  EXPECT_NEAR(w(1), 0.4, 1e-12);
  // Without u' (a model that uses none) the run's last station is still the run's height.
  RoadInputSampler heights_only(Vector::Zero(1), Vector::Zero(1), {false});
  heights_only.sample(flat_then_ramp, 4.9, 4.0, 0.0, &w);
  heights_only.sample(flat_then_ramp, 5.0, 4.0, 0.0, &w);
  EXPECT_EQ(w(0), 0.0);
  EXPECT_EQ(w(1), 0.0);
}

// Where patches meet, u' is the slope of the cell ahead in whatever grid answers there, never a
// difference across two grids: a newer patch 1 mm above an older one, ending at the contact,
// once gave u' = -1e-3 m / 1e-6 m * v = -1e4 m/s, a one-step spike of 0.13 m/s in the bundled
// vehicle's hull velocity. At the end of coverage u' = 0 (Terrain::slope() at a terrain's end);
// on a grid's first station its cell's slope exactly, whatever the datum; and a contact moved back
// onto the station that starts a sloped cell gets that station's height, not the one held from
// inside the cell.
TEST(RoadInputSampler, RateAcrossPatchesIsTheCellAheadNeverAStep) {
  Vector w(2);
  const Eigen::Vector2d lines(-1.0, 1.0);
  terrain::TerrainBuffer stepped;
  stepped.addPatch(0.0, 0.5, lines, Matrix::Zero(2, 21));           // 0 .. 10 m, flat
  stepped.addPatch(3.0, 0.5, lines, Matrix::Constant(2, 7, 1e-3));  // newer: 3 .. 6 m, 1 mm up
  RoadInputSampler sampler(Vector::Zero(1), Vector::Zero(1));
  for (const double x : {5.999999, 6.0, 6.000001}) {
    sampler.sample(stepped, x, 10.0, 0.0, &w);
    EXPECT_EQ(w(1), 0.0) << x;
  }
  terrain::TerrainBuffer behind;  // a patch re-sent behind an older one ahead of it
  behind.addPatch(10.0, 0.5, lines, Matrix::Constant(2, 5, 1e-3));
  behind.addPatch(0.0, 0.5, lines, Matrix::Zero(2, 21));
  sampler.sample(behind, 10.0, 10.0, 0.0, &w);
  EXPECT_EQ(w(1), 0.0);
  // A newer patch ending inside an older one where that one rises: the older grid's cell ahead,
  // times the speed (0.1 m/m at 10 m/s).
  Matrix rise(2, 21);  // 0 .. 10 m: flat to 6 m, then 0.1 m/m
  for (int j = 0; j <= 20; ++j)
    rise.col(j).setConstant(j <= 12 ? 0.0 : 0.05 * (j - 12));
  terrain::TerrainBuffer rising;
  rising.addPatch(0.0, 0.5, lines, rise);
  rising.addPatch(3.0, 0.5, lines, Matrix::Zero(2, 7));  // newer: 3 .. 6 m, flat
  RoadInputSampler onto_rise(Vector::Zero(1), Vector::Zero(1));
  onto_rise.sample(rising, 6.0, 10.0, 0.0, &w);
  EXPECT_NEAR(w(1), 10.0 * 0.1, 1e-9);

  // The end of coverage: 0, 0, 0.1 on stations 0, 1, 2.
  Matrix end(2, 3);
  end << 0.0, 0.0, 0.1, 0.0, 0.0, 0.1;
  terrain::TerrainBuffer ends;
  ends.addPatch(0.0, 1.0, lines, end);
  const terrain::Terrain whole(Eigen::Vector3d(0.0, 1.0, 2.0), lines, end, "end");
  RoadInputSampler at_end(Vector::Zero(1), Vector::Zero(1));
  at_end.sample(ends, 2.0, 10.0, 0.0, &w);
  EXPECT_EQ(w(1), 10.0 * whole.slope(2.0, 0.0));
  EXPECT_EQ(w(1), 0.0);

  // A grid's first station, far from the origin and the datum: the cell's slope, exactly.
  Matrix high(2, 3);
  high << 1000.0, 1000.1, 1000.2, 1000.0, 1000.1, 1000.2;
  terrain::TerrainBuffer far;
  far.addPatch(1e7, 1.0, lines, high);
  const terrain::Terrain far_grid(Eigen::Vector3d(1e7, 1e7 + 1.0, 1e7 + 2.0), lines, high, "far");
  EXPECT_EQ(far_grid.stationWeightOf(1e7).edge, 0);
  EXPECT_EQ(far_grid.slope(far_grid.stationWeightOf(1e7), far_grid.lateralCellOf(0.0)),
            far_grid.slope(1e7, 0.0));
  RoadInputSampler first(Vector::Zero(1), Vector::Zero(1));
  first.sample(far, 1e7, 1.0, 0.0, &w);
  EXPECT_EQ(w(0), 1000.0);
  EXPECT_EQ(w(1), far_grid.slope(1e7, 0.0));

  // Heights only (no u'): inside the sloped cell [1, 2] m, then back onto its station 1 m.
  Matrix ramp(2, 4);
  ramp << 0.0, 0.1, 0.3, 0.6, 0.0, 0.1, 0.3, 0.6;
  terrain::TerrainBuffer ramps;
  ramps.addPatch(0.0, 1.0, lines, ramp);
  RoadInputSampler heights(Vector::Zero(1), Vector::Zero(1), {false});
  heights.sample(ramps, 1.5, 1.0, 0.0, &w);
  EXPECT_DOUBLE_EQ(w(0), 0.2);
  heights.sample(ramps, 1.0, 1.0, 0.0, &w);
  EXPECT_EQ(w(0), 0.1);
}

TEST(OnlineVehicle, PointAccelerationAddsTheModelsElasticPart) {
  // A crew seat that also follows the front wheel by 0.3 of its travel (a seat on a flexible
  // mount, say): its acceleration is the hull's exact rigid motion plus 0.3 of the wheel's.
  reduction::ReducedModel model = test::toyModel();
  const auto& names = model.system.output_names;
  const auto row = std::find(names.begin(), names.end(), "crew_seat uz") - names.begin();
  model.system.output(row, 2) = 0.3;  // state 2: the front wheel's vertical displacement
  OnlineVehicle vehicle(model, test::toyGeometry(),
                        options(dynamics::DiscretizationMethod::ModalDecoupled));
  EXPECT_FALSE(vehicle.pointIsRigid(0));
  for (const TerrainPatch& p : patches(bump(), 50))
    vehicle.addTerrain(p);
  vehicle.setSpeed(10.0);
  const Vector3 point = vehicle.geometry().points[0].position;
  double peak = 0.0, worst = 0.0;
  for (int k = 0; k < 600; ++k) {
    vehicle.step();
    const Vector3 rigid =
        rigidPointAcceleration(vehicle.geometry().cog, vehicle.hullDisplacement(),
                               vehicle.hullVelocity(), vehicle.hullAcceleration(), point);
    const Vector3 expected = rigid + Vector3(0.0, 0.0, 0.3 * vehicle.wheels()[0].acceleration);
    peak = std::max(peak, 0.3 * std::abs(vehicle.wheels()[0].acceleration));
    worst = std::max(worst, (vehicle.pointAcceleration(0) - expected).norm());
  }
  EXPECT_GT(peak, 1.0);  // the elastic part is there
  EXPECT_LE(worst, 1e-9 * peak);
}

TEST(OnlineVehicle, GroundContactWatchSeesTheTyresLeaveTheRoad) {
  // The toy's tyres are its ground contacts: F_i = k_t (u_i - z_i) + c_t (u_i' - z_i'). At rest
  // they carry the weight; driven at 15 m/s over the 0.1 m bump (0.13 s long, near the wheels'
  // 10.8 Hz hop) a wheel leaves the road, which the watch must see at the step where the forces,
  // recomputed here from the simulator's state, first pull.
  using T = test::ToyVehicle;
  OnlineVehicle vehicle(test::toyModel(), test::toyGeometry(),
                        options(dynamics::DiscretizationMethod::ModalDecoupled));
  dynamics::GroundContactWatch* watch = vehicle.groundContactWatch();
  ASSERT_NE(watch, nullptr) << vehicle.groundContactUnavailable();
  ASSERT_EQ(watch->contactCount(), 2);
  EXPECT_EQ(watch->pullingAtRest(), 0);
  const double weight = (T::kHullMass + 2.0 * T::kWheelMass) * kStandardGravity;
  EXPECT_NEAR(watch->forces().sum(), weight, 1e-9 * weight);
  EXPECT_NEAR(watch->forces()(0), watch->forces()(1), 1e-9 * weight);  // CoG midway

  for (const TerrainPatch& p : patches(bump(), 50))
    vehicle.addTerrain(p);
  vehicle.setSpeed(15.0);
  double first_pull = NAN, first_station = NAN, min_force = INFINITY;
  long pulls = 0;
  for (int k = 0; k < 600; ++k) {
    vehicle.step();
    vehicle.checkGroundContact();
    const Vector z = vehicle.simulator().state();
    const Vector& w = vehicle.simulator().input();
    for (int i = 0; i < 2; ++i) {
      const double f = T::kTyre * (w(i) - z(2 + i)) + T::kTyreDamping * (w(2 + i) - z(4 + 2 + i));
      ASSERT_NEAR(watch->forces()(i), f, 1e-9 * weight) << k;
      min_force = std::min(min_force, f);
    }
    const int pulling = (watch->forces().array() < 0.0).count();
    EXPECT_EQ(watch->now().pulling, pulling);
    pulls += pulling > 0;
    if (pulling > 0 && std::isnan(first_pull)) {
      first_pull = vehicle.time();
      first_station = vehicle.station();
    }
  }
  ASSERT_GT(pulls, 0) << "the bump should lift a wheel (min force " << min_force << " N)";
  const dynamics::GroundContactRecord& run = watch->sinceRestart();
  EXPECT_EQ(run.checks, 600);
  EXPECT_EQ(run.checks_beyond, pulls);
  EXPECT_DOUBLE_EQ(run.first_beyond_time, first_pull);
  EXPECT_DOUBLE_EQ(run.first_beyond_station, first_station);
  EXPECT_DOUBLE_EQ(run.min_force, min_force);
  EXPECT_EQ(watch->takeInterval().checks_beyond, pulls);

  // A reset restarts the record from the new rest.
  vehicle.reset();
  EXPECT_EQ(watch->sinceRestart().checks, 0);
  EXPECT_FALSE(watch->sinceRestart().beyondRange());
  EXPECT_NEAR(watch->forces().sum(), weight, 1e-9 * weight);
}

TEST(OnlineVehicle, ContactGroupsMakeTheWatchsPads) {
  // Both tyres as one pad: its force is their sum (the weight at rest), and it pulls only when
  // the sum does, at the same checks the recomputed forces say.
  OnlineVehicle vehicle(test::toyModel(), test::toyGeometry(),
                        options(dynamics::DiscretizationMethod::ModalDecoupled), {0, 0});
  dynamics::GroundContactWatch* watch = vehicle.groundContactWatch();
  ASSERT_NE(watch, nullptr) << vehicle.groundContactUnavailable();
  ASSERT_EQ(watch->groupCount(), 1);
  EXPECT_NEAR(watch->groupForces()(0), watch->forces().sum(), 1e-12 * watch->forces().sum());
  for (const TerrainPatch& p : patches(bump(), 50))
    vehicle.addTerrain(p);
  vehicle.setSpeed(15.0);
  long sole_pulls = 0, pad_pulls = 0;
  for (int k = 0; k < 600; ++k) {
    vehicle.step();
    vehicle.checkGroundContact();
    const double total = watch->forces().sum();
    EXPECT_NEAR(watch->groupForces()(0), total, 1e-9 * std::abs(total) + 1e-6) << k;
    EXPECT_EQ(watch->now().groups_pulling, total < 0.0 ? 1 : 0) << k;
    sole_pulls += watch->now().pulling > 0;
    pad_pulls += total < 0.0;
  }
  EXPECT_GT(sole_pulls, 0);
  EXPECT_EQ(watch->sinceRestart().checks_groups_beyond, pad_pulls);
  EXPECT_LE(pad_pulls, sole_pulls);  // a pad pulls only when a sole does

  // Each tyre a pad of its own (the second given none: watched as its own pad): a pad pulls
  // exactly when its tyre does, at the same checks.
  OnlineVehicle single(test::toyModel(), test::toyGeometry(),
                       options(dynamics::DiscretizationMethod::ModalDecoupled), {0, -1});
  dynamics::GroundContactWatch* own = single.groundContactWatch();
  ASSERT_NE(own, nullptr);
  ASSERT_EQ(own->groupCount(), 2);
  for (const TerrainPatch& p : patches(bump(), 50))
    single.addTerrain(p);
  single.setSpeed(15.0);
  long tyre_pulls = 0;
  for (int k = 0; k < 600; ++k) {
    single.step();
    single.checkGroundContact();
    EXPECT_EQ(own->now().groups_pulling, own->now().pulling) << k;
    tyre_pulls += own->now().pulling > 0;
  }
  EXPECT_GT(tyre_pulls, 0);
  EXPECT_EQ(own->sinceRestart().checks_groups_beyond, tyre_pulls);
  EXPECT_EQ(own->sinceRestart().first_group_beyond_time, own->sinceRestart().first_beyond_time);

  expectInputError(
      [] { OnlineVehicle(test::toyModel(), test::toyGeometry(), {}, std::vector<int>{0}); },
      "1 contact groups for 2 road inputs");
}

TEST(OnlineVehicle, GroundContactWatchSaysWhyAModelCannotBeChecked) {
  // A road input that acts on two coordinates is no ground spring: the vehicle runs unchecked.
  reduction::ReducedModel model = test::toyModel();
  model.system.input_stiffness(0, 0) = 1.0;
  model.system.stiffness(0, 0) += 1.0;
  OnlineVehicle vehicle(model, test::toyGeometry());
  EXPECT_EQ(vehicle.groundContactWatch(), nullptr);
  EXPECT_NE(vehicle.groundContactUnavailable().find("road input 0"), std::string::npos)
      << vehicle.groundContactUnavailable();
  vehicle.checkGroundContact();  // nothing to do
}

#if TVD_COUNTS_ALLOCATIONS  // glibc, no sanitizer: see count_allocations.h
TEST(OnlineVehicle, StepAllocatesNothing) {
  for (auto method : {dynamics::DiscretizationMethod::ModalDecoupled,
                      dynamics::DiscretizationMethod::AugmentedExponential})
    for (const double slew : {0.0, 2.0}) {  // without and with the speed slew (travel inertia)
      OnlineVehicleOptions o = options(method);
      o.max_acceleration = o.max_deceleration = slew;
      OnlineVehicle vehicle(test::toyModel(), test::toyGeometry(), o);
      for (const TerrainPatch& p : patches(bump(), 40))
        vehicle.addTerrain(p);
      vehicle.setSpeed(5.0);
      vehicle.step();
      g_allocations = 0;
      g_count_allocations = true;
      for (int k = 0; k < 500; ++k)
        vehicle.step();
      g_count_allocations = false;
      EXPECT_EQ(g_allocations, 0);
    }
}
#endif

TEST(RoadInputSampler, SlopeIsTheCellSlopeOfTerrainSlope) {
  const terrain::Terrain t = bump();
  terrain::TerrainBuffer buffer;
  buffer.addPatch(t.startStation(), t.spacing(), t.lateral(), t.heights());
  RoadInputSampler sampler(Eigen::Vector2d(0.0, 0.3), Eigen::Vector2d(0.5, -0.5));
  Vector w(4);
  ASSERT_EQ(sampler.sample(buffer, 2.513, 4.0, 0.25, &w), 0);
  EXPECT_NEAR(w(0), t.height(2.513, 0.75), 1e-15);
  EXPECT_NEAR(w(1), t.height(2.813, -0.25), 1e-15);
  EXPECT_NEAR(w(2), 4.0 * t.slope(2.513, 0.75), 1e-9);
  EXPECT_NEAR(w(3), 4.0 * t.slope(2.813, -0.25), 1e-9);
  // Exactly on a station the slope is the cell ahead's, as Terrain::slope() (RoadExcitation)
  // takes it, bit for bit.
  const double x = t.stations()(145);  // 2.25 m, on the bump
  ASSERT_EQ(sampler.sample(buffer, x, 1.0, 0.25, &w), 0);
  const double left = (t.height(x, 0.75) - t.height(x - t.spacing(), 0.75)) / t.spacing();
  const double right = (t.height(x + t.spacing(), 0.75) - t.height(x, 0.75)) / t.spacing();
  ASSERT_GT(std::abs(right - left), 1e-3);
  EXPECT_NEAR(w(2), right, 1e-12);
  EXPECT_EQ(w(2), t.slope(x, 0.75));
  // Off the terrain: held, rate 0, counted.
  EXPECT_EQ(sampler.sample(buffer, 20.0, 4.0, 0.0, &w), 2);
  EXPECT_EQ(w(2), 0.0);
}

// The sampler remembers where each contact found its terrain (road_input_sampler.h); through
// patches arriving, overlapping, dropped behind, gaps and a changing lateral offset its heights
// stay those of the buffer itself, bit for bit.
// Contacts share stations (sampled together) and the terrain differs across the width.
TEST(RoadInputSampler, RememberedLookupsGiveTheBuffersHeights) {
  const terrain::Terrain flat_across = bump();
  Matrix across = flat_across.heights();
  across.row(1) = 1.7 * across.row(0).array() + 0.01;
  const terrain::Terrain t(flat_across.stations(), flat_across.lateral(), across, "bump across");
  Vector xq(8), yq(8);
  xq << -2.0, -0.7, 0.0, 0.9, 2.1, 0.9, -2.0, 0.9;
  yq << 0.5, -0.5, 0.2, 0.5, -0.3, -0.8, 0.9, 0.1;
  // Without u' the flat runs are skipped (their heights held), with u' they are not.
  RoadInputSampler sampler(xq, yq, std::vector<bool>(8, false));
  RoadInputSampler with_rates(xq, yq);
  terrain::TerrainBuffer buffer;
  Vector w(16), w_rates(16);
  const double spacing = t.spacing();
  const Eigen::Index per_patch = 40;
  Eigen::Index next = 0;  // first sample of the next patch to add
  auto addNext = [&] {
    const Eigen::Index count = std::min<Eigen::Index>(per_patch, t.stations().size() - next);
    if (count <= 0)
      return;
    buffer.addPatch(t.stations()(next), spacing, t.lateral(), t.heights().middleCols(next, count));
    next += count;
  };
  for (int i = 0; i < 4; ++i)
    addNext();
  long checked = 0;
  for (int k = 0; k < 3000; ++k) {
    const double station = t.startStation() + 2.0 + 0.0013 * k;
    const double offset = k < 1500 ? 0.25 : -0.1;
    if (k % 97 == 0)
      addNext();
    if (k % 211 == 0)
      buffer.dropBehind(station - 2.5);
    if (k == 700) {  // a newer patch over part of the older ones
      Vector y(1);
      y << 0.0;
      buffer.addPatch(station + 0.5, spacing, y, Matrix::Constant(1, 30, 0.3));
    }
    const int uncovered = sampler.sample(buffer, station, 0.0, offset, &w);
    EXPECT_EQ(with_rates.sample(buffer, station, 0.0, offset, &w_rates), uncovered);
    int not_covered = 0;
    for (Eigen::Index q = 0; q < xq.size(); ++q) {
      const double x = station + xq(q);
      if (!buffer.covers(x)) {
        ++not_covered;
        continue;
      }
      ASSERT_EQ(w(q), buffer.height(x, yq(q) + offset)) << "contact " << q << " step " << k;
      ASSERT_EQ(w_rates(q), w(q)) << "contact " << q << " step " << k;
      ++checked;
    }
    EXPECT_EQ(uncovered, not_covered) << "step " << k;
  }
  EXPECT_GT(checked, 16000);
}
