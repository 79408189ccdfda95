// The hand estimate a vehicle-dynamics engineer checks a model against: the hull on its road
// wheels' torsion bars and pads alone, every arm turning alike (a load through the CoG).
//   wheel rate at the wheel centre   k_r = k_t / (a cos beta)^2
//   in series with the pad           k_s = k_r k_z / (k_r + k_z)     (k_z: assembly compression)
//   n road wheels under a sprung mass m:
//     sag  d = m g / (n k_s),   bounce  f = sqrt(n k_s / m) / (2 pi)
//   attitude (a rigid hull on equal wheel rates at stations x_i about their mean, the CoG of the
//   sprung mass at x_G): pitch  phi = m g x_G / (k_s sum_i x_i^2)   (positive: nose down)
// The model stiffens this through paths the estimate leaves out, by design in the paper's
// vehicle: the road wheels locked to their links fore and aft (suspension.contact_shear_stiffness:
// an arm's rotation drags its contact patch against the pads' shear) and, tracked, the chain's
// bending (track_assembly.link_member_bending_inertia). How far the paper's vehicle goes sets the
// limits beyond which the model is said to be carried by those paths rather than by its
// suspension: the usual sign of values copied from the paper's 55 t vehicle onto a light one.
#pragma once

#include <string>
#include <vector>

#include "tracked_vehicle_dynamics/types.h"
#include "tracked_vehicle_dynamics/vehicle/mode_classification.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_description.h"
#include "tracked_vehicle_dynamics/vehicle/vehicle_model.h"

namespace tracked_vehicle_dynamics {
namespace vehicle {

struct WheelRateEstimate {
  double wheel_rate = 0.0;   ///< k_r at the wheel centre [N/m]
  double series_rate = 0.0;  ///< k_s, with the pad in series [N/m]
  int wheels = 0;            ///< road wheels n
  /// m: the hull, and in the tracked variant the sprockets, idlers and rollers rigid with it [kg]
  double sprung_mass = 0.0;
  double sag = 0.0;          ///< d, positive down [m]
  double bounce_hz = 0.0;    ///< f [Hz]
  double cog_x = 0.0;        ///< x_G of the sprung mass from the wheelbase's middle [m]
  double pitch = 0.0;        ///< phi [rad], positive nose down (REP-103: about +y)
  double end_station = 0.0;  ///< the foremost axle's x, half the wheelbase [m]
};

/// The estimate for a description's variant (closed form above). Tracked, the idler's x is
/// where the chain closes (solveIdlerX): throws InputError for a chain that cannot close, as
/// building the model does.
WheelRateEstimate wheelRateEstimate(const VehicleDescription& description, Variant variant);

/// The model's static sag below this share of the estimate (or a hull that rises) is taken for
/// a hull carried by the paths above. The paper's vehicle: tracked 0.28 bonded (4.5 mm against
/// 16.2), 0.50 with contacts that cannot pull (8.1 mm); un-tracked 1.06 (15.3 mm against 14.5).
/// Copied onto a 9-12 t vehicle: 0.03-0.04.
constexpr double kMinSagShare = 0.2;
/// The hull bounce mode above this multiple of the estimate's, un-tracked: the paper's vehicle
/// 1.22 (5.06 Hz against 4.14; its Table 4 gives 4.93 Hz, 1.19); copied onto a 9-12 t vehicle,
/// 2.5-2.7.
constexpr double kMaxUntrackedBounceRatio = 1.5;
/// The same, tracked: the paper's vehicle 2.0 (7.80 Hz against 3.91; its Table 4 gives 8.49 Hz,
/// 2.2); copied onto a 9-12 t vehicle, 5-6.
constexpr double kMaxTrackedBounceRatio = 2.5;

/// A warning when the hull's static z displacement `hull_sag` [m] (negative: down; a static
/// solution of `variant`, StaticSummary::hull_sag or a reduced model's) is less than
/// kMinSagShare of the estimate's sag, naming the estimate and the description keys that carry
/// the hull; "" otherwise.
std::string sagShareWarning(double hull_sag, const VehicleDescription& description,
                            Variant variant);

/// The model's static pitch off the estimate's by more than this share of the estimate's sag at
/// the end axles (|phi - phi_e| x_end > share d): a hull that does not sit on its torsion bars
/// as the hand estimate does. The paper's vehicle: 0.05 tracked (bonded), 0.03 un-tracked; a
/// light front-drive carrier whose chain bends a hundred times more easily than the paper's
/// (link_member_bending_inertia 1e-10 m^4; test/data/front_drive_carrier.yaml):
/// 0.39 bonded (0.74 deg nose up against 0.64 deg nose down), 0.06 with contacts that cannot
/// pull (0.85 deg nose down).
constexpr double kMaxPitchShare = 0.25;

/// A warning when the hull's static pitch `hull_pitch` [rad] (positive nose down,
/// StaticSummary::hull_pitch or a reduced model's) is off the estimate's beyond kMaxPitchShare,
/// naming both attitudes, how far off the end axles are and the keys; "" otherwise.
std::string attitudeWarning(double hull_pitch, const VehicleDescription& description,
                            Variant variant);

/// Both of the above for a static solution at rest (sag, then attitude), the non-empty ones:
/// what tvd statics, modes and mac and the node say of a hull its suspension does not carry.
std::vector<std::string> restWarnings(double hull_sag, double hull_pitch,
                                      const VehicleDescription& description, Variant variant);

/// A warning when the lowest mode whose main motion is the hull's bounce lies above the
/// variant's limit times the estimate's bounce, naming the mode, the ratio and the keys, or when
/// no mode among `classes` (frequencies_hz, same order) bounces at all while they already reach
/// beyond that limit (the bounce is above them all); "" otherwise. The sprung mass leaves out the
/// chain's top run lying on the chain wheels (a few % of the hull's).
std::string bounceWarning(const VehicleDescription& description, Variant variant,
                          const std::vector<ModeClass>& classes, const Vector& frequencies_hz);

}  // namespace vehicle
}  // namespace tracked_vehicle_dynamics
