#include "tracked_vehicle_dynamics/terrain/iso8608.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <complex>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/terrain/harmonic_sum.h"

namespace tracked_vehicle_dynamics {
namespace terrain {
namespace {

// G_d(n0) of class A [m^3]; each further class is x4 (ISO 8608, the classes' geometric means).
constexpr double kClassAReferencePsd = 16e-6;
constexpr double kClassRatio = 4.0;
// The profile's heights and its chirp z-transform's buffers (harmonic_sum.h: three complex arrays
// of up to 1.25 (stations + harmonics)) are held in memory: 2e7 stations, 1000 km at 5 cm, take
// about 2 GB. A typo in the length is refused rather than exhausting the machine.
constexpr double kMaxStations = 2e7;
// Amplitude of a harmonic whose bin misses the band: no harmonic, no phase drawn.
constexpr double kNoBin = -1.0;

[[noreturn]] void fail(const std::string& what) {
  throw InputError("ISO 8608 road: " + what);
}

int classIndex(char road_class) {
  const char upper = static_cast<char>(std::toupper(static_cast<unsigned char>(road_class)));
  if (upper < 'A' || upper > 'H') {
    fail(std::string("class '") + road_class + "' is not one of A..H");
  }
  return upper - 'A';
}

/// Uniform on [0, 1) from the top 53 bits: the same on every standard library.
double uniform(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

/// One profile of the band's harmonics (k_first + p) Δn with fresh phases from rng, at stations
/// j spacing, j = 0 .. count-1: Re Σ_p a_p e^{i φ_p} e^{i 2π (k_first + p) j spacing / length}.
Vector synthesise(long long k_first, const std::vector<double>& amplitudes, double ratio,
                  Eigen::Index count, std::mt19937_64& rng) {
  std::vector<std::complex<double>> coefficients(amplitudes.size());
  for (std::size_t p = 0; p < amplitudes.size(); ++p) {
    // A bin outside the band (amplitude kNoBin) draws no phase.
    if (amplitudes[p] >= 0.0)
      coefficients[p] = std::polar(amplitudes[p], 2.0 * kPi * uniform(rng));
  }
  return harmonicSum(coefficients, k_first, ratio, count);
}

}  // namespace

double iso8608ReferencePsd(char road_class) {
  return kClassAReferencePsd * std::pow(kClassRatio, classIndex(road_class));
}

double iso8608Psd(char road_class, double n, double waviness) {
  const double reference = iso8608ReferencePsd(road_class);
  if (!(n > 0.0) || !std::isfinite(n))
    fail("spatial frequency " + brief(n) + " must be > 0");
  return reference * std::pow(n / kIso8608ReferenceFrequency, -waviness);
}

double iso8608Variance(char road_class, double n_low, double n_high, double waviness) {
  const double reference = iso8608ReferencePsd(road_class);
  if (!(n_low > 0.0 && n_low <= n_high && std::isfinite(n_high))) {
    fail("band [" + brief(n_low) + ", " + brief(n_high) +
         "] cycles/m must satisfy 0 < low <= high");
  }
  const double n0 = kIso8608ReferenceFrequency;
  // ∫ G0 (n/n0)^-w dn = G0 n0^w [n^(1-w) / (1-w)], or G0 n0 ln(n) for w = 1.
  if (std::abs(waviness - 1.0) < 1e-12)
    return reference * n0 * std::log(n_high / n_low);
  const double e = 1.0 - waviness;
  return reference * std::pow(n0, waviness) * (std::pow(n_high, e) - std::pow(n_low, e)) / e;
}

Terrain makeIso8608(char road_class, double length, double width, double spacing,
                    std::uint64_t seed, const Iso8608Options& options) {
  const char upper = static_cast<char>('A' + classIndex(road_class));
  if (!(std::isfinite(length) && length > 0.0))
    fail("length " + brief(length) + " m must be > 0");
  if (!(std::isfinite(width) && width >= 0.0))
    fail("width " + brief(width) + " m must be >= 0");
  if (!(std::isfinite(spacing) && spacing > 0.0 && spacing <= length)) {
    fail("spacing " + brief(spacing) + " m must be in (0, length]");
  }
  if (!(std::isfinite(options.waviness) && options.waviness > 0.0)) {
    fail("waviness " + brief(options.waviness) + " must be > 0");
  }
  const double nyquist = 0.5 / spacing;
  if (!(options.min_frequency > 0.0 && options.min_frequency < options.max_frequency &&
        options.max_frequency <= nyquist)) {
    fail("band [" + brief(options.min_frequency) + ", " + brief(options.max_frequency) +
         "] cycles/m must satisfy 0 < min < max <= Nyquist 1/(2 spacing) = " + brief(nyquist));
  }
  if (!(std::isfinite(options.taper_length) && options.taper_length >= 0.0 &&
        options.taper_length <= 0.5 * length)) {
    fail("taper_length " + brief(options.taper_length) + " m must be in [0, length / 2]");
  }
  const bool sides = options.correlation == LateralCorrelation::IndependentSides;
  if (sides && !(options.side_gap > 0.0 && options.side_gap < width)) {
    fail("side_gap " + brief(options.side_gap) + " m must be in (0, width = " + brief(width) +
         " m) for independent sides");
  }

  const double stations = std::floor(length / spacing + 1e-9) + 1.0;
  if (stations > kMaxStations) {
    fail("length " + brief(length) + " m at spacing " + brief(spacing) + " m needs " +
         brief(stations) + " stations; at most " + brief(kMaxStations) +
         " (1000 km at 0.05 m, about 2 GB): generate a shorter road");
  }

  // Harmonics k Δn whose bins [(k - 1/2) Δn, (k + 1/2) Δn] meet the band, below Nyquist (they
  // number fewer than half the stations): k_first, k_first + 1, ..., kNoBin for a bin that misses
  // the band (at most one at either end, by round-off).
  const double dn = 1.0 / length;
  const auto k_first =
      std::max<long long>(1, static_cast<long long>(std::floor(options.min_frequency / dn + 0.5)));
  const auto k_last = static_cast<long long>(std::ceil(options.max_frequency / dn - 0.5));
  std::vector<double> amplitudes;
  bool any = false;
  for (long long k = k_first; k <= k_last; ++k) {
    const double n = static_cast<double>(k) * dn;
    if (n >= nyquist)
      break;
    const double low = std::max(options.min_frequency, n - 0.5 * dn);
    const double high = std::min(options.max_frequency, n + 0.5 * dn);
    amplitudes.push_back(
        high > low ? std::sqrt(2.0 * iso8608Variance(upper, low, high, options.waviness)) : kNoBin);
    any = any || high > low;
  }
  if (!any) {
    fail("band [" + brief(options.min_frequency) + ", " + brief(options.max_frequency) +
         "] cycles/m holds no harmonic of 1/length = " + brief(dn) + " cycles/m");
  }

  const auto count = static_cast<Eigen::Index>(stations);
  Vector x(count);
  for (Eigen::Index i = 0; i < count; ++i)
    x(i) = static_cast<double>(i) * spacing;

  // ω_k x_j = 2π k j (spacing / length).
  const double ratio = spacing / length;
  std::mt19937_64 rng(seed);
  const Vector right = synthesise(k_first, amplitudes, ratio, count, rng);
  const Vector left = sides ? synthesise(k_first, amplitudes, ratio, count, rng) : right;

  Vector taper = Vector::Ones(count);
  if (options.taper_length > 0.0) {
    const double end = x(count - 1);
    for (Eigen::Index i = 0; i < count; ++i) {
      const double d = std::min(x(i), end - x(i));
      if (d < options.taper_length) {
        taper(i) = 0.5 * (1.0 - std::cos(kPi * d / options.taper_length));
      }
    }
  }

  Vector y;
  Matrix h;
  if (sides) {
    y.resize(4);
    y << -0.5 * width, -0.5 * options.side_gap, 0.5 * options.side_gap, 0.5 * width;
    h.resize(4, count);
    h.row(0) = h.row(1) = right.cwiseProduct(taper).transpose();
    h.row(2) = h.row(3) = left.cwiseProduct(taper).transpose();
  } else if (width > 0.0) {
    y.resize(2);
    y << -0.5 * width, 0.5 * width;
    h.resize(2, count);
    h.row(0) = h.row(1) = right.cwiseProduct(taper).transpose();
  } else {
    y = Vector::Zero(1);
    h = right.cwiseProduct(taper).transpose();
  }
  std::ostringstream name;
  name << "iso8608_" << upper << "_seed" << seed;
  return Terrain(x, y, h, name.str());
}

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
