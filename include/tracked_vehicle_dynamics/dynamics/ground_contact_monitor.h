// Watches the ground contact forces of a run (ground_contact.h, compression positive) for the
// limit of the bonded linear model: a contact force F_i < 0 is the road pulling the vehicle
// down, which no road does; from the first such sample on, a real vehicle would have lifted
// that contact and the linear result no longer describes it.
//
// Per sample k it reduces F_k [n_contacts] to the total ground force per side (left: y > 0,
// right: y < 0) and the number of contacts in tension, and over the run keeps per contact the
// minimum force, the first sample with a contact in tension (time, station, contact), the
// largest number in tension at once and the share of samples with any.
//
// The first sample is taken as the state at rest (a run starts from static equilibrium): the
// bonded statics may already pull on some contacts there (the tracked model pulls on the road
// between its wheels, doc/vehicle_model.md), so contacts in tension at rest are counted apart,
// and the run's own departure from the range is the first sample where a contact that was in
// compression at rest goes into tension.
#pragma once

#include <limits>
#include <vector>

#include "tracked_vehicle_dynamics/dynamics/ground_contact.h"
#include "tracked_vehicle_dynamics/types.h"

namespace tracked_vehicle_dynamics {
namespace dynamics {

struct GroundContactSummary {
  DofIndex contacts = 0;
  long samples = 0;
  long tension_samples = 0;     ///< samples with at least one contact in tension
  DofIndex max_in_tension = 0;  ///< most contacts in tension at one sample
  /// The first sample with a contact in tension: time [s], station [m] and the contact (the one
  /// pulling hardest there); NaN and -1 when none.
  double first_tension_time = std::numeric_limits<double>::quiet_NaN();
  double first_tension_station = std::numeric_limits<double>::quiet_NaN();
  DofIndex first_tension_contact = -1;
  DofIndex in_tension_at_rest = 0;  ///< contacts in tension at the first sample
  /// The first sample at which a contact in compression at rest is in tension: time [s], station
  /// [m], contact (the one pulling hardest there among those); NaN and -1 when none. Equal to
  /// first_tension_* when nothing is in tension at rest.
  double first_new_tension_time = std::numeric_limits<double>::quiet_NaN();
  double first_new_tension_station = std::numeric_limits<double>::quiet_NaN();
  DofIndex first_new_tension_contact = -1;
  long new_tension_samples = 0;  ///< samples with a contact in tension that was not at rest
  Vector min_force;              ///< per contact, the lowest F_i of the run [N]
  /// The same per group (GroundContact::group, e.g. a pad: the sum of its contacts' forces);
  /// groups = 0 when no contact has one.
  int groups = 0;
  int groups_in_tension_at_rest = 0;
  int max_groups_in_tension = 0;
  long new_group_tension_samples = 0;  ///< samples with a group pressed at rest in tension
  double first_new_group_tension_time = std::numeric_limits<double>::quiet_NaN();
  double first_new_group_tension_station = std::numeric_limits<double>::quiet_NaN();
  int first_new_group_tension = -1;
  double min_group_force = std::numeric_limits<double>::infinity();  ///< [N]
  int min_group = -1;
  /// The lowest F_i over every contact and sample [N], its contact and time [s].
  double min_contact_force = std::numeric_limits<double>::infinity();
  DofIndex min_contact = -1;
  double min_contact_time = std::numeric_limits<double>::quiet_NaN();
  /// Total ground force per side over the run [N]: largest and lowest.
  double peak_left = -std::numeric_limits<double>::infinity();
  double min_left = std::numeric_limits<double>::infinity();
  double peak_right = -std::numeric_limits<double>::infinity();
  double min_right = std::numeric_limits<double>::infinity();

  bool anyTension() const { return tension_samples > 0; }
  /// tension_samples / samples (0 for no samples).
  double tensionFraction() const;
  /// new_tension_samples / samples (0 for no samples).
  double newTensionFraction() const;
  /// new_group_tension_samples / samples (0 for no samples).
  double newGroupTensionFraction() const;
  /// Contacts whose minimum is below zero (in tension at some sample, not necessarily at once).
  DofIndex contactsEverInTension() const;
};

class GroundContactMonitor {
 public:
  /// Throws InputError for an empty contact list.
  explicit GroundContactMonitor(const std::vector<GroundContact>& contacts);

  /// Adds samples: forces [b x n_contacts] [N] (row j at times(j) [s], stations(j) [m]), in
  /// time order. Appends each sample's side totals and tension count to the series below.
  /// Throws InputError for mismatched sizes.
  void add(const Eigen::Ref<const Matrix>& forces, const Vector& times, const Vector& stations);

  const GroundContactSummary& summary() const { return summary_; }
  /// Per sample added: total ground force on the left and right side [N], contacts in tension.
  const std::vector<double>& leftForce() const { return left_; }
  const std::vector<double>& rightForce() const { return right_; }
  const std::vector<int>& contactsInTension() const { return in_tension_; }

 private:
  std::vector<GroundContact> contacts_;
  Vector left_selector_, right_selector_;  // 1 on the side's contacts, 0 elsewhere
  std::vector<char> compressed_at_rest_;   // per contact, F >= 0 at the first sample
  Matrix group_selector_;  // [n_contacts x groups]: 1 where a contact is in the group
  std::vector<char> group_compressed_at_rest_;
  GroundContactSummary summary_;
  std::vector<double> left_, right_;
  std::vector<int> in_tension_;
};

}  // namespace dynamics
}  // namespace tracked_vehicle_dynamics
