// Closed-form checks of the beam element, the assembly and the solvers.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/beam_element.h"
#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/static_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"

namespace tvd = tracked_vehicle_dynamics;
using tvd::kPi;
using tvd::fem::Model;

namespace {

constexpr double kE = 210e9, kG = 81e9, kRho = 7850.0;
constexpr double kWidth = 0.05, kHeight = 0.02;  // rectangular section [m]
constexpr double kLength = 2.0;
constexpr double kFrequencyTolerance = 0.005;  // 0.5 % of Euler-Bernoulli
constexpr double kIdentityTolerance = 1e-8;

double areaOf() {
  return kWidth * kHeight;
}
double iyOf() {
  return kWidth * kHeight * kHeight * kHeight / 12.0;
}  // bending in x-z
double izOf() {
  return kHeight * kWidth * kWidth * kWidth / 12.0;
}  // bending in x-y

// A straight beam along x with `elements` elements; optionally clamped at node 0.
Model makeBeam(int elements, bool clamped) {
  Model m;
  m.name = "beam";
  for (int i = 0; i <= elements; ++i)
    m.addNode(i + 1, tvd::Vector3(kLength * i / elements, 0, 0));
  m.materials.push_back({"steel", kE, kG, kRho});
  tvd::fem::Section s;
  s.name = "rect";
  s.area = areaOf();
  s.iy = iyOf();
  s.iz = izOf();
  s.torsion = 0.229 * kWidth * kHeight * kHeight * kHeight;  // b/h = 2.5 (Roark)
  m.sections.push_back(s);
  for (int i = 0; i < elements; ++i) {
    tvd::fem::Beam b;
    b.n1 = i + 1;
    b.n2 = i + 2;
    b.material = "steel";
    b.section = "rect";
    b.orientation = tvd::Vector3::UnitZ();
    m.beams.push_back(b);
  }
  if (clamped)
    m.fixed.push_back({1, {{true, true, true, true, true, true}}});
  return m;
}

// Cantilever roots beta_n L of 1 + cos(bL) cosh(bL) = 0.
constexpr double kCantileverRoots[4] = {1.875104068711961, 4.694091132974175, 7.854757438237613,
                                        10.995540734875467};
// Free-free roots of 1 - cos(bL) cosh(bL) = 0.
constexpr double kFreeFreeRoots[3] = {4.730040744862704, 7.853204624095838, 10.995607838001671};

double bendingFrequency(double beta_l, double inertia) {
  const double m_per_length = kRho * areaOf();
  return beta_l * beta_l / (2 * kPi * kLength * kLength) * std::sqrt(kE * inertia / m_per_length);
}

std::vector<double> sortedFrequencies(const tvd::fem::ModalBasis& basis) {
  return std::vector<double>(basis.frequencies_hz.data(),
                             basis.frequencies_hz.data() + basis.frequencies_hz.size());
}

}  // namespace

TEST(BeamModes, CantileverMatchesEulerBernoulli) {
  const tvd::fem::System sys = tvd::fem::assemble(makeBeam(60, true));
  EXPECT_EQ(sys.size(), 360);
  tvd::fem::ModalRequest req;
  req.count = 12;
  const tvd::fem::ModalBasis basis = tvd::fem::solveModes(sys.stiffness, sys.mass, req);
  ASSERT_EQ(basis.count(), 12);
  // Both bending planes: the lowest 4 roots in each must be found among the modes.
  for (double inertia : {iyOf(), izOf()}) {
    for (double root : kCantileverRoots) {
      const double expected = bendingFrequency(root, inertia);
      double best = 1e9;
      for (double f : sortedFrequencies(basis))
        best = std::min(best, std::abs(f - expected) / expected);
      EXPECT_LT(best, kFrequencyTolerance) << "bending mode at " << expected << " Hz";
    }
  }
}

TEST(BeamModes, FreeFreeHasSixRigidBodyModesThenFlexible) {
  const tvd::fem::System sys = tvd::fem::assemble(makeBeam(60, false));
  tvd::fem::ModalRequest req;
  req.count = 9;
  const tvd::fem::ModalBasis basis = tvd::fem::solveModes(sys.stiffness, sys.mass, req);
  const double first_flexible = bendingFrequency(kFreeFreeRoots[0], iyOf());
  for (int i = 0; i < 6; ++i)
    EXPECT_LT(basis.frequencies_hz(i), 1e-4 * first_flexible) << i;
  EXPECT_NEAR(basis.frequencies_hz(6), first_flexible, kFrequencyTolerance * first_flexible);
  // Next: the first bending mode in the stiffer plane (I_z = 6.25 I_y), then the second in x-z.
  const double stiff_plane = bendingFrequency(kFreeFreeRoots[0], izOf());
  EXPECT_NEAR(basis.frequencies_hz(7), stiff_plane, kFrequencyTolerance * stiff_plane);
  const double second = bendingFrequency(kFreeFreeRoots[1], iyOf());
  EXPECT_NEAR(basis.frequencies_hz(8), second, kFrequencyTolerance * second);
}

TEST(BeamModes, LanczosMatchesDenseAndIdentitiesHold) {
  // 60 elements x 6 DOF = 360 > the dense threshold: exercises the Spectra path.
  const tvd::fem::System sys = tvd::fem::assemble(makeBeam(60, true));
  tvd::fem::ModalRequest req;
  req.count = 20;
  const tvd::fem::ModalBasis lanczos = tvd::fem::solveModes(sys.stiffness, sys.mass, req);
  const tvd::fem::ModalBasis dense =
      tvd::fem::solveModesDense(tvd::Matrix(sys.stiffness), tvd::Matrix(sys.mass));
  // Both are double-precision answers of a pencil whose eigenvalues spread from 689 to
  // ||K|| ||M^-1||-scale ~1e10 (the axial modes): the lowest one is determined only to about
  // eps * 1e8 = 2e-8 of itself (their Rayleigh quotients agree to that; SIMD builds moved both by
  // 1.3e-8). A wrong mode or a missed one would be off by percents.
  for (int i = 0; i < 20; ++i)
    EXPECT_NEAR(lanczos.eigenvalues(i), dense.eigenvalues(i), 1e-7 * dense.eigenvalues(i));
  const tvd::Matrix& phi = lanczos.shapes;
  const tvd::Matrix orth = phi.transpose() * (sys.mass * phi);
  EXPECT_LT((orth - tvd::Matrix::Identity(20, 20)).cwiseAbs().maxCoeff(), kIdentityTolerance);
  const tvd::Matrix residual =
      sys.stiffness * phi - sys.mass * phi * lanczos.eigenvalues.asDiagonal();
  const double scale = (sys.stiffness * phi).norm();
  EXPECT_LT(residual.norm() / scale, kIdentityTolerance);
}

TEST(BeamModes, FrequencyLimitReturnsAllModesBelowIt) {
  const tvd::fem::System sys = tvd::fem::assemble(makeBeam(60, true));
  tvd::fem::ModalRequest req;
  req.count = 100;
  req.max_frequency_hz = 200.0;
  const tvd::fem::ModalBasis limited = tvd::fem::solveModes(sys.stiffness, sys.mass, req);
  const tvd::fem::ModalBasis dense =
      tvd::fem::solveModesDense(tvd::Matrix(sys.stiffness), tvd::Matrix(sys.mass));
  int below = 0;
  while (dense.frequencies_hz(below) <= 200.0)
    ++below;
  EXPECT_EQ(limited.count(), below);
}

TEST(BeamStatics, CantileverTipDeflection) {
  Model m = makeBeam(10, true);
  const tvd::fem::System sys = tvd::fem::assemble(m);
  const double load = -1000.0;  // [N] along z at the tip
  tvd::Vector f = tvd::Vector::Zero(sys.size());
  f(sys.dofs.requireActive(11, 2)) = load;
  const tvd::fem::StaticResult r = tvd::fem::solveStatic(sys, f);
  // Cubic Hermite elements are exact for a tip load: P L^3 / (3 E I).
  const double expected = load * std::pow(kLength, 3) / (3 * kE * iyOf());
  EXPECT_NEAR(r.displacement(sys.dofs.requireActive(11, 2)), expected, 1e-9 * std::abs(expected));
  // ... and the tip slope P L^2 / (2 E I), negative ry for a downward deflection.
  const double slope = -load * kLength * kLength / (2 * kE * iyOf());
  EXPECT_NEAR(r.displacement(sys.dofs.requireActive(11, 4)), slope, 1e-9 * std::abs(slope));
  EXPECT_LT(r.residual, 1e-10);
}

// A cantilever's tip deflection with shear: P L^3 / (3 E I) + P L / (kappa G A), in each bending
// plane (x-z: shear_factor_z, I_y; x-y: shear_factor_y, I_z), whose Timoshenko blocks are apart.
TEST(BeamStatics, TimoshenkoAddsShearDeflection) {
  struct Plane {
    double tvd::fem::Section::*shear_factor;
    int dof;  // the tip's translation loaded
    double inertia;
  };
  for (const Plane& plane : {Plane{&tvd::fem::Section::shear_factor_z, 2, iyOf()},
                             Plane{&tvd::fem::Section::shear_factor_y, 1, izOf()}}) {
    SCOPED_TRACE("tip dof " + std::to_string(plane.dof));
    Model m = makeBeam(10, true);
    m.sections[0].*plane.shear_factor = 5.0 / 6.0;
    const tvd::fem::System sys = tvd::fem::assemble(m);
    tvd::Vector f = tvd::Vector::Zero(sys.size());
    const double load = -1000.0;
    f(sys.dofs.requireActive(11, plane.dof)) = load;
    const tvd::fem::StaticResult r = tvd::fem::solveStatic(sys, f);
    const double expected = load * std::pow(kLength, 3) / (3 * kE * plane.inertia) +
                            load * kLength / (5.0 / 6.0 * kG * areaOf());
    EXPECT_NEAR(r.displacement(sys.dofs.requireActive(11, plane.dof)), expected,
                1e-9 * std::abs(expected));
  }
}

TEST(BeamStatics, AxialAndTorsion) {
  Model m = makeBeam(4, true);
  const tvd::fem::System sys = tvd::fem::assemble(m);
  tvd::Vector f = tvd::Vector::Zero(sys.size());
  f(sys.dofs.requireActive(5, 0)) = 5e4;
  f(sys.dofs.requireActive(5, 3)) = 10.0;
  const tvd::fem::StaticResult r = tvd::fem::solveStatic(sys, f);
  EXPECT_NEAR(r.displacement(sys.dofs.requireActive(5, 0)), 5e4 * kLength / (kE * areaOf()), 1e-15);
  const double j = m.sections[0].torsion;
  EXPECT_NEAR(r.displacement(sys.dofs.requireActive(5, 3)), 10.0 * kLength / (kG * j), 1e-12);
}

TEST(BeamStatics, RotatedBeamGivesTheSameAnswer) {
  // The same cantilever along a skew axis, loaded perpendicular to it, deflects by P L^3 / 3EI.
  Model m = makeBeam(8, true);
  const tvd::Vector3 axis = tvd::Vector3(1, 2, 2).normalized();
  for (auto& n : m.nodes)
    n.position = axis * n.position.x();
  const tvd::Vector3 perp = axis.cross(tvd::Vector3::UnitX()).normalized();
  for (auto& b : m.beams)
    b.orientation = perp;  // local z = perp, bending about local y
  const tvd::fem::System sys = tvd::fem::assemble(m);
  tvd::Vector f = tvd::Vector::Zero(sys.size());
  const double load = 100.0;
  for (int d = 0; d < 3; ++d)
    f(sys.dofs.requireActive(9, d)) = load * perp(d);
  const tvd::fem::StaticResult r = tvd::fem::solveStatic(sys, f);
  tvd::Vector3 tip;
  for (int d = 0; d < 3; ++d)
    tip(d) = r.displacement(sys.dofs.requireActive(9, d));
  const double expected = load * std::pow(kLength, 3) / (3 * kE * iyOf());
  EXPECT_NEAR(tip.dot(perp), expected, 1e-9 * expected);
  EXPECT_NEAR(tip.dot(axis), 0.0, 1e-12);
}

TEST(BeamStatics, BeamMassAndGravityLoad) {
  Model m = makeBeam(5, false);
  const tvd::fem::System sys = tvd::fem::assemble(m);
  const double mass = kRho * areaOf() * kLength;
  EXPECT_NEAR(m.totalMass(), mass, 1e-12 * mass);
  double fz = 0.0;
  for (tvd::DofIndex i = 0; i < sys.size(); ++i)
    if (sys.dofs.dofOf(i).direction == 2)
      fz += sys.gravity_load(i);
  EXPECT_NEAR(fz, -mass * tvd::kStandardGravity, 1e-9 * mass);
}

TEST(BeamModes, ShapesAreSignedSoThatTheirLargestComponentIsPositive) {
  // An eigenvector is defined up to its sign; the solver fixes it (largest-magnitude component
  // positive) so that shapes, MACs of signed quantities and written files are reproducible and
  // the dense and Lanczos paths give the same vectors, not their negatives.
  const tvd::fem::System sys = tvd::fem::assemble(makeBeam(60, true));
  tvd::fem::ModalRequest req;
  req.count = 12;
  const tvd::fem::ModalBasis lanczos = tvd::fem::solveModes(sys.stiffness, sys.mass, req);
  const tvd::fem::ModalBasis dense =
      tvd::fem::solveModesDense(tvd::Matrix(sys.stiffness), tvd::Matrix(sys.mass));
  for (const tvd::fem::ModalBasis* basis : {&lanczos, &dense})
    for (int i = 0; i < 12; ++i) {
      const tvd::Vector phi = basis->shapes.col(i);
      EXPECT_EQ(phi.maxCoeff(), phi.cwiseAbs().maxCoeff()) << "mode " << i;
    }
  // Same sign on both paths: M-inner products of the matching mass-normalised shapes are +1.
  const tvd::Matrix cross = lanczos.shapes.transpose() * (sys.mass * dense.shapes.leftCols(12));
  for (int i = 0; i < 12; ++i)
    EXPECT_NEAR(cross(i, i), 1.0, 1e-6) << "mode " << i;
}

TEST(BeamElement, RigidMotionCarriesTheMassAndTheInertiaOfTheBeam) {
  // The consistent mass interpolates rigid motions exactly, so for a rigid motion with velocity
  // v of the midpoint and angular velocity w the kinetic energy 1/2 q'^T M q' is that of the
  // beam as a body: q'^T M q' = m v.v + w^T J w, with m = rho A L and, about the midpoint,
  // J = rho A L^3 / 12 (I - e e^T) + rho (Iy + Iz) L e e^T (e the axis; Euler-Bernoulli mass
  // has no rotary inertia of the section in bending, but the polar one in torsion).
  // Iy != Iz and J_torsion != Iy + Iz, so the torsion row must use the polar moment.
  tvd::fem::Material mat{"steel", kE, kG, kRho};
  tvd::fem::Section sec;
  sec.area = areaOf();
  sec.iy = iyOf();
  sec.iz = izOf();
  sec.torsion = 0.3 * (sec.iy + sec.iz);
  const tvd::Vector3 x1(0.3, -0.2, 0.5), x2(1.5, 0.3, 0.1);
  const tvd::fem::BeamMatrices e =
      tvd::fem::beamMatrices(x1, x2, tvd::Vector3(0.2, 0.1, 1.0), mat, sec);
  const double length = (x2 - x1).norm();
  const tvd::Vector3 axis = (x2 - x1) / length, mid = 0.5 * (x1 + x2);
  const double mass = kRho * sec.area * length;
  const tvd::Matrix3 inertia = kRho * sec.area * length * length * length / 12.0 *
                                   (tvd::Matrix3::Identity() - axis * axis.transpose()) +
                               kRho * (sec.iy + sec.iz) * length * axis * axis.transpose();
  const tvd::Vector3 perpendicular = axis.cross(tvd::Vector3::UnitZ()).normalized();
  const std::vector<std::pair<tvd::Vector3, tvd::Vector3>> motions = {
      {axis, tvd::Vector3::Zero()},           // along the axis: the axial mass
      {perpendicular, tvd::Vector3::Zero()},  // across it: the bending mass
      {tvd::Vector3::Zero(), axis},           // torsion: the polar moment
      {tvd::Vector3::Zero(), perpendicular},  // rotation about a transverse axis
      {tvd::Vector3(0.3, -1.1, 0.7), tvd::Vector3(-0.4, 0.9, 1.3)}};
  for (const auto& [v, w] : motions) {
    tvd::Vector q(12);
    for (int n = 0; n < 2; ++n) {
      const tvd::Vector3 x = n == 0 ? x1 : x2;
      q.segment<3>(6 * n) = v + w.cross(x - mid);
      q.segment<3>(6 * n + 3) = w;
    }
    const double expected = mass * v.squaredNorm() + w.dot(inertia * w);
    EXPECT_NEAR(q.dot(e.mass * q), expected, 1e-10 * expected)
        << "v " << v.transpose() << ", w " << w.transpose();
  }
}
