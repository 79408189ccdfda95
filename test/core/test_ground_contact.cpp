// Ground contact forces of the bonded linear model (ground_contact.h): the spring structure read
// from K_u and C_u, the forces of a run against closed forms, the monitor's reductions, and the
// bundled vehicle's static ground forces against its weight.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <set>

#include "dynamics_test_models.h"
#include "expect_input_error.h"
#include "tracked_vehicle_dynamics/dynamics/discretization.h"
#include "tracked_vehicle_dynamics/dynamics/ground_contact.h"
#include "tracked_vehicle_dynamics/dynamics/ground_contact_forces.h"
#include "tracked_vehicle_dynamics/dynamics/ground_contact_monitor.h"
#include "tracked_vehicle_dynamics/dynamics/modal_system.h"
#include "tracked_vehicle_dynamics/dynamics/simulator.h"
#include "tracked_vehicle_dynamics/dynamics/static_equilibrium.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/reduction/contact_groups.h"
#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "tracked_vehicle_dynamics/vehicle/static_summary.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

#ifndef TVD_SOURCE_DIR
#define TVD_SOURCE_DIR "."
#endif

using namespace tracked_vehicle_dynamics;
using dynamics::GroundContact;
using dynamics::GroundContactForces;
using dynamics::GroundContactMonitor;
using dynamics::SecondOrderSystem;
using dynamics::SimulatorOptions;

namespace {

constexpr double kGravity = 9.81;          // [m/s^2]
constexpr double kStaticTolerance = 1e-6;  // sum of the static contact forces vs the weight
constexpr double kForceTolerance = 1e-4;   // run vs closed form, relative to the force amplitude

// The one-DOF mass on a ground spring and damper, under gravity f_g = -m g.
struct Toy {
  double m = 100.0, k = 1e6, c = 2e3;  // [kg, N/m, N s/m]: f_n = 15.9 Hz, zeta = 0.1
  SecondOrderSystem system() const { return dynamics::test::oneDof(m, c, k, c); }
  Vector gravity() const { return Vector::Constant(1, -m * kGravity); }
};

// Steady harmonic base excitation u = A sin(w t) of the toy: x = Im(X e^{j w t}) about the static
// position, X = (k + j w c) A / (k - m w^2 + j w c). Every force on the mass is the contact's
// and its weight, so F = m g + m x'' = m g - m w^2 |X| sin(w t + arg X).
struct Harmonic {
  double amplitude, omega;
  std::complex<double> response(const Toy& toy) const {
    const std::complex<double> j(0.0, 1.0);
    return (toy.k + j * omega * toy.c) * amplitude /
           (toy.k - toy.m * omega * omega + j * omega * toy.c);
  }
  double force(const Toy& toy, double t) const {
    const std::complex<double> x = response(toy);
    return toy.m * kGravity -
           toy.m * omega * omega * std::abs(x) * std::sin(omega * t + std::arg(x));
  }
  // w = [u, u'] at t = k dt, k = 0 .. samples-1.
  Matrix inputs(long samples, double dt) const {
    Matrix w(samples, 2);
    for (long k = 0; k < samples; ++k) {
      const double t = static_cast<double>(k) * dt;
      w(k, 0) = amplitude * std::sin(omega * t);
      w(k, 1) = amplitude * omega * std::cos(omega * t);
    }
    return w;
  }
  // The steady state at t = 0: q = q_static + x(0), q' = x'(0).
  Vector state(const Toy& toy) const {
    const std::complex<double> x = response(toy);
    Vector z(2);
    z << -toy.m * kGravity / toy.k + x.imag(), omega * x.real();
    return z;
  }
};

// Runs the toy over `samples` of the harmonic with `options` and monitors it.
GroundContactMonitor runToy(const Toy& toy, const Harmonic& h, double dt, long samples,
                            Matrix* forces) {
  const SecondOrderSystem s = toy.system();
  SimulatorOptions options;
  options.time_step = dt;
  options.hold = dynamics::InputHold::FirstOrder;
  options.method = dynamics::DiscretizationMethod::ModalDecoupled;
  options.generalized_force = toy.gravity();
  GroundContactForces contact(s, dynamics::groundContacts(s), options);
  const Matrix w = h.inputs(samples, dt);
  contact.reset(h.state(toy), w.row(0).transpose());
  *forces = contact.simulate(w);
  GroundContactMonitor monitor(contact.contacts());
  Vector times(samples);
  for (long k = 0; k < samples; ++k)
    times(k) = static_cast<double>(k) * dt;
  monitor.add(*forces, times, 10.0 * times);  // a station: 10 m/s
  return monitor;
}

// A dense series as a held one: one channel per column, an event at every step.
dynamics::HeldInputSeries held(const Matrix& w) {
  dynamics::HeldInputSeries s;
  s.samples = w.rows();
  s.initial = w.row(0).transpose();
  for (DofIndex j = 0; j < w.cols(); ++j) {
    dynamics::HeldInputSeries::Channel ch;
    ch.columns = {j};
    for (long k = 1; k < w.rows(); ++k) {
      ch.steps.push_back(k);
      ch.values.push_back(w(k, j));
    }
    s.channels.push_back(ch);
  }
  return s;
}

}  // namespace

TEST(GroundContact, ReadsTheSpringOfEachRoadInput) {
  const SecondOrderSystem s = dynamics::test::quarterCar(300.0, 30.0, 3e4, 2e3, 2e10, 50.0);
  const std::vector<GroundContact> contacts = dynamics::groundContacts(s);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(contacts[0].input, 0);
  EXPECT_EQ(contacts[0].coordinate, 1);  // the wheel, not the hull
  EXPECT_EQ(contacts[0].stiffness, 2e10);
  EXPECT_EQ(contacts[0].damping, 50.0);
  EXPECT_EQ(contacts[0].side, dynamics::ContactSide::Centre);
}

TEST(GroundContact, RefusesInputsThatAreNotASpringOnOneCoordinate) {
  SecondOrderSystem two = dynamics::test::quarterCar();
  two.input_stiffness(0, 0) = 1e3;  // the road input also acts on the hull
  expectInputError([&] { dynamics::groundContacts(two); }, {"road input 0", "coordinates 0 and 1"});
  SecondOrderSystem none = dynamics::test::quarterCar();
  none.input_stiffness.setZero();
  expectInputError([&] { dynamics::groundContacts(none); }, {"road input 0", "zero K_u column"});
  SecondOrderSystem damper = dynamics::test::quarterCar();
  damper.input_damping(0, 0) = 10.0;  // a damper on the hull, the spring on the wheel
  expectInputError([&] { dynamics::groundContacts(damper); },
                   {"road input 0", "C_u acts on coordinate 0"});
  SecondOrderSystem negative = dynamics::test::quarterCar();
  negative.input_stiffness(1, 0) = -1.0;
  expectInputError([&] { dynamics::groundContacts(negative); }, {"road input 0", "not positive"});
  // Modal coordinates (a full model's K_u = Phi^T K_u) spread each input over every mode.
  const SecondOrderSystem car = dynamics::test::quarterCar();
  const dynamics::ModalSystem modal(car);
  SecondOrderSystem modal_form = car;
  modal_form.input_stiffness = modal.modalInputStiffness();
  expectInputError([&] { dynamics::groundContacts(modal_form); },
                   {"road input 0", "not of the form k e_m"});
  expectInputError([&] { dynamics::groundContacts(car, 2); }, "2 road inputs asked for");
  // A system whose sizes disagree is refused by name before any column is read.
  SecondOrderSystem short_lateral = dynamics::test::quarterCar();
  short_lateral.input_lateral = Vector::Zero(2);
  expectInputError([&] { dynamics::groundContacts(short_lateral); }, "input_lateral");
  SecondOrderSystem short_ku = dynamics::test::quarterCar();
  short_ku.input_stiffness = Matrix::Zero(1, 1);
  expectInputError([&] { dynamics::groundContacts(short_ku); }, "input stiffness K_u");
}

TEST(GroundContact, HarmonicBaseExcitationBeyondLiftOffGoesIntoTension) {
  // r = w / w_n = 0.5, A = 10 mm: the dynamic force amplitude m w^2 |X| = 3.4 m g.
  const Toy toy;
  const Harmonic h{0.01, 50.0};
  const double dt = 1e-4;
  const long samples = 2000;  // 0.2 s: 1.6 periods
  Matrix forces;
  const GroundContactMonitor monitor = runToy(toy, h, dt, samples, &forces);
  const double amplitude = toy.m * h.omega * h.omega * std::abs(h.response(toy));
  ASSERT_GT(amplitude, toy.m * kGravity);
  for (long k = 0; k < samples; ++k)
    ASSERT_NEAR(forces(k, 0), h.force(toy, static_cast<double>(k) * dt),
                kForceTolerance * amplitude)
        << k;
  // First tension: sin(w t + arg X) = g / (w^2 |X|), rising.
  const double t1 = (std::asin(toy.m * kGravity / amplitude) - std::arg(h.response(toy))) / h.omega;
  const dynamics::GroundContactSummary& s = monitor.summary();
  ASSERT_TRUE(s.anyTension());
  EXPECT_GE(s.first_tension_time, t1);
  EXPECT_LT(s.first_tension_time, t1 + dt);
  EXPECT_DOUBLE_EQ(s.first_tension_station, 10.0 * s.first_tension_time);
  EXPECT_EQ(s.first_tension_contact, 0);
  EXPECT_EQ(s.max_in_tension, 1);
  EXPECT_NEAR(s.min_contact_force, toy.m * kGravity - amplitude, kForceTolerance * amplitude);
  // In tension while sin(...) > g / (w^2 |X|): a share (pi - 2 asin(g/(w^2|X|))) / (2 pi) of a
  // period, here over the 1.6 periods of the run (counted from the closed form).
  long expected = 0;
  for (long k = 0; k < samples; ++k)
    expected += h.force(toy, static_cast<double>(k) * dt) < 0.0;
  EXPECT_NEAR(static_cast<double>(s.tension_samples), static_cast<double>(expected), 2.0);
  EXPECT_NEAR(s.tensionFraction(), static_cast<double>(expected) / samples, 2.0 / samples);
}

TEST(GroundContact, HarmonicBaseExcitationBelowLiftOffStaysInCompression) {
  const Toy toy;
  const Harmonic h{0.002, 50.0};  // m w^2 |X| = 0.68 m g
  Matrix forces;
  const GroundContactMonitor monitor = runToy(toy, h, 1e-4, 2000, &forces);
  const double amplitude = toy.m * h.omega * h.omega * std::abs(h.response(toy));
  const dynamics::GroundContactSummary& s = monitor.summary();
  EXPECT_FALSE(s.anyTension());
  EXPECT_TRUE(std::isnan(s.first_tension_time));
  EXPECT_EQ(s.first_tension_contact, -1);
  EXPECT_EQ(s.tensionFraction(), 0.0);
  EXPECT_NEAR(s.min_contact_force, toy.m * kGravity - amplitude, kForceTolerance * amplitude);
}

TEST(GroundContact, HeldSeriesGivesTheDenseSeriesForces) {
  const Toy toy;
  const Harmonic h{0.01, 50.0};
  const SecondOrderSystem s = toy.system();
  SimulatorOptions options;
  options.time_step = 1e-3;
  options.hold = dynamics::InputHold::FirstOrder;
  options.method = dynamics::DiscretizationMethod::ModalDecoupled;
  options.generalized_force = toy.gravity();
  const Matrix w = h.inputs(600, options.time_step);
  GroundContactForces dense(s, dynamics::groundContacts(s), options);
  GroundContactForces sparse(s, dynamics::groundContacts(s), options);
  dense.reset(h.state(toy), w.row(0).transpose());
  sparse.reset(h.state(toy), w.row(0).transpose());
  const Matrix a = dense.simulate(w);
  const Matrix b = sparse.simulate(held(w));
  EXPECT_LT((a - b).cwiseAbs().maxCoeff(), 1e-9 * a.cwiseAbs().maxCoeff());
}

// From rest (48 states) under the series w: the two give the same forces to the bit, not all zero.
void expectSameForces(GroundContactForces& own, GroundContactForces& shared, const Matrix& w) {
  own.reset(Vector::Zero(48), w.row(0).transpose());
  shared.reset(Vector::Zero(48), w.row(0).transpose());
  const Matrix a = own.simulate(w);
  ASSERT_GT(a.cwiseAbs().maxCoeff(), 0.0);
  EXPECT_EQ(a, shared.simulate(w));
}

// tvd simulate hands the run's ModalSystem to its contact forces: the same forces as from their
// own decomposition, to the bit (the same eigen-solve, H Phi with the contacts' rows), for both
// holds, with and without truncated modes; and a Simulator on a ModalSystem is the one built from
// the system.
TEST(GroundContact, TheRunsModalDecompositionGivesTheSameForces) {
  const SecondOrderSystem s = dynamics::test::randomVehicle(24, 5, 4, 11);
  const dynamics::ModalSystem modal(s);
  const std::vector<GroundContact> contacts = dynamics::groundContacts(s);
  // Bumps under each input in turn (u, u').
  const double pi = std::acos(-1.0);
  Matrix w = Matrix::Zero(400, 10);
  for (long k = 0; k < w.rows(); ++k)
    for (int q = 0; q < 5; ++q) {
      const double t = 1e-3 * static_cast<double>(k) - 0.05 * q;
      if (t > 0.0 && t < 0.1) {
        w(k, q) = 0.02 * (1.0 - std::cos(20.0 * pi * t));
        w(k, 5 + q) = 0.4 * pi * std::sin(20.0 * pi * t);
      }
    }
  for (const auto hold : {dynamics::InputHold::ZeroOrder, dynamics::InputHold::FirstOrder})
    for (const double cut_hz : {0.0, 150.0}) {  // 150 Hz: the tyre modes are quasi-static
      SCOPED_TRACE("cut " + std::to_string(cut_hz) + " Hz");
      SimulatorOptions options;
      options.time_step = 1e-3;
      options.hold = hold;
      options.method = dynamics::DiscretizationMethod::ModalDecoupled;
      options.max_mode_frequency_hz = cut_hz;
      options.generalized_force = Vector::LinSpaced(24, -900.0, 300.0);
      GroundContactForces own(s, contacts, options);
      GroundContactForces shared(s, contacts, options, &modal);
      expectSameForces(own, shared, w);

      dynamics::Simulator from_system(s, options);
      dynamics::Simulator from_modes(s, modal, options);
      EXPECT_EQ(from_modes.quasiStaticModeCount(), from_system.quasiStaticModeCount());
      EXPECT_EQ(from_modes.quasiStaticModeCount() > 0, cut_hz > 0.0);
      EXPECT_EQ(from_modes.outputNames(), from_system.outputNames());
      EXPECT_EQ(from_modes.simulate(w), from_system.simulate(w));
    }

  // Other outputs: H Phi of the new rows, named "output i" when no names are given.
  const dynamics::ModalSystem two = modal.withOutput(s.output.topRows(2), {});
  EXPECT_EQ(two.outputNames(), (std::vector<std::string>{"output 0", "output 1"}));
  EXPECT_EQ(two.modalOutput(), modal.modalOutput().topRows(2));
  SimulatorOptions options;
  options.method = dynamics::DiscretizationMethod::ModalDecoupled;
  EXPECT_EQ(dynamics::Simulator(s, two, options).outputCount(), 2);

  // Refused: another method, ratios beside the ModalSystem's, a decomposition of another size,
  // H of the wrong width, names that do not match its rows.
  SimulatorOptions exact = options;
  exact.method = dynamics::DiscretizationMethod::AugmentedExponential;
  expectInputError([&] { dynamics::Simulator(s, modal, exact); }, "ModalDecoupled");
  SimulatorOptions ratios = options;
  ratios.modal_damping_ratios = Vector::Constant(24, 0.05);
  expectInputError([&] { dynamics::Simulator(s, modal, ratios); }, "modal_damping_ratios");
  const dynamics::ModalSystem other(dynamics::test::randomVehicle(20, 5, 4, 11));
  expectInputError([&] { dynamics::Simulator(s, other, options); }, "20 modes");
  expectInputError([&] { modal.withOutput(Matrix::Zero(2, 23), {}); }, "24 columns");
  expectInputError([&] { modal.withOutput(Matrix::Zero(2, 24), {"a"}); }, "1 names for 2");
}

// tvd simulate --method exact hands the run's discretisation to its contact forces: the same
// forces as from their own augmented exponential, to the bit, for both holds and with a damped
// contact (velocity outputs); a discretisation of another system is refused.
TEST(GroundContact, TheRunsExactDiscretisationGivesTheSameForces) {
  const SecondOrderSystem base = dynamics::test::randomVehicle(24, 5, 4, 11);
  Matrix w = Matrix::Zero(300, 10);
  for (long k = 0; k < w.rows(); ++k)
    for (int q = 0; q < 5; ++q) {
      w(k, q) = 0.01 * std::sin(0.05 * static_cast<double>(k * (q + 1)));
      w(k, 5 + q) = 0.5 * (q + 1) * 0.01 * std::cos(0.05 * static_cast<double>(k * (q + 1)));
    }
  for (const bool damped : {false, true}) {
    // The test vehicle's tyres are damped (C_u != 0: velocity outputs too); without C_u not.
    SecondOrderSystem s = base;
    if (!damped)
      s.input_damping.setZero();
    const std::vector<GroundContact> contacts = dynamics::groundContacts(s);
    ASSERT_EQ(contacts.front().damping != 0.0, damped);
    for (const auto hold : {dynamics::InputHold::ZeroOrder, dynamics::InputHold::FirstOrder}) {
      SCOPED_TRACE(std::string(damped ? "damped" : "undamped") + ", hold " +
                   dynamics::holdName(hold));
      SimulatorOptions options;
      options.time_step = 1e-3;
      options.hold = hold;
      options.method = dynamics::DiscretizationMethod::AugmentedExponential;
      options.generalized_force = Vector::LinSpaced(24, -900.0, 300.0);
      const dynamics::StateSpace discrete = dynamics::exactDiscretization(s, options);
      GroundContactForces own(s, contacts, options);
      GroundContactForces shared(s, contacts, options, discrete);
      expectSameForces(own, shared, w);
      // The run's Simulator on the same discretisation is the one built from the system.
      dynamics::Simulator from_system(s, options);
      dynamics::Simulator from_discrete(discrete);
      EXPECT_EQ(from_discrete.simulate(w), from_system.simulate(w));
    }
  }
  SimulatorOptions options;
  options.method = dynamics::DiscretizationMethod::AugmentedExponential;
  const SecondOrderSystem other = dynamics::test::randomVehicle(20, 5, 4, 11);
  const dynamics::StateSpace wrong =
      dynamics::discretize(dynamics::fromSecondOrder(other), options.time_step, options.hold);
  const std::vector<GroundContact> contacts = dynamics::groundContacts(base);
  expectInputError([&] { GroundContactForces(base, contacts, options, wrong); }, "40 states");
  options.method = dynamics::DiscretizationMethod::ModalDecoupled;
  expectInputError([&] { GroundContactForces(base, contacts, options, wrong); },
                   "augmented exponential");
}

TEST(GroundContactMonitor, TensionAtRestIsCountedApart) {
  std::vector<GroundContact> contacts(2);
  GroundContactMonitor monitor(contacts);
  Matrix f(4, 2);
  f << -1, 5,  // contact 0 pulled at rest (a bonded equilibrium's own)
      -2, 5,   //
      -1, -1,  // contact 1, pressed at rest, goes into tension
      1, 1;
  const Vector t = Vector::LinSpaced(4, 0.0, 3.0);
  monitor.add(f, t, t);
  const dynamics::GroundContactSummary& s = monitor.summary();
  EXPECT_EQ(s.in_tension_at_rest, 1);
  EXPECT_DOUBLE_EQ(s.first_tension_time, 0.0);
  EXPECT_EQ(s.first_tension_contact, 0);
  EXPECT_DOUBLE_EQ(s.first_new_tension_time, 2.0);
  EXPECT_EQ(s.first_new_tension_contact, 1);
  EXPECT_EQ(s.tension_samples, 3);
  EXPECT_EQ(s.new_tension_samples, 1);
  EXPECT_DOUBLE_EQ(s.newTensionFraction(), 0.25);
}

// A pad's soles carry its moment as opposite forces: a sole can pull while the pad presses.
TEST(GroundContactMonitor, GroupsSumTheirContacts) {
  std::vector<GroundContact> contacts(4);
  contacts[0].group = contacts[1].group = 0;
  contacts[2].group = contacts[3].group = 1;
  GroundContactMonitor monitor(contacts);
  Matrix f(3, 4);
  f << 5, 5, 5, 5,    //
      -3, 8, 5, 5,    // a sole pulls, its pad presses (5)
      -3, 1, -4, -1;  // both pads pull
  const Vector t = Vector::LinSpaced(3, 0.0, 2.0);
  monitor.add(f, t, 3.0 * t);
  const dynamics::GroundContactSummary& s = monitor.summary();
  EXPECT_EQ(s.groups, 2);
  EXPECT_EQ(s.groups_in_tension_at_rest, 0);
  EXPECT_DOUBLE_EQ(s.first_new_tension_time, 1.0);
  EXPECT_DOUBLE_EQ(s.first_new_group_tension_time, 2.0);
  EXPECT_DOUBLE_EQ(s.first_new_group_tension_station, 6.0);
  EXPECT_EQ(s.first_new_group_tension, 1);  // -5 against -2
  EXPECT_EQ(s.max_groups_in_tension, 2);
  EXPECT_EQ(s.new_group_tension_samples, 1);
  EXPECT_EQ(s.min_group_force, -5.0);
  EXPECT_EQ(s.min_group, 1);
}

TEST(GroundContactMonitor, SidesCountsAndFirstTension) {
  std::vector<GroundContact> contacts(3);
  contacts[0].side = dynamics::ContactSide::Left;
  contacts[1].side = dynamics::ContactSide::Right;
  contacts[2].side = dynamics::ContactSide::Left;
  GroundContactMonitor monitor(contacts);
  Matrix f(4, 3);
  f << 10, 20, 30,  //
      5, -1, 30,    // contact 1 in tension
      -2, -3, 30,   // 0 and 1
      4, 5, 6;
  const Vector t = Vector::LinSpaced(4, 0.0, 0.3);
  monitor.add(f.topRows(2), t.head(2), 2.0 * t.head(2));
  monitor.add(f.bottomRows(2), t.tail(2), 2.0 * t.tail(2));
  const dynamics::GroundContactSummary& s = monitor.summary();
  EXPECT_EQ(s.samples, 4);
  EXPECT_EQ(s.tension_samples, 2);
  EXPECT_EQ(s.max_in_tension, 2);
  EXPECT_DOUBLE_EQ(s.first_tension_time, 0.1);
  EXPECT_DOUBLE_EQ(s.first_tension_station, 0.2);
  EXPECT_EQ(s.first_tension_contact, 1);
  EXPECT_EQ(s.min_contact_force, -3.0);
  EXPECT_EQ(s.min_contact, 1);
  EXPECT_DOUBLE_EQ(s.min_contact_time, 0.2);
  EXPECT_EQ(s.contactsEverInTension(), 2);
  EXPECT_DOUBLE_EQ(s.tensionFraction(), 0.5);
  EXPECT_EQ(monitor.leftForce(), (std::vector<double>{40, 35, 28, 10}));
  EXPECT_EQ(monitor.rightForce(), (std::vector<double>{20, -1, -3, 5}));
  EXPECT_EQ(monitor.contactsInTension(), (std::vector<int>{0, 1, 2, 0}));
  EXPECT_EQ(s.in_tension_at_rest, 0);
  EXPECT_EQ(s.first_new_tension_contact, 1);
  EXPECT_DOUBLE_EQ(s.first_new_tension_time, 0.1);
  EXPECT_EQ(s.new_tension_samples, 2);
  EXPECT_EQ(s.peak_left, 40.0);
  EXPECT_EQ(s.min_right, -3.0);
  expectInputError([&] { monitor.add(Matrix(1, 2), Vector(1), Vector(1)); }, "for 3 contacts");
}

// The simulator starts from static equilibrium in total displacements, so the contact forces at
// rest carry the vehicle: their sum is its weight (from the full FE model's masses), and each is
// the full model's static pad load (Craig-Bampton statics are exact).
TEST(GroundContact, StaticForcesOfTheBundledVehicleCarryItsWeight) {
  const vehicle::VehicleDescription d = vehicle::loadVehicleDescription(
      std::string(TVD_SOURCE_DIR) + "/config/vehicles/paper_vehicle.yaml");
  for (const vehicle::Variant variant : {vehicle::Variant::Untracked, vehicle::Variant::Tracked}) {
    SCOPED_TRACE(vehicle::variantName(variant));
    const reduction::ReducedModel reduced = reduction::reduceVehicle(d, variant, {});
    const std::vector<GroundContact> contacts = dynamics::groundContacts(reduced.system);
    ASSERT_EQ(static_cast<DofIndex>(contacts.size()), reduced.system.inputCount());
    for (const GroundContact& c : contacts) {
      // Each road input acts on a master: a physical ground DOF, uz.
      ASSERT_LT(c.coordinate, reduced.masterCount());
      EXPECT_EQ(reduced.masters[static_cast<std::size_t>(c.coordinate)].direction,
                static_cast<int>(Direction::Uz));
      EXPECT_NE(c.side, dynamics::ContactSide::Centre);
    }
    const Vector u0 = Vector::Zero(reduced.system.inputCount());
    const Vector z0 = dynamics::staticEquilibrium(reduced.system, u0, reduced.gravity_load);
    SimulatorOptions options;
    options.method = dynamics::DiscretizationMethod::ModalDecoupled;
    options.generalized_force = reduced.gravity_load;
    const GroundContactForces forces(reduced.system, contacts, options);
    const Vector f = forces.forces(z0, Vector::Zero(2 * reduced.system.inputCount()));

    const vehicle::VehicleModel built = vehicle::buildVehicleModel(d, variant);
    const vehicle::StaticSummary statics =
        vehicle::computeStaticSummary(built, fem::assemble(built.model));
    EXPECT_NEAR(f.sum(), statics.weight, kStaticTolerance * statics.weight);
    ASSERT_EQ(static_cast<std::size_t>(f.size()), statics.pad_loads.size());
    for (DofIndex i = 0; i < f.size(); ++i)
      EXPECT_NEAR(f(i), statics.pad_loads[static_cast<std::size_t>(i)],
                  kStaticTolerance * statics.weight)
          << i;
    // Left and right carry the weight between them.
    GroundContactMonitor monitor(contacts);
    monitor.add(f.transpose(), Vector::Zero(1), Vector::Zero(1));
    EXPECT_NEAR(monitor.leftForce()[0] + monitor.rightForce()[0], statics.weight,
                kStaticTolerance * statics.weight);
    const dynamics::GroundContactSummary& s = monitor.summary();
    EXPECT_EQ(s.in_tension_at_rest, (f.array() < 0.0).count());
    EXPECT_EQ(s.first_new_tension_contact, -1);  // nothing pressed at rest is in tension there
    // Pads: one group per track assembly with soles on the road, every sole in one, on one side;
    // per road input the same group (the node's form).
    std::vector<GroundContact> grouped = contacts;
    const int pads = reduction::groupContactsByAssembly(built, reduced, &grouped);
    std::set<int> assemblies;
    for (const vehicle::RoadInput& r : built.layout.road_inputs)
      assemblies.insert(r.assembly);
    EXPECT_EQ(pads, static_cast<int>(assemblies.size()));
    EXPECT_EQ(pads, variant == vehicle::Variant::Untracked ? 14 : 60);  // 2 x 7 wheels; 2 x 30
    const std::vector<int> per_input = reduction::roadInputGroups(built, reduced);
    std::vector<dynamics::ContactSide> side_of(static_cast<std::size_t>(pads),
                                               dynamics::ContactSide::Centre);
    for (const GroundContact& c : grouped) {
      ASSERT_GE(c.group, 0);
      ASSERT_LT(c.group, pads);
      EXPECT_EQ(per_input[static_cast<std::size_t>(c.input)], c.group);
      dynamics::ContactSide& side = side_of[static_cast<std::size_t>(c.group)];
      if (side == dynamics::ContactSide::Centre)
        side = c.side;
      EXPECT_EQ(c.side, side) << "pad " << c.group;
      const NodeId node = reduced.masters[static_cast<std::size_t>(c.coordinate)].node;
      const auto r = std::find_if(built.layout.road_inputs.begin(), built.layout.road_inputs.end(),
                                  [&](const vehicle::RoadInput& x) { return x.node == node; });
      ASSERT_NE(r, built.layout.road_inputs.end());
      // Contacts of one pad share its assembly, and only they do.
      for (const GroundContact& other : grouped) {
        const NodeId other_node = reduced.masters[static_cast<std::size_t>(other.coordinate)].node;
        const auto o =
            std::find_if(built.layout.road_inputs.begin(), built.layout.road_inputs.end(),
                         [&](const vehicle::RoadInput& x) { return x.node == other_node; });
        ASSERT_NE(o, built.layout.road_inputs.end());
        EXPECT_EQ(o->assembly == r->assembly, other.group == c.group);
      }
    }
    if (variant == vehicle::Variant::Untracked) {
      EXPECT_GT(f.minCoeff(), 0.0);  // every sole pressed at rest
      EXPECT_FALSE(s.anyTension());
    } else {
      // The bonded chain pulls on the road between the wheels at rest (doc/vehicle_model.md).
      EXPECT_LT(f.minCoeff(), 0.0);
      EXPECT_GT(s.in_tension_at_rest, 0);
    }
  }
}
