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
  int groups = 0;
  for (const GroundContact& c : contacts_)
    groups = std::max(groups, c.group + 1);
  group_contact_.assign(static_cast<std::size_t>(groups), -1);
  for (std::size_t i = contacts_.size(); i-- > 0;)
    if (contacts_[i].group >= 0)
      group_contact_[static_cast<std::size_t>(contacts_[i].group)] = static_cast<DofIndex>(i);
  group_pressed_at_rest_.assign(static_cast<std::size_t>(groups), 0);
  group_forces_.setZero(groups);
}

void GroundContactWatch::evaluate(const Vector& state, const Vector& input) {
  contactForces(contacts_, state, input, input_count_, forces_, "ground contact watch");
  // F_g = sum of F_i over the contacts i of group g.
  group_forces_.setZero();
  for (DofIndex i = 0; i < contactCount(); ++i) {
    const int g = contacts_[static_cast<std::size_t>(i)].group;
    if (g >= 0)
      group_forces_(g) += forces_(i);
  }
}

void GroundContactWatch::restart(double time, const Vector& state, const Vector& input) {
  evaluate(state, input);
  pulling_at_rest_ = 0;
  rest_force_ = forces_.sum();
  for (DofIndex i = 0; i < contactCount(); ++i) {
    const bool pressed = forces_(i) >= 0.0;
    pressed_at_rest_[static_cast<std::size_t>(i)] = pressed ? 1 : 0;
    pulling_at_rest_ += pressed ? 0 : 1;
  }
  groups_pulling_at_rest_ = 0;
  for (int g = 0; g < groupCount(); ++g) {
    const bool pressed = group_forces_(g) >= 0.0;
    group_pressed_at_rest_[static_cast<std::size_t>(g)] = pressed ? 1 : 0;
    groups_pulling_at_rest_ += pressed ? 0 : 1;
  }
  since_restart_ = GroundContactRecord{};
  interval_ = GroundContactRecord{};
  tally(time);
  tallyGroups();
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
    if (f < 0.0) {
      ++now_.pulling;
      now_.pull -= f;
    }
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
  const int lowest_group = tallyGroups();
  for (GroundContactRecord* r : {&since_restart_, &interval_}) {
    ++r->checks;
    if (lowest >= 0 && forces_(lowest) < r->min_force) {
      r->min_force = forces_(lowest);
      r->min_contact = lowest;
      r->min_force_time = time;
    }
    if (lowest_group >= 0 && group_forces_(lowest_group) < r->min_group_force) {
      r->min_group_force = group_forces_(lowest_group);
      r->min_group = lowest_group;
      r->min_group_force_time = time;
    }
    if (now_.groups_pulling > 0) {
      ++r->checks_groups_beyond;
      r->most_groups_pulling = std::max(r->most_groups_pulling, now_.groups_pulling);
      if (r->first_group_beyond < 0) {
        r->first_group_beyond_time = time;
        r->first_group_beyond_station = station;
        r->first_group_beyond = lowest_group;
      }
    }
    if (now_.pulling == 0)
      continue;
    ++r->checks_beyond;
    r->most_pulling = std::max(r->most_pulling, now_.pulling);
    r->max_pull = std::max(r->max_pull, now_.pull);
    if (r->first_beyond_contact < 0) {
      r->first_beyond_time = time;
      r->first_beyond_station = station;
      r->first_beyond_contact = lowest;
    }
  }
}

int GroundContactWatch::tallyGroups() {
  now_.groups_pulling = 0;
  now_.groups_pulling_at_rest = 0;
  int lowest = -1;
  for (int g = 0; g < groupCount(); ++g) {
    const double f = group_forces_(g);
    if (group_contact_[static_cast<std::size_t>(g)] < 0)
      continue;  // a group number no contact carries
    if (!group_pressed_at_rest_[static_cast<std::size_t>(g)]) {
      now_.groups_pulling_at_rest += f < 0.0 ? 1 : 0;
      continue;
    }
    if (lowest < 0 || f < group_forces_(lowest))
      lowest = g;
    if (f < 0.0)
      ++now_.groups_pulling;
  }
  return lowest;
}

GroundContactRecord GroundContactWatch::takeInterval() {
  GroundContactRecord taken = interval_;
  interval_ = GroundContactRecord{};
  return taken;
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
