#include "tracked_vehicle_dynamics/dynamics/seat_comfort.h"

#include <cmath>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {
namespace {

ComfortOptions options(Weighting weighting, double running_rms_time) {
  ComfortOptions o;
  o.weighting = weighting;
  o.running_rms_time = running_rms_time;
  if (weighting == Weighting::Wk)
    o.absorbed_power = absorbedPowerVerticalSections();  // the vertical axis only
  return o;
}

}  // namespace

SeatComfortMeter::SeatComfortMeter(double sample_rate, double running_rms_time)
    : vertical_(sample_rate, options(Weighting::Wk, running_rms_time)),
      longitudinal_(sample_rate, options(Weighting::Wd, running_rms_time)),
      lateral_(sample_rate, options(Weighting::Wd, running_rms_time)),
      roll_(sample_rate, options(Weighting::We, running_rms_time)),
      pitch_(sample_rate, options(Weighting::We, running_rms_time)),
      yaw_(sample_rate, options(Weighting::We, running_rms_time)) {}

void SeatComfortMeter::add(const SeatAcceleration& a) {
  // Checked as a whole first: a sample is taken on every axis or on none.
  const double values[] = {a.x, a.y, a.z, a.roll, a.pitch, a.yaw};
  for (double v : values)
    if (!std::isfinite(v))
      throw InputError("seat comfort: a non-finite acceleration sample");
  vertical_.add(a.z);
  longitudinal_.add(a.x);
  lateral_.add(a.y);
  roll_.add(a.roll);
  pitch_.add(a.pitch);
  yaw_.add(a.yaw);
}

void SeatComfortMeter::reset() {
  for (ComfortMeter* m : {&vertical_, &longitudinal_, &lateral_, &roll_, &pitch_, &yaw_})
    m->reset();
}

double SeatComfortMeter::translationalTotalValue() const {
  return seatTranslationalTotalValue(longitudinal_.weightedRms(), lateral_.weightedRms(),
                                     vertical_.weightedRms());
}

double SeatComfortMeter::rotationalTotalValue() const {
  return seatRotationalTotalValue(roll_.weightedRms(), pitch_.weightedRms(), yaw_.weightedRms());
}

double SeatComfortMeter::seatSurfaceTotalValue() const {
  return std::hypot(translationalTotalValue(), rotationalTotalValue());
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
