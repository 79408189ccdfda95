// Travel inertia of a braking or accelerating vehicle (dynamics/travel_inertia.h): the load
// a(t) f_a, f_a = -T^T M e_x, of the path frame's forward acceleration a.
//  - the augmented system and input rows have the documented layout, and validate;
//  - full FE model: the static response to f_a is held by ground reactions along x that sum to
//    the vehicle's mass times 1 m/s^2 (d'Alembert), relative 1e-6, as the vertical ones sum to
//    its weight under gravity;
//  - the Craig-Bampton model's static response (hull surge and pitch) matches the full model's;
//  - braking (a < 0) pitches the nose down (REP-103: positive rotation about +y, y left) and
//    surges the hull forward relative to the path frame;
//  - in time, under constant braking on a flat road, the hull pitch settles to a times the static
//    pitch per unit a, and the relative x acceleration to 0;
//  - the travel load reduces like gravity (T^T f_a);
//  - braking moves the vertical ground load forward by the inertia moment: with every contact on
//    the ground plane z0, moments about the y axis through the origin at z0 give
//      sum_i x_i F_i = -a sum_j m_j (z_j - z0) = -a m h_G,
//    F_i the contact forces (compression positive) recovered from the reduced model as simulate
//    and the node recover them (dynamics::contactForces), the right side summed independently
//    over the FE model's masses and beams (m (z + offset_z) and rho A L at the beam's mid-height:
//    the consistent beam mass carries a uniform beam's rigid-body inertia exactly).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <string>

#include "tracked_vehicle_dynamics/dynamics/ground_contact.h"
#include "tracked_vehicle_dynamics/dynamics/simulator.h"
#include "tracked_vehicle_dynamics/dynamics/static_equilibrium.h"
#include "tracked_vehicle_dynamics/dynamics/travel_inertia.h"
#include "tracked_vehicle_dynamics/dynamics/validation.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/static_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/reduction/reduced_model.h"
#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "tracked_vehicle_dynamics/vehicle/static_summary.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace {

const std::string kVehicle = std::string(TVD_SOURCE_DIR) + "/config/vehicles/paper_vehicle.yaml";
constexpr double kGravity = 9.80665;          // [m/s^2], the models' gravity
constexpr double kBraking = -0.3 * kGravity;  // 0.3 g [m/s^2]
// Ground reactions against the mass: both sides are sums of the same masses, the reactions
// rounded through one sparse solve.
constexpr double kBalanceTolerance = 1e-6;
// Reduced against full static response to f_a (hull surge and pitch). The Craig-Bampton
// constraint modes give the exact static response to loads on the masters, and the travel load,
// like gravity, sits where the mass does; measured 3e-12 (un-tracked) and 8e-12 (tracked), so a
// reduction that dropped or mis-projected part of it would show far above this.
constexpr double kReductionTolerance = 1e-8;
// Settling of the time response to the static pitch (the brief's 1 %).
constexpr double kSettleTolerance = 1e-2;

struct Full {
  vehicle::VehicleDescription description;
  vehicle::VehicleModel model;
  fem::System system;
  double mass = 0.0;                                            // [kg], statics.weight / g
  std::vector<std::vector<std::pair<DofIndex, double>>> terms;  // vehicleOutputs()
  std::vector<std::string> names;
};

const Full& full(vehicle::Variant variant) {
  static std::map<vehicle::Variant, std::unique_ptr<Full>> cache;
  auto& slot = cache[variant];
  if (!slot) {
    slot = std::make_unique<Full>();
    slot->description = vehicle::loadVehicleDescription(kVehicle);
    slot->model = vehicle::buildVehicleModel(slot->description, variant);
    slot->system = fem::assemble(slot->model.model);
    slot->mass = vehicle::computeStaticSummary(slot->model, slot->system).weight / kGravity;
    const auto outputs = reduction::vehicleOutputs(slot->model, slot->description);
    slot->terms = reduction::outputTerms(slot->system.dofs, outputs);
    slot->names = reduction::outputNames(outputs);
  }
  return *slot;
}

const reduction::ReducedModel& reduced(vehicle::Variant variant) {
  static std::map<vehicle::Variant, std::unique_ptr<reduction::ReducedModel>> cache;
  auto& slot = cache[variant];
  if (!slot)
    slot = std::make_unique<reduction::ReducedModel>(
        reduction::reduceVehicle(vehicle::loadVehicleDescription(kVehicle), variant, {}));
  return *slot;
}

std::size_t indexOf(const std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end())
    throw std::logic_error("no output " + name);
  return static_cast<std::size_t>(it - names.begin());
}

// An output of the full model from its active-DOF displacement.
double fullOutput(const Full& f, const Vector& x, const std::string& name) {
  double y = 0.0;
  for (const auto& [active, coefficient] : f.terms[indexOf(f.names, name)])
    y += coefficient * x(active);
  return y;
}

// The reduced model's static response to its travel load per unit a: y = H K_R^-1 T^T f_a.
Vector reducedStaticPerUnitA(const reduction::ReducedModel& m) {
  return m.system.output * m.system.stiffness.ldlt().solve(m.travel_load);
}

TEST(TravelInertia, AugmentedSystemAndInputsHaveTheDocumentedLayout) {
  dynamics::SecondOrderSystem s;
  s.mass = Matrix::Identity(2, 2);
  s.damping = Matrix::Zero(2, 2);
  s.stiffness = Matrix::Identity(2, 2) * 4.0;
  s.input_stiffness = (Matrix(2, 1) << 1.0, 2.0).finished();
  s.input_damping = (Matrix(2, 1) << 0.1, 0.2).finished();
  s.output = Matrix::Identity(2, 2);
  s.input_stations = Vector::Constant(1, 1.5);
  s.input_lateral = Vector::Constant(1, -0.5);
  const Vector f_a = (Vector(2) << -3.0, 0.5).finished();
  const dynamics::SecondOrderSystem a = dynamics::withTravelInertia(s, f_a);
  ASSERT_EQ(a.inputCount(), 2);
  EXPECT_EQ(a.input_stiffness.col(0), s.input_stiffness.col(0));
  EXPECT_EQ(a.input_stiffness.col(1), f_a);
  EXPECT_EQ(a.input_damping.col(0), s.input_damping.col(0));
  EXPECT_EQ(a.input_damping.col(1), Vector::Zero(2));
  EXPECT_EQ(a.input_stations, (Vector(2) << 1.5, 0.0).finished());
  EXPECT_EQ(a.input_lateral, (Vector(2) << -0.5, 0.0).finished());
  EXPECT_NO_THROW(dynamics::validateSystem(a));
  EXPECT_EQ(a.mass, s.mass);
  EXPECT_EQ(a.stiffness, s.stiffness);
  // Statics: K q = K_u u + f_a a.
  const Vector q =
      dynamics::staticEquilibrium(a, (Vector(2) << 0.2, -2.0).finished(), Vector::Zero(2));
  EXPECT_LT((q.head(2) - (s.input_stiffness.col(0) * 0.2 + f_a * -2.0) / 4.0).norm(), 1e-15);

  // Rows [u, u'] -> [u, a, u', 0], one row or a block.
  const Matrix w = (Matrix(2, 4) << 1, 2, 3, 4, 5, 6, 7, 8).finished();
  const Matrix wide = dynamics::withTravelInput(w, (Vector(2) << -1.0, -2.0).finished());
  EXPECT_EQ(wide, (Matrix(2, 6) << 1, 2, -1, 3, 4, 0, 5, 6, -2, 7, 8, 0).finished());
  Vector row(6);
  dynamics::widenTravelInput(w.row(1).transpose(), -2.0, row);
  EXPECT_EQ(row, wide.row(1).transpose());
  EXPECT_THROW(dynamics::withTravelInertia(s, Vector::Zero(3)), InputError);
  EXPECT_THROW(dynamics::withTravelInertia(s, Vector::Constant(2, NAN)), InputError);
  EXPECT_THROW(dynamics::withTravelInput(w, Vector::Zero(3)), InputError);
  Vector short_row(5);
  EXPECT_THROW(dynamics::widenTravelInput(w.row(0).transpose(), 0.0, short_row), InputError);
}

class TravelInertiaOfVehicle : public ::testing::TestWithParam<vehicle::Variant> {};

TEST_P(TravelInertiaOfVehicle, GroundReactionsAlongXCarryTheMassTimesTheAcceleration) {
  const Full& f = full(GetParam());
  const fem::System& sys = f.system;
  // e: the rigid unit translation along x in active DOFs (every x translation 1, rotations 0;
  // rigid-joint slaves follow). K e is non-zero only where springs tie the structure to the
  // ground, so the ground's force on the structure along x is -(K e)^T x.
  Vector e = Vector::Zero(sys.size());
  for (DofIndex j = 0; j < sys.size(); ++j)
    if (sys.dofs.dofOf(j).direction == 0)
      e(j) = 1.0;
  const Vector ke = sys.stiffness * e;
  // The load itself: -m per unit a.
  EXPECT_NEAR(e.dot(sys.travel_load), -f.mass, kBalanceTolerance * f.mass);
  // The ground's reaction to it: by the symmetry of K, -(K e)^T x = -e^T K x = -e^T f_a, so this
  // checks that the solve balances the load through the ground springs (the physics is the line
  // above).
  const fem::StaticResult r = fem::solveStatic(sys, sys.travel_load);
  const double reaction = -ke.dot(r.displacement);
  EXPECT_NEAR(reaction, f.mass, kBalanceTolerance * f.mass) << "mass " << f.mass << " kg";
  // No vertical or lateral resultant: gravity's consistent load along z carries the same mass.
  Vector ez = Vector::Zero(sys.size());
  for (DofIndex j = 0; j < sys.size(); ++j)
    if (sys.dofs.dofOf(j).direction == 2)
      ez(j) = 1.0;
  EXPECT_NEAR(ez.dot(sys.gravity_load), -f.mass * kGravity, kBalanceTolerance * f.mass * kGravity);
  EXPECT_LT(std::abs(ez.dot(sys.travel_load)), 1e-12 * f.mass);
}

TEST_P(TravelInertiaOfVehicle, BrakingPitchesTheNoseDownAndSurgesTheHullForward) {
  const Full& f = full(GetParam());
  const Vector x = fem::solveStatic(f.system, f.system.travel_load).displacement;
  // Per unit a; braking is a < 0.
  const double pitch = kBraking * fullOutput(f, x, "hull ry");
  const double surge = kBraking * fullOutput(f, x, "hull ux");
  EXPECT_GT(pitch, 0.0) << "nose down is +ry (REP-103)";
  EXPECT_GT(surge, 0.0) << "forward is +x";
  // The hull's CoG sits above the ground: the nose goes down and the front pads take load, so a
  // point ahead of the CoG sinks more than one behind it (z = -x ry for small ry).
  std::cout << vehicle::variantName(GetParam()) << " full model at " << kBraking
            << " m/s^2: hull pitch " << pitch * 180.0 / M_PI << " deg (" << pitch * 1e3
            << " mrad), surge " << surge * 1e3 << " mm\n";
}

TEST_P(TravelInertiaOfVehicle, ReducedStaticResponseMatchesTheFullModel) {
  const Full& f = full(GetParam());
  const reduction::ReducedModel& m = reduced(GetParam());
  ASSERT_EQ(m.travel_load.size(), m.size());
  const Vector x = fem::solveStatic(f.system, f.system.travel_load).displacement;
  const Vector y = reducedStaticPerUnitA(m);
  for (const std::string name : {"hull ux", "hull ry", "hull uz"}) {
    const double full_y = fullOutput(f, x, name);
    const double reduced_y = y(static_cast<Eigen::Index>(indexOf(m.system.output_names, name)));
    std::cout << vehicle::variantName(GetParam()) << " " << name << " per unit a: full " << full_y
              << ", reduced " << reduced_y << " (relative difference "
              << std::abs(reduced_y - full_y) / std::abs(full_y) << ")\n";
    if (name == "hull uz")
      continue;  // a by-product of the pitch; not asserted
    EXPECT_NEAR(reduced_y, full_y, kReductionTolerance * std::abs(full_y)) << name;
  }
  // Reduced like gravity: the total x load is still -m (the masters carry the rigid translation).
  EXPECT_GT(m.travel_load.norm(), 0.0);
}

// sum_j m_j (z_j - z0) over the FE model's masses and beams [kg m].
double massMomentAbove(const fem::Model& model, double z0) {
  const auto index = model.nodeIndex();
  const auto z = [&](NodeId id) { return model.nodes[index.at(id)].position.z(); };
  double moment = 0.0;
  for (const fem::Mass& mass : model.masses)
    moment += mass.mass * (z(mass.node) + mass.offset.z() - z0);
  for (const fem::Beam& beam : model.beams) {
    const Vector3 a = model.nodes[index.at(beam.n1)].position;
    const Vector3 b = model.nodes[index.at(beam.n2)].position;
    const double m = model.findMaterial(beam.material)->density *
                     model.findSection(beam.section)->area * (b - a).norm();
    moment += m * (0.5 * (a.z() + b.z()) - z0);
  }
  return moment;
}

TEST_P(TravelInertiaOfVehicle, BrakingMovesTheVerticalGroundLoadForwardByTheInertiaMoment) {
  const Full& f = full(GetParam());
  const reduction::ReducedModel& m = reduced(GetParam());
  const std::vector<vehicle::RoadInput>& inputs = f.model.layout.road_inputs;
  ASSERT_EQ(static_cast<DofIndex>(inputs.size()), m.system.inputCount());
  // The ground plane: every contact (sole) on it, so the horizontal ground springs, at z0, add
  // no moment about an axis at z0.
  const auto index = f.model.model.nodeIndex();
  const double z0 = f.model.model.nodes[index.at(inputs.front().node)].position.z();
  for (const vehicle::RoadInput& input : inputs)
    ASSERT_NEAR(f.model.model.nodes[index.at(input.node)].position.z(), z0, 1e-12);
  const double h_g = massMomentAbove(f.model.model, z0) / f.mass;
  // The hull's CoG is 1.57 m up (Table 1); wheels and chain sit lower.
  EXPECT_GT(h_g, 0.3);
  EXPECT_LT(h_g, 1.57);

  // The reduced model at rest on a flat road under a alone (u = u' = 0): K_R q = a f_a.
  const Vector q = kBraking * m.system.stiffness.ldlt().solve(m.travel_load);
  const std::vector<dynamics::GroundContact> contacts = dynamics::groundContacts(m.system);
  const DofIndex n_u = m.system.inputCount();
  Vector state = Vector::Zero(2 * m.size());
  state.head(m.size()) = q;
  Vector forces(static_cast<Eigen::Index>(contacts.size()));
  dynamics::contactForces(contacts, state, Vector::Zero(2 * n_u), n_u, forces, "test");
  double sum = 0.0, moment = 0.0;
  for (std::size_t c = 0; c < contacts.size(); ++c) {
    const double force = forces(static_cast<Eigen::Index>(c));
    sum += force;
    moment += inputs[static_cast<std::size_t>(contacts[c].input)].x * force;
  }
  const double expected = -kBraking * f.mass * h_g;  // > 0: the load moves forward
  EXPECT_LT(std::abs(sum), kBalanceTolerance * f.mass * std::abs(kBraking))
      << "no vertical resultant";
  EXPECT_NEAR(moment, expected, kBalanceTolerance * std::abs(expected));
  std::cout << vehicle::variantName(GetParam()) << " at " << kBraking << " m/s^2: h_G " << h_g
            << " m above the ground, sum x_i F_i " << moment << " N m (m a h_G " << expected
            << ")\n";
}

TEST_P(TravelInertiaOfVehicle, ConstantBrakingSettlesToTheStaticPitch) {
  const reduction::ReducedModel& m = reduced(GetParam());
  const dynamics::SecondOrderSystem s = dynamics::withTravelInertia(m.system, m.travel_load);
  const DofIndex n_u = m.system.inputCount();
  dynamics::SimulatorOptions o;
  constexpr double kDt = 1e-3;
  o.time_step = kDt;
  o.hold = dynamics::InputHold::FirstOrder;
  o.method = dynamics::DiscretizationMethod::ModalDecoupled;
  o.generalized_force = m.gravity_load;
  o.max_mode_frequency_hz = 0.5 / kDt;
  o.quantities = {dynamics::OutputQuantity::Displacement, dynamics::OutputQuantity::Acceleration};
  dynamics::Simulator sim(s, o);
  // Flat road (u = 0), at rest under gravity, then a = 0.3 g braking from t = 0 for 20 s: with
  // 5 % modal damping a 1 Hz mode's transient falls to 0.2 % (exp(-0.05 2 pi 1 Hz 20 s)).
  const long steps = 20000;
  Matrix w = Matrix::Zero(steps + 1, 2 * (n_u + 1));
  w.col(n_u).setConstant(kBraking);
  w(0, n_u) = 0.0;
  sim.reset(dynamics::staticEquilibrium(s, Vector::Zero(n_u + 1), m.gravity_load),
            w.row(0).transpose());
  const Matrix y = sim.simulate(w);
  const auto pitch = static_cast<Eigen::Index>(indexOf(sim.outputNames(), "hull ry/disp"));
  const auto surge_acc = static_cast<Eigen::Index>(indexOf(sim.outputNames(), "hull ux/acc"));
  const double expected =
      y(0, pitch) + kBraking * reducedStaticPerUnitA(m)(static_cast<Eigen::Index>(
                                   indexOf(m.system.output_names, "hull ry")));
  EXPECT_NEAR(y(steps, pitch), expected, kSettleTolerance * std::abs(expected - y(0, pitch)));
  // Settled: the hull no longer accelerates relative to the path frame (an accelerometer reads
  // a itself, simulate's absolute x columns).
  EXPECT_LT(std::abs(y(steps, surge_acc)), 1e-2 * std::abs(kBraking));
  std::cout << vehicle::variantName(GetParam()) << " reduced model at " << kBraking
            << " m/s^2: hull pitch " << (y(steps, pitch) - y(0, pitch)) * 180.0 / M_PI << " deg ("
            << (y(steps, pitch) - y(0, pitch)) * 1e3 << " mrad), surge "
            << kBraking *
                   reducedStaticPerUnitA(m)(
                       static_cast<Eigen::Index>(indexOf(m.system.output_names, "hull ux"))) *
                   1e3
            << " mm\n";
}

INSTANTIATE_TEST_SUITE_P(Variants, TravelInertiaOfVehicle,
                         ::testing::Values(vehicle::Variant::Untracked, vehicle::Variant::Tracked),
                         [](const auto& info) { return vehicle::variantName(info.param); });

}  // namespace
}  // namespace tracked_vehicle_dynamics
