// Damping of the ground ties to an inertial frame (ground_tie_damping.h), on the quarter car
// q = [z_s, z_u] whose wheel hangs on a stiff tyre k_t: the absolute damping ratio against
// closed forms for mass-proportional, stiffness-proportional, relative and modal damping; the tie
// mode's frequency against the roots of the 2-DOF characteristic equation; and when the warning
// is given.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "dynamics_test_models.h"
#include "expect_input_error.h"
#include "tracked_vehicle_dynamics/dynamics/ground_contact.h"
#include "tracked_vehicle_dynamics/dynamics/ground_tie_damping.h"
#include "tracked_vehicle_dynamics/dynamics/modal_system.h"

using namespace tracked_vehicle_dynamics;
using dynamics::SecondOrderSystem;

namespace {

constexpr double kMs = 300.0, kMu = 30.0, kKs = 3e4, kKt = 2e10;  // [kg, kg, N/m, N/m]
constexpr double kTwoPi = 2.0 * 3.14159265358979323846;

SecondOrderSystem quarterCar(double c_s = 0.0) {
  return dynamics::test::quarterCar(kMs, kMu, kKs, c_s, kKt, 0.0);
}

// C = M Phi diag(2 zeta omega) Phi^T M: modal damping of every mode (paper eq. 20).
Matrix modalDamping(const SecondOrderSystem& s, double zeta) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> es(s.stiffness, s.mass);
  const Vector two_zeta_omega = 2.0 * zeta * es.eigenvalues().cwiseSqrt();
  return s.mass * es.eigenvectors() * two_zeta_omega.asDiagonal() * es.eigenvectors().transpose() *
         s.mass;
}

// The tie mode: the higher root of det(K - lambda M) = 0,
// m_s m_u lambda^2 - (m_s (k_s + k_t) + m_u k_s) lambda + k_s k_t = 0.
double tieModeHz() {
  const double a = kMs * kMu, b = -(kMs * (kKs + kKt) + kMu * kKs), c = kKs * kKt;
  const double lambda = (-b + std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
  return std::sqrt(lambda) / kTwoPi;
}

TEST(GroundTieDamping, MassProportionalDampingIsAlphaMOverTheTiesCriticalDamping) {
  SecondOrderSystem s = quarterCar();
  const double alpha = 3.0;  // [1/s]
  s.damping = alpha * s.mass;
  // Rigid lift r = [1, 1]: the force on the wheel is alpha m_u, against 2 sqrt(k_t m_u).
  const Vector ratio = dynamics::absoluteContactDamping(s, dynamics::groundContacts(s));
  ASSERT_EQ(ratio.size(), 1);
  EXPECT_NEAR(ratio(0), alpha * kMu / (2.0 * std::sqrt(kKt * kMu)), 1e-9 * ratio(0));
}

TEST(GroundTieDamping, RelativeDampersHoldNothingToTheInertialFrame) {
  // A suspension damper, and damping proportional to K with the tyre's damper in C_u: a rigid
  // lift with the road strains neither.
  SecondOrderSystem s = quarterCar(2e3);
  EXPECT_LT(dynamics::absoluteContactDamping(s, dynamics::groundContacts(s))(0), 1e-12);
  const double beta = 1e-4;  // [s]
  s.damping = beta * s.stiffness;
  s.input_damping = beta * s.input_stiffness;
  EXPECT_LT(dynamics::absoluteContactDamping(s, dynamics::groundContacts(s))(0), 1e-12);
}

TEST(GroundTieDamping, ModalDampingHoldsTheTieWithItsRatio) {
  // The tie mode (the wheel on the tyre, m_u on k_t + k_s) carries nearly all of the wheel's
  // share of the rigid lift: f = 2 zeta omega_t m_u, i.e. zeta sqrt((k_t + k_s) / k_t) of the
  // tie's critical damping, plus the bounce mode's share (k_s / k_t smaller).
  SecondOrderSystem s = quarterCar();
  const double zeta = 0.05;
  s.damping = modalDamping(s, zeta);
  const double ratio = dynamics::absoluteContactDamping(s, dynamics::groundContacts(s))(0);
  EXPECT_NEAR(ratio, zeta, 1e-3 * zeta);
}

TEST(GroundTieDamping, TheTieModeIsTheWheelOnItsTyre) {
  const SecondOrderSystem s = quarterCar();
  const dynamics::ModalSystem modal(s);
  const double hz = dynamics::groundTieModeRangeHz(modal, dynamics::groundContacts(s)).first;
  EXPECT_NEAR(hz, tieModeHz(), 1e-9 * hz);
  // Without contacts there is no tie mode.
  EXPECT_TRUE(std::isinf(dynamics::groundTieModeRangeHz(modal, {}).first));
}

TEST(GroundTieDamping, WarnsOnlyWhenDampedTieModesAreDynamic) {
  SecondOrderSystem s = quarterCar();
  s.damping = modalDamping(s, 0.05);
  const auto contacts = dynamics::groundContacts(s);
  const dynamics::ModalSystem modal(s);
  const double tie_hz = tieModeHz();
  // Quasi-static: below the tie mode's frequency.
  EXPECT_EQ(dynamics::groundTieDampingWarning(s, contacts, &modal, 0.5 * tie_hz, "how", "do"), "");
  // Dynamic: a cut-off above it, every mode (0), or a method without modes (exact).
  const std::string above =
      dynamics::groundTieDampingWarning(s, contacts, &modal, 2.0 * tie_hz, "--max-mode-hz", "do");
  EXPECT_NE(above.find("the ground-tie modes (" + brief(std::round(tie_hz)) + " to " +
                       brief(std::round(tie_hz)) + " Hz"),
            std::string::npos)
      << above;
  EXPECT_NE(above.find("(--max-mode-hz)"), std::string::npos) << above;
  EXPECT_NE(above.find("up to 5 % of a tie's critical damping"), std::string::npos) << above;
  EXPECT_NE(dynamics::groundTieDampingWarning(s, contacts, &modal, 0.0, "all", "do"), "");
  const std::string exact =
      dynamics::groundTieDampingWarning(s, contacts, nullptr, 0.0, "--method exact", "do");
  EXPECT_EQ(exact,
            dynamics::groundTieDampingWarning(s, contacts, &modal, 0.0, "--method exact", "do"));
  EXPECT_NE(exact.find("For contact forces, do"), std::string::npos) << exact;
  // Damping that does not hold the tie to the inertial frame, or too little of it: no warning.
  s.damping = 1e-4 * s.stiffness;
  s.input_damping = 1e-4 * s.input_stiffness;
  EXPECT_EQ(
      dynamics::groundTieDampingWarning(s, dynamics::groundContacts(s), nullptr, 0.0, "h", "d"),
      "");
  s = quarterCar();
  s.damping = 1.0 * s.mass;  // alpha / (2 omega_t) = 6e-7
  EXPECT_EQ(dynamics::groundTieDampingWarning(s, contacts, nullptr, 0.0, "h", "d"), "");
}

TEST(GroundTieDamping, ACompliantTieIsARideModeWhateverTheStep) {
  // A soft tyre (2e5 N/m, 6.7 times the suspension): the wheel hops at 13 Hz on it, a mode with
  // most of its energy in the tyre, but a tyre, not a penalty for a rigid contact: its modal
  // damping is the model's choice, and nothing is said even with every mode dynamic.
  SecondOrderSystem s = dynamics::test::quarterCar(kMs, kMu, kKs, 0.0, 2e5, 0.0);
  s.damping = modalDamping(s, 0.05);
  const auto contacts = dynamics::groundContacts(s);
  EXPECT_TRUE(dynamics::stiffTies(s, contacts).empty());
  const dynamics::ModalSystem modal(s);
  const double hop_hz = dynamics::groundTieModeRangeHz(modal, contacts).first;
  EXPECT_GT(hop_hz, 10.0);
  EXPECT_LT(hop_hz, 20.0);
  EXPECT_EQ(dynamics::groundTieDampingWarning(s, contacts, nullptr, 0.0, "h", "d"), "");
  // The stiff tyre of the other tests is a stiff tie.
  const SecondOrderSystem stiff = quarterCar();
  EXPECT_EQ(dynamics::stiffTies(stiff, dynamics::groundContacts(stiff)).size(), 1u);
}

TEST(GroundTieDamping, APartlyDynamicSetOfTiesIsNamedAsSuch) {
  // Two wheels (30 and 60 kg) under one body, each on a 2e10 N/m tie: tie modes at
  // sqrt((k_t + k_s) / m_u) / 2 pi = 4109 and 2906 Hz (to 1e-3 Hz: the body barely moves).
  // A cut-off between them makes the lower one dynamic only.
  SecondOrderSystem s;
  s.mass = Eigen::Vector3d(kMs, 30.0, 60.0).asDiagonal();
  s.stiffness.resize(3, 3);
  s.stiffness << 2 * kKs, -kKs, -kKs, -kKs, kKs + kKt, 0.0, -kKs, 0.0, kKs + kKt;
  s.input_stiffness = (Matrix(3, 2) << 0.0, 0.0, kKt, 0.0, 0.0, kKt).finished();
  s.input_damping = Matrix::Zero(3, 2);
  s.output = Matrix::Identity(3, 3);
  s.output_names = {"hull uz", "front uz", "rear uz"};
  s.input_stations = Vector::Zero(2);
  s.damping = modalDamping(s, 0.05);
  const auto contacts = dynamics::groundContacts(s);
  const dynamics::ModalSystem modal(s);
  const auto [low, high] = dynamics::groundTieModeRangeHz(modal, contacts);
  EXPECT_NEAR(low, std::sqrt((kKt + kKs) / 60.0) / kTwoPi, 1e-3);
  EXPECT_NEAR(high, std::sqrt((kKt + kKs) / 30.0) / kTwoPi, 1e-3);
  const std::string part =
      dynamics::groundTieDampingWarning(s, contacts, &modal, 3500.0, "--max-mode-hz 3500", "do");
  EXPECT_NE(part.find("the ground-tie modes from 2906 Hz up to the cut-off 3500 Hz (of 2906 to "
                      "4109 Hz"),
            std::string::npos)
      << part;
  EXPECT_EQ(dynamics::groundTieDampingWarning(s, contacts, &modal, 2000.0, "h", "d"), "");
}

TEST(GroundTieDamping, ContactsOutsideTheSystemAndAFloatingModelAreRefused) {
  SecondOrderSystem s = quarterCar();
  auto contacts = dynamics::groundContacts(s);
  contacts[0].coordinate = 2;
  expectInputError([&] { dynamics::absoluteContactDamping(s, contacts); },
                   {"road input 0", "coordinate 2", "2-coordinate"});
  // No ground spring in K: the lift has nothing to stand on.
  contacts = dynamics::groundContacts(s);
  s.stiffness(1, 1) = kKs;
  EXPECT_THROW(dynamics::absoluteContactDamping(s, contacts), SolverError);
}

}  // namespace
