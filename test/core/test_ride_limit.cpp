// Ride-limit building blocks: Butterworth low-pass sections against |H|^2 = 1/(1 + (f/fc)^2n)
// (analogue) and its bilinear image 1/(1 + (tan(πf/fs) / tan(πfc/fs))^2n) (digital); the shock
// meter's peaks of sinusoids against the filter's gain; the limit-speed search on closed-form
// metrics (crossing of v^2, exact on a linear metric, the first of several crossings).
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <limits>
#include <string>
#include <vector>

#include "expect_input_error.h"
#include "tracked_vehicle_dynamics/dynamics/butterworth.h"
#include "tracked_vehicle_dynamics/dynamics/comfort.h"
#include "tracked_vehicle_dynamics/dynamics/limit_crossing.h"
#include "tracked_vehicle_dynamics/dynamics/shock_meter.h"
#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {
namespace {

constexpr double kExact = 1e-12;

TEST(Butterworth, AnalogueMagnitudeIsMaximallyFlat) {
  for (int n = 1; n <= 6; ++n) {
    const std::vector<AnalogSection> sections = butterworthLowPass(n, 30.0);
    EXPECT_EQ(sections.size(), static_cast<std::size_t>((n + 1) / 2));
    for (double f : {0.0, 3.0, 15.0, 30.0, 45.0, 120.0}) {
      const double expected = 1.0 / std::sqrt(1.0 + std::pow(f / 30.0, 2 * n));
      EXPECT_NEAR(std::abs(analogResponse(sections, f)), expected, kExact * expected)
          << n << " " << f;
    }
  }
  // The 4th order's quality factors 1/(2 sin(π/8)) and 1/(2 sin(3π/8)).
  const std::vector<AnalogSection> fourth = butterworthLowPass(4, 1.0 / (2.0 * kPi));  // ω_c = 1
  EXPECT_NEAR(1.0 / fourth[0].a1, 1.3065629648763766, kExact);
  EXPECT_NEAR(1.0 / fourth[1].a1, 0.5411961001461970, kExact);
}

TEST(Butterworth, BilinearImageIsTheDigitalButterworth) {
  const double fs = 1000.0, fc = 30.0;
  for (int n : {2, 3, 4}) {
    const WeightingFilter filter(butterworthLowPass(n, fc), fs, Discretisation::BilinearPrewarped);
    for (double f : {0.0, 10.0, 30.0, 60.0, 200.0, 450.0}) {
      const double ratio = std::tan(kPi * f / fs) / std::tan(kPi * fc / fs);
      const double expected = 1.0 / std::sqrt(1.0 + std::pow(ratio, 2 * n));
      EXPECT_NEAR(std::abs(filter.response(f)), expected, kExact) << n << " " << f;
    }
    EXPECT_NEAR(std::abs(filter.response(fc)), std::sqrt(0.5), kExact);
    EXPECT_NEAR(std::abs(filter.response(0.5 * fs)), 0.0, kExact);  // zeros at Nyquist
  }
}

TEST(Butterworth, RejectsBadOrderAndCorner) {
  expectInputError([] { butterworthLowPass(0, 30.0); }, "order must be 1..12, got 0");
  expectInputError([] { butterworthLowPass(13, 30.0); }, "order must be 1..12, got 13");
  expectInputError([] { butterworthLowPass(4, 0.0); }, "corner frequency");
  expectInputError([] { butterworthLowPass(4, std::numeric_limits<double>::quiet_NaN()); },
                   "corner frequency");
}

std::vector<double> sineSamples(double amplitude, double frequency, double fs, double seconds) {
  std::vector<double> a;
  for (long k = 0; k < std::lround(seconds * fs); ++k)
    a.push_back(amplitude * std::sin(2.0 * kPi * frequency * k / fs));
  return a;
}

TEST(ShockMeter, PeaksOfSinusoidsFollowTheLowPassGain) {
  const double fs = 1000.0;
  const WeightingFilter reference(butterworthLowPass(4, 30.0), fs,
                                  Discretisation::BilinearPrewarped);
  // Well inside the pass band: the peak is the amplitude times the gain, within the start-up
  // transient of a 4th-order filter (below 0.5 % for a 2 Hz sine).
  ShockMeter pass(fs);
  for (double a : sineSamples(20.0, 2.0, fs, 5.0))
    pass.add(a);
  const double gain = std::abs(reference.response(2.0));
  EXPECT_NEAR(pass.peakUp(), 20.0 * gain, 0.005 * 20.0);
  EXPECT_NEAR(pass.peakAbsolute(), 20.0 * gain, 0.005 * 20.0);
  // Far in the stop band (100 Hz: gain 0.0078), the contact ringing the filter is there to
  // remove; faded in over 0.5 s (sin^2), since a sine switched on at once carries a broadband
  // onset of its own.
  ShockMeter stop(fs);
  const std::vector<double> fast = sineSamples(20.0, 100.0, fs, 2.0);
  for (std::size_t k = 0; k < fast.size(); ++k)
    stop.add(fast[k] * (k < 500 ? std::pow(std::sin(0.5 * kPi * k / 500.0), 2) : 1.0));
  const double stop_gain = std::abs(reference.response(100.0));
  EXPECT_NEAR(stop.peakAbsolute(), 20.0 * stop_gain, 0.02 * 20.0 * stop_gain);
  // Unfiltered: the samples' own extremes; peak up of a signal that only falls stays 0.
  ShockOptions raw;
  raw.lowpass_corner_hz = 0.0;
  ShockMeter plain(fs, raw);
  for (double a : {0.0, -3.0, 1.5, -7.25, 2.0})
    plain.add(a);
  EXPECT_EQ(plain.peakUp(), 2.0);
  EXPECT_EQ(plain.peakAbsolute(), 7.25);
  ShockMeter falling(fs, raw);
  for (double a : {0.0, -1.0, -2.0})
    falling.add(a);
  EXPECT_EQ(falling.peakUp(), 0.0);
  plain.reset();
  EXPECT_EQ(plain.peakAbsolute(), 0.0);
}

TEST(ShockMeter, RejectsBadCornerAndSamples) {
  ShockOptions high;
  high.lowpass_corner_hz = 500.0;
  expectInputError([&] { ShockMeter(1000.0, high); }, "fs/2 = 500");
  ShockOptions negative;
  negative.lowpass_corner_hz = -1.0;
  expectInputError([&] { ShockMeter(1000.0, negative); }, "got -1");
  expectInputError([] { ShockMeter(0.0); }, "sample rate");
  ShockMeter meter(1000.0);
  meter.add(1.0);
  const double before = meter.peakUp();
  expectInputError([&] { meter.add(std::numeric_limits<double>::infinity()); }, "not finite");
  EXPECT_EQ(meter.peakUp(), before);
}

std::vector<double> evaluateAll(const std::vector<double>& v, double (*f)(double)) {
  std::vector<double> m;
  for (double x : v)
    m.push_back(f(x));
  return m;
}

double square(double v) {
  return v * v;
}
double line(double v) {
  return 0.75 * v - 1.0;
}

TEST(LimitCrossing, BisectsToTheCrossingOfASquare) {
  const std::vector<double> speeds = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
  int calls = 0;
  const LimitCrossing c =
      findLimitCrossing(speeds, evaluateAll(speeds, square), 6.0, 1e-3, [&](double v) {
        ++calls;
        return square(v);
      });
  EXPECT_EQ(c.status, LimitCrossing::Status::Reached);
  EXPECT_LE(c.lower, std::sqrt(6.0));
  EXPECT_GE(c.upper, std::sqrt(6.0));
  EXPECT_LE(c.upper - c.lower, 1e-3);
  EXPECT_NEAR(c.speed, std::sqrt(6.0), 1e-6);  // chord of v^2 over 1e-3: error (Δv)^2 / 8 / (2v)
  EXPECT_EQ(c.refinements, 10);                // 2^-10 < 1e-3 < 2^-9
  EXPECT_EQ(calls, c.refinements);
  EXPECT_LT(c.lower_value, 6.0);
  EXPECT_GE(c.upper_value, 6.0);
}

TEST(LimitCrossing, ExactOnALinearMetricWithoutRefinement) {
  const std::vector<double> speeds = {0, 4, 8};
  const LimitCrossing c =
      findLimitCrossing(speeds, evaluateAll(speeds, line), 2.5, 10.0,
                        [](double) -> double { throw std::logic_error("not needed"); });
  EXPECT_EQ(c.status, LimitCrossing::Status::Reached);
  EXPECT_NEAR(c.speed, 3.5 / 0.75, kExact);
  EXPECT_EQ(c.refinements, 0);
}

TEST(LimitCrossing, ReportsTheFirstCrossingAndTheEnds) {
  // Up, down, up again: the first interval that brackets the limit is the one searched.
  const std::vector<double> speeds = {0, 1, 2, 3};
  const std::vector<double> bumpy = {0, 10, 2, 10};
  const LimitCrossing first =
      findLimitCrossing(speeds, bumpy, 5.0, 0.25, [](double v) { return 10.0 * v; });
  EXPECT_EQ(first.status, LimitCrossing::Status::Reached);
  EXPECT_NEAR(first.speed, 0.5, kExact);
  const LimitCrossing low =
      findLimitCrossing(speeds, {7, 8, 9, 10}, 5.0, 0.1, [](double) { return 0.0; });
  EXPECT_EQ(low.status, LimitCrossing::Status::AtLowest);
  EXPECT_EQ(low.speed, 0.0);
  const LimitCrossing none =
      findLimitCrossing(speeds, {1, 2, 3, 4}, 5.0, 0.1, [](double) { return 0.0; });
  EXPECT_EQ(none.status, LimitCrossing::Status::NotReached);
  EXPECT_EQ(none.speed, 3.0);
  EXPECT_STREQ(limitStatusName(none.status), "not_reached");
  // The limit itself counts as reached.
  EXPECT_EQ(findLimitCrossing({1, 2}, {1, 5}, 5.0, 2.0, square).speed, 2.0);
}

TEST(LimitCrossing, RejectsBadSweeps) {
  auto f = [](double v) { return v; };
  expectInputError([&] { findLimitCrossing({}, {}, 1.0, 0.1, f); }, "no speeds");
  expectInputError([&] { findLimitCrossing({1, 2}, {1}, 1.0, 0.1, f); }, "1 values for 2 speeds");
  expectInputError([&] { findLimitCrossing({1, 1}, {1, 2}, 1.5, 0.1, f); }, "strictly increasing");
  expectInputError([&] { findLimitCrossing({1, 2}, {1, 2}, 1.5, 0.0, f); }, "tolerance");
  expectInputError(
      [&] {
        findLimitCrossing({1, 2}, {1, 2}, std::nan(""), 0.1, f);
      },
      "limit is not finite");
  // A tolerance below one ulp of the speed stops at adjacent doubles instead of looping forever.
  const LimitCrossing fine = findLimitCrossing({1, 2}, {1, 2}, 1.5, 1e-300, f);
  EXPECT_EQ(fine.status, LimitCrossing::Status::Reached);
  EXPECT_EQ(std::nextafter(fine.lower, 2.0), fine.upper);
  EXPECT_NEAR(fine.speed, 1.5, 1e-15);
  expectInputError(
      [&] {
        findLimitCrossing({1, 2}, {1, std::nan("")}, 1.5, 0.1, f);
      },
      "at speed 2");
  expectInputError(
      [&] {
        findLimitCrossing({1, 2}, {1, 2}, 1.5, 0.01, [](double) { return std::nan(""); });
      },
      "at speed 1.5");
}

}  // namespace
}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
