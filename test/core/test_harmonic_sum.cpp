// harmonicSum (the chirp z-transform behind the ISO 8608 roads) against the term-by-term sum it
// replaces.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "tracked_vehicle_dynamics/terrain/harmonic_sum.h"

namespace tracked_vehicle_dynamics {
namespace terrain {
namespace {

using Complex = std::complex<double>;

std::vector<Complex> randomCoefficients(std::size_t count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> amplitude(0.0, 1.0), phase(0.0, 2.0 * kPi);
  std::vector<Complex> c(count);
  for (Complex& value : c)
    value = std::polar(amplitude(rng), phase(rng));
  return c;
}

/// Re Σ_p c_p e^{i 2π r (first + p) j}, its phase reduced in long double from the exact integer
/// (first + p) j: the reference, accurate to ~1e-19 per term.
double directSum(const std::vector<Complex>& c, long long first, double r, long long j) {
  long double sum = 0.0L;
  for (std::size_t p = 0; p < c.size(); ++p) {
    const long long kj = (first + static_cast<long long>(p)) * j;
    const long double cycles = static_cast<long double>(kj) * static_cast<long double>(r);
    const long double turn = cycles - std::floor(cycles);
    const long double angle = 2.0L * 3.14159265358979323846264338327950288L * turn;
    sum += static_cast<long double>(c[p].real()) * std::cos(angle) -
           static_cast<long double>(c[p].imag()) * std::sin(angle);
  }
  return static_cast<double>(sum);
}

double absoluteSum(const std::vector<Complex>& c) {
  double total = 0.0;
  for (const Complex& value : c)
    total += std::abs(value);
  return total;
}

struct Case {
  Eigen::Index stations;
  long long first;
  std::size_t harmonics;
  double r;
};

// Every station against the reference: a road length a whole number of spacings (r = 1/M, a
// plain DFT), one that is not (r irrational), one harmonic, one station, the first harmonic at 0
// and far up, more harmonics than stations, sizes that are and are not 2^a 3^b 5^c.
TEST(HarmonicSum, EqualsTheTermByTermSum) {
  const std::vector<Case> cases = {
      {2001, 1, 566, 1.0 / 2000.0},           // 100 m at 5 cm, ISO band from 0.011 cycles/m
      {2001, 3, 563, 0.05 / 100.3},           // a length not a multiple of the spacing
      {1000, 0, 1, std::sqrt(2.0) / 1000.0},  // a single harmonic, the constant one
      {1, 5, 40, 0.001},                      // a single station: Re Σ c_p
      {1, 0, 1, 0.1},                         // one station, one harmonic: a transform of 2
      {1, 1000000, 1, 0.1},                   // the same far up
      {777, 4000, 300, 1.0 / 776.0},          // harmonics above Nyquist alias, as in the sum
      {50, 2, 1000, 0.013},                   // more harmonics than stations
      {4097, 17, 2049, 1.0 / 4096.0},         // N + K - 1 just above a power of two
  };
  unsigned seed = 1;
  for (const Case& test : cases) {
    const std::vector<Complex> c = randomCoefficients(test.harmonics, seed++);
    const Vector h = harmonicSum(c, test.first, test.r, test.stations);
    ASSERT_EQ(h.size(), test.stations);
    double worst = 0.0;
    for (Eigen::Index j = 0; j < test.stations; ++j)
      worst = std::max(worst, std::abs(h(j) - directSum(c, test.first, test.r, j)));
    EXPECT_LT(worst, 1e-14 * absoluteSum(c))
        << test.stations << " stations, harmonics " << test.first << " + " << test.harmonics;
  }
}

// A long road: 2.6 km at 5 mm (520,001 stations, 7,300 harmonics: 3.8e9 terms, over a minute
// summed term by term). The chirp phases grow to ~(N + K)^2 r = 5e5 turns; reduced exactly they
// lose nothing, so the far end is as accurate as the start (checked at 40 stations).
TEST(HarmonicSum, LongRoadsKeepTheirPhase) {
  const Eigen::Index stations = 520001;
  const long long first = 29;
  const std::vector<Complex> c = randomCoefficients(7330, 11);
  const double r = 0.005 / 2600.0;
  const Vector h = harmonicSum(c, first, r, stations);
  double worst = 0.0;
  for (Eigen::Index j = 0; j < stations; j += stations / 37)
    worst = std::max(worst, std::abs(h(j) - directSum(c, first, r, j)));
  worst = std::max(worst, std::abs(h(stations - 1) - directSum(c, first, r, stations - 1)));
  EXPECT_LT(worst, 1e-14 * absoluteSum(c));
}

TEST(HarmonicSum, NoHarmonicsIsZeroAndBadArgumentsThrow) {
  EXPECT_EQ(harmonicSum({}, 3, 0.01, 5), Vector::Zero(5));
  EXPECT_THROW(harmonicSum({Complex(1.0, 0.0)}, 0, 0.01, 0), std::invalid_argument);
  EXPECT_THROW(harmonicSum({Complex(1.0, 0.0)}, -1, 0.01, 5), std::invalid_argument);
  EXPECT_THROW(harmonicSum({Complex(1.0, 0.0)}, 0, std::nan(""), 5), std::invalid_argument);
  EXPECT_THROW(harmonicSum({Complex(1.0, 0.0)}, 0, 1.5, 5), std::invalid_argument);
}

}  // namespace
}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
