// The online ground-contact check (ground_contact_watch.h): forces recovered from a stepping
// simulator's state against the closed form of a harmonically excited mass and against the
// offline forces (GroundContactForces) of the same run; the bookkeeping of contacts pulling at
// rest, of the records since the restart and per interval; refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <random>

#include "dynamics_test_models.h"
#include "expect_input_error.h"
#include "tracked_vehicle_dynamics/dynamics/ground_contact.h"
#include "tracked_vehicle_dynamics/dynamics/ground_contact_forces.h"
#include "tracked_vehicle_dynamics/dynamics/ground_contact_monitor.h"
#include "tracked_vehicle_dynamics/dynamics/ground_contact_watch.h"
#include "tracked_vehicle_dynamics/dynamics/simulator.h"

using namespace tracked_vehicle_dynamics;
using dynamics::ContactSide;
using dynamics::GroundContact;
using dynamics::GroundContactRecord;
using dynamics::GroundContactWatch;

namespace {

constexpr double kGravity = 9.81;  // [m/s^2]

// A mass on a ground spring and damper under gravity, its base moved as u = A sin(w t) from the
// steady state: the only forces on the mass are its weight and the contact's, so
//   F = m g + m x'' = m g - m w^2 |X| sin(w t + arg X),  X = (k + j w c) A / (k - m w^2 + j w c).
struct HarmonicToy {
  double m = 100.0, k = 1e6, c = 2e3;  // f_n = 15.9 Hz, zeta = 0.1
  double amplitude = 0.01, omega = 50.0;
  std::complex<double> response() const {
    const std::complex<double> j(0.0, 1.0);
    return (k + j * omega * c) * amplitude / (k - m * omega * omega + j * omega * c);
  }
  double dynamicAmplitude() const { return m * omega * omega * std::abs(response()); }
  double force(double t) const {
    return m * kGravity - dynamicAmplitude() * std::sin(omega * t + std::arg(response()));
  }
  Vector input(double t) const {
    return (Vector(2) << amplitude * std::sin(omega * t), amplitude * omega * std::cos(omega * t))
        .finished();
  }
  Vector steadyState() const {
    const std::complex<double> x = response();
    return (Vector(2) << -m * kGravity / k + x.imag(), omega * x.real()).finished();
  }
};

GroundContact contact(DofIndex input, DofIndex coordinate, double k, double c, double y) {
  GroundContact g;
  g.input = input;
  g.coordinate = coordinate;
  g.stiffness = k;
  g.damping = c;
  g.lateral = y;
  g.side = y > 0 ? ContactSide::Left : y < 0 ? ContactSide::Right : ContactSide::Centre;
  return g;
}

}  // namespace

TEST(GroundContactWatch, StepByStepChecksFindTheClosedFormLiftOff) {
  const HarmonicToy toy;
  const dynamics::SecondOrderSystem system = dynamics::test::oneDof(toy.m, toy.c, toy.k, toy.c);
  dynamics::SimulatorOptions options;
  options.time_step = 1e-4;
  options.hold = dynamics::InputHold::FirstOrder;
  options.method = dynamics::DiscretizationMethod::ModalDecoupled;
  options.generalized_force = Vector::Constant(1, -toy.m * kGravity);
  dynamics::Simulator sim(system, options);
  dynamics::GroundContactForces offline(system, dynamics::groundContacts(system), options);
  const long samples = 2000;  // 0.2 s: 1.6 periods
  Matrix w(samples, 2);
  for (long k = 0; k < samples; ++k)
    w.row(k) = toy.input(static_cast<double>(k) * options.time_step).transpose();
  offline.reset(toy.steadyState(), w.row(0).transpose());
  const Matrix offline_forces = offline.simulate(w);

  GroundContactWatch watch(dynamics::groundContacts(system), system.inputCount());
  sim.reset(toy.steadyState(), w.row(0).transpose());
  watch.restart(0.0, sim.state(), sim.input());
  ASSERT_GT(watch.forces()(0), 0.0);  // pressed at the start
  EXPECT_EQ(watch.pullingAtRest(), 0);
  const double amplitude = toy.dynamicAmplitude();
  ASSERT_GT(amplitude, toy.m * kGravity);  // it must lift off
  long pulling = 0;
  for (long k = 1; k < samples; ++k) {
    const double t = static_cast<double>(k) * options.time_step;
    sim.step(w.row(k).transpose());
    watch.check(t, 10.0 * t, sim.state(), sim.input());
    // The same force as the offline series of the same run, and as the closed form.
    ASSERT_NEAR(watch.forces()(0), offline_forces(k, 0), 1e-9 * amplitude) << k;
    ASSERT_NEAR(watch.forces()(0), toy.force(t), 1e-4 * amplitude) << k;
    pulling += watch.forces()(0) < 0.0;
    EXPECT_EQ(watch.now().pulling, watch.forces()(0) < 0.0 ? 1 : 0);
  }
  // First pull: sin(w t + arg X) = m g / (m w^2 |X|), rising.
  const double t1 =
      (std::asin(toy.m * kGravity / amplitude) - std::arg(toy.response())) / toy.omega;
  const GroundContactRecord& r = watch.sinceRestart();
  ASSERT_TRUE(r.beyondRange());
  EXPECT_GE(r.first_beyond_time, t1);
  EXPECT_LT(r.first_beyond_time, t1 + options.time_step);
  EXPECT_DOUBLE_EQ(r.first_beyond_station, 10.0 * r.first_beyond_time);
  EXPECT_EQ(r.first_beyond_contact, 0);
  EXPECT_EQ(r.checks, samples - 1);
  EXPECT_EQ(r.checks_beyond, pulling);
  EXPECT_EQ(r.most_pulling, 1);
  EXPECT_NEAR(r.min_force, toy.m * kGravity - amplitude, 1e-4 * amplitude);
  EXPECT_NEAR(r.min_force, offline_forces.col(0).minCoeff(), 1e-9 * amplitude);
}

TEST(GroundContactWatch, CountsPullingAtRestApartAndKeepsTwoRecords) {
  // Three contacts on coordinates 0..2 of a 3-DOF state, inputs w = [u0 u1 u2 u0' u1' u2'].
  std::vector<GroundContact> contacts = {
      contact(0, 0, 1e5, 10.0, 1.0), contact(1, 1, 2e5, 0.0, -1.0), contact(2, 2, 1e5, 0.0, 1.0)};
  GroundContactWatch watch(contacts, 3);
  Vector w = Vector::Zero(6);
  // At rest: contacts 0 and 1 pressed (q below the road), contact 2 already pulling (q above).
  Vector z = Vector::Zero(6);
  z << -0.01, -0.02, 0.001, 0.0, 0.0, 0.0;
  watch.restart(5.0, z, w);
  EXPECT_EQ(watch.pullingAtRest(), 1);
  EXPECT_DOUBLE_EQ(watch.forces()(0), 1e3);
  EXPECT_DOUBLE_EQ(watch.forces()(1), 4e3);
  EXPECT_DOUBLE_EQ(watch.forces()(2), -1e2);
  EXPECT_DOUBLE_EQ(watch.now().left, 1e3 - 1e2);
  EXPECT_DOUBLE_EQ(watch.now().right, 4e3);
  EXPECT_EQ(watch.now().pulling, 0);
  EXPECT_EQ(watch.now().pulling_at_rest, 1);

  // Contact 2 pulls harder: still no departure from the range (it pulled at rest).
  z(2) = 0.05;
  watch.check(5.1, 51.0, z, w);
  EXPECT_FALSE(watch.sinceRestart().beyondRange());
  EXPECT_EQ(watch.sinceRestart().checks, 1);
  EXPECT_DOUBLE_EQ(watch.sinceRestart().min_force, 1e3);  // among the contacts pressed at rest
  EXPECT_EQ(watch.sinceRestart().min_contact, 0);

  // Contact 0 rises above its road and moves up faster: F0 = 1e5 (0 - 0.002) + 10 (0 - 1).
  z(0) = 0.002;
  z(3) = 1.0;
  watch.check(5.2, 52.0, z, w);
  EXPECT_DOUBLE_EQ(watch.forces()(0), -210.0);
  EXPECT_EQ(watch.now().pulling, 1);
  EXPECT_DOUBLE_EQ(watch.now().pull, 210.0);
  EXPECT_DOUBLE_EQ(watch.restForce(), 1e3 + 4e3 - 1e2);  // every contact, as at the restart
  const GroundContactRecord first = watch.takeInterval();
  EXPECT_EQ(first.checks, 2);
  EXPECT_EQ(first.checks_beyond, 1);
  EXPECT_DOUBLE_EQ(first.first_beyond_time, 5.2);
  EXPECT_DOUBLE_EQ(first.first_beyond_station, 52.0);
  EXPECT_EQ(first.first_beyond_contact, 0);
  EXPECT_DOUBLE_EQ(first.min_force, -210.0);

  // Both pressed contacts pull, contact 1 harder; the interval starts afresh, the run's record
  // keeps its first departure.
  z(1) = 0.01;
  watch.check(5.3, 53.0, z, w);
  const GroundContactRecord second = watch.takeInterval();
  EXPECT_EQ(second.checks, 1);
  EXPECT_EQ(second.most_pulling, 2);
  EXPECT_DOUBLE_EQ(second.max_pull, 210.0 + 2e3);  // contact 2, pulling at rest, not counted
  EXPECT_EQ(second.first_beyond_contact, 1);       // the hardest pull of that check
  EXPECT_DOUBLE_EQ(second.first_beyond_time, 5.3);
  EXPECT_DOUBLE_EQ(second.min_force, -2e3);
  const GroundContactRecord& run = watch.sinceRestart();
  EXPECT_EQ(run.checks, 3);
  EXPECT_EQ(run.checks_beyond, 2);
  EXPECT_EQ(run.most_pulling, 2);
  EXPECT_DOUBLE_EQ(run.max_pull, 210.0 + 2e3);
  EXPECT_DOUBLE_EQ(run.first_beyond_time, 5.2);
  EXPECT_EQ(run.first_beyond_contact, 0);
  EXPECT_EQ(watch.now().pulling_at_rest, 1);
  EXPECT_EQ(watch.takeInterval().checks, 0);

  // A restart forgets the run: everything pressed there is the new rest.
  watch.restart(6.0, z, w);
  EXPECT_EQ(watch.pullingAtRest(), 3);
  EXPECT_EQ(watch.sinceRestart().checks, 0);
  EXPECT_FALSE(watch.sinceRestart().beyondRange());
  EXPECT_TRUE(std::isnan(watch.sinceRestart().first_beyond_time));
}

TEST(GroundContactWatch, APadPullsOnlyWhenTheSumOfItsSolesDoes) {
  // One pad of two soles (contacts 0, 1 on coordinates 0, 1, group 0), one pad of one sole
  // (contact 2, group 1) and a contact on no pad (3). With k = 1e5 N/m, no damper and u = 0:
  // F_i = -1e5 q_i.
  std::vector<GroundContact> contacts = {contact(0, 0, 1e5, 0.0, 1.0), contact(1, 1, 1e5, 0.0, 1.0),
                                         contact(2, 2, 1e5, 0.0, -1.0),
                                         contact(3, 3, 1e5, 0.0, -1.0)};
  contacts[0].group = 0;
  contacts[1].group = 0;
  contacts[2].group = 1;
  GroundContactWatch watch(contacts, 4);
  EXPECT_EQ(watch.groupCount(), 2);
  EXPECT_EQ(watch.groupContact(0), 0);
  EXPECT_EQ(watch.groupContact(1), 2);
  const Vector w = Vector::Zero(8);
  Vector z = Vector::Zero(8);
  z.head(4) << -0.01, -0.01, -0.02, -0.01;  // every sole pressed: 1, 1, 2, 1 kN
  watch.restart(0.0, z, w);
  EXPECT_EQ(watch.groupsPullingAtRest(), 0);
  EXPECT_DOUBLE_EQ(watch.groupForces()(0), 2e3);
  EXPECT_DOUBLE_EQ(watch.groupForces()(1), 2e3);

  // The pad rocks: sole 0 pulls 0.5 kN, sole 1 presses 2.5 kN; the pad still presses 2 kN.
  z(0) = 0.005;
  z(1) = -0.025;
  watch.check(0.1, 1.0, z, w);
  EXPECT_EQ(watch.now().pulling, 1);
  EXPECT_EQ(watch.now().groups_pulling, 0);
  EXPECT_TRUE(watch.sinceRestart().beyondRange());
  EXPECT_FALSE(watch.sinceRestart().groupsBeyondRange());
  EXPECT_DOUBLE_EQ(watch.sinceRestart().min_group_force, 2e3);
  EXPECT_EQ(watch.sinceRestart().min_group, 0);  // the lower of two equal totals: the first

  // The pad lifts as a whole (-0.5 + -0.1 kN); the contact on no pad pulling adds no group.
  z(1) = 0.001;
  z(3) = 0.01;
  watch.check(0.2, 2.0, z, w);
  EXPECT_EQ(watch.now().pulling, 3);
  EXPECT_EQ(watch.now().groups_pulling, 1);
  const GroundContactRecord& run = watch.sinceRestart();
  EXPECT_EQ(run.checks_groups_beyond, 1);
  EXPECT_EQ(run.most_groups_pulling, 1);
  EXPECT_EQ(run.first_group_beyond, 0);
  EXPECT_DOUBLE_EQ(run.first_group_beyond_time, 0.2);
  EXPECT_DOUBLE_EQ(run.first_group_beyond_station, 2.0);
  EXPECT_DOUBLE_EQ(run.min_group_force, -600.0);
  EXPECT_DOUBLE_EQ(run.min_group_force_time, 0.2);

  // Restarted there, the lifted pad is one pulling at rest: counted apart, as the soles are.
  watch.restart(1.0, z, w);
  EXPECT_EQ(watch.groupsPullingAtRest(), 1);
  z(1) = 0.002;
  watch.check(1.1, 3.0, z, w);
  EXPECT_EQ(watch.now().groups_pulling, 0);
  EXPECT_EQ(watch.now().groups_pulling_at_rest, 1);
  EXPECT_FALSE(watch.sinceRestart().groupsBeyondRange());
  EXPECT_DOUBLE_EQ(watch.sinceRestart().min_group_force, 2e3);  // only the pad pressed at rest
}

TEST(GroundContactWatch, PadRecordsAgreeWithTheOfflineMonitor) {
  // Random sole forces, checked one sample at a time by the watch (F_i = -k q_i with u = 0) and
  // handed whole to GroundContactMonitor: the same first whole-pad departure, the same count of
  // samples with one. Eight contacts: pads {0, 1, 2}, {3, 4}, {6}, {7}; contact 5 on none. Pad 3
  // (contact 7) pulls at rest and throughout: the watch leaves it out of its counts and minimum,
  // the monitor counts it among the pads pulling at once.
  std::vector<GroundContact> contacts;
  const int group_of[] = {0, 0, 0, 1, 1, -1, 2, 3};
  for (DofIndex i = 0; i < 8; ++i) {
    contacts.push_back(contact(i, i, 1e5, 0.0, i < 3 ? 1.0 : -1.0));
    contacts.back().group = group_of[i];
  }
  const long samples = 400;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  Matrix forces(samples, 8);
  for (long k = 0; k < samples; ++k) {
    for (int i = 0; i < 7; ++i)  // pressed at rest by 1 kN; later samples wander by ~0.6 kN
      forces(k, i) = k == 0 ? 1e3 : 1e3 + 600.0 * noise(rng) - 3.0 * static_cast<double>(k);
    forces(k, 7) = -2e5;  // below every other force: the monitor's minimum, not the watch's
  }
  const Vector times = Vector::LinSpaced(samples, 0.0, 0.02 * static_cast<double>(samples - 1));
  const Vector stations = 3.0 * times;
  dynamics::GroundContactMonitor monitor(contacts);
  monitor.add(forces, times, stations);
  GroundContactWatch watch(contacts, 8);
  const Vector w = Vector::Zero(16);
  Vector z = Vector::Zero(16);
  for (long k = 0; k < samples; ++k) {
    z.head(8) = -forces.row(k).transpose() / 1e5;
    if (k == 0)
      watch.restart(times(k), z, w);
    else
      watch.check(times(k), stations(k), z, w);
  }
  const dynamics::GroundContactSummary& s = monitor.summary();
  const GroundContactRecord& run = watch.sinceRestart();
  ASSERT_EQ(s.groups, watch.groupCount());
  ASSERT_GT(s.new_group_tension_samples, 10);  // the comparison compares something
  EXPECT_EQ(run.checks_groups_beyond, s.new_group_tension_samples);
  EXPECT_EQ(run.first_group_beyond, s.first_new_group_tension);
  EXPECT_DOUBLE_EQ(run.first_group_beyond_time, s.first_new_group_tension_time);
  EXPECT_DOUBLE_EQ(run.first_group_beyond_station, s.first_new_group_tension_station);
  EXPECT_EQ(watch.groupsPullingAtRest(), 1);
  EXPECT_EQ(s.groups_in_tension_at_rest, 1);
  EXPECT_EQ(run.most_groups_pulling + 1, s.max_groups_in_tension);  // + the one pulling at rest
  EXPECT_DOUBLE_EQ(s.min_group_force, -2e5);
  EXPECT_EQ(s.min_group, 3);
  EXPECT_GT(run.min_group_force, -2e5);  // among the pads pressed at rest only
  EXPECT_NE(run.min_group, 3);
  // Their minimum is the lowest pad total pressed at rest over the checks.
  double lowest = INFINITY;
  for (long k = 1; k < samples; ++k)
    lowest = std::min({lowest, forces(k, 0) + forces(k, 1) + forces(k, 2),
                       forces(k, 3) + forces(k, 4), forces(k, 6)});
  EXPECT_DOUBLE_EQ(run.min_group_force, lowest);
  EXPECT_EQ(run.checks_beyond, s.new_tension_samples);
}

TEST(GroundContactWatch, RefusesWhatItCannotCheck) {
  const std::vector<GroundContact> one = {contact(0, 0, 1e5, 0.0, 1.0)};
  expectInputError([&] { GroundContactWatch({}, 1); }, "no contacts");
  expectInputError([&] { GroundContactWatch(one, 0); }, "reads input 0 of 0");
  GroundContactWatch watch(one, 1);
  expectInputError([&] { watch.check(0.0, 0.0, Vector::Zero(2), Vector::Zero(2)); },
                   "before restart");
  expectInputError([&] { watch.restart(0.0, Vector::Zero(3), Vector::Zero(2)); }, "state of 3");
  expectInputError([&] { watch.restart(0.0, Vector::Zero(2), Vector::Zero(4)); }, "input of 4");
  const std::vector<GroundContact> far = {contact(0, 5, 1e5, 0.0, 1.0)};
  GroundContactWatch off_state(far, 1);
  expectInputError([&] { off_state.restart(0.0, Vector::Zero(2), Vector::Zero(2)); },
                   "coordinate 5");
}
