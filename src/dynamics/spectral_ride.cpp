#include "tracked_vehicle_dynamics/dynamics/spectral_ride.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <map>
#include <string>
#include <utility>

#include <Eigen/Eigenvalues>

#include "checks.h"
#include "tracked_vehicle_dynamics/dynamics/comfort.h"
#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

namespace {

// Frequencies evaluated together: one matrix product forms their modal forces. 256 keeps the
// block's products (modes x 512 doubles, about 1.8 MB for 430 modes) in cache-friendly sizes.
constexpr Eigen::Index kBlock = 256;
constexpr double kMinPointsPerDecade = SpectralRideOptions::kMinPointsPerDecade;
constexpr double kMaxPointsPerDecade = SpectralRideOptions::kMaxPointsPerDecade;
constexpr double kMaxGridPoints = 1e6;
// The local grid of a resonance the log grid does not resolve (grid()).
constexpr double kRefineBelow = 1.5;    // for ζ < kRefineBelow h (h the log grid's step)
constexpr double kRefineCut = 5.0;      // or ζ < kRefineCut h with a band end in
constexpr double kCutWithin = 5.0;      // f_r (1 ± kCutWithin ζ)
constexpr double kRefineInner = 2.0;    // evenly over f_r (1 ± kRefineInner ζ)
constexpr int kRefineInnerPoints = 33;  // points there (16 per half-power band)
constexpr double kRefineRatio = 1.02;   // then each point this many times farther out
constexpr double kRefineReach = 10.0;   // to f_r (1 ± max(kRefineReach h, 10ζ))

[[noreturn]] void fail(const std::string& what) {
  throw InputError("spectral ride: " + what);
}

// Class (iso8608ReferencePsd throws naming it), band and waviness, as terrain::makeIso8608
// checks them (the band without the Nyquist bound: a PSD has no sampling).
void checkRoad(const RoadSpectrum& road) {
  terrain::iso8608ReferencePsd(road.road_class);  // throws naming an unknown class
  if (!(std::isfinite(road.min_frequency) && std::isfinite(road.max_frequency) &&
        road.min_frequency > 0.0 && road.min_frequency < road.max_frequency))
    fail("band [" + brief(road.min_frequency) + ", " + brief(road.max_frequency) +
         "] cycles/m must satisfy 0 < n_min < n_max");
  if (!(std::isfinite(road.waviness) && road.waviness > 0.0))
    fail("waviness " + brief(road.waviness) + " must be > 0");
  if (road.correlation == terrain::LateralCorrelation::IndependentSides &&
      !(std::isfinite(road.side_gap) && road.side_gap > 0.0))
    fail("side gap " + brief(road.side_gap) + " m must be > 0 for independent sides");
}

void checkSpeed(double speed) {
  if (!(std::isfinite(speed) && speed > 0.0))
    fail("speed " + brief(speed) + " m/s must be positive and finite");
}

// Weight of the left profile in the height an input at y sees (terrain::makeIso8608's blend
// across the centre strip): 1 left of it, 0 right of it, linear in between.
double leftWeight(double y, double gap) {
  return std::clamp((y + 0.5 * gap) / gap, 0.0, 1.0);
}

}  // namespace

void checkSpectralInput(const RoadSpectrum& road, const SpectralRideOptions& options) {
  checkRoad(road);
  if (!(options.points_per_decade >= kMinPointsPerDecade &&
        options.points_per_decade <= kMaxPointsPerDecade))
    fail("points per decade " + brief(options.points_per_decade) + " must be in [" +
         brief(kMinPointsPerDecade) + ", " + brief(kMaxPointsPerDecade) + "]");
  // The grid's size depends on the band's ratio only: [v n_min, v n_max] spans the same decades
  // at every speed.
  const double points =
      std::ceil(options.points_per_decade * std::log10(road.max_frequency / road.min_frequency)) +
      1.0;
  if (!(points <= kMaxGridPoints))
    fail("the band [" + brief(road.min_frequency) + ", " + brief(road.max_frequency) +
         "] cycles/m at " + brief(options.points_per_decade) + " points per decade needs " +
         brief(points) + " frequencies; at most " + brief(kMaxGridPoints));
}

double temporalRoadPsd(const RoadSpectrum& road, double frequency, double speed) {
  checkRoad(road);
  checkSpeed(speed);
  // The band's ends inclusive, to rounding: v n_min / v may come out an ulp below n_min.
  constexpr double kEnd = 1e-12;
  const double n = frequency / speed;
  if (!(n >= road.min_frequency * (1.0 - kEnd) && n <= road.max_frequency * (1.0 + kEnd)))
    return 0.0;
  return terrain::iso8608Psd(road.road_class, n, road.waviness) / speed;
}

Matrix modalDamping(const ModalSystem& modal, const SecondOrderSystem& system) {
  const ModeShapes& phi = modal.shapes();
  if (system.damping.rows() != phi.rows() || system.damping.cols() != phi.rows())
    fail("the damping matrix is " + std::to_string(system.damping.rows()) + " x " +
         std::to_string(system.damping.cols()) + " for " + std::to_string(phi.rows()) +
         " modal shape rows");
  return phi.transpose() * system.damping * phi;
}

SpectralRide::SpectralRide(const ModalSystem& modal, const Vector& input_lateral,
                           const std::vector<DofIndex>& output_rows, const RoadSpectrum& road,
                           const SpectralRideOptions& options, const Matrix& modal_damping)
    : road_(road), options_(options) {
  checkSpectralInput(road, options);
  const DofIndex inputs = modal.inputCount();
  const Vector& stations = modal.inputStations();
  if (inputs == 0)
    fail("the model has no road input");
  if (stations.size() != inputs)
    fail("the model has " + std::to_string(stations.size()) + " input stations for " +
         std::to_string(inputs) + " inputs");
  detail::requireLength("spectral ride", "input lateral positions", input_lateral, inputs);
  if (!stations.allFinite() || !input_lateral.allFinite())
    fail("input stations and lateral positions must be finite");
  if (output_rows.empty())
    fail("no output to rate");
  output_.resize(static_cast<Eigen::Index>(output_rows.size()), modal.modeCount());
  for (std::size_t i = 0; i < output_rows.size(); ++i) {
    const DofIndex row = output_rows[i];
    if (row < 0 || row >= modal.outputCount())
      fail("output row " + std::to_string(row) + " is not one of the model's " +
           std::to_string(modal.outputCount()) + " outputs");
    output_.row(static_cast<Eigen::Index>(i)) = modal.modalOutput().row(row);
  }
  checkWeightings();
  omega_squared_ = modal.naturalFrequencies().cwiseAbs2();
  damping_ = modal.dampingCoefficients();

  // Per side, the weight of each input in that side's profile: Uniform, every input 1 on the one
  // profile; IndependentSides, w_L on the left and 1 - w_L on the right.
  std::vector<Vector> weights;
  if (road.correlation == terrain::LateralCorrelation::Uniform) {
    weights.push_back(Vector::Ones(inputs));
  } else {
    Vector left(inputs);
    for (DofIndex q = 0; q < inputs; ++q)
      left(q) = leftWeight(input_lateral(q), road.side_gap);
    weights.push_back(left);
    weights.push_back(Vector::Ones(inputs) - left);
  }
  // L_q behind the front-most input (InputDelay::travelling).
  const double front = stations.maxCoeff();
  const Matrix& k_u = modal.modalInputStiffness();
  const Matrix& c_u = modal.modalInputDamping();
  for (const Vector& w : weights) {
    // Inputs of one station and one weight see one signal: their columns are summed once here,
    // which divides the per-frequency work by the inputs per station (12 on the tracked reduced
    // model: 360 inputs at 30 stations).
    std::map<std::pair<double, double>, std::vector<DofIndex>> groups;
    for (DofIndex q = 0; q < inputs; ++q)
      if (w(q) != 0.0)
        groups[{stations(q), w(q)}].push_back(q);
    Side side;
    const auto count = static_cast<Eigen::Index>(groups.size());
    side.lags.resize(count);
    side.input = Matrix::Zero(modal.modeCount(), 2 * count);
    Eigen::Index g = 0;
    for (const auto& [key, members] : groups) {
      side.lags(g) = front - key.first;
      for (DofIndex q : members) {
        side.input.col(g) += key.second * k_u.col(q);
        side.input.col(count + g) += key.second * c_u.col(q);
      }
      ++g;
    }
    sides_.push_back(std::move(side));
  }

  setComplexModes(modal, modal_damping);
  // Once: grid() consults it at every speed.
  mode_damping_ = computeModeDamping();
}

void SpectralRide::setComplexModes(const ModalSystem& modal, const Matrix& modal_damping) {
  const DofIndex n = modal.modeCount();
  if (modal_damping.size() == 0)
    return;
  if (modal_damping.rows() != n || modal_damping.cols() != n)
    fail("the modal damping matrix is " + std::to_string(modal_damping.rows()) + " x " +
         std::to_string(modal_damping.cols()) + " for " + std::to_string(n) + " modes");
  if (!modal_damping.allFinite())
    fail("the modal damping matrix is not finite");
  if (!(maxOffDiagonalRatio(modal_damping) > kModalDampingCouplingTolerance))
    return;
  // Complex modes of A = [0 Ω; -Ω -D] (see the header).
  complex_modes_ = true;
  Matrix a = Matrix::Zero(2 * n, 2 * n);
  a.topRightCorner(n, n).diagonal() = modal.naturalFrequencies();
  a.bottomLeftCorner(n, n).diagonal() = -modal.naturalFrequencies();
  a.bottomRightCorner(n, n) = -modal_damping;
  const Eigen::EigenSolver<Matrix> eigen(a, true);
  if (eigen.info() != Eigen::Success)
    throw SolverError("spectral ride: the eigen-solve of the damped modes failed");
  const ComplexMatrix v = eigen.eigenvectors();
  const Eigen::PartialPivLU<ComplexMatrix> lu(v);
  // Eigenvectors that are nearly dependent (a defective A: critical damping, to round-off) would
  // amplify round-off by 1 / rcond; 1e-10 leaves 1e-6 of the result.
  if (!(lu.rcond() > 1e-10))
    throw SolverError(
        "spectral ride: the damped modes' eigenvectors are not independent to working "
        "precision (a mode damped critically?)");
  eigenvalues_ = eigen.eigenvalues();
  const ComplexMatrix inverse = lu.inverse();
  for (Side& side : sides_) {
    const ComplexMatrix product = inverse.rightCols(n) * side.input.cast<Complex>();
    side.complex_input_re = product.real();
    side.complex_input_im = product.imag();
  }
  complex_output_ = output_.cast<Complex>() * v.bottomRows(n);
}

SpectralRide SpectralRide::withMaxFrequency(double max_frequency,
                                            const SpectralRideOptions& options) const {
  SpectralRide other = *this;
  other.road_.max_frequency = max_frequency;
  other.options_ = options;
  checkSpectralInput(other.road_, other.options_);
  other.checkWeightings();
  return other;
}

void SpectralRide::checkWeightings() const {
  const std::size_t given = options_.weightings.size();
  if (given != 0 && given != static_cast<std::size_t>(output_.rows()))
    fail(std::to_string(given) + " weightings for " + std::to_string(output_.rows()) +
         " output rows: give one per output, or none for Wk on every one");
}

Vector SpectralRide::grid(double speed) const {
  checkSpeed(speed);
  const double low = speed * road_.min_frequency, high = speed * road_.max_frequency;
  const double decades = std::log10(high / low);
  const auto count = std::max<Eigen::Index>(
      2, static_cast<Eigen::Index>(std::ceil(options_.points_per_decade * decades - 1e-9)) + 1);
  std::vector<double> f(static_cast<std::size_t>(count));
  for (Eigen::Index i = 0; i < count; ++i)
    f[static_cast<std::size_t>(i)] =
        low * std::pow(high / low, static_cast<double>(i) / static_cast<double>(count - 1));
  f.front() = low;
  f.back() = high;
  // A resonance narrower than the log grid resolves well (ζ < 1.5 h, h = ln(10) / points per
  // decade: at ζ = h its half-power band 2ζf spans two steps and the trapezoid errs by up to
  // 4e-3 of its share, 9 % at h/2, with a sign that changes with speed), or one that a band end
  // cuts (ζ < 5 h, the end within f_r (1 ± 5ζ): the end's interval misses the peak's flank),
  // gets points of its own: kRefineInnerPoints evenly over f_r (1 ± 2ζ), then geometrically
  // (each kRefineRatio times farther) out to f_r (1 ± 10 h) (10ζ for a wider cut peak), where
  // the log grid's step has become small beside the distance to the peak. The trapezoid then errs
  // by under 5e-4 of the band's integral (an oscillator with ζ from 1e-4 to 2 %, its peak whole or
  // cut by the band's top; spectral_ride's tests), at some 300-850 more frequencies per such mode.
  // Undamped modes (ζ = 0) are left alone: no grid integrates them.
  const double step = std::log(10.0) / options_.points_per_decade;
  const std::size_t base = f.size();
  for (const ModeDamping& mode : modeDamping()) {
    const double zeta = mode.ratio, f_r = mode.frequency_hz;
    const bool narrow = zeta < kRefineBelow * step;
    const bool cut =
        zeta < kRefineCut * step &&
        ((f_r * (1.0 - kCutWithin * zeta) < low && f_r * (1.0 + kCutWithin * zeta) > low) ||
         (f_r * (1.0 - kCutWithin * zeta) < high && f_r * (1.0 + kCutWithin * zeta) > high));
    const double reach = std::max(kRefineReach * step, 10.0 * zeta);
    if (!(zeta > 0.0) || !(narrow || cut) || f_r * (1.0 - reach) > high ||
        f_r * (1.0 + reach) < low)
      continue;  // resolved, undamped, or far outside the band
    const auto add = [&](double x) {
      const double at = f_r * (1.0 + x);
      if (at > low && at < high)
        f.push_back(at);
    };
    const double inner = kRefineInner * zeta;
    for (int k = 0; k < kRefineInnerPoints; ++k)
      add(-inner + 2.0 * inner * k / (kRefineInnerPoints - 1));
    for (double x = inner * kRefineRatio; x < reach; x *= kRefineRatio) {
      add(x);
      add(-x);
    }
  }
  if (f.size() > base) {
    std::sort(f.begin(), f.end());
    // Points closer than round-off to a neighbour would give a trapezoid of zero width.
    f.erase(std::unique(f.begin(), f.end(),
                        [](double a, double b) { return b - a <= 1e-12 * std::abs(b); }),
            f.end());
  }
  return Eigen::Map<const Vector>(f.data(), static_cast<Eigen::Index>(f.size()));
}

std::vector<DofIndex> SpectralRide::inputGroupCounts() const {
  std::vector<DofIndex> counts;
  for (const Side& s : sides_)
    counts.push_back(s.lags.size());
  return counts;
}

namespace {

// [Re τ, Im τ; -ω Im τ, ω Re τ] for frequencies f(first .. first + nb - 1), τ_g = exp(-jω L_g / v):
// times [Φ^T K_u | Φ^T C_u] it gives [Re F | Im F] of F = (Φ^T K_u + jω Φ^T C_u) τ.
void delayColumns(const Vector& f, Eigen::Index first, Eigen::Index nb, const Vector& lags,
                  double speed, Matrix* x) {
  const Eigen::Index groups = lags.size();
  x->resize(2 * groups, 2 * nb);
  for (Eigen::Index i = 0; i < nb; ++i) {
    const double omega = kTwoPi * f(first + i);
    for (Eigen::Index g = 0; g < groups; ++g) {
      const double phase = omega * lags(g) / speed;
      const double re = std::cos(phase), im = -std::sin(phase);
      (*x)(g, i) = re;
      (*x)(g, nb + i) = im;
      (*x)(groups + g, i) = -omega * im;
      (*x)(groups + g, nb + i) = omega * re;
    }
  }
}

}  // namespace

Matrix SpectralRide::realModeGain(const Vector& f, double speed) const {
  const Eigen::Index count = f.size(), outputs = output_.rows(), modes = output_.cols();
  Matrix gain = Matrix::Zero(count, outputs);
  Matrix x, forces, eta(modes, 2 * kBlock), y;
  for (Eigen::Index first = 0; first < count; first += kBlock) {
    const Eigen::Index nb = std::min(kBlock, count - first);
    for (const Side& side : sides_) {
      delayColumns(f, first, nb, side.lags, speed, &x);
      forces.noalias() = side.input * x;
      // η_r = F_r / D_r, D_r = ω_r^2 - ω^2 + j d_r ω.
      eta.resize(modes, 2 * nb);
      for (Eigen::Index i = 0; i < nb; ++i) {
        const double omega = kTwoPi * f(first + i);
        for (Eigen::Index r = 0; r < modes; ++r) {
          const std::complex<double> d(omega_squared_(r) - omega * omega, damping_(r) * omega);
          const std::complex<double> e = std::complex<double>(forces(r, i), forces(r, nb + i)) / d;
          eta(r, i) = e.real();
          eta(r, nb + i) = e.imag();
        }
      }
      y.noalias() = output_ * eta;
      // Acceleration -ω^2 H Φ η: |.|^2 = ω^4 |H Φ η|^2.
      for (Eigen::Index i = 0; i < nb; ++i) {
        const double omega = kTwoPi * f(first + i);
        const double omega4 = omega * omega * omega * omega;
        for (Eigen::Index o = 0; o < outputs; ++o)
          gain(first + i, o) += omega4 * (y(o, i) * y(o, i) + y(o, nb + i) * y(o, nb + i));
      }
    }
  }
  return gain;
}

Matrix SpectralRide::complexModeGain(const Vector& f, double speed) const {
  const Eigen::Index count = f.size(), outputs = complex_output_.rows(),
                     states = complex_output_.cols();
  Matrix gain = Matrix::Zero(count, outputs);
  Matrix x, re, im;
  ComplexMatrix z(states, kBlock), y;
  for (Eigen::Index first = 0; first < count; first += kBlock) {
    const Eigen::Index nb = std::min(kBlock, count - first);
    for (const Side& side : sides_) {
      delayColumns(f, first, nb, side.lags, speed, &x);
      // W = V^-1 [0; input] = P + jQ times x = [Re F | Im F] = [a | b]: W F = (P a - Q b) +
      // j (Q a + P b).
      re.noalias() = side.complex_input_re * x;
      im.noalias() = side.complex_input_im * x;
      z.resize(states, nb);
      for (Eigen::Index i = 0; i < nb; ++i) {
        const Complex j_omega(0.0, kTwoPi * f(first + i));
        for (Eigen::Index k = 0; k < states; ++k)
          z(k, i) = Complex(re(k, i) - im(k, nb + i), im(k, i) + re(k, nb + i)) /
                    (j_omega - eigenvalues_(k));
      }
      y.noalias() = complex_output_ * z;
      // Acceleration jω H Φ η': |.|^2 = ω^2 |H Φ V_2 z|^2.
      for (Eigen::Index i = 0; i < nb; ++i) {
        const double omega = kTwoPi * f(first + i);
        for (Eigen::Index o = 0; o < outputs; ++o)
          gain(first + i, o) += omega * omega * std::norm(y(o, i));
      }
    }
  }
  return gain;
}

std::vector<SpectralRide::ModeDamping> SpectralRide::computeModeDamping() const {
  std::vector<ModeDamping> modes;
  if (complex_modes_) {
    // λ = -ζω ± jω sqrt(1 - ζ^2): one of each conjugate pair (overdamped pairs, on the real
    // axis, have no resonance).
    for (Eigen::Index k = 0; k < eigenvalues_.size(); ++k) {
      const Complex lambda = eigenvalues_(k);
      if (lambda.imag() > 0.0)
        modes.push_back({lambda.imag() / kTwoPi, -lambda.real() / std::abs(lambda)});
    }
  } else {
    // d_r = 2 ζ_r ω_r.
    for (Eigen::Index r = 0; r < omega_squared_.size(); ++r) {
      const double omega = std::sqrt(std::max(omega_squared_(r), 0.0));
      if (omega > 0.0)
        modes.push_back({omega / kTwoPi, damping_(r) / (2.0 * omega)});
    }
  }
  std::sort(modes.begin(), modes.end(), [](const ModeDamping& a, const ModeDamping& b) {
    return a.frequency_hz < b.frequency_hz;
  });
  return modes;
}

SpectralRideResult SpectralRide::evaluate(double speed) const {
  const Vector f = grid(speed);
  const Eigen::Index count = f.size(), outputs = output_.rows();
  // Σ_sides |H_v,side|^2 per frequency and output.
  const Matrix gain = complex_modes_ ? complexModeGain(f, speed) : realModeGain(f, speed);
  for (Eigen::Index i = 0; i < count; ++i)
    if (!gain.row(i).allFinite())
      throw SolverError("spectral ride: the response is not finite at " + brief(f(i)) +
                        " Hz on the grid at " + brief(speed) +
                        " m/s: an undamped mode lies on it (give the model damping)");

  // Trapezoidal weights on the (non-uniform) grid: ∫ g df ≈ Σ_i w_i g_i.
  Vector weight(count);
  for (Eigen::Index i = 0; i < count; ++i)
    weight(i) = 0.5 * (f(std::min(i + 1, count - 1)) - f(std::max<Eigen::Index>(i - 1, 0)));
  const std::vector<AnalogSection> power_filter = absorbedPowerVerticalSections();
  // Each output's weighting sections, built once (Wk when none is given).
  std::vector<std::vector<AnalogSection>> weighting(static_cast<std::size_t>(outputs));
  for (Eigen::Index o = 0; o < outputs; ++o)
    weighting[static_cast<std::size_t>(o)] = iso2631Sections(
        options_.weightings.empty() ? Weighting::Wk
                                    : options_.weightings[static_cast<std::size_t>(o)]);
  SpectralRideResult result;
  result.speed = speed;
  Vector road_psd(count);
  Vector sum_squares = Vector::Zero(outputs), sum_weighted = Vector::Zero(outputs),
         sum_power = Vector::Zero(outputs);
  for (Eigen::Index i = 0; i < count; ++i) {
    // S_h = G_d(f / v) / v; every grid point lies in [v n_min, v n_max].
    road_psd(i) = terrain::iso8608Psd(road_.road_class, f(i) / speed, road_.waviness) / speed;
    result.road_variance += weight(i) * road_psd(i);
    const double k = std::norm(analogResponse(power_filter, f(i)));
    for (Eigen::Index o = 0; o < outputs; ++o) {
      const double s = weight(i) * gain(i, o) * road_psd(i);
      sum_squares(o) += s;
      sum_weighted(o) +=
          std::norm(analogResponse(weighting[static_cast<std::size_t>(o)], f(i))) * s;
      sum_power(o) += k * s;
    }
  }
  for (Eigen::Index o = 0; o < outputs; ++o)
    result.outputs.push_back({std::sqrt(sum_squares(o)), std::sqrt(sum_weighted(o)), sum_power(o)});
  if (options_.keep_psd) {
    result.frequencies_hz = f;
    result.psd = gain.array().colwise() * road_psd.array();
    result.road_psd = std::move(road_psd);
  }
  return result;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
