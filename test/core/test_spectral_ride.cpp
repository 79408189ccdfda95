// Spectral ride (spectral_ride.h): the acceleration variance of a base-excited oscillator in
// closed form; the default grid against an independent fine quadrature of the closed-form FRF;
// the travelled PSD against the direct FRF (grouping of inputs, the sides' weights); the
// wheelbase filter's notches; independent sides on a mirror-symmetric body (heave halved, roll
// only there); the class scale law; bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "dynamics_test_models.h"
#include "expect_input_error.h"
#include "tracked_vehicle_dynamics/dynamics/comfort.h"
#include "tracked_vehicle_dynamics/dynamics/frf.h"
#include "tracked_vehicle_dynamics/dynamics/spectral_ride.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/terrain/iso8608.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {
namespace {

// coupled: the whole damping (modalDamping), else the modal damping's diagonal (eq. 20).
SpectralRide rideOf(const SecondOrderSystem& s, const std::vector<DofIndex>& rows,
                    const RoadSpectrum& road, bool keep_psd = false, bool coupled = false) {
  SpectralRideOptions options;
  options.keep_psd = keep_psd;
  const Vector lateral = s.input_lateral.size() ? s.input_lateral : Vector::Zero(s.inputCount());
  const ModalSystem modal(s);
  return SpectralRide(modal, lateral, rows, road, options,
                      coupled ? modalDamping(modal, s) : Matrix());
}

/// S_a(f) [(m/s^2)^2/Hz] of the base-excited oscillator test::oneDof(m, c, k, c) on `road` at
/// `speed`: |-ω^2 (k + jωc) / (k - ω^2 m + jωc)|^2 S_h(f).
std::function<double(double)> oneDofPsd(double m, double c, double k, const RoadSpectrum& road,
                                        double speed) {
  return [=](double f) {
    const double w = kTwoPi * f;
    const std::complex<double> h =
        -w * w * std::complex<double>(k, w * c) / std::complex<double>(k - w * w * m, w * c);
    return std::norm(h) * temporalRoadPsd(road, f, speed);
  };
}

// A discrete damper c between DOFs i and j (an arm damper): C no longer a combination of M, K.
void addDamper(SecondOrderSystem* s, int i, int j, double c) {
  s->damping(i, i) += c;
  s->damping(j, j) += c;
  s->damping(i, j) -= c;
  s->damping(j, i) -= c;
}

// The largest relative difference between the ride's PSD and Σ_sides |H_v,side|^2 S_h, H_v the
// travelled FRF by frfDirect (an independent dense solve of eq. 18, no grouping), over both
// lateral correlations, for a model whose inputs share stations in pairs with an input in the
// centre strip (y = 0.02, gap 0.1: w_L = 0.7); also checks the grouping and the road's PSD.
double psdAgainstTheTravelledFrf(const SecondOrderSystem& s, bool coupled) {
  const std::vector<DofIndex> rows = {0, 3, 4};
  const double speed = 7.0;
  double worst = 0.0;
  for (terrain::LateralCorrelation correlation :
       {terrain::LateralCorrelation::Uniform, terrain::LateralCorrelation::IndependentSides}) {
    RoadSpectrum road;
    road.correlation = correlation;
    const SpectralRide ride = rideOf(s, rows, road, true, coupled);
    EXPECT_EQ(ride.complexModes(), coupled && ModalSystem(s).maxOffDiagonalDampingRatio() >
                                                  kModalDampingCouplingTolerance);
    const SpectralRideResult r = ride.evaluate(speed);
    const Vector& f = r.frequencies_hz;
    const InputDelay delay = InputDelay::travelling(s.input_stations, speed);
    Matrix expected = Matrix::Zero(f.size(), 3);
    std::vector<Vector> weights;
    if (correlation == terrain::LateralCorrelation::Uniform) {
      weights = {Vector::Ones(6)};
      // Stations 2, 0.5, -1: three groups.
      EXPECT_EQ(ride.inputGroupCounts(), std::vector<DofIndex>{3});
    } else {
      Vector left(6);
      left << 1, 0, 1, 0, 0.7, 0;
      weights = {left, Vector::Ones(6) - left};
      // Left: 2, 0.5 and (-1, 0.7); right: 2, 0.5, (-1, 0.3) and (-1, 1).
      EXPECT_EQ(ride.inputGroupCounts(), (std::vector<DofIndex>{3, 4}));
    }
    for (const Vector& w : weights) {
      SecondOrderSystem side = s;
      side.input_stiffness = s.input_stiffness * w.asDiagonal();
      side.input_damping = s.input_damping * w.asDiagonal();
      const ComplexMatrix h = frfDirect(side, f, delay, OutputQuantity::Acceleration);
      for (int j = 0; j < 3; ++j)
        expected.col(j) += h.col(rows[j]).cwiseAbs2();
    }
    for (Eigen::Index i = 0; i < f.size(); ++i) {
      EXPECT_NEAR(r.road_psd(i), temporalRoadPsd(road, f(i), speed), 1e-15 * r.road_psd(i));
      for (int j = 0; j < 3; ++j)
        worst = std::max(worst, std::abs(r.psd(i, j) / (expected(i, j) * r.road_psd(i)) - 1.0));
    }
  }
  return worst;
}

// ∫ g(f) df over [a, b] by composite Simpson in t = ln f (g f dt), `points` (odd) nodes: an
// independent, much finer quadrature than the class's trapezoid.
double simpsonLog(const std::function<double(double)>& g, double a, double b, int points) {
  const double h = std::log(b / a) / (points - 1);
  double sum = 0.0;
  for (int i = 0; i < points; ++i) {
    const double f = a * std::exp(i * h);
    const double w = (i == 0 || i == points - 1) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += w * g(f) * f;
  }
  return sum * h / 3.0;
}

// m x'' + c x' + k x = k u + c u': with u on a road of waviness 4 the acceleration variance has
// a closed form. |H_a|^2 = ω^4 |H_d|^2 and S_h = (G0 / v) (v n0)^4 f^-4, so
//   ∫ |H_a|^2 S_h df = (2π)^4 (G0 / v) (v n0)^4 ∫_0^∞ |H_d|^2 df,
// and for H_d = (k + c s) / (m s^2 + c s + k) the standard integral
// (1/2π) ∫_-∞^∞ |(b0 + b1 s) / (a0 + a1 s + a2 s^2)|^2 dω = (b1^2 a0 + b0^2 a2) / (2 a0 a1 a2)
// gives ∫_0^∞ |H_d|^2 df = (k m + c^2) / (4 c m). The band [1e-4, 1e4] Hz misses the tails
// ∫_0^f_lo 1 df = f_lo and ∫_f_hi^∞ c^2 / (m^2 ω^2) df = c^2 / (4π^2 m^2 f_hi), subtracted.
TEST(SpectralRide, BaseExcitedOscillatorMatchesClosedForm) {
  const double m = 1.0, k = kTwoPi * kTwoPi, c = 2.0 * 0.1 * std::sqrt(k * m);  // 1 Hz, ζ 10 %
  const double speed = 10.0;
  RoadSpectrum road;
  road.road_class = 'C';
  road.waviness = 4.0;
  road.min_frequency = 1e-5;  // 1e-4 Hz at 10 m/s
  road.max_frequency = 1e3;   // 1e4 Hz
  const SpectralRide ride = rideOf(test::oneDof(m, c, k, c), {0}, road);
  const SpectralRideResult r = ride.evaluate(speed);
  const double g0 = terrain::iso8608ReferencePsd('C'), n0 = terrain::kIso8608ReferenceFrequency;
  const double scale = std::pow(kTwoPi, 4) * g0 / speed * std::pow(speed * n0, 4);
  const double f_lo = speed * road.min_frequency, f_hi = speed * road.max_frequency;
  const double expected =
      scale * ((k * m + c * c) / (4.0 * c * m) - f_lo - c * c / (4.0 * kPi * kPi * m * m * f_hi));
  // Trapezoid at 400 points per decade: 5.5e-6 (h^2: 5.5e-8 at 4000).
  EXPECT_NEAR(r.outputs[0].rms * r.outputs[0].rms / expected, 1.0, 1e-5);
  // The road's own variance on the grid against iso8608Variance: the trapezoid in f on a log grid
  // (f_i+1 = f_i e^h) over f^-w errs by h^2 w (w + 1) / 12 relative (Σ Δf^3 g'' / 12 with
  // Δf = h f), 5.5e-5 here.
  const double h = std::log(10.0) / 400.0;
  EXPECT_NEAR(
      r.road_variance / terrain::iso8608Variance('C', road.min_frequency, road.max_frequency, 4.0) -
          1.0,
      h * h * 20.0 / 12.0, 0.01 * h * h * 20.0 / 12.0);
}

// On the ISO default (waviness 2, 0.011..2.83 cycles/m) with a lightly (2 %) damped oscillator
// in the band, a_rms, a_w and P of the default grid against Simpson on 2e5 points of the closed
// form |H_a|^2 S_h times 1, |W_k|^2 and K: the integration error of 400 points per decade.
// The log grid (400 per decade: step h = 0.58 %) with the points grid() adds around a
// resonance it does not resolve (zeta < 1.5 h) or that a band end cuts: zeta 2 % (resolved),
// 0.69 % (1.2 h), 0.29 % (h/2), 0.2 % and 0.01 %, at speeds whose band holds the 1.3 Hz peak
// whole (2, 8, 20 m/s) and at speeds whose top end cuts it (the end 3 zeta below the peak, on it,
// 1.5 zeta above; or as far about the peak, the bottom end); within 1e-5 where the log grid
// alone resolves the peak whole, else 5e-4.
struct GridCase {
  double zeta;
  bool cut;
  bool bottom = false;  // the band's bottom end cuts the peak, not its top
};
class SpectralRideGrid : public ::testing::TestWithParam<GridCase> {};
INSTANTIATE_TEST_SUITE_P(Damping, SpectralRideGrid,
                         ::testing::Values(GridCase{0.02, false}, GridCase{0.02, true},
                                           GridCase{0.0069, false}, GridCase{0.0069, true},
                                           GridCase{0.00288, false}, GridCase{0.002, false},
                                           GridCase{0.002, true}, GridCase{1e-4, false},
                                           GridCase{1e-4, true}, GridCase{0.02, true, true},
                                           GridCase{0.002, true, true}));

TEST_P(SpectralRideGrid, DefaultGridResolvesALightlyDampedResonance) {
  const double zeta = GetParam().zeta;
  const bool cut = GetParam().cut;
  const double tolerance = zeta > 0.01 && !cut ? 1e-5 : 5e-4;
  const double m = 500.0, f_n = 1.3, k = m * std::pow(kTwoPi * f_n, 2);
  const double c = 2.0 * zeta * std::sqrt(k * m);
  const SecondOrderSystem s = test::oneDof(m, c, k, c);
  const RoadSpectrum road;  // class C, ISO band
  const SpectralRide ride = rideOf(s, {0}, road);
  const std::vector<AnalogSection> power = absorbedPowerVerticalSections();
  const double n_max = road.max_frequency, n_min = road.min_frequency;
  const std::vector<double> speeds =
      !cut                ? std::vector<double>{2.0, 8.0, 20.0}
      : GetParam().bottom ? std::vector<double>{f_n * (1.0 + 3.0 * zeta) / n_min, f_n / n_min,
                                                f_n * (1.0 - 1.5 * zeta) / n_min}
                          : std::vector<double>{f_n * (1.0 - 3.0 * zeta) / n_max, f_n / n_max,
                                                f_n * (1.0 + 1.5 * zeta) / n_max};
  for (double speed : speeds) {
    const SpectralRideResult r = ride.evaluate(speed);
    const auto s_a = oneDofPsd(m, c, k, road, speed);
    const double lo = speed * road.min_frequency, hi = speed * road.max_frequency;
    const int n = 200001;
    const double mean_square = simpsonLog(s_a, lo, hi, n);
    const double weighted = simpsonLog(
        [&](double f) { return std::norm(iso2631Response(Weighting::Wk, f)) * s_a(f); }, lo, hi, n);
    const double absorbed = simpsonLog(
        [&](double f) { return std::norm(analogResponse(power, f)) * s_a(f); }, lo, hi, n);
    const SpectralOutput& o = r.outputs[0];
    EXPECT_NEAR(o.rms * o.rms / mean_square, 1.0, tolerance) << speed;
    EXPECT_NEAR(o.weighted_rms * o.weighted_rms / weighted, 1.0, tolerance) << speed;
    EXPECT_NEAR(o.absorbed_power / absorbed, 1.0, tolerance) << speed;
    EXPECT_GT(o.absorbed_power, 0.0);
    // The road variance in the band (closed form), within the rule's error h^2 w (w + 1) / 12 =
    // 1.7e-5 (previous test).
    EXPECT_NEAR(r.road_variance / terrain::iso8608Variance('C', 0.011, 2.83), 1.0, 2e-5);
    // 400 per decade over [v n_min, v n_max], both ends on the grid; more around a resonance
    // the log grid does not resolve, ascending.
    const Vector f = ride.grid(speed);
    const auto log_grid =
        static_cast<Eigen::Index>(std::ceil(400.0 * std::log10(2.83 / 0.011))) + 1;
    if (zeta > 1.5 * std::log(10.0) / 400.0 && !cut)
      EXPECT_EQ(f.size(), log_grid);
    else
      EXPECT_GT(f.size(), log_grid + 15);
    EXPECT_DOUBLE_EQ(f(0), lo);
    EXPECT_DOUBLE_EQ(f(f.size() - 1), hi);
    for (Eigen::Index i = 1; i < f.size(); ++i)
      ASSERT_GT(f(i), f(i - 1));
  }
}

// Each output is weighted by its own ISO 2631-1 weighting (Wd for x and y, We for a rotation):
// the same response rated three ways, each a_w^2 the integral of |W|^2 S_a (Simpson on a fine
// grid), and the unweighted metrics untouched.
TEST(SpectralRide, EachOutputTakesItsWeighting) {
  const double m = 800.0, f_n = 1.1, k = m * std::pow(kTwoPi * f_n, 2);
  const double c = 2.0 * 0.1 * std::sqrt(k * m);
  const SecondOrderSystem s = test::oneDof(m, c, k, c);
  const RoadSpectrum road;
  SpectralRideOptions options;
  const std::vector<Weighting> weightings = {Weighting::Wk, Weighting::Wd, Weighting::We};
  options.weightings = weightings;
  const ModalSystem modal(s);
  const SpectralRide ride(modal, Vector::Zero(1), {0, 0, 0}, road, options);
  const double speed = 6.0;
  const SpectralRideResult r = ride.evaluate(speed);
  const auto s_a = oneDofPsd(m, c, k, road, speed);
  const double lo = speed * road.min_frequency, hi = speed * road.max_frequency;
  std::vector<double> weighted;
  for (std::size_t o = 0; o < weightings.size(); ++o) {
    const double expected =
        simpsonLog([&](double f) { return std::norm(iso2631Response(weightings[o], f)) * s_a(f); },
                   lo, hi, 200001);
    EXPECT_NEAR(std::pow(r.outputs[o].weighted_rms, 2) / expected, 1.0, 1e-5) << o;
    EXPECT_EQ(r.outputs[o].rms, r.outputs[0].rms);
    EXPECT_EQ(r.outputs[o].absorbed_power, r.outputs[0].absorbed_power);
    weighted.push_back(r.outputs[o].weighted_rms);
  }
  // Near 1 Hz the three differ (Wk 0.48, Wd 1.01, We 0.88): a weighting ignored would show.
  EXPECT_GT(weighted[1] / weighted[0], 1.5);
  EXPECT_LT(weighted[2] / weighted[1], 0.95);
  // The wider band keeps the weightings; a count that does not match the outputs is refused.
  const SpectralRideResult wide = ride.withMaxFrequency(5.0, options).evaluate(speed);
  EXPECT_GT(wide.outputs[2].weighted_rms, weighted[2]);
  SpectralRideOptions two = options;
  two.weightings.pop_back();
  expectInputError(
      [&] {
        SpectralRide(modal, Vector::Zero(1), {0, 0, 0}, road, two);
      },
      "2 weightings for 3 output rows");
  expectInputError([&] { ride.withMaxFrequency(5.0, two); }, "2 weightings for 3 output rows");
}

// Each mode's damping ratio, as the grid-resolution check reads it: ζ of a 1-DOF oscillator
// (0 undamped), and with a damper that couples two of three uncoupled oscillators (complex
// modes) the third one undamped, the two others damped.
TEST(SpectralRide, ModeDampingRatiosOfRealAndComplexModes) {
  const double m = 400.0, k = m * std::pow(kTwoPi * 2.0, 2);
  const RoadSpectrum road;
  for (double zeta : {0.0, 0.003, 0.05}) {
    const double c = 2.0 * zeta * std::sqrt(k * m);
    const std::vector<SpectralRide::ModeDamping> modes =
        rideOf(test::oneDof(m, c, k, c), {0}, road).modeDamping();
    ASSERT_EQ(modes.size(), 1u);
    EXPECT_NEAR(modes[0].frequency_hz, 2.0, 1e-12);
    EXPECT_NEAR(modes[0].ratio, zeta, 1e-12);
  }
  SecondOrderSystem s;
  const Eigen::Vector3d f_n(1.5, 2.5, 4.0);
  s.mass = Matrix::Identity(3, 3) * m;
  s.stiffness = Matrix::Zero(3, 3);
  for (int i = 0; i < 3; ++i)
    s.stiffness(i, i) = m * std::pow(kTwoPi * f_n(i), 2);
  s.damping = Matrix::Zero(3, 3);
  addDamper(&s, 0, 1, 500.0);
  s.input_stiffness = s.stiffness;
  s.input_damping = Matrix::Zero(3, 3);
  s.input_stations =
      (Vector(3) << 1.0, 0.0, -1.0).finished();  // not a Vector3d: GCC 12 warns (-Warray-bounds)
  s.input_lateral = Vector::Zero(3);
  s.output = Matrix::Identity(3, 3);
  s.output_names = {"a uz", "b uz", "c uz"};
  const SpectralRide ride = rideOf(s, {0, 1, 2}, road, false, true);
  ASSERT_TRUE(ride.complexModes());
  const std::vector<SpectralRide::ModeDamping> modes = ride.modeDamping();
  ASSERT_EQ(modes.size(), 3u);
  EXPECT_GT(modes[0].ratio, 1e-3);
  EXPECT_GT(modes[1].ratio, 1e-3);
  EXPECT_NEAR(modes[2].frequency_hz, 4.0, 1e-9);  // untouched by the damper
  EXPECT_LT(modes[2].ratio, 1e-12);
  // The coupled pair are roots of the characteristic equation det(λ² M + λ C + K) = 0 at
  // λ = -ζ ω_d / sqrt(1 - ζ²) + j ω_d, ω_d = 2π f: the header's ω_d / 2π and -Re λ / |λ| (not
  // |λ| / 2π, nor -Re λ / Im λ, each off by a factor sqrt(1 - ζ²)).
  for (std::size_t r = 0; r < 2; ++r) {
    const double zeta = modes[r].ratio, omega_d = kTwoPi * modes[r].frequency_hz;
    const Complex lambda(-zeta * omega_d / std::sqrt(1.0 - zeta * zeta), omega_d);
    const ComplexMatrix d = (lambda * lambda * s.mass.cast<Complex>() +
                             lambda * s.damping.cast<Complex>() + s.stiffness.cast<Complex>())
                                .topLeftCorner(2, 2);
    EXPECT_LT(std::abs(d.determinant()) / std::norm(lambda * lambda * m), 1e-9)
        << "mode " << r << ", zeta " << zeta;
  }
}

// The PSD is Σ_sides |H_v,side|^2 S_h with H_v the travelled FRF (frfDirect), on a random
// Rayleigh-damped model (modal = direct), independent sides included.
TEST(SpectralRide, PsdIsTheTravelledFrfOfEachSide) {
  SecondOrderSystem s = test::randomVehicle(20, 6, 5, 13);
  s.input_stations << 2.0, 2.0, 0.5, 0.5, -1.0, -1.0;
  s.input_lateral.resize(6);
  s.input_lateral << 0.8, -0.8, 0.8, -0.8, 0.02, -0.8;
  EXPECT_LT(psdAgainstTheTravelledFrf(s, false), 1e-8);
  // Given its (diagonal) damping whole, the ride stays on real modes: the same numbers.
  EXPECT_LT(psdAgainstTheTravelledFrf(s, true), 1e-8);
}

// Dampers between DOFs couple the modes: given Φ^T C Φ whole, the ride's complex modes give
// eq. 18's PSD to round-off of the eigenvectors (on 2e10 N/m tyres: A's entries span 1e-1 to
// 1e5 rad/s: 1e-9 of it); eq. 20's diagonal misses it by up to 60 times here.
TEST(SpectralRide, CoupledDampingByComplexModesIsTheTravelledFrf) {
  SecondOrderSystem s = test::randomVehicle(20, 6, 5, 13);
  s.input_stations << 2.0, 2.0, 0.5, 0.5, -1.0, -1.0;
  s.input_lateral.resize(6);
  s.input_lateral << 0.8, -0.8, 0.8, -0.8, 0.02, -0.8;
  addDamper(&s, 3, 12, 4e4);
  addDamper(&s, 0, 19, 2e4);
  ASSERT_GT(ModalSystem(s).maxOffDiagonalDampingRatio(), 0.1);
  const double exact = psdAgainstTheTravelledFrf(s, true);
  const double diagonal = psdAgainstTheTravelledFrf(s, false);
  std::cout << "complex modes " << exact << ", eq. 20 " << diagonal << "\n";
  EXPECT_LT(exact, 1e-7);
  EXPECT_GT(diagonal, 0.1);
  // A damping matrix of the wrong size is named.
  const ModalSystem modal(s);
  expectInputError(
      [&] {
        SpectralRide(modal, s.input_lateral, {0}, RoadSpectrum(), {}, Matrix::Identity(3, 3));
      },
      "modal damping matrix is 3 x 3 for 20 modes");
}

// A bar on two equal spring-dampers at x = ±a (heave z, pitch θ about its centre): the front and
// rear inputs give the same heave and opposite pitch. Travelled on one profile,
//   |H_v|^2 = |H_1 + H_2 e^{-jωL/v}|^2,  L = 2a,
// so heave vanishes at f = v / (2L) (e^{-jπ} = -1) and pitch at f = v / L.
TEST(SpectralRide, WheelbaseFilterNotches) {
  const double m = 2000.0, j = 1500.0, a = 1.5, k = 8e4, c = 3e3;
  SecondOrderSystem s;
  s.mass = Matrix::Zero(2, 2);
  s.mass.diagonal() << m, j;
  // Spring deflection at x: z - x θ - u; rows of [1, -x].
  Matrix b(2, 2);
  b << 1.0, 1.0, -a, a;  // columns: front (x = a), rear (x = -a)
  s.stiffness = k * b * b.transpose();
  s.damping = c * b * b.transpose();
  s.input_stiffness = k * b;
  s.input_damping = c * b;
  s.output = Matrix::Identity(2, 2);
  s.output_names = {"hull uz", "hull ry"};
  s.input_stations.resize(2);
  s.input_stations << a, -a;
  s.input_lateral = Vector::Zero(2);
  const double speed = 5.0, wheelbase = 2 * a;

  // The identity on the whole grid, H_1 and H_2 from each input alone (frfDirect).
  RoadSpectrum road;
  const SpectralRideResult r = rideOf(s, {0, 1}, road, true).evaluate(speed);
  ComplexMatrix h[2];
  for (int q = 0; q < 2; ++q) {
    SecondOrderSystem single = s;
    single.input_stiffness = s.input_stiffness.col(q);
    single.input_damping = s.input_damping.col(q);
    single.input_stations = s.input_stations.segment(q, 1);
    single.input_lateral = s.input_lateral.segment(q, 1);
    h[q] = frfDirect(single, r.frequencies_hz, InputDelay::synchronous());
  }
  for (Eigen::Index i = 0; i < r.frequencies_hz.size(); ++i) {
    const double omega = kTwoPi * r.frequencies_hz(i);
    for (int o = 0; o < 2; ++o) {
      const double gain =
          std::norm(h[0](i, o) + h[1](i, o) * std::polar(1.0, -omega * wheelbase / speed));
      ASSERT_NEAR(r.psd(i, o) / r.road_psd(i), gain, 1e-9 * std::norm(h[0](i, o)) + 1e-300);
    }
    EXPECT_NEAR(std::abs(h[0](i, 0) - h[1](i, 0)), 0.0, 1e-9 * std::abs(h[0](i, 0)));
    EXPECT_NEAR(std::abs(h[0](i, 1) + h[1](i, 1)), 0.0, 1e-9 * std::abs(h[0](i, 1)));
  }
  // The notches, each placed on the grid's first point (n_min = 1 / (2L), 1 / L).
  for (int o = 0; o < 2; ++o) {
    RoadSpectrum from_notch;
    from_notch.min_frequency = o == 0 ? 0.5 / wheelbase : 1.0 / wheelbase;
    const SpectralRideResult n = rideOf(s, {0, 1}, from_notch, true).evaluate(speed);
    EXPECT_NEAR(n.frequencies_hz(0), (o == 0 ? 0.5 : 1.0) * speed / wheelbase, 1e-15);
    EXPECT_LT(n.psd(0, o), 1e-20 * n.psd.col(o).maxCoeff()) << "output " << o;
    EXPECT_GT(n.psd(0, 1 - o), 1e-3 * n.psd.col(1 - o).maxCoeff()) << "output " << 1 - o;
  }
}

// The grid's error where it is largest on a vehicle: the wheelbase filter makes |H_v|^2 ripple in
// f with period v / L, which the log grid (step h f) samples 1 / (L h n_max) times per period at
// the top of the band, whatever the speed: 12 times for L = 5 m at 400 per decade. On a bar of
// that wheelbase the metrics of 400 per decade are within 5e-4 of 40000's (the bundled tracked
// vehicle: 4.2e-4, README), and the error falls as h^2: 100x less at 4000.
TEST(SpectralRide, GridErrorOnTheWheelbaseRippleFallsAsTheStepSquared) {
  const double m = 2000.0, j = 3000.0, a = 2.5, k = 8e4, c = 2.5e3;
  SecondOrderSystem s;
  s.mass = Matrix::Zero(2, 2);
  s.mass.diagonal() << m, j;
  Matrix b(2, 2);
  b << 1.0, 1.0, -a, a;
  s.stiffness = k * b * b.transpose();
  s.damping = c * b * b.transpose();
  s.input_stiffness = k * b;
  s.input_damping = c * b;
  s.output = Eigen::RowVector2d(1.0, -1.5);  // a seat 1.5 m ahead of the centre
  s.output_names = {"seat uz"};
  s.input_stations.resize(2);
  s.input_stations << a, -a;
  const ModalSystem modal(s);
  auto power = [&](double points_per_decade, double speed) {
    SpectralRideOptions o;
    o.points_per_decade = points_per_decade;
    const SpectralRideResult r =
        SpectralRide(modal, Vector::Zero(2), {0}, RoadSpectrum(), o).evaluate(speed);
    return std::vector<double>{r.outputs[0].absorbed_power, r.outputs[0].weighted_rms,
                               r.outputs[0].rms};
  };
  for (double speed : {1.5, 4.0, 12.0}) {
    const std::vector<double> p400 = power(400, speed), p4000 = power(4000, speed),
                              exact = power(40000, speed);
    for (int q = 0; q < 3; ++q) {
      const double e400 = std::abs(p400[q] / exact[q] - 1.0),
                   e4000 = std::abs(p4000[q] / exact[q] - 1.0);
      EXPECT_LT(e400, 5e-4) << speed << " m/s, metric " << q;
      EXPECT_LT(e4000, 1e-2 * e400 * 1.5) << speed << " m/s, metric " << q;
    }
  }
}

// A body (heave z, pitch θ, roll φ) on four equal corners at x = 1.4, -1.1, y = ±0.8: mirror
// images left and right. Heave and pitch respond alike to both sides (H_L = H_R = H):
// uniform |H_L + H_R|^2 = 4 |H|^2, independent |H_L|^2 + |H_R|^2 = 2 |H|^2, exactly half.
// Roll responds oppositely (H_L = -H_R = B): uniform 0, independent 2 |B|^2. A seat at (x_s,
// y_s), z - x_s θ + y_s φ, mixes both: independent = uniform / 2 + y_s^2 roll(independent).
TEST(SpectralRide, IndependentSidesHalveHeaveAndAloneExciteRoll) {
  const double m = 3000.0, jy = 4000.0, jx = 1200.0, k = 6e4, c = 4e3;
  const double xs[2] = {1.4, -1.1}, ys[2] = {0.8, -0.8};
  const double seat_x = 1.0, seat_y = 0.5;
  SecondOrderSystem s;
  s.mass = Eigen::Vector3d(m, jy, jx).asDiagonal();
  Matrix b(3, 4);  // corner displacement z - x θ + y φ, per corner
  s.input_stations.resize(4);
  s.input_lateral.resize(4);
  for (int i = 0; i < 2; ++i)
    for (int side = 0; side < 2; ++side) {
      const int q = 2 * i + side;
      b.col(q) << 1.0, -xs[i], ys[side];
      s.input_stations(q) = xs[i];
      s.input_lateral(q) = ys[side];
    }
  s.stiffness = k * b * b.transpose();
  s.damping = c * b * b.transpose();
  s.input_stiffness = k * b;
  s.input_damping = c * b;
  s.output.resize(4, 3);
  s.output << Matrix::Identity(3, 3), Eigen::RowVector3d(1.0, -seat_x, seat_y);
  s.output_names = {"hull uz", "hull ry", "hull rx", "seat uz"};
  RoadSpectrum uniform, independent;
  independent.correlation = terrain::LateralCorrelation::IndependentSides;
  const std::vector<DofIndex> rows = {0, 1, 2, 3};
  for (double speed : {3.0, 12.0}) {
    const SpectralRideResult u = rideOf(s, rows, uniform, true).evaluate(speed);
    const SpectralRideResult i = rideOf(s, rows, independent, true).evaluate(speed);
    ASSERT_EQ(u.frequencies_hz, i.frequencies_hz);
    const double roll_peak = i.psd.col(2).maxCoeff();
    EXPECT_GT(roll_peak, 0.0);
    for (Eigen::Index f = 0; f < u.frequencies_hz.size(); ++f) {
      for (int o : {0, 1})
        ASSERT_NEAR(i.psd(f, o), 0.5 * u.psd(f, o), 1e-12 * u.psd(f, o)) << "output " << o;
      ASSERT_LT(u.psd(f, 2), 1e-24 * roll_peak);
      ASSERT_NEAR(i.psd(f, 3), 0.5 * u.psd(f, 3) + seat_y * seat_y * i.psd(f, 2),
                  1e-12 * i.psd(f, 3));
    }
    // Integrals inherit it: heave power halves, uniform roll is nothing.
    EXPECT_NEAR(i.outputs[0].absorbed_power / u.outputs[0].absorbed_power, 0.5, 1e-12);
    EXPECT_LT(u.outputs[2].rms, 1e-12 * i.outputs[2].rms);
  }
}

// The classes are x4 apart in G_d(n0): the PSD, the power and the mean squares scale by 4
// exactly, the r.m.s. values by 2 (a linear model).
TEST(SpectralRide, ClassScaleLaw) {
  const SecondOrderSystem s = test::randomVehicle(12, 4, 3, 5);
  RoadSpectrum c, d;
  c.road_class = 'C';
  d.road_class = 'd';  // either case
  const SpectralRideResult rc = rideOf(s, {0, 2}, c, true).evaluate(9.0);
  const SpectralRideResult rd = rideOf(s, {0, 2}, d, true).evaluate(9.0);
  EXPECT_LT((rd.psd - 4.0 * rc.psd).cwiseAbs().maxCoeff(), 1e-14 * rd.psd.maxCoeff());
  for (int o = 0; o < 2; ++o) {
    EXPECT_NEAR(rd.outputs[o].absorbed_power / rc.outputs[o].absorbed_power, 4.0, 1e-13);
    EXPECT_NEAR(rd.outputs[o].weighted_rms / rc.outputs[o].weighted_rms, 2.0, 1e-13);
    EXPECT_NEAR(rd.outputs[o].rms / rc.outputs[o].rms, 2.0, 1e-13);
  }
  // keep_psd off: the metrics alone.
  const SpectralRideResult plain = rideOf(s, {0, 2}, c).evaluate(9.0);
  EXPECT_EQ(plain.psd.size(), 0);
  EXPECT_EQ(plain.outputs[1].absorbed_power, rc.outputs[1].absorbed_power);
}

TEST(SpectralRide, BadInputIsNamed) {
  const SecondOrderSystem s = test::randomVehicle(8, 2, 2, 3);
  const ModalSystem modal(s);
  const Vector lateral = Vector::Zero(2);
  RoadSpectrum road;
  auto make = [&](const RoadSpectrum& r, const std::vector<DofIndex>& rows = {0},
                  const Vector& y = Vector::Zero(2), double ppd = 400.0) {
    SpectralRideOptions o;
    o.points_per_decade = ppd;
    return SpectralRide(modal, y, rows, r, o);
  };
  RoadSpectrum bad = road;
  bad.road_class = 'Q';
  expectInputError([&] { make(bad); }, "class 'Q' is not one of A..H");
  bad = road;
  bad.min_frequency = 3.0;
  expectInputError([&] { make(bad); }, "band [3, 2.83] cycles/m must satisfy 0 < n_min < n_max");
  bad = road;
  bad.min_frequency = 0.0;
  expectInputError([&] { make(bad); }, "0 < n_min < n_max");
  bad = road;
  bad.waviness = -1.0;
  expectInputError([&] { make(bad); }, "waviness -1 must be > 0");
  bad = road;
  bad.correlation = terrain::LateralCorrelation::IndependentSides;
  bad.side_gap = 0.0;
  expectInputError([&] { make(bad); }, "side gap 0 m must be > 0");
  expectInputError([&] { make(road, {}); }, "no output to rate");
  expectInputError([&] { make(road, {2}); }, "output row 2 is not one of the model's 2 outputs");
  expectInputError([&] { make(road, {0}, Vector::Zero(3)); },
                   "input lateral positions has 3 entries, expected 2");
  expectInputError([&] { make(road, {0}, Vector::Constant(2, NAN)); }, "must be finite");
  expectInputError([&] { make(road, {0}, lateral, 5.0); },
                   "points per decade 5 must be in [10, 100000]");
  SecondOrderSystem no_stations = s;
  no_stations.input_stations.resize(0);
  expectInputError([&] { SpectralRide(ModalSystem(no_stations), lateral, {0}, road); },
                   "0 input stations for 2 inputs");
  const SpectralRide ride = make(road);
  expectInputError([&] { ride.evaluate(0.0); }, "speed 0 m/s must be positive and finite");
  expectInputError([&] { ride.evaluate(INFINITY); }, "must be positive and finite");
  expectInputError([&] { temporalRoadPsd(road, 1.0, -2.0); }, "speed -2 m/s");
  // Outside the band S_h is 0; inside, G_d(f / v) / v.
  EXPECT_EQ(temporalRoadPsd(road, 0.0105 * 4.0, 4.0), 0.0);
  EXPECT_EQ(temporalRoadPsd(road, 2.84 * 4.0, 4.0), 0.0);
  EXPECT_DOUBLE_EQ(temporalRoadPsd(road, 0.4, 4.0), terrain::iso8608Psd('C', 0.1) / 4.0);
}

}  // namespace
}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
