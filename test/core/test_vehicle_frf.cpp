// The reduced vehicle against the full FE model (issues 4 and 5): comfort FRFs (paper §4.1,
// Figs. 13-16) and time responses over the long hill (§4.2, Figs. 18-19), on the default vehicle.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>

#include "tracked_vehicle_dynamics/dynamics/frf.h"
#include "tracked_vehicle_dynamics/dynamics/frf_state_space.h"
#include "tracked_vehicle_dynamics/dynamics/modal_system.h"
#include "tracked_vehicle_dynamics/dynamics/road_excitation.h"
#include "tracked_vehicle_dynamics/dynamics/simulator.h"
#include "tracked_vehicle_dynamics/dynamics/spectral_ride.h"
#include "tracked_vehicle_dynamics/dynamics/static_equilibrium.h"
#include "tracked_vehicle_dynamics/error.h"
#include "tracked_vehicle_dynamics/fem/modal_solver.h"
#include "tracked_vehicle_dynamics/fem/system.h"
#include "tracked_vehicle_dynamics/reduction/full_model_reference.h"
#include "tracked_vehicle_dynamics/reduction/global_modes.h"
#include "tracked_vehicle_dynamics/reduction/vehicle_reduction.h"
#include "tracked_vehicle_dynamics/terrain/terrain_lines.h"
#include "tracked_vehicle_dynamics/terrain/tracks.h"
#include "tracked_vehicle_dynamics/vehicle/mode_classification.h"

#ifndef TVD_SOURCE_DIR
#define TVD_SOURCE_DIR "."
#endif

using namespace tracked_vehicle_dynamics;
using dynamics::ComplexMatrix;
using dynamics::InputDelay;
using dynamics::OutputQuantity;

namespace {

const std::string kDescriptionFile =
    std::string(TVD_SOURCE_DIR) + "/config/vehicles/paper_vehicle.yaml";
constexpr double kBandHz = 30.0;         // the CMS band of the paper
constexpr double kFrfToleranceDb = 1.0;  // issue 4: reduced vs full within 1 dB
constexpr double kTimeTolerance = 0.02;  // issue 5: within 2 % of the peak
// A frequency is "near an anti-resonance" when the full FRF is 12 dB below its largest value
// within +-1 Hz; those points are excluded from the dB comparison.
constexpr double kAntiResonanceRatio = 0.25;
constexpr double kAntiResonanceWindowHz = 1.0;
const char* const kComfortOutputs[] = {"hull uz", "hull ry", "road_wheel_left_1 uz",
                                       "road_wheel_left_7 uz"};

struct Variant {
  reduction::ReducedModel reduced;
  reduction::FullModelReference full;
};

// Both models of both variants, built once for the whole test program.
const Variant& models(vehicle::Variant variant) {
  static std::map<vehicle::Variant, std::unique_ptr<Variant>> cache;
  auto& slot = cache[variant];
  if (!slot) {
    const vehicle::VehicleDescription d = vehicle::loadVehicleDescription(kDescriptionFile);
    slot = std::make_unique<Variant>(Variant{reduction::reduceVehicle(d, variant, {}),
                                             reduction::buildVehicleReference(d, variant)});
  }
  return *slot;
}

DofIndex column(const std::vector<std::string>& names, const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  EXPECT_NE(it, names.end()) << name;
  return static_cast<DofIndex>(it - names.begin());
}

// The full FE model of the default vehicle's `variant`, its lowest `count` modes and their types.
struct ClassifiedModes {
  vehicle::VehicleModel model;
  fem::System system;
  fem::ModalBasis modes;
  std::vector<vehicle::ModeClass> classes;
};
ClassifiedModes classifiedModes(vehicle::Variant variant, int count) {
  ClassifiedModes c;
  c.model = vehicle::buildVehicleModel(vehicle::loadVehicleDescription(kDescriptionFile), variant);
  c.system = fem::assemble(c.model.model);
  fem::ModalRequest request;
  request.count = count;
  c.modes = fem::solveModes(c.system.stiffness, c.system.mass, request);
  c.classes = vehicle::classifyModes(c.model, c.system, c.modes);
  return c;
}

Vector frequencies(double max_hz, double step) {
  const auto n = static_cast<Eigen::Index>(std::lround(max_hz / step)) + 1;
  return Vector::LinSpaced(n, 0.0, (n - 1) * step);
}

InputDelay delayAt(const dynamics::SecondOrderSystem& s, double speed_kmh) {
  return speed_kmh > 0 ? InputDelay::travelling(s.input_stations, speed_kmh / 3.6)
                       : InputDelay::synchronous();
}

// Largest |20 log10(|reduced| / |full|)| over (0, band], skipping anti-resonances; also the
// fraction of points compared (so that the test cannot pass by excluding everything).
std::pair<double, double> worstDb(const Vector& hz, const Vector& full, const Vector& reduced) {
  const double step = hz(1) - hz(0);
  const auto window = static_cast<Eigen::Index>(std::lround(kAntiResonanceWindowHz / step));
  double worst = 0.0;
  int compared = 0, in_band = 0;
  for (Eigen::Index i = 1; i < hz.size() && hz(i) <= kBandHz + 1e-9; ++i) {
    ++in_band;
    const Eigen::Index a = std::max<Eigen::Index>(0, i - window);
    const Eigen::Index b = std::min<Eigen::Index>(hz.size() - 1, i + window);
    if (full(i) < kAntiResonanceRatio * full.segment(a, b - a + 1).maxCoeff())
      continue;
    ++compared;
    worst = std::max(worst, std::abs(20.0 * std::log10(reduced(i) / full(i))));
  }
  return {worst, static_cast<double>(compared) / in_band};
}

}  // namespace

// The full-model reference is exact in statics (K^-1 through its residual), and so is
// Craig-Bampton: their displacement FRFs at 0 Hz agree to rounding, for every input pattern.
TEST(FullReference, StaticsEqualTheReducedModel) {
  const Variant& v = models(vehicle::Variant::Untracked);
  const Vector zero = Vector::Zero(1);
  for (double speed : {0.0, 30.0}) {
    const ComplexMatrix full =
        v.full.frf(zero, delayAt(v.full.modal, speed), OutputQuantity::Displacement);
    const ComplexMatrix reduced = dynamics::frfModal(
        v.reduced.system, zero, delayAt(v.reduced.system, speed), OutputQuantity::Displacement);
    ASSERT_EQ(full.cols(), reduced.cols());
    // Lifting every input by 1 m lifts the whole vehicle by 1 m.
    EXPECT_NEAR(std::abs(full(0, column(v.full.modal.output_names, "hull uz"))), 1.0, 1e-6);
    EXPECT_LT((full - reduced).cwiseAbs().maxCoeff(), 1e-6 * reduced.cwiseAbs().maxCoeff());
  }
  EXPECT_GT(v.full.frequencies_hz.size(), 10);
  EXPECT_LE(v.full.frequencies_hz.maxCoeff(), 100.0);
}

// Figs. 13-15: hull vertical and pitch, front and rear wheel acceleration FRFs of the reduced
// model within 1 dB of the full model up to 30 Hz, both variants, synchronous and at 30 km/h.
// The MAC selection pairs global modes only, those with 1 % or more of their kinetic energy in the
// hull and running gear: of the un-tracked 40 the 6 hull and 14 wheel modes (97 % and more), not
// the assemblies' local modes (0 %: at 35.79 and 107.72 Hz); of the tracked ones neither the
// chain modes that leave the vehicle alone (mode 30 at 22.94 Hz, 0.002 %, had a MAC of 0.89 with
// the un-tracked yaw). The default 40 cut the un-tracked 12 at 107.72 Hz after 6; not being
// global, that warns no more.
TEST(VehicleReduction, MacSelectionPairsGlobalModesOnly) {
  const vehicle::VehicleDescription d = vehicle::loadVehicleDescription(kDescriptionFile);
  reduction::VehicleReductionReport report;
  const reduction::ReducedModel tracked =
      reduction::reduceVehicle(d, vehicle::Variant::Tracked, {}, &report);
  EXPECT_EQ(report.mac_reference_modes, 20);
  EXPECT_TRUE(report.warnings.empty()) << report.warnings.front();
  // The candidates' energy, from the full model's modes as the reduction solved them.
  const vehicle::VehicleModel full = vehicle::buildVehicleModel(d, vehicle::Variant::Tracked);
  const fem::System system = fem::assemble(full.model);
  fem::ModalRequest request;
  request.count = 40;
  const fem::ModalBasis modes = fem::solveModes(system.stiffness, system.mass, request);
  const std::vector<bool> global = reduction::globalModes(full, system, modes);
  int global_in_band = 0;
  for (int j = 0; j < modes.count(); ++j)
    global_in_band += modes.frequencies_hz(j) <= kBandHz && global[static_cast<std::size_t>(j)];
  EXPECT_EQ(report.mac_candidate_modes, global_in_band);
  EXPECT_FALSE(global[29]);  // the chain mode at 22.94 Hz that paired the un-tracked yaw
  ASSERT_FALSE(tracked.selected_modes.empty());
  for (const reduction::SelectedMode& m : tracked.selected_modes) {
    EXPECT_TRUE(global[static_cast<std::size_t>(m.mode)])
        << "mode " << m.mode + 1 << ": " << m.reason;
    // "MAC 0.93 with untracked mode 1 (2.14 Hz); also 0.82 with mode 5": every mode named.
    int named = 0;
    for (std::size_t at = m.reason.find("mode "); at != std::string::npos;
         at = m.reason.find("mode ", at + 1)) {
      const int reference = std::atoi(m.reason.c_str() + at + 5);
      EXPECT_GE(reference, 1) << m.reason;
      EXPECT_LE(reference, 20) << m.reason;
      ++named;
    }
    EXPECT_GE(named, 1) << m.reason;
  }
}

// A repeated eigenvalue is judged as an eigenspace, whichever basis the solver returns: one mode
// holding a few per cent of its energy in the vehicle, spread evenly over five vectors with four
// modes that hold none, leaves each vector under 1 % but the eigenspace global. Single modes are
// judged by their own share (vehicleEnergy's diagonal, classifyModes' hull + wheel share).
// Global modes that end below the band (the MAC's 12 on a light vehicle) once left the modes
// between unchecked: the report said "within 2 %" over the band while the reduced model missed
// some. The check now solves the band's modes itself, and the additions reach them.
TEST(VehicleReduction, BandCheckCoversTheBandWhenTheGlobalModesEndBelowIt) {
  const vehicle::VehicleDescription d =
      vehicle::loadVehicleDescription(std::string(TVD_SOURCE_DIR) + "/test/data/light_5_axle.yaml");
  reduction::VehicleReductionOptions options;
  options.global_modes = 12;
  reduction::VehicleReductionReport report;
  const reduction::ReducedModel reduced =
      reduction::reduceVehicle(d, vehicle::Variant::Tracked, options, &report);
  // Every full-model mode below the band, solved independently.
  const fem::System system =
      fem::assemble(vehicle::buildVehicleModel(d, vehicle::Variant::Tracked).model);
  fem::ModalRequest request;
  request.count = 100;
  request.max_frequency_hz = kBandHz;
  const fem::ModalBasis band = fem::solveModes(system.stiffness, system.mass, request);
  ASSERT_GT(band.count(), options.global_modes);  // the 12 end below the band
  ASSERT_LT(band.count(), request.count);
  ASSERT_EQ(report.full_frequencies_hz.size(), static_cast<std::size_t>(band.count()));
  for (int r = 0; r < band.count(); ++r)
    EXPECT_NEAR(report.full_frequencies_hz[static_cast<std::size_t>(r)], band.frequencies_hz(r),
                1e-6 * band.frequencies_hz(r));
  const fem::ModalBasis mine = fem::solveModesDense(reduced.system.stiffness, reduced.system.mass);
  for (int r = 0; r < band.count(); ++r)
    EXPECT_LE(std::abs(mine.frequencies_hz(r) / band.frequencies_hz(r) - 1.0),
              reduction::kBandFrequencyTolerance)
        << "mode " << r + 1 << " at " << band.frequencies_hz(r) << " Hz";
  EXPECT_LE(report.max_relative_frequency_error, reduction::kBandFrequencyTolerance);
  bool said = false;
  for (const std::string& w : report.warnings)
    said =
        said || w.find("the reduced model was checked against the " + std::to_string(band.count()) +
                       " full-model modes below 30 Hz") != std::string::npos;
  EXPECT_TRUE(said);
  // The warning names the count that covers the band, one mode past its last; with it the
  // selection sees the whole band and the warning is gone.
  const std::string cover = "--global-modes " + std::to_string(band.count() + 1) + ",";
  bool named = false;
  for (const std::string& w : report.warnings)
    named = named || w.find(cover) != std::string::npos;
  EXPECT_TRUE(named) << cover;
  options.global_modes = band.count() + 1;
  reduction::VehicleReductionReport covered;
  reduction::reduceVehicle(d, vehicle::Variant::Tracked, options, &covered);
  for (const std::string& w : covered.warnings)
    EXPECT_EQ(w.find("below the band's"), std::string::npos) << w;
}

TEST(VehicleReduction, GlobalModesDoNotDependOnTheBasisOfAnEigenspace) {
  const ClassifiedModes solved = classifiedModes(vehicle::Variant::Tracked, 40);
  const vehicle::VehicleModel& full = solved.model;
  const fem::System& system = solved.system;
  const fem::ModalBasis& modes = solved.modes;
  const std::vector<vehicle::ModeClass>& classes = solved.classes;
  const Vector share = vehicle::vehicleEnergy(full, system, modes.shapes).diagonal();
  const std::vector<bool> global = reduction::globalModes(full, system, modes);
  std::vector<int> carrier, idle;  // a mode with 1-5 % in the vehicle; modes with ~0
  for (int j = 0; j < modes.count(); ++j) {
    EXPECT_NEAR(share(j), classes[j].hull_share + classes[j].wheel_share, 1e-9) << j;
    EXPECT_EQ(global[static_cast<std::size_t>(j)], share(j) >= reduction::kGlobalEnergyShare) << j;
    if (share(j) >= 0.01 && share(j) < 0.05)
      carrier.push_back(j);
    if (share(j) < 1e-12)
      idle.push_back(j);
  }
  ASSERT_FALSE(carrier.empty());
  ASSERT_GE(idle.size(), 4u);
  fem::ModalBasis group;
  group.shapes.resize(modes.shapes.rows(), 5);
  group.shapes.col(0) = modes.shapes.col(carrier[0]);
  for (int k = 0; k < 4; ++k)
    group.shapes.col(k + 1) = modes.shapes.col(idle[k]);
  // An orthogonal mix (Householder reflection to (1, 1, 1, 1, 1) / sqrt 5): each new vector takes
  // a fifth of the carrier; the shapes stay M-orthonormal.
  Vector u = Vector::Constant(5, 1.0 / std::sqrt(5.0));
  u(0) -= 1.0;
  const Matrix q = Matrix::Identity(5, 5) - 2.0 * u * u.transpose() / u.squaredNorm();
  group.shapes = (group.shapes * q).eval();
  group.eigenvalues = Vector::Constant(5, 100.0);
  group.frequencies_hz = Vector::Constant(5, 10.0);  // one repeated eigenvalue
  const Vector spread = vehicle::vehicleEnergy(full, system, group.shapes).diagonal();
  EXPECT_LT(spread.maxCoeff(), reduction::kGlobalEnergyShare);
  EXPECT_NEAR(spread.sum(), share(carrier[0]), 1e-9);
  EXPECT_EQ(reduction::globalModes(full, system, group), std::vector<bool>(5, true));
  group.frequencies_hz << 10.0, 11.0, 12.0, 13.0, 14.0;  // five distinct modes: none is global
  EXPECT_EQ(reduction::globalModes(full, system, group), std::vector<bool>(5, false));
}

TEST(VehicleFrf, ReducedMatchesFullWithinOneDecibel) {
  const Vector hz = frequencies(kBandHz + 2.0, 0.05);
  for (vehicle::Variant variant : {vehicle::Variant::Untracked, vehicle::Variant::Tracked}) {
    const Variant& v = models(variant);
    for (double speed : {0.0, 30.0}) {
      const ComplexMatrix full =
          v.full.frf(hz, delayAt(v.full.modal, speed), OutputQuantity::Acceleration);
      const ComplexMatrix reduced = dynamics::frfModal(
          v.reduced.system, hz, delayAt(v.reduced.system, speed), OutputQuantity::Acceleration);
      double worst = 0.0;
      for (const char* output : kComfortOutputs) {
        const DofIndex jf = column(v.full.modal.output_names, output);
        const DofIndex jr = column(v.reduced.system.output_names, output);
        const auto [db, fraction] =
            worstDb(hz, full.col(jf).cwiseAbs(), reduced.col(jr).cwiseAbs());
        const std::string what = std::string(vehicle::variantName(variant)) + " " + output +
                                 " at " + std::to_string(speed) + " km/h";
        EXPECT_LT(db, kFrfToleranceDb) << what;
        EXPECT_GT(fraction, 0.45) << what << ": too few points compared";
        worst = std::max(worst, db);
      }
      // The README's figure.
      std::cout << vehicle::variantName(variant) << " at " << speed << " km/h: worst " << worst
                << " dB\n";
    }
  }
}

// The wheelbase filter (eqs. 21-24, Figs. 15-16): travelled excitation tends to the synchronous
// one as f -> 0 and as v -> infinity; within the band its hull-vertical peak does not exceed the
// synchronous peak (10 % margin); and the track filters the wheel input: at 30 km/h the tracked
// wheel FRF falls further below its synchronous value than the un-tracked one.
TEST(VehicleFrf, WheelbaseFilter) {
  const Vector hz = frequencies(kBandHz, 0.05);
  std::map<vehicle::Variant, double> wheel_attenuation;
  for (vehicle::Variant variant : {vehicle::Variant::Untracked, vehicle::Variant::Tracked}) {
    const dynamics::SecondOrderSystem& s = models(variant).reduced.system;
    const dynamics::ModalSystem modal(s);
    const auto magnitude = [&](double speed) {
      return Matrix(dynamics::frfModal(modal, hz, delayAt(s, speed), OutputQuantity::Displacement)
                        .cwiseAbs());
    };
    const Matrix sync = magnitude(0.0), at30 = magnitude(30.0), fast = magnitude(1e7);
    const DofIndex hull = column(s.output_names, "hull uz");
    const DofIndex wheel = column(s.output_names, "road_wheel_left_1 uz");
    const std::string name = vehicle::variantName(variant);
    EXPECT_NEAR(at30(1, hull) / sync(1, hull), 1.0, 0.01) << name;  // 0.05 Hz
    EXPECT_LT((fast - sync).cwiseAbs().maxCoeff(), 1e-3 * sync.maxCoeff()) << name;
    const double a = std::pow(2.0 * M_PI, 2);  // displacement -> acceleration, for the peaks
    const Vector acc_sync = sync.col(hull).cwiseProduct(hz.cwiseAbs2()) * a;
    const Vector acc_30 = at30.col(hull).cwiseProduct(hz.cwiseAbs2()) * a;
    EXPECT_LE(acc_30.maxCoeff(), 1.1 * acc_sync.maxCoeff()) << name;
    // Acceleration peaks: the band's resonances rather than the quasi-static 1 m/m at 0 Hz.
    wheel_attenuation[variant] = at30.col(wheel).cwiseProduct(hz.cwiseAbs2()).maxCoeff() /
                                 sync.col(wheel).cwiseProduct(hz.cwiseAbs2()).maxCoeff();
  }
  EXPECT_LT(wheel_attenuation[vehicle::Variant::Tracked],
            0.7 * wheel_attenuation[vehicle::Variant::Untracked])
      << "tracked " << wheel_attenuation[vehicle::Variant::Tracked] << ", untracked "
      << wheel_attenuation[vehicle::Variant::Untracked];
}

// Anti-phase roads (input_delay.h): left +h, right -h. On the symmetric bundled vehicle they
// leave heave and pitch alone and roll the hull, whose roll FRF peaks at the un-tracked roll mode
// (the full model's mode led by roll); in-phase roads do the opposite; the reduced roll FRF is the
// full model's within 1 dB; and by linearity the left track's road alone gives half their sum,
// which a delay that lifts the left inputs only must give, travelled at 30 km/h too (the factors
// ride on the lags).
TEST(VehicleFrf, AntiPhaseRoadsRollTheHullAtItsRollMode) {
  const Vector hz = frequencies(kBandHz, 0.05);
  const Variant& v = models(vehicle::Variant::Untracked);
  const dynamics::SecondOrderSystem& s = v.reduced.system;
  const Vector sides = InputDelay::antiPhaseFactors(s.input_lateral);
  ASSERT_EQ(sides.cwiseAbs().minCoeff(), 1.0);  // every input on one track or the other
  ASSERT_NEAR(sides.sum(), 0.0, 0.0);           // as many left as right
  const dynamics::ModalSystem modal(s);
  const ComplexMatrix in_phase =
      dynamics::frfModal(modal, hz, InputDelay::synchronous(), OutputQuantity::Acceleration);
  const ComplexMatrix anti = dynamics::frfModal(modal, hz, InputDelay::synchronous().scaled(sides),
                                                OutputQuantity::Acceleration);
  const DofIndex uz = column(s.output_names, "hull uz"), ry = column(s.output_names, "hull ry"),
                 rx = column(s.output_names, "hull rx");
  const auto peak = [&](const ComplexMatrix& h, DofIndex c) {
    return h.col(c).cwiseAbs().maxCoeff();
  };
  // The reduced model is symmetric to the MoGeSeC masters' placement (1e-5, test_reduced_model).
  EXPECT_LT(peak(anti, uz), 1e-3 * peak(in_phase, uz));
  EXPECT_LT(peak(anti, ry), 1e-3 * peak(in_phase, ry));
  EXPECT_LT(peak(in_phase, rx), 1e-3 * peak(anti, rx));
  Eigen::Index top = 0;
  anti.col(rx).cwiseAbs().maxCoeff(&top);
  // Left up, right down: the hull's left side rises, a positive roll about +x (REP-103), so at low
  // frequency its roll acceleration -omega^2 theta is in opposition to the road (180 deg).
  const dynamics::Complex low = anti(1, rx);
  EXPECT_LT(low.real(), 0.0) << low;
  EXPECT_LT(std::abs(low.imag()), 0.01 * std::abs(low.real())) << low;
  // At the un-tracked hull's roll mode: the mode of the full FE model whose kinetic energy is
  // led by the hull's roll (classifyModes), within a grid step and the acceleration peak's shift
  // above the natural frequency for 5 % damping, 1/sqrt(1 - 2 zeta^2) - 1 = 0.25 %.
  {
    const ClassifiedModes solved = classifiedModes(vehicle::Variant::Untracked, 12);
    std::vector<double> roll_hz;
    for (int j = 0; j < solved.modes.count(); ++j) {
      const vehicle::ModeClass& c = solved.classes[static_cast<std::size_t>(j)];
      if (c.kind == vehicle::ModeKind::Hull && c.hull_motions.front() == vehicle::HullMotion::Roll)
        roll_hz.push_back(solved.modes.frequencies_hz(j));
    }
    ASSERT_EQ(roll_hz.size(), 1u) << "one hull mode led by roll below mode 12";
    EXPECT_NEAR(hz(top), roll_hz[0] * 1.0025, 0.05 / 2 + 1e-9) << "roll FRF peak";
  }
  const ComplexMatrix full = v.full.frf(
      hz,
      InputDelay::synchronous().scaled(InputDelay::antiPhaseFactors(v.full.modal.input_lateral)),
      OutputQuantity::Acceleration);
  const auto [db, fraction] =
      worstDb(hz, full.col(column(v.full.modal.output_names, "hull rx")).cwiseAbs(),
              anti.col(rx).cwiseAbs());
  EXPECT_LT(db, kFrfToleranceDb);
  EXPECT_GT(fraction, 0.45);
  const Vector left_only = (sides.array() > 0.0).cast<double>();
  const ComplexMatrix left = dynamics::frfModal(
      modal, hz, InputDelay::travelling(s.input_stations, 30 / 3.6).scaled(left_only),
      OutputQuantity::Acceleration);
  const ComplexMatrix sum =
      0.5 * (dynamics::frfModal(modal, hz, InputDelay::travelling(s.input_stations, 30 / 3.6),
                                OutputQuantity::Acceleration) +
             dynamics::frfModal(modal, hz,
                                InputDelay::travelling(s.input_stations, 30 / 3.6).scaled(sides),
                                OutputQuantity::Acceleration));
  EXPECT_LT((left - sum).cwiseAbs().maxCoeff(), 1e-12 * left.cwiseAbs().maxCoeff());
  EXPECT_THROW(InputDelay::travelling(s.input_stations, 1.0).scaled(Vector::Ones(3)), InputError);
  EXPECT_THROW(InputDelay::synchronous().scaled(Vector::Ones(3)).at(1.0, 4), InputError);
}

// Paper §4.1.3: "the un-tracked vehicle road wheels are uncoupled each other, hence their
// response is unaffected by the longitudinal vehicle speed. Differently, for the tracked vehicle,
// unsprung mass FRFs have lower amplitudes [...] since the track is coupling axles." Acceleration
// peaks of the front and rear wheels in the CMS band at 10, 30 and 50 km/h against synchronous:
// un-tracked within 10 %, tracked below 0.7. It holds because a pad reads the road at one station
// (ties.road_input_station: pad_centre); with every sole column reading it under itself, the
// 0.14 m pad filters the un-tracked wheel's own resonance at 10 km/h to below half.
TEST(VehicleFrf, UntrackedWheelsIgnoreSpeedTrackedWheelsStayBelowSynchronous) {
  const Vector hz = frequencies(kBandHz, 0.05);
  const auto peakRatio = [&](const dynamics::SecondOrderSystem& s, const std::string& output,
                             double speed_kmh) {
    const dynamics::ModalSystem modal(s);
    const DofIndex k = column(s.output_names, output);
    const auto peak = [&](double v) {
      const Matrix m =
          dynamics::frfModal(modal, hz, delayAt(s, v), OutputQuantity::Acceleration).cwiseAbs();
      return m.col(k).maxCoeff();
    };
    return peak(speed_kmh) / peak(0.0);
  };
  for (const char* wheel : {"road_wheel_left_1 uz", "road_wheel_left_7 uz"})
    for (double speed : {10.0, 30.0, 50.0}) {
      const double untracked =
          peakRatio(models(vehicle::Variant::Untracked).reduced.system, wheel, speed);
      const double tracked =
          peakRatio(models(vehicle::Variant::Tracked).reduced.system, wheel, speed);
      EXPECT_NEAR(untracked, 1.0, 0.1) << wheel << " at " << speed << " km/h";
      EXPECT_LT(tracked, 0.7) << wheel << " at " << speed << " km/h";
    }
  vehicle::VehicleDescription sole = vehicle::loadVehicleDescription(kDescriptionFile);
  sole.ties.road_input_station = vehicle::RoadInputStation::Sole;
  const reduction::ReducedModel filtered =
      reduction::reduceVehicle(sole, vehicle::Variant::Untracked, {});
  EXPECT_LT(peakRatio(filtered.system, "road_wheel_left_1 uz", 10.0), 0.5);
}

// Figs. 18-19: the un-tracked vehicle over the long hill at 5 and 50 km/h, reduced vs full:
// hull heave, pitch and every wheel displacement within 2 % of their peaks.
TEST(VehicleTimeResponse, ReducedMatchesFullOnLongHill) {
  const Variant& v = models(vehicle::Variant::Untracked);
  const terrain::Terrain track = terrain::makeTrack("long_hill");
  const double dt = 1e-3;
  for (double speed_kmh : {5.0, 50.0}) {
    const double speed = speed_kmh / 3.6;
    const long steps = static_cast<long>(std::ceil(track.length() / speed / dt));
    // Runs one model; returns the displacement outputs [steps + 1 x n_y] from the start.
    auto run = [&](const dynamics::SecondOrderSystem& s, const Vector& gravity,
                   const reduction::FullModelReference* full, double max_mode_hz) {
      dynamics::SimulatorOptions o;
      o.time_step = dt;
      o.hold = dynamics::InputHold::FirstOrder;
      o.method = dynamics::DiscretizationMethod::ModalDecoupled;
      o.generalized_force = gravity;
      o.max_mode_frequency_hz = max_mode_hz;
      dynamics::Simulator sim(s, o);
      const dynamics::RoadExcitation road(s.input_stations, s.input_lateral);
      const terrain::TerrainLines lines(track, road.inputY());
      const Matrix w = road.sampleSeries(lines, track.startStation(), speed, dt, 0, steps + 1);
      sim.reset(
          dynamics::staticEquilibrium(s, w.row(0).head(road.inputCount()).transpose(), gravity),
          w.row(0).transpose());
      Matrix y = sim.simulate(w).leftCols(s.outputCount());
      if (full)
        full->addResidual(w, OutputQuantity::Displacement, y);
      return Matrix(y.rowwise() - y.row(0));
    };
    const Matrix full = run(v.full.modal, v.full.modal_gravity, &v.full, 0.0);
    const Matrix reduced = run(v.reduced.system, v.reduced.gravity_load, nullptr, 0.5 / dt);
    for (const std::string& name : v.reduced.system.output_names) {
      if (name != "hull uz" && name != "hull ry" && name.rfind("road_wheel", 0) != 0)
        continue;
      const DofIndex jf = column(v.full.modal.output_names, name);
      const DofIndex jr = column(v.reduced.system.output_names, name);
      const double peak = full.col(jf).cwiseAbs().maxCoeff();
      ASSERT_GT(peak, 0.0) << name;
      EXPECT_LT((full.col(jf) - reduced.col(jr)).cwiseAbs().maxCoeff(), kTimeTolerance * peak)
          << name << " at " << speed_kmh << " km/h";
    }
    // The hill lifts the hull by its height (0.4 m). At 5 km/h it sits still on the 10 m top
    // while every wheel is on it (§4.2.2: "stationary ... on the hill"): reference station
    // 11 + 2.34 to 21 - 2.34 m; here 14-18 m, past the entry's settling. At 50 km/h it swings
    // about the hill height, above it.
    const Vector heave = full.col(column(v.full.modal.output_names, "hull uz"));
    if (speed_kmh == 5.0) {
      for (long k = 0; k <= steps; ++k) {
        const double station = track.startStation() + speed * dt * static_cast<double>(k);
        if (station >= 14.0 && station <= 18.0) {
          ASSERT_NEAR(heave(k), terrain::kLongHillHeight, 0.005) << "station " << station;
        }
      }
    } else {
      EXPECT_GT(heave.maxCoeff(), terrain::kLongHillHeight);
      EXPECT_LT(heave.maxCoeff(), 1.5 * terrain::kLongHillHeight);
    }
  }
}

// Discrete arm dampers couple the full model's modes: its reference FRF then solves eq. 18 in
// its modal coordinates with the whole D = Phi_k^T C Phi_k, and equals the sparse direct
// solution of the whole FE model (K - omega^2 M + j omega C) x = (K_u + j omega C_u) tau up to
// what the static residual leaves out, its inertia and its static response to the dampers'
// force (8e-4 of each output's peak at most, at 30 km/h, with the modes up to 100 Hz); eq. 20
// on the diagonal of D is off by 80-350 %.
TEST(FullReference, CoupledDampingEqualsTheSparseDirectSolution) {
  vehicle::VehicleDescription d = vehicle::loadVehicleDescription(kDescriptionFile);
  d.suspension.arm_damping = 2.0e4;  // N m s/rad on axles 1 and 7
  d.damping.damped_stations = {1, 7};
  d.damping.model = vehicle::DampingModel::Rayleigh;
  d.damping.rayleigh_alpha = 2.0;  // 1/s: mass-proportional, so the residual's share is exact
  d.damping.rayleigh_beta = 0.0;
  const vehicle::VehicleModel model = vehicle::buildVehicleModel(d, vehicle::Variant::Untracked);
  const fem::System system = fem::assemble(model.model);
  const std::vector<reduction::OutputDof> outputs = reduction::vehicleOutputs(model, d);
  const reduction::FullModelReference ref =
      reduction::buildVehicleReference(d, vehicle::Variant::Untracked);
  ASSERT_TRUE(ref.dampingCouplesModes());
  EXPECT_GT(ref.dampingCoupling(), 0.1);

  dynamics::SparseSecondOrderSystem direct;
  direct.mass = system.mass;
  direct.stiffness = system.stiffness;
  direct.damping = system.damping + d.damping.rayleigh_alpha * system.mass;
  direct.input_stiffness = system.input_stiffness;
  direct.input_damping = system.input_damping;
  direct.input_stations = ref.modal.input_stations;
  std::vector<Eigen::Triplet<double>> entries;
  const auto terms = reduction::outputTerms(system.dofs, outputs);
  for (std::size_t i = 0; i < terms.size(); ++i)
    for (const auto& [dof, coefficient] : terms[i])
      entries.emplace_back(static_cast<DofIndex>(i), dof, coefficient);
  direct.output.resize(static_cast<DofIndex>(outputs.size()), system.size());
  direct.output.setFromTriplets(entries.begin(), entries.end());

  const Vector hz = frequencies(30.0, 0.25);
  for (double speed_kmh : {0.0, 30.0}) {
    const InputDelay delay = delayAt(ref.modal, speed_kmh);
    const ComplexMatrix exact = dynamics::frfDirect(direct, hz, delay);
    const ComplexMatrix coupled = ref.frf(hz, delay, OutputQuantity::Acceleration);
    // What eq. 20 keeps: the same reference with D's diagonal only.
    reduction::FullModelReference diagonal = ref;
    diagonal.modal.damping = Matrix(ref.modal.damping.diagonal().asDiagonal());
    ASSERT_FALSE(diagonal.dampingCouplesModes());
    const ComplexMatrix modal = diagonal.frf(hz, delay, OutputQuantity::Acceleration);
    for (const char* name : kComfortOutputs) {
      const DofIndex j = column(ref.modal.output_names, name);
      const double peak = exact.col(j).cwiseAbs().maxCoeff();
      const double error = (coupled.col(j) - exact.col(j)).cwiseAbs().maxCoeff() / peak;
      const double dropped = (modal.col(j) - exact.col(j)).cwiseAbs().maxCoeff() / peak;
      std::cout << name << " at " << speed_kmh << " km/h: error " << error
                << " of the peak, eq. 20 " << dropped << "\n";
      EXPECT_LT(error, 2e-3) << name << " at " << speed_kmh << " km/h";
      EXPECT_GT(dropped, 0.1) << name << " at " << speed_kmh << " km/h";
    }
  }
}

// The spectral ride of the un-tracked vehicle with arm dampers on axles 1 and 7 (tvd ride
// --iso8608): its complex modes give the PSD of the exact travelled FRF (frfStateSpace, eq. 18)
// on the reduced model's 254 states, on every point of its grid.
TEST(VehicleFrf, SpectralRideOfCoupledDampingIsTheExactFrf) {
  vehicle::VehicleDescription d = vehicle::loadVehicleDescription(kDescriptionFile);
  d.suspension.arm_damping = 2.0e4;
  d.damping.damped_stations = {1, 7};
  const reduction::ReducedModel reduced =
      reduction::reduceVehicle(d, vehicle::Variant::Untracked, {});
  const dynamics::SecondOrderSystem& s = reduced.system;
  const dynamics::ModalSystem modal(s);
  ASSERT_GT(modal.maxOffDiagonalDampingRatio(), 0.1);
  const std::vector<DofIndex> rows = {column(s.output_names, "hull uz"),
                                      column(s.output_names, "road_wheel_left_1 uz")};
  dynamics::SpectralRideOptions options;
  options.keep_psd = true;
  const dynamics::RoadSpectrum road;
  const dynamics::SpectralRide ride(modal, s.input_lateral, rows, road, options,
                                    dynamics::modalDamping(modal, s));
  ASSERT_TRUE(ride.complexModes());
  const double speed = 30.0 / 3.6;
  const dynamics::SpectralRideResult r = ride.evaluate(speed);
  const ComplexMatrix h = dynamics::frfStateSpace(s, modal, r.frequencies_hz,
                                                  InputDelay::travelling(s.input_stations, speed));
  double worst = 0.0;
  for (Eigen::Index i = 0; i < h.rows(); ++i)
    for (std::size_t j = 0; j < rows.size(); ++j) {
      const double exact = std::norm(h(i, rows[j])) * r.road_psd(i);
      worst = std::max(worst, std::abs(r.psd(i, static_cast<Eigen::Index>(j)) / exact - 1.0));
    }
  std::cout << "spectral ride against the exact FRF: " << worst << " at most\n";
  EXPECT_LT(worst, 1e-6);
}
