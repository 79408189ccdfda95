#include "tracked_vehicle_dynamics/dynamics/ground_contact_monitor.h"

#include <algorithm>
#include <string>

#include "tracked_vehicle_dynamics/error.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

double GroundContactSummary::tensionFraction() const {
  return samples > 0 ? static_cast<double>(tension_samples) / static_cast<double>(samples) : 0.0;
}

double GroundContactSummary::newTensionFraction() const {
  return samples > 0 ? static_cast<double>(new_tension_samples) / static_cast<double>(samples)
                     : 0.0;
}

double GroundContactSummary::newGroupTensionFraction() const {
  return samples > 0 ? static_cast<double>(new_group_tension_samples) / static_cast<double>(samples)
                     : 0.0;
}

DofIndex GroundContactSummary::contactsEverInTension() const {
  return (min_force.array() < 0.0).count();
}

GroundContactMonitor::GroundContactMonitor(const std::vector<GroundContact>& contacts)
    : contacts_(contacts) {
  if (contacts_.empty())
    throw InputError("ground contact monitor: no contacts");
  const auto n_c = static_cast<DofIndex>(contacts_.size());
  left_selector_.setZero(n_c);
  right_selector_.setZero(n_c);
  for (DofIndex i = 0; i < n_c; ++i) {
    const ContactSide side = contacts_[static_cast<std::size_t>(i)].side;
    if (side == ContactSide::Left)
      left_selector_(i) = 1.0;
    if (side == ContactSide::Right)
      right_selector_(i) = 1.0;
  }
  int groups = 0;
  for (const GroundContact& c : contacts_)
    groups = std::max(groups, c.group + 1);
  group_selector_.setZero(n_c, groups);
  for (DofIndex i = 0; i < n_c; ++i)
    if (contacts_[static_cast<std::size_t>(i)].group >= 0)
      group_selector_(i, contacts_[static_cast<std::size_t>(i)].group) = 1.0;
  summary_.groups = groups;
  summary_.contacts = n_c;
  summary_.min_force = Vector::Constant(n_c, std::numeric_limits<double>::infinity());
}

void GroundContactMonitor::add(const Eigen::Ref<const Matrix>& forces, const Vector& times,
                               const Vector& stations) {
  const DofIndex n_c = summary_.contacts;
  if (forces.cols() != n_c || times.size() != forces.rows() || stations.size() != forces.rows())
    throw InputError("ground contact monitor: " + std::to_string(forces.rows()) + "x" +
                     std::to_string(forces.cols()) + " forces for " + std::to_string(n_c) +
                     " contacts, " + std::to_string(times.size()) + " times, " +
                     std::to_string(stations.size()) + " stations");
  const DofIndex b = forces.rows();
  if (b == 0)
    return;
  // Column-wise passes over the column-major block: each contact's samples are contiguous.
  const Vector left = forces * left_selector_;
  const Vector right = forces * right_selector_;
  GroundContactSummary& s = summary_;
  if (s.samples == 0) {
    compressed_at_rest_.assign(static_cast<std::size_t>(n_c), 1);
    for (DofIndex i = 0; i < n_c; ++i)
      if (forces(0, i) < 0.0) {
        compressed_at_rest_[static_cast<std::size_t>(i)] = 0;
        ++s.in_tension_at_rest;
      }
  }
  Eigen::VectorXi tension = Eigen::VectorXi::Zero(b), fresh = Eigen::VectorXi::Zero(b);
  for (DofIndex i = 0; i < n_c; ++i) {
    const double* f = forces.col(i).data();
    double lowest = s.min_force(i);
    const bool watch = compressed_at_rest_[static_cast<std::size_t>(i)];
    for (DofIndex k = 0; k < b; ++k) {
      tension(k) += f[k] < 0.0;
      if (f[k] < lowest)
        lowest = f[k];
    }
    if (watch && lowest < 0.0)
      for (DofIndex k = 0; k < b; ++k)
        fresh(k) += f[k] < 0.0;
    s.min_force(i) = lowest;
    if (lowest < s.min_contact_force) {
      DofIndex k_min = 0;
      forces.col(i).minCoeff(&k_min);
      s.min_contact_force = lowest;
      s.min_contact = i;
      s.min_contact_time = times(k_min);
    }
  }
  for (DofIndex k = 0; k < b; ++k) {
    const int count = tension(k);
    if (count > 0) {
      ++s.tension_samples;
      s.max_in_tension = std::max<DofIndex>(s.max_in_tension, count);
      if (s.first_tension_contact < 0) {
        DofIndex c = 0;
        forces.row(k).minCoeff(&c);
        s.first_tension_time = times(k);
        s.first_tension_station = stations(k);
        s.first_tension_contact = c;
      }
    }
    if (fresh(k) > 0) {
      ++s.new_tension_samples;
      if (s.first_new_tension_contact < 0) {
        DofIndex c = -1;
        for (DofIndex i = 0; i < n_c; ++i)
          if (compressed_at_rest_[static_cast<std::size_t>(i)] &&
              (c < 0 || forces(k, i) < forces(k, c)))
            c = i;
        s.first_new_tension_time = times(k);
        s.first_new_tension_station = stations(k);
        s.first_new_tension_contact = c;
      }
    }
    left_.push_back(left(k));
    right_.push_back(right(k));
    in_tension_.push_back(count);
  }
  if (s.groups > 0) {
    // A group's force is the sum of its contacts'.
    const Matrix group_forces = forces * group_selector_;
    if (s.samples == 0) {
      group_compressed_at_rest_.assign(static_cast<std::size_t>(s.groups), 1);
      for (int g = 0; g < s.groups; ++g)
        if (group_forces(0, g) < 0.0) {
          group_compressed_at_rest_[static_cast<std::size_t>(g)] = 0;
          ++s.groups_in_tension_at_rest;
        }
    }
    for (DofIndex k = 0; k < b; ++k) {
      int count = 0, fresh_count = 0, worst = -1;
      for (int g = 0; g < s.groups; ++g) {
        const double f = group_forces(k, g);
        if (f < s.min_group_force) {
          s.min_group_force = f;
          s.min_group = g;
        }
        if (!(f < 0.0))
          continue;
        ++count;
        if (!group_compressed_at_rest_[static_cast<std::size_t>(g)])
          continue;
        ++fresh_count;
        if (worst < 0 || f < group_forces(k, worst))
          worst = g;
      }
      s.max_groups_in_tension = std::max(s.max_groups_in_tension, count);
      if (fresh_count == 0)
        continue;
      ++s.new_group_tension_samples;
      if (s.first_new_group_tension < 0) {
        s.first_new_group_tension = worst;
        s.first_new_group_tension_time = times(k);
        s.first_new_group_tension_station = stations(k);
      }
    }
  }
  s.samples += b;
  s.peak_left = std::max(s.peak_left, left.maxCoeff());
  s.min_left = std::min(s.min_left, left.minCoeff());
  s.peak_right = std::max(s.peak_right, right.maxCoeff());
  s.min_right = std::min(s.min_right, right.minCoeff());
}

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
