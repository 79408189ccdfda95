#include "tracked_vehicle_dynamics/terrain/harmonic_sum.h"

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace tracked_vehicle_dynamics {
namespace terrain {
namespace {

using Complex = std::complex<double>;

// |m| below which m^2 is exact in a double (2^53).
constexpr long long kMaxChirpIndex = 94906265;

/// w_m = e^{i π r m^2}. The phase r m^2 grows to about (N + K)^2 r, 3e7 half-turns on a
/// 2e7-station road: its rounding alone would cost ~1e-8 rad there. Split exactly as hi + lo (the
/// rounded product and its error by fma) and reduce hi modulo 2 (fmod is exact), so every chirp
/// carries the error of r's own rounding only, and that cancels between the three chirps of a
/// term: their phases add up to 2π r k j for the one r used.
Complex chirp(double r, long long m) {
  const double m2 = static_cast<double>(m * m);
  const double hi = m2 * r;
  const double lo = std::fma(m2, r, -hi);
  return std::polar(1.0, kPi * (std::fmod(hi, 2.0) + lo));
}

/// Smallest 2^a 3^b 5^c >= n: the radices the FFT does fastest, at most 25 % above n.
std::size_t fftSize(std::size_t n) {
  std::size_t best = 1;
  while (best < n)
    best *= 2;
  for (std::size_t p3 = 1; p3 < best; p3 *= 3) {
    for (std::size_t p35 = p3; p35 < best; p35 *= 5) {
      std::size_t size = p35;
      while (size < n)
        size *= 2;
      best = std::min(best, size);
    }
  }
  return best;
}

}  // namespace

Vector harmonicSum(const std::vector<Complex>& c, long long first, double r, Eigen::Index count) {
  // |r| <= 1 (a road's spacing over its length): beyond it r m^2 leaves the range where the
  // chirps' phases are exact.
  if (count < 1 || first < 0 || !(std::abs(r) <= 1.0))
    throw std::invalid_argument("harmonicSum: count >= 1, first >= 0 and |r| <= 1 needed");
  const auto harmonics = static_cast<long long>(c.size());
  if (harmonics == 0)
    return Vector::Zero(count);
  const long long stations = count;
  if (first + harmonics > kMaxChirpIndex || stations > kMaxChirpIndex)
    throw std::invalid_argument("harmonicSum: more than 9.4e7 harmonics or stations");

  // H_j = w_j y_j,  y_j = Σ_p A_p b_{j+K-1-p},  A_p = c_p w_{first+p},
  // b_q = conj(w_{q-(first+K-1)}) for q = 0 .. N+K-2: a linear convolution, taken as a circular
  // one of size P >= N + K - 1 (its indices j + K - 1 - p stay in [0, N + K - 2]: no wrap).
  // At least 2: kissfft fails on a transform of one point (one station and one harmonic).
  const std::size_t size =
      fftSize(std::max<std::size_t>(2, static_cast<std::size_t>(stations + harmonics - 1)));
  Eigen::FFT<double> fft;
  std::vector<Complex> a_spectrum;
  {
    std::vector<Complex> a(size, Complex(0.0, 0.0));
    for (long long p = 0; p < harmonics; ++p)
      a[p] = c[p] * chirp(r, first + p);
    fft.fwd(a_spectrum, a);
  }
  {
    std::vector<Complex> b(size, Complex(0.0, 0.0));
    const long long shift = first + harmonics - 1;
    for (long long q = 0; q < stations + harmonics - 1; ++q)
      b[q] = std::conj(chirp(r, q - shift));
    std::vector<Complex> b_spectrum;
    fft.fwd(b_spectrum, b);
    for (std::size_t i = 0; i < size; ++i)
      a_spectrum[i] *= b_spectrum[i];
  }
  std::vector<Complex> y;
  fft.inv(y, a_spectrum);  // scaled by 1/P

  Vector h(count);
  for (long long j = 0; j < stations; ++j)
    h(j) = (chirp(r, j) * y[j + harmonics - 1]).real();
  return h;
}

}  // namespace terrain
}  // namespace tracked_vehicle_dynamics
