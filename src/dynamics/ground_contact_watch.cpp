#include "tracked_vehicle_dynamics/dynamics/ground_contact_watch.h"

#include <algorithm>
#include <string>
#include <utility>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

GroundContactWatch::GroundContactWatch(std::vector<GroundContact> contacts, DofIndex input_count)
    : contacts_(std::move(contacts)), input_count_(input_count) {
  if (contacts_.empty())
    throw InputError("ground contact watch: no contacts");
  for (std::size_t i = 0; i < contacts_.size(); ++i)
    if (contacts_[i].input < 0 || contacts_[i].input >= input_count_)
      throw InputError("ground contact watch: contact " + std::to_string(i) + " reads input " +
                       std::to_string(contacts_[i].input) + " of " + std::to_string(input_count_));
  pressed_at_rest_.assign(contacts_.size(), 0);
  forces_.setZero(contactCount());
}

void GroundContactWatch::evaluate(const Vector& state, const Vector& input) {
  contactForces(contacts_, state, input, input_count_, forces_, "ground contact watch");
}

void GroundContactWatch::restart(double time, const Vector& state, const Vector& input) {
  evaluate(state, input);
  pulling_at_rest_ = 0;
  for (DofIndex i = 0; i < contactCount(); ++i) {
    const bool pressed = forces_(i) >= 0.0;
    pressed_at_rest_[static_cast<std::size_t>(i)] = pressed ? 1 : 0;
    pulling_at_rest_ += pressed ? 0 : 1;
  }
  since_restart_ = GroundContactRecord{};
  interval_ = GroundContactRecord{};
  tally(time);
  started_ = true;
}

DofIndex GroundContactWatch::tally(double time) {
  now_ = GroundContactNow{};
  now_.time = time;
  DofIndex lowest = -1;
  for (DofIndex i = 0; i < contactCount(); ++i) {
    const double f = forces_(i);
    const GroundContact& c = contacts_[static_cast<std::size_t>(i)];
    if (c.side == ContactSide::Left)
      now_.left += f;
    else if (c.side == ContactSide::Right)
      now_.right += f;
    if (!pressed_at_rest_[static_cast<std::size_t>(i)]) {
      now_.pulling_at_rest += f < 0.0 ? 1 : 0;
      continue;
    }
    if (lowest < 0 || f < forces_(lowest))
      lowest = i;
    if (f < 0.0)
      ++now_.pulling;
  }
  return lowest;
}

void GroundContactWatch::check(double time, double station, const Vector& state,
                               const Vector& input) {
  if (!started_)
    throw InputError("ground contact watch: check() before restart() (no state at rest)");
  evaluate(state, input);
  // The lowest force among the contacts pressed at rest is also the hardest pull when any pulls.
  const DofIndex lowest = tally(time);
  for (GroundContactRecord* r : {&since_restart_, &interval_}) {
    ++r->checks;
    if (lowest >= 0 && forces_(lowest) < r->min_force) {
      r->min_force = forces_(lowest);
      r->min_contact = lowest;
      r->min_force_time = time;
    }
    if (now_.pulling == 0)
      continue;
    ++r->checks_beyond;
    r->most_pulling = std::max(r->most_pulling, now_.pulling);
    if (r->first_beyond_contact < 0) {
      r->first_beyond_time = time;
      r->first_beyond_station = station;
      r->first_beyond_contact = lowest;
    }
  }
}

GroundContactRecord GroundContactWatch::takeInterval() {
  GroundContactRecord taken = interval_;
  interval_ = GroundContactRecord{};
  return taken;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
