#include "tracked_vehicle_dynamics/dynamics/comfort.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Butterworth quality factor of the band-limiting filters.
const double kButterworthQ = 1.0 / std::sqrt(2.0);
// Above this fraction of fs the 100 Hz band-limiting low-pass is not discretised (file comment).
constexpr double kLowPassLimit = 0.4;
// Magnitude-matched fit: log grid points, and the weight of the grid above kFitKnee * fs. A
// digital biquad cannot follow an analogue flank all the way to Nyquist; weighting the top down
// buys ~0.01 dB up to fs/10 (0.05 dB to fs/4) for ~1.5 dB near Nyquist, where |W| < -30 dB.
constexpr int kFitGridPoints = 240;
constexpr double kFitKnee = 0.25;
constexpr double kFitTopWeight = 0.03;
// A section of two finite zeros and two poles, all within |s| T <= this (below fs / 12.6): its
// zeros are mapped as its poles are (matched z-transform) instead of fitted.
constexpr double kMatchedRootLimit = 0.5;

const char* weightingName(Weighting weighting) {
  switch (weighting) {
    case Weighting::Wk:
      return "Wk";
    case Weighting::Wd:
      return "Wd";
    case Weighting::We:
      return "We";
  }
  return "?";
}

void checkSampleRate(double sample_rate) {
  if (!std::isfinite(sample_rate) || sample_rate <= 0.0) {
    throw InputError("comfort: sample rate " + brief(sample_rate) + " Hz must be positive");
  }
}

void checkOptions(const ComfortOptions& options) {
  if (!std::isfinite(options.running_rms_time) || options.running_rms_time <= 0.0) {
    throw InputError("comfort: running_rms_time " + brief(options.running_rms_time) +
                     " s must be positive");
  }
}

/// The ISO weighting filter of `options`, after checking the sample rate and options.
WeightingFilter validatedWeighting(double sample_rate, const ComfortOptions& options) {
  checkSampleRate(sample_rate);
  checkOptions(options);
  return WeightingFilter::iso2631(options.weighting, sample_rate, options.discretisation);
}

std::complex<double> sectionResponse(const AnalogSection& section, double frequency) {
  const std::complex<double> s(0.0, 2.0 * kPi * frequency);
  return (section.b0 + s * (section.b1 + s * section.b2)) /
         (section.a0 + s * (section.a1 + s * section.a2));
}

}  // namespace

Iso2631Parameters iso2631Parameters(Weighting weighting) {
  // ISO 2631-1:1997, Annex A.
  switch (weighting) {
    case Weighting::Wk:
      return {0.4, 100.0, 12.5, 12.5, 0.63, 2.37, 0.91, 3.35, 0.91};
    case Weighting::Wd:
      return {0.4, 100.0, 2.0, 2.0, 0.63, kInfinity, 0.0, kInfinity, 0.0};
    case Weighting::We:
      return {0.4, 100.0, 1.0, 1.0, 0.63, kInfinity, 0.0, kInfinity, 0.0};
  }
  throw InputError("comfort: unknown weighting " + std::to_string(static_cast<int>(weighting)));
}

std::vector<AnalogSection> iso2631Sections(Weighting weighting) {
  const Iso2631Parameters p = iso2631Parameters(weighting);
  const double w1 = 2.0 * kPi * p.f1;
  const double w2 = 2.0 * kPi * p.f2;
  const double w3 = 2.0 * kPi * p.f3;
  const double w4 = 2.0 * kPi * p.f4;
  std::vector<AnalogSection> sections;
  // H_h = s^2 / (s^2 + ω1 s / Q1 + ω1^2)
  sections.push_back({0.0, 0.0, 1.0, w1 * w1, w1 / kButterworthQ, 1.0, p.f1});
  // H_l = ω2^2 / (s^2 + ω2 s / Q1 + ω2^2)
  sections.push_back({w2 * w2, 0.0, 0.0, w2 * w2, w2 / kButterworthQ, 1.0, p.f2});
  // H_t = (1 + s / ω3) / (1 + s / (Q4 ω4) + s^2 / ω4^2)
  sections.push_back({1.0, 1.0 / w3, 0.0, 1.0, 1.0 / (p.q4 * w4), 1.0 / (w4 * w4), p.f4});
  if (std::isfinite(p.f5)) {
    // H_s = (s^2 + ω5 s / Q5 + ω5^2) / (s^2 + ω6 s / Q6 + ω6^2): 1 at high frequency,
    // (f5/f6)^2 below the step.
    const double w5 = 2.0 * kPi * p.f5;
    const double w6 = 2.0 * kPi * p.f6;
    sections.push_back({w5 * w5, w5 / p.q5, 1.0, w6 * w6, w6 / p.q6, 1.0, std::sqrt(p.f5 * p.f6)});
  }
  return sections;
}

std::complex<double> analogResponse(const std::vector<AnalogSection>& sections, double frequency) {
  std::complex<double> h(1.0, 0.0);
  for (const AnalogSection& section : sections)
    h *= sectionResponse(section, frequency);
  return h;
}

std::complex<double> iso2631Response(Weighting weighting, double frequency) {
  return analogResponse(iso2631Sections(weighting), frequency);
}

double seatTranslationalTotalValue(double x, double y, double z) {
  return std::sqrt(x * x + y * y + z * z);
}

double seatRotationalTotalValue(double roll, double pitch, double yaw) {
  return seatTranslationalTotalValue(SeatRotationFactors::roll * roll,
                                     SeatRotationFactors::pitch * pitch,
                                     SeatRotationFactors::yaw * yaw);
}

std::vector<AnalogSection> absorbedPowerVerticalSections() {
  // H_p(s) = 14.5 s (s + 44) / ((s + 63)(s^2 + 24 s + 750)) for ft/s^2 (header comment); a in
  // m/s^2 is a / 0.3048 in ft/s^2, so the gain for m/s^2 is 14.5 / 0.3048.
  constexpr double kGainPerFootPerSecond2 = 14.5;
  constexpr double kMetresPerFoot = 0.3048;
  const double gain = kGainPerFootPerSecond2 / kMetresPerFoot;
  AnalogSection band;
  band.b0 = 0.0;
  band.b1 = 44.0 * gain;
  band.b2 = gain;
  band.a0 = 750.0;
  band.a1 = 24.0;
  band.a2 = 1.0;
  AnalogSection low_pass;
  low_pass.b0 = 1.0;
  low_pass.a0 = 63.0;
  low_pass.a1 = 1.0;
  return {band, low_pass};
}

// ---------------------------------------------------------------------------------------------

double WeightingFilter::Biquad::step(double x) {
  const double y = b0 * x + s1;
  s1 = b1 * x - a1 * y + s2;
  s2 = b2 * x - a2 * y;
  return y;
}

namespace {

/// Roots of c2 s^2 + c1 s + c0 (one or none when the polynomial is of lower degree).
std::vector<std::complex<double>> roots(double c2, double c1, double c0) {
  if (c2 != 0.0) {
    const std::complex<double> root = std::sqrt(std::complex<double>(c1 * c1 - 4.0 * c2 * c0));
    return {(-c1 + root) / (2.0 * c2), (-c1 - root) / (2.0 * c2)};
  }
  if (c1 != 0.0)
    return {std::complex<double>(-c0 / c1, 0.0)};
  return {};
}

std::vector<std::complex<double>> poles(const AnalogSection& a) {
  return roots(a.a2, a.a1, a.a0);
}

/// Weighted least squares min Σ_i w_i^2 ((features_i · x - target_i) / target_i)^2.
Vector fitRelative(const Matrix& features, const Vector& target, const Vector& weights) {
  const Matrix rows = (weights.array() / target.array()).matrix().asDiagonal() * features;
  return rows.colPivHouseholderQr().solve(weights);
}

}  // namespace

WeightingFilter::Biquad WeightingFilter::bilinear(const AnalogSection& a, double sample_rate) {
  // s = K (1 - z^-1) / (1 + z^-1); both polynomials multiplied by (1 + z^-1)^2.
  const double wp = 2.0 * kPi * a.prewarp_frequency;
  const double k =
      a.prewarp_frequency > 0.0 ? wp / std::tan(wp / (2.0 * sample_rate)) : 2.0 * sample_rate;
  const double k2 = k * k;
  const double n0 = a.b0 + a.b1 * k + a.b2 * k2;
  const double n1 = 2.0 * (a.b0 - a.b2 * k2);
  const double n2 = a.b0 - a.b1 * k + a.b2 * k2;
  const double d0 = a.a0 + a.a1 * k + a.a2 * k2;
  const double d1 = 2.0 * (a.a0 - a.a2 * k2);
  const double d2 = a.a0 - a.a1 * k + a.a2 * k2;
  return {n0 / d0, n1 / d0, n2 / d0, d1 / d0, d2 / d0};
}

WeightingFilter::Biquad WeightingFilter::matchedMagnitude(const AnalogSection& a,
                                                          double sample_rate) {
  const double t = 1.0 / sample_rate;
  // Poles: z = exp(p T), exactly.
  Biquad q{0.0, 0.0, 0.0, 0.0, 0.0};
  const std::vector<std::complex<double>> p = poles(a);
  if (p.size() == 2) {
    const std::complex<double> z1 = std::exp(p[0] * t);
    const std::complex<double> z2 = std::exp(p[1] * t);
    q.a1 = -(z1 + z2).real();
    q.a2 = (z1 * z2).real();
  } else if (p.size() == 1) {
    q.a1 = -std::exp(p[0].real() * t);
  }
  // Zeros of H at s = 0 stay exact zeros at z = 1: B(z) = (1 - z^-1)^m R(z), deg R = 2 - m.
  const int m = a.b0 != 0.0 ? 0 : (a.b1 != 0.0 ? 1 : 2);

  // Two finite zeros and two poles, all well below Nyquist (Wk's upward step): the zeros too are
  // mapped exactly, z = exp(s_z T), and the gain matched at DC, B(1)/A(1) = H(0). With equal
  // degrees the mapping distorts numerator and denominator alike and the two cancel: for the
  // upward step within 0.002 dB of |H| up to fs/10 from fs ≈ 42 Hz (the lowest rate at which its
  // roots satisfy |s| T <= kMatchedRootLimit), 1e-5 dB at 1 kHz. The fit below
  // cannot recover such zeros at a high fs, whose radius differs from 1 by 2 zeta omega T ~ 1e-4
  // (the 8 Hz weighted 11 dB low at fs = 100 kHz; review 133). (1 - z) = -expm1(s T) keeps the
  // DC products accurate when every root is near z = 1.
  if (m == 0 && a.b2 != 0.0 && p.size() == 2) {
    const std::vector<std::complex<double>> zeros = roots(a.b2, a.b1, a.b0);
    const std::complex<double>& s1 = zeros[0];
    const std::complex<double>& s2 = zeros[1];
    double largest = 0.0;
    for (const std::complex<double>& r : {s1, s2, p[0], p[1]})
      largest = std::max(largest, std::abs(r) * t);
    if (largest <= kMatchedRootLimit) {
      const auto expm1 = [](const std::complex<double>& x) {
        // exp(x) - 1 accurate for small |x|: expm1 of the real part, the rotation apart.
        const double e = std::expm1(x.real());
        return std::complex<double>(
            e * std::cos(x.imag()) - 2.0 * std::pow(std::sin(0.5 * x.imag()), 2),
            (e + 1.0) * std::sin(x.imag()));
      };
      const std::complex<double> z1 = std::exp(s1 * t);
      const std::complex<double> z2 = std::exp(s2 * t);
      const double numerator_dc = (expm1(s1 * t) * expm1(s2 * t)).real();  // (1 - z1)(1 - z2)
      const double denominator_dc = (expm1(p[0] * t) * expm1(p[1] * t)).real();
      const double gain = (a.b0 / a.a0) * denominator_dc / numerator_dc;
      q.b0 = gain;
      q.b1 = -gain * (z1 + z2).real();
      q.b2 = gain * (z1 * z2).real();
      return q;
    }
  }

  // Log grid from well below the section's slowest root to Nyquist (and DC when H(0) != 0).
  double slowest = 0.5 * sample_rate;
  for (const std::complex<double>& pole : p) {
    slowest = std::min(slowest, std::abs(pole) / (2.0 * kPi));
  }
  if (m == 0 && a.b1 != 0.0)
    slowest = std::min(slowest, std::abs(a.b0 / a.b1) / (2.0 * kPi));
  const double low = 1e-2 * slowest;
  const double high = 0.5 * sample_rate;
  std::vector<double> frequencies;
  if (m == 0)
    frequencies.push_back(0.0);
  for (int i = 0; i < kFitGridPoints; ++i) {
    frequencies.push_back(low *
                          std::pow(high / low, static_cast<double>(i) / (kFitGridPoints - 1)));
  }

  const int unknowns = 3 - m;
  Matrix features(static_cast<Eigen::Index>(frequencies.size()), unknowns);
  Vector target(static_cast<Eigen::Index>(frequencies.size()));
  Vector weights(static_cast<Eigen::Index>(frequencies.size()));
  for (std::size_t i = 0; i < frequencies.size(); ++i) {
    const double w = 2.0 * kPi * frequencies[i] * t;
    const double phi1 = std::pow(std::sin(0.5 * w), 2);
    const double phi0 = 1.0 - phi1;
    const std::complex<double> z_inv = std::polar(1.0, -w);
    const double denominator = std::norm(1.0 + z_inv * (q.a1 + z_inv * q.a2));
    // |R|^2 = |H|^2 |A|^2 / |1 - z^-1|^(2m), |1 - z^-1|^2 = 4 phi1.
    const auto row = static_cast<Eigen::Index>(i);
    target(row) =
        std::norm(sectionResponse(a, frequencies[i])) * denominator / std::pow(4.0 * phi1, m);
    weights(row) = frequencies[i] > kFitKnee * sample_rate ? kFitTopWeight : 1.0;
    if (m == 0)
      features.row(row) << phi0, phi1, 4.0 * phi0 * phi1;
    if (m == 1)
      features.row(row) << phi0, phi1;
    if (m == 2)
      features.row(row) << 1.0;
  }
  const Vector x = fitRelative(features, target, weights);
  if (m == 0) {
    const double r0 = std::sqrt(std::max(0.0, x(0)));  // |b0 + b1 + b2|
    const double r1 = std::sqrt(std::max(0.0, x(1)));  // |b0 - b1 + b2|
    const double sum = 0.5 * (r0 + r1);                // b0 + b2
    const double root = std::sqrt(std::max(0.0, sum * sum + x(2)));
    q.b0 = 0.5 * (sum + root);  // the larger root: |b2| <= |b0|, zeros inside the unit circle
    q.b1 = 0.5 * (r0 - r1);
    q.b2 = 0.5 * (sum - root);
  } else if (m == 1) {
    const double r0 = std::sqrt(std::max(0.0, x(0)));
    const double r1 = std::sqrt(std::max(0.0, x(1)));
    const double beta0 = 0.5 * (r0 + r1);
    const double beta1 = 0.5 * (r0 - r1);
    q.b0 = beta0;
    q.b1 = beta1 - beta0;
    q.b2 = -beta1;
  } else {
    const double k = std::sqrt(std::max(0.0, x(0)));
    q.b0 = k;
    q.b1 = -2.0 * k;
    q.b2 = k;
  }
  // The fit fixes |B| only: take the sign of H.
  double agreement = 0.0;
  for (double f : frequencies) {
    const std::complex<double> z_inv = std::polar(1.0, -2.0 * kPi * f * t);
    const std::complex<double> digital =
        (q.b0 + z_inv * (q.b1 + z_inv * q.b2)) / (1.0 + z_inv * (q.a1 + z_inv * q.a2));
    agreement += (digital * std::conj(sectionResponse(a, f))).real();
  }
  if (agreement < 0.0) {
    q.b0 = -q.b0;
    q.b1 = -q.b1;
    q.b2 = -q.b2;
  }
  return q;
}

WeightingFilter::WeightingFilter(std::vector<AnalogSection> sections, double sample_rate,
                                 Discretisation discretisation)
    : sections_(std::move(sections)), sample_rate_(sample_rate) {
  checkSampleRate(sample_rate);
  const double nyquist = 0.5 * sample_rate;
  for (std::size_t i = 0; i < sections_.size(); ++i) {
    const AnalogSection& a = sections_[i];
    const std::string where = "weighting filter section " + std::to_string(i) + ": ";
    for (double c : {a.b0, a.b1, a.b2, a.a0, a.a1, a.a2, a.prewarp_frequency}) {
      if (!std::isfinite(c))
        throw InputError(where + "coefficient is not finite");
    }
    if (a.b0 == 0.0 && a.b1 == 0.0 && a.b2 == 0.0)
      throw InputError(where + "numerator is zero");
    if (a.a0 == 0.0 && a.a1 == 0.0 && a.a2 == 0.0)
      throw InputError(where + "denominator is zero");
    for (const std::complex<double>& pole : poles(a)) {
      if (!(pole.real() < 0.0)) {
        throw InputError(where + "pole " + brief(pole.real()) + (pole.imag() < 0 ? " - " : " + ") +
                         brief(std::abs(pole.imag())) +
                         "j rad/s is not in the open left half-plane (unstable filter)");
      }
      if (discretisation == Discretisation::MatchedMagnitude &&
          std::abs(pole.imag()) >= kPi * sample_rate) {
        throw InputError(where + "pole oscillates at " +
                         brief(std::abs(pole.imag()) / (2.0 * kPi)) +
                         " Hz, not below fs/2 = " + brief(nyquist) + " Hz");
      }
    }
    if (discretisation == Discretisation::BilinearPrewarped) {
      if (a.prewarp_frequency < 0.0 || a.prewarp_frequency >= nyquist) {
        throw InputError(where + "pre-warping frequency " + brief(a.prewarp_frequency) +
                         " Hz must be in [0, fs/2 = " + brief(nyquist) + " Hz)");
      }
      biquads_.push_back(bilinear(a, sample_rate));
    } else {
      biquads_.push_back(matchedMagnitude(a, sample_rate));
    }
  }
}

WeightingFilter WeightingFilter::iso2631(Weighting weighting, double sample_rate,
                                         Discretisation discretisation) {
  checkSampleRate(sample_rate);
  const Iso2631Parameters p = iso2631Parameters(weighting);
  const double needed = 2.0 * std::max(p.f4, std::isfinite(p.f5) ? std::sqrt(p.f5 * p.f6) : 0.0);
  if (sample_rate <= needed) {
    throw InputError("comfort: sample rate " + brief(sample_rate) +
                     " Hz is too low for ISO 2631-1 " + weightingName(weighting) + " (needs > " +
                     brief(needed) + " Hz)");
  }
  std::vector<AnalogSection> sections = iso2631Sections(weighting);
  if (p.f2 > kLowPassLimit * sample_rate)
    sections.erase(sections.begin() + 1);
  return WeightingFilter(std::move(sections), sample_rate, discretisation);
}

double WeightingFilter::step(double input) {
  double x = input;
  for (Biquad& biquad : biquads_)
    x = biquad.step(x);
  return x;
}

Vector WeightingFilter::filter(const Vector& input) const {
  WeightingFilter fresh = *this;
  fresh.reset();
  Vector output(input.size());
  for (Eigen::Index i = 0; i < input.size(); ++i)
    output(i) = fresh.step(input(i));
  return output;
}

void WeightingFilter::reset() {
  for (Biquad& biquad : biquads_)
    biquad.s1 = biquad.s2 = 0.0;
}

std::complex<double> WeightingFilter::response(double frequency) const {
  const std::complex<double> z_inv = std::polar(1.0, -2.0 * kPi * frequency / sample_rate_);
  std::complex<double> h(1.0, 0.0);
  for (const Biquad& q : biquads_) {
    h *= (q.b0 + z_inv * (q.b1 + z_inv * q.b2)) / (1.0 + z_inv * (q.a1 + z_inv * q.a2));
  }
  return h;
}

std::complex<double> WeightingFilter::analogResponse(double frequency) const {
  return dynamics::analogResponse(sections_, frequency);
}

// ---------------------------------------------------------------------------------------------

ComfortMetrics evaluateComfort(const Vector& acceleration, double sample_rate,
                               const ComfortOptions& options) {
  checkSampleRate(sample_rate);
  checkOptions(options);
  for (Eigen::Index i = 0; i < acceleration.size(); ++i) {
    if (!std::isfinite(acceleration(i))) {
      throw InputError("comfort: acceleration sample " + std::to_string(i) + " is not finite");
    }
  }
  WeightingFilter weighting =
      WeightingFilter::iso2631(options.weighting, sample_rate, options.discretisation);
  std::optional<WeightingFilter> absorbed;
  if (!options.absorbed_power.empty()) {
    absorbed.emplace(options.absorbed_power, sample_rate, options.discretisation);
  }

  ComfortMetrics metrics;
  metrics.samples = static_cast<std::size_t>(acceleration.size());
  metrics.duration = static_cast<double>(acceleration.size()) / sample_rate;
  if (acceleration.size() == 0) {
    if (absorbed)
      metrics.absorbed_power = 0.0;
    return metrics;
  }
  const Vector weighted = weighting.filter(acceleration);
  const double n = static_cast<double>(weighted.size());
  metrics.weighted_rms = std::sqrt(weighted.squaredNorm() / n);
  metrics.vdv = std::pow(weighted.array().square().square().sum() / sample_rate, 0.25);
  const double alpha = -std::expm1(-1.0 / (sample_rate * options.running_rms_time));
  double mean_square = 0.0;
  double peak = 0.0;
  for (Eigen::Index i = 0; i < weighted.size(); ++i) {
    mean_square += alpha * (weighted(i) * weighted(i) - mean_square);
    peak = std::max(peak, mean_square);
  }
  metrics.mtvv = std::sqrt(peak);
  LinearRunningMeanSquare window(sample_rate, options.running_rms_time);
  double linear_peak = 0.0;
  for (Eigen::Index i = 0; i < weighted.size(); ++i)
    linear_peak = std::max(linear_peak, window.add(weighted(i) * weighted(i)));
  metrics.mtvv_linear = std::sqrt(linear_peak);
  metrics.peak_weighted = weighted.cwiseAbs().maxCoeff();
  if (absorbed)
    metrics.absorbed_power = absorbed->filter(acceleration).squaredNorm() / n;
  return metrics;
}

BasicMethodRatios basicMethodRatios(const ComfortMetrics& metrics) {
  BasicMethodRatios r;
  const double rms = metrics.weighted_rms;
  if (!(rms > 0.0) || !(metrics.duration > 0.0))
    return r;
  r.crest_factor = metrics.peak_weighted / rms;
  r.mtvv_ratio = metrics.mtvv / rms;
  r.mtvv_linear_ratio = metrics.mtvv_linear / rms;
  // VDV^4 = Σ a_w^4 / fs; for a signal of constant a_w,rms the VDV is a_w T^(1/4) times a shape
  // factor (1 for a square wave, (3/2)^(1/4) for a sinusoid): the ratio is that shape factor.
  r.vdv_ratio = metrics.vdv / (rms * std::pow(metrics.duration, 0.25));
  return r;
}

ComfortMeter::ComfortMeter(double sample_rate, const ComfortOptions& options)
    : weighting_(validatedWeighting(sample_rate, options)),
      sample_rate_(sample_rate),
      running_alpha_(-std::expm1(-1.0 / (sample_rate * options.running_rms_time))),
      linear_window_(sample_rate, options.running_rms_time) {
  if (!options.absorbed_power.empty()) {
    absorbed_power_.emplace(options.absorbed_power, sample_rate, options.discretisation);
  }
}

void ComfortMeter::add(double acceleration) {
  if (!std::isfinite(acceleration)) {
    throw InputError("comfort meter: acceleration sample " + std::to_string(count_) +
                     " is not finite");
  }
  const double y = weighting_.step(acceleration);
  const double y2 = y * y;
  ++count_;
  sum_squares_ += y2;
  sum_fourth_ += y2 * y2;
  running_mean_square_ += running_alpha_ * (y2 - running_mean_square_);
  max_running_mean_square_ = std::max(max_running_mean_square_, running_mean_square_);
  max_linear_mean_square_ = std::max(max_linear_mean_square_, linear_window_.add(y2));
  peak_weighted_ = std::max(peak_weighted_, std::abs(y));
  last_weighted_ = y;
  if (absorbed_power_) {
    const double z = absorbed_power_->step(acceleration);
    sum_power_ += z * z;
  }
}

void ComfortMeter::reset() {
  weighting_.reset();
  if (absorbed_power_)
    absorbed_power_->reset();
  count_ = 0;
  sum_squares_ = sum_fourth_ = sum_power_ = 0.0;
  running_mean_square_ = max_running_mean_square_ = peak_weighted_ = last_weighted_ = 0.0;
  linear_window_.reset();
  max_linear_mean_square_ = 0.0;
}

double ComfortMeter::weightedRms() const {
  return count_ == 0 ? 0.0 : std::sqrt(sum_squares_ / static_cast<double>(count_));
}

double ComfortMeter::vibrationDoseValue() const {
  return std::pow(sum_fourth_ / sample_rate_, 0.25);
}

double ComfortMeter::maximumTransientVibrationValue() const {
  return std::sqrt(max_running_mean_square_);
}

double ComfortMeter::maximumTransientVibrationValueLinear() const {
  return std::sqrt(max_linear_mean_square_);
}

double ComfortMeter::runningRms() const {
  return std::sqrt(running_mean_square_);
}

std::optional<double> ComfortMeter::absorbedPower() const {
  if (!absorbed_power_)
    return std::nullopt;
  return count_ == 0 ? 0.0 : sum_power_ / static_cast<double>(count_);
}

double ComfortMeter::duration() const {
  return static_cast<double>(count_) / sample_rate_;
}

ComfortMetrics ComfortMeter::metrics() const {
  ComfortMetrics metrics;
  metrics.weighted_rms = weightedRms();
  metrics.vdv = vibrationDoseValue();
  metrics.mtvv = maximumTransientVibrationValue();
  metrics.mtvv_linear = maximumTransientVibrationValueLinear();
  metrics.peak_weighted = peak_weighted_;
  metrics.absorbed_power = absorbedPower();
  metrics.duration = duration();
  metrics.samples = count_;
  return metrics;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
